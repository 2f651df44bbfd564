;;;; witness/disagreements/accumulated-bounce-numeric-start.lisp -- a known disagreement
;;;; found by the witness (issue 21); run: bin/ames check THIS-FILE --numeric
;;;;
;;;; A ball dropped from h = 1 (g = 9.81, e = 1/2) bounces; AMES sums the Zeno sequence of
;;;; impacts and starts the state at rest (state 2) at the accumulation time
;;;; 3 sqrt(2 h / g) = 1.3545709 s, as its closed form :start says. But its :numeric :start
;;;; for that state is 0.9030473 s: add-numeric-values (src/simulator/simulate.lisp) takes
;;;; each state's numeric start as the running sum of the numeric durations, which skips
;;;; the summed impacts. The witness (Siconos, event-driven) puts the end of the sequence at
;;;; 1.3545703 s (its own tolerance ends the series; compared to 1e-5). Every scenario with
;;;; a summed Zeno sequence and parameter values shows it (any 0 < e < 1 bounce).
;;;; t/witness.lisp keeps this file in *KNOWN-DISAGREEMENTS*: when it is fixed, the test
;;;; says so.

(scenario accumulated-bounce-numeric-start
  "A ball dropped on the floor bounces with e = 1/2 until it comes to rest."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (h :positive (:value 1)))
  (gravity g)
  (restitution 1/2)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body ball  :mass m :position (0 h) :velocity (0 0) :shape point)
  (simulate :states 6))
