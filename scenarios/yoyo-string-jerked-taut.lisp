;;;; scenarios/yoyo-string-jerked-taut.lisp -- a yo-yo dropped with its string slack falls
;;;; freely the height s until the string, wound on its axle, jerks taut (an impact through
;;;; a rope wound on a turning disc), then falls unwinding.
;;;;
;;;; Expected results (textbook): it arrives at v = -sqrt(2 g s); the plastic jerk J keeps
;;;; the string's length (v' = -r omega'): m (v' - v) = J, I omega' = r J, so
;;;; v' = m r^2 v / (I + m r^2), omega' = m r |v| / (I + m r^2) (counter-clockwise: the string
;;;; leaves the axle on its right), J = m I |v| / (I + m r^2), and the energy lost
;;;; m g s I / (I + m r^2). After it, the yo-yo's a = -g / (1 + I / (m r^2)).

(scenario yoyo-string-jerked-taut
  "A yo-yo dropped with its string slack falls freely until the string jerks taut."
  (parameters (m :positive (:value 1/5)) (g :positive (:value 981/100))
              (big-r :positive (:value 1/20)) (r :positive (< r big-r) (:value 1/100))
              (i :positive (:value 1/4000)) (top :positive (> top big-r) (:value 1))
              (s :positive (< s top) (:value 1/5)))
  (gravity g)
  (body ceiling :fixed t :shape (half-plane (0 top) (1 top)))
  (body yoyo :mass m :inertia i :shape (circle big-r) :position (0 (- s)) :velocity (0 0))
  (rope string :length (+ top s s) :through ((ceiling (r top)) (yoyo (r 0) :wound)))
  (simulate :states 2))
