;;;; refused-step-meets-undecided.lisp -- FIXED (now agrees; t/witness-refusals-roots.lisp):
;;;; the particle crosses the line of the step's bottom face, beyond the face's end, at the
;;;; moment it lands on the floor; the search for a later crossing took that root again,
;;;; Maxima's sign() having called the product of the roots (0, written with radicals) "neg"
;;;; (src/algebra/round-off.lisp decides such a constant exactly or leaves it open).
;;;; Was: a refusal make crosscheck finds in the step family
;;;; (seed 777 #235): a particle thrown horizontally at 5/2 from (0, 4) toward a step
;;;; (x from 3/4 to 9/4, top at 5/4), g = 29/4, e = 1/2. By hand: it lands on the step's top
;;;; at t = sqrt(22/29) = 0.871, x = 2.177 (< 9/4), and bounces up at 3.16 while moving right
;;;; at 5/2: it passes the step's right end (x = 9/4) 0.029 s later, 0.09 above the top, and
;;;; lands on the floor (state 1, tau = (sqrt(11) + sqrt(31))/sqrt(58) = 1.167). State 0
;;;; checks; in state 1 AMES leaves open "(:meets particle step)", a contact with the step the
;;;; particle, above the top and then beyond the step moving away, never makes: refused
;;;; (ambiguous), never wrong. Left for the corners helper / lead (a face's extent).
;;;; Run: bin/ames run witness/disagreements/refused-step-meets-undecided.lisp --numeric

(scenario step-235 "A particle thrown toward a step on the floor." (gravity 29/4) (restitution 1/2)
 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body step :fixed t :shape (polygon (3/4 0) ((+ 3/4 3/2) 0) ((+ 3/4 3/2) 5/4) (3/4 5/4)))
 (body particle :mass 1 :position (0 (+ 5/4 11/4)) :velocity (5/2 0) :shape point)
 (simulate :states 3))
