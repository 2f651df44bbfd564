;;;; scenarios/block-pushed-into-wall.lisp -- a block on a frictionless floor, pushed by a
;;;; constant force toward a wall: a plastic impact (e = 0) stops it there.
;;;;
;;;; Expected results: it reaches the wall after sqrt(2 m d / f) with speed sqrt(2 f d / m);
;;;; the impact takes all that momentum (impulse m sqrt(2 f d / m), kinetic energy lost f d);
;;;; then it stays against the wall, which pushes back with N = f, forever.

(scenario block-pushed-into-wall
  "A block pushed along a frictionless floor into a wall stays against it."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (f :positive (:value 5)) (d :positive (:value 1)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall  :fixed t :shape (half-plane ((+ d 1) 1) ((+ d 1) 0)))
  (body block :mass m :position (0 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (force push :on block :value (f 0))
  (simulate :states 3))
