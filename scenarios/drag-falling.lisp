;;;; scenarios/drag-falling.lisp -- a ball dropped from rest in a viscous medium (linear drag).
;;;;
;;;; Expected results (m v' = -m g - c v, v(0) = 0): v(t) = -(m g / c) (1 - exp(-c t / m)),
;;;; approaching the terminal velocity -m g / c; y(t) = h - (m g / c) t + (m^2 g / c^2)
;;;; (1 - exp(-c t / m)). With the ground below, the ball reaches it at a time with no
;;;; elementary closed form (a Lambert W): a number under values.

(scenario drag-falling
  "A ball dropped from rest through a viscous medium, linear drag -c v."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (c :positive (:value 1/2)) (h :positive (:value 10)))
  (gravity g)
  (body ball :mass m :position (0 h) :velocity (0 0) :shape point)
  (drag air :on ball :linear c)
  (simulate :states 1))
