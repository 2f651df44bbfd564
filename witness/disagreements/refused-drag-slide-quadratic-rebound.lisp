;;;; refused-drag-slide-quadratic-rebound.lisp -- a refusal make crosscheck found (drag-slide,
;;;; seed 5, #2): a block under quadratic drag on a frictionless floor bounces off a wall
;;;; (e = 1/2). After the rebound AMES cannot decide which event ends the state ("ambiguous":
;;;; the earliest root of expressions with abs(...) of the velocity, a turning point that
;;;; never comes: under quadratic drag the velocity v0 / (1 + c v0 t / m) never reaches 0).
;;;; For the lead: the sign of |v| v along a line where v keeps its sign.
;;;; Run: bin/ames check witness/disagreements/refused-drag-slide-quadratic-rebound.lisp --numeric

(scenario drag-slide-2 "A block slides through a medium with drag on a frictionless floor."
 (gravity 47/4) (restitution 1/2) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body wall :fixed t :shape (polygon (6 0) (7 0) (7 2) (6 2)))
 (body block :mass 3/4 :position (0 0) :velocity (4 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
 (drag oil :on block :quadratic 3/50) (simulate :states 3))
