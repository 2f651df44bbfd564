;;;; scenarios/quadratic-drag-falling.lisp -- a ball dropped from rest through air (quadratic drag).
;;;;
;;;; Expected results (m v' = -m g + k v^2 while it falls, v(0) = 0): the velocity
;;;; v(t) = -sqrt(m g / k) tanh(t sqrt(g k / m)), approaching the terminal velocity
;;;; -sqrt(m g / k); the height y(t) = h - (m / k) ln cosh(t sqrt(g k / m)). The state lasts
;;;; forever (nothing below).

(scenario quadratic-drag-falling
  "A ball dropped from rest through air, quadratic drag -k |v| v."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (k :positive (:value 1/10)) (h :positive (:value 100)))
  (gravity g)
  (body ball :mass m :position (0 h) :velocity (0 0) :shape point)
  (drag air :on ball :quadratic k)
  (simulate :states 1))
