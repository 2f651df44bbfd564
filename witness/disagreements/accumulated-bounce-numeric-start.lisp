;;;; scenarios/bouncing-ball.lisp -- a ball dropped on the floor bounces with coefficient of
;;;; restitution 1/2; the bounces come faster and faster, at times in a geometric series.
;;;;
;;;; Expected results: it lands after sqrt(2 h / g) with speed sqrt(2 g h), leaves at half
;;;; that speed and rises to h / 4 (then h / 16 ...); the impacts repeat with the factor
;;;; 1/2 and accumulate at sqrt(2 h / g) (1 + e) / (1 - e) = 3 sqrt(2 h / g); from then on
;;;; the ball rests on the floor (N = m g), forever.

(scenario bouncing-ball
  "A ball dropped on the floor bounces with e = 1/2 until it comes to rest."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (h :positive (:value 1)))
  (gravity g)
  (restitution 1/2)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body ball  :mass m :position (0 h) :velocity (0 0) :shape point)
  (simulate :states 6))
