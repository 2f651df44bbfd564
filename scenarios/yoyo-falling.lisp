;;;; scenarios/yoyo-falling.lisp -- a yo-yo falls as its string, wound on its
;;;; axle and tied to the ceiling, unwinds.
;;;;
;;;; The yo-yo: a disc of radius R, mass m, inertia I about its centre; the string is wound
;;;; on its axle of radius r and goes straight up to the ceiling.
;;;; Expected results (textbook): a = g / (1 + I / (m r^2)) downwards, tension
;;;; m g - m a = m g / (1 + m r^2 / I), angular acceleration a / r (counter-clockwise: the
;;;; string leaves the axle on its right side, at (r 0)).

(scenario yoyo-falling
  "A yo-yo falls as its string unwinds from its axle."
  (parameters (m :positive (:value 1/5)) (g :positive (:value 981/100))
              (big-r :positive (:value 1/20)) (r :positive (< r big-r) (:value 1/100))
              (i :positive (:value 1/4000)) (top :positive (> top big-r) (:value 1)))
  (gravity g)
  (body ceiling :fixed t :shape (half-plane (0 top) (1 top)))
  (body yoyo :mass m :inertia i :shape (circle big-r) :position (0 0) :velocity (0 0))
  (rope string :length top :through ((ceiling (r top)) (yoyo (r 0) :wound)))
  (simulate :states 1 :until 1/2))
