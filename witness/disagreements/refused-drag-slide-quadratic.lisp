;;;; refused-drag-slide-quadratic.lisp -- FIXED (now agrees: abs() of a linear function of
;;;; known sign written without it before the root search, src/simulator/abs-signs.lisp;
;;;; test QUADRATIC-DRAG-SLIDE-NEVER-TURNS). Was: a refusal make crosscheck found (drag-slide, seed 5,
;;;; #38; 5 of 10 drag-slide scenarios of that run are refused alike): a block sliding alone
;;;; on a frictionless floor under quadratic drag. Its velocity 9 / (9 + 2 tau) never
;;;; vanishes, but AMES cannot decide that the "turns" candidate has no root: the earliest
;;;; root of (81 + 18 tau + 9 |9 + 2 tau|) / ((9 + 2 tau) |9 + 2 tau|) = 0, where every term
;;;; is positive for tau >= 0 ("ambiguous", the run refused). For the lead: abs() of an
;;;; expression whose sign is known on tau >= 0 left in the candidate's equation.
;;;; Run: bin/ames check witness/disagreements/refused-drag-slide-quadratic.lisp --numeric

(scenario drag-slide-38 "A block slides through a medium with drag on a frictionless floor."
 (gravity 13/2) (restitution 1) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body block :mass 9/4 :position (0 0) :velocity (1 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
 (drag oil :on block :quadratic 1/2) (simulate :states 3))
