;;;; refused-drag-slide-log-gap-4242-4.lisp -- FIXED (now agrees; t/witness-refusals.lisp).
;;;; Was: a refusal make crosscheck found (drag-slide, seed 4242, #4): a block under quadratic
;;;; drag bounces off a wall (e = 1/2) and moves away; its gap to the wall grows as
;;;; (m/c) log(1 + c v' tau / m), whose root at the start the root search could not set
;;;; aside ("ambiguous": the earliest root of a log). Fixed: a gap proven of one sign after
;;;; the start under tau > 0 (Maxima's signs know log(X) > 0 for X > 1) never meets.
;;;; Run: bin/ames check witness/disagreements/refused-drag-slide-log-gap-4242-4.lisp --numeric

(scenario drag-slide-4 "A block slides through a medium with drag on a frictionless floor."
 (gravity 25/2) (restitution 1/2) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body wall :fixed t :shape (polygon (16 0) (17 0) (17 2) (16 2)))
 (body block :mass 9/4 :position (0 0) :velocity (3 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
 (drag oil :on block :quadratic 2/5) (simulate :states 3))
