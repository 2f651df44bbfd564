;;;; refused-drag-slide-wall-start.lisp -- refusals make crosscheck finds in the drag-slide
;;;; family (seed 4242 #21; seed 2611 #21 alike): a block at rest on a frictionless floor,
;;;; coasting under drag toward a wall. AMES: "No set of contacts and modes is consistent at
;;;; the start of the state" before its first state (same on main). Without the wall both
;;;; complete; the first (linear drag, b = 1/2, wall at 16) completes with the wall at 6, the
;;;; second (quadratic drag, wall at 6) does not, nor with a lower wall. Cause not found (no
;;;; time left): for the lead. The witness has it slide and hit the wall (or coast on).
;;;; Run: bin/ames check witness/disagreements/refused-drag-slide-wall-start.lisp --numeric

(scenario drag-slide-21 "A block slides through a medium with drag on a frictionless floor."
 (gravity 41/4) (restitution 0) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body wall :fixed t :shape (polygon (16 0) (17 0) (17 2) (16 2)))
 (body block :mass 5/2 :position (0 0) :velocity (3 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
 (drag oil :on block :linear 1/2) (simulate :states 3))

(scenario drag-slide-21-quadratic "A block slides through a medium with drag on a frictionless floor."
 (gravity 37/4) (restitution 0) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body wall :fixed t :shape (polygon (6 0) (7 0) (7 2) (6 2)))
 (body block :mass 2 :position (0 0) :velocity (5/2 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
 (drag oil :on block :quadratic 9/50) (simulate :states 3))
