;;;; refused-drag-slide-wall-start.lisp -- FIXED (both agree; t/witness-refusals.lisp). Was:
;;;; refusals make crosscheck found in the drag-slide family (seed 4242 #21; seed 2611 #21
;;;; alike): a block on a frictionless floor, coasting under drag toward a wall. AMES: "No set
;;;; of contacts and modes is consistent at the start of the state". Two causes:
;;;;  - linear drag, the wall at 16 exactly where the block's coasting ends (x0 + m v / b):
;;;;    the gap 45 exp(-tau/5) has no root, but the root search could not say so, and the
;;;;    numeric root search took the round-off at tau = 184 for a collision; the next state
;;;;    (at rest against the wall, as if it had arrived) was inconsistent. Fixed: a gap proven
;;;;    of one sign after the start (Maxima's signs under tau > 0) never meets.
;;;;  - quadratic drag, the block stopped against the wall by its plastic impact: the wall's
;;;;    normal force is zero at the start and its series has derivatives of |v| = 0/0 at
;;;;    v = 0. Fixed: the one-sided series for tau > 0 (src/simulator/one-sided-series.lisp).
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
