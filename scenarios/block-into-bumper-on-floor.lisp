;;;; scenarios/block-into-bumper-on-floor.lisp -- a block slides along a frictionless floor
;;;; into a bumper spring fixed to a wall (a half-plane), compresses it and comes back.
;;;;
;;;; Expected results: the block meets the bumper's free end after d / v; it presses the
;;;; bumper for pi sqrt(m/k) (half a period of the block on the spring), the compression
;;;; reaching v sqrt(m/k) half-way (l0 > v sqrt(m/k): it never reaches the wall); it leaves
;;;; the bumper with velocity +v and slides away forever. The floor's normal force is m g
;;;; throughout; kinetic plus elastic energy stays m v^2 / 2.

(scenario block-into-bumper-on-floor
  "A block slides on a floor into a bumper spring on a wall and comes back."
  (parameters (m :positive (:value 2)) (k :positive (:value 8)) (g :positive (:value 981/100))
              (v :positive (:value 1)) (d :positive (:value 3))
              (l0 :positive (> l0 (* v (sqrt (/ m k)))) (:value 2)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (half-plane (0 0) (0 1)))
  (body block :mass m :position ((+ l0 d) 0) :velocity ((- v) 0)
        :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (spring bumper :from (wall (0 1/2)) :toward (1 0) :stiffness k :rest-length l0)
  (simulate :states 4))
