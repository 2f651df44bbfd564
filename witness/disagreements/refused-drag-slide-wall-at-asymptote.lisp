;;;; refused-drag-slide-wall-at-asymptote.lisp -- a refusal make crosscheck found (drag-slide,
;;;; seed 4242, #21): a block coasting under linear drag, b = 1/2, m = 5/2, v = 3, toward a
;;;; wall whose face is exactly at the coast's asymptote: the block's front x + 1 tends to
;;;; 1 + m v / b = 16 and never reaches the wall (the witness: it slides on forever). AMES:
;;;; "No set of contacts and modes is consistent at the start of the state" (same on main;
;;;; with the wall at 6 or with no wall the run completes). For the lead: an AMES defect
;;;; at the start of a state whose only event candidate never happens, asymptotically. The
;;;; generator no longer puts the wall there (generate-drag.lisp).
;;;; Run: bin/ames check witness/disagreements/refused-drag-slide-wall-at-asymptote.lisp --numeric

(scenario drag-slide-21 "A block slides through a medium with drag on a frictionless floor."
 (gravity 41/4) (restitution 0) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body wall :fixed t :shape (polygon (16 0) (17 0) (17 2) (16 2)))
 (body block :mass 5/2 :position (0 0) :velocity (3 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
 (drag oil :on block :linear 1/2) (simulate :states 3))
