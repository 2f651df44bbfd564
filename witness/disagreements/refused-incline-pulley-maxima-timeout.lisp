;;;; refused-incline-pulley-maxima-timeout.lisp -- AMES stops with "Maxima did not answer
;;;; within 20.00 s" (at the body particle) on a particle on an incline tied over a pulley
;;;; on the slope's line to a hanging mass, exact values (the scenarios/incline-and-hanging-
;;;; mass.lisp pattern with other numbers). Found by make crosscheck (family incline-pulley:
;;;; most of them).
;;;; Fixed (branch refusals): the particle and the weight, coupled only through the rope over
;;;; the incline's pulley, were integrated as two groups (the weight's motion solved with the
;;;; particle's state as constants: the timeout). Now state 0 agrees with the witness, state 1
;;;; (the particle off the top corner, the rope turning) is integrated numerically and ends
;;;; when the particle reaches the pulley (:rope-piece-closes), which the witness does not
;;;; model (verdict unsupported); a third state would be refused as not modelled.

(scenario incline-pulley-11 "A particle on an incline pulled over a pulley by a hanging mass."
 (gravity 43/4) (body incline :fixed t :shape (polygon (0 0) (6 0) (6 5/2)))
 (body particle :mass 5/2 :position (9/2 15/8) :velocity (0 0) :shape point)
 (pulley top :on incline :at (15/2 25/8))
 (body weight :mass 7/4 :position (15/2 15/8) :velocity (0 0) :shape point)
 (rope line :length 9/2 :through ((particle (0 0)) top (weight (0 0)))) (simulate :states 2))
