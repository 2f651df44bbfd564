;;;; scenarios/quadratic-drag-projectile.lisp -- a ball launched at an angle through air
;;;; (quadratic drag).
;;;;
;;;; Expected results: the motion in two dimensions has no closed form (the state says so
;;;; without values); under values it is integrated numerically until the ball meets the
;;;; ground, at about t = 1.733 (m = 1, g = 9.81, k = 0.05, v = (10, 10); without drag it
;;;; would be 2.039). Nothing ends the flight earlier: the velocity never reverses.

(scenario quadratic-drag-projectile
  "A ball launched at an angle over flat ground, quadratic drag -k |v| v."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (k :positive (:value 1/20)) (vx :positive (:value 10)) (vy :positive (:value 10)))
  (gravity g)
  (body ground :fixed t :shape (half-plane (1 0) (0 0)))
  (body ball :mass m :position (0 0) :velocity (vx vy) :shape point)
  (drag air :on ball :quadratic k)
  (simulate :states 1))
