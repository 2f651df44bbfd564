;;;; scenarios/block-hits-bumper.lisp -- a block slides on a frictionless floor into a bumper
;;;; spring fixed to a wall, is pushed back and leaves it.
;;;;
;;;; Expected results: the block meets the bumper's free end after d / v0; the contact lasts
;;;; pi sqrt(m/k) (half a period of the block on the spring), the compression reaching
;;;; v0 sqrt(m/k) half-way; the block leaves the bumper with velocity -v0 and slides away
;;;; forever. Kinetic plus elastic energy stays m v0^2 / 2 while it is pressed.

(scenario block-hits-bumper
  "A block slides into a bumper spring on a frictionless floor."
  (parameters (m :positive (:value 1)) (k :positive (:value 4)) (g :positive (:value 981/100))
              (v0 :positive (:value 1)) (d :positive (:value 1))
              (l0 :positive (> l0 (* v0 (sqrt (/ m k)))) (:value 1)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (polygon (-1 0) (0 0) (0 2) (-1 2)))
  (body block :mass m :position ((+ l0 d) 0) :velocity ((- v0) 0)
        :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (spring bumper :from (wall (0 1/2)) :toward (1 0) :stiffness k :rest-length l0)
  (simulate :states 3))
