;;;; scenarios/quadratic-drag-projectile.lisp -- a ball launched at an angle through air
;;;; (quadratic drag): the motion in two dimensions has no closed form; under values it is
;;;; integrated numerically until the ball lands on the ground.

(scenario quadratic-drag-projectile
  "A ball launched at an angle over flat ground, quadratic drag -k |v| v."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (k :positive (:value 1/20)) (vx :positive (:value 10)) (vy :positive (:value 10)))
  (gravity g)
  (body ground :fixed t :shape (half-plane (1 0) (0 0)))
  (body ball :mass m :position (0 0) :velocity (vx vy) :shape point)
  (drag air :on ball :quadratic k)
  (simulate :states 1))
