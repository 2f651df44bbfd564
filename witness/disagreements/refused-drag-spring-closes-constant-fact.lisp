;;;; refused-drag-spring-closes-constant-fact.lisp -- FIXED on main before this note (now
;;;; agrees, one state forever; t/witness-refusals.lisp's springs in oil test the cause).
;;;; Was: a refusal make crosscheck finds in the
;;;; drag-spring family (seed 777 #109; #225 and #312 alike): a block on a spring (rest length
;;;; 1, stretched to 1.15) in a viscous medium, moving away from the post at 2. AMES: "the run ended
;;;; ambiguous or undecided": the candidate (:spring-closes S) (the spring through zero length,
;;;; kb/springs.lisp's SPRING-CLOSING) has its time "not decided: -30139/32519 > 0", a constant
;;;; fact, false, that the earliest-event search leaves open instead of deciding (the spring,
;;;; damped, never reaches zero length: the candidate is :never). By hand: m = 3, k = 15/2,
;;;; b = 59/20: u = L - 1 = e^(-gamma t) (A cos w t + B sin w t), gamma = 59/120, w = 1.5028,
;;;; A = 3/20, B = 1.3800; its least value is -0.3244 (t = 2.853), so the length stays above
;;;; 0.676 and never reaches 0. Left for the lead (not a witness defect).
;;;; Run: bin/ames run witness/disagreements/refused-drag-spring-closes-constant-fact.lisp --numeric

(scenario drag-spring-109 "A block on a spring in a viscous medium." (gravity 53/4)
 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body post :fixed t :position (-1 0) :shape point)
 (body block :mass 3 :position ((+ 1 3/20) 0) :velocity (2 0) :shape point)
 (spring s :from (post (1 0)) :to (block (0 0)) :stiffness 15/2 :rest-length 1)
 (drag oil :on block :linear 59/20) (simulate :states 2))
