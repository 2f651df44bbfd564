;;;; ames-wrong-rod-on-ledge.lisp -- a wrong impact found in the closing review (issue 23), left.
;;;; A fresh textbook problem: a uniform rod (length 2) falls flat from 0.2 onto a ledge whose
;;;; top ends at x = 0; the rod spans x in [-0.1, 1.9], so it lands on its left end (-0.1)
;;;; and on the ledge's corner (0, 0). Right answer (plastic, I = m l^2 / 12): only the
;;;; ledge's corner pushes (arm 0.9): J = m v / 3.43 = 0.583 m, v' = 1.417 down, omega' =
;;;; 1.574 clockwise, the left end leaving upward.
;;;; AMES (bin/ames run FILE --numeric, exit 3): the impact takes both ends of the rod as
;;;; corner contacts on the ledge's top face, the right end (x = 1.9) past the face's end
;;;; included (corner-touching in src/kb/corners.lisp is the gap alone, without the place
;;;; within the face), and stops the rod dead with two equal impulses m v / 2; then it forks
;;;; and the branch fails. Two things are missing: the face's extent in a corner's
;;;; activation, and a fixed body's corner against a rotating body's face.
(scenario rod-on-ledge "A horizontal rod falls and one end strikes a ledge."
  (parameters (m :positive (:value 1)) (g :positive (:value 10)) (l :positive (:value 2))
              (h :positive (:value 1/5)))
  (gravity g)
  (body ledge :fixed t :shape (polygon (-3 -1) (0 -1) (0 0) (-3 0)))
  (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
            :position ((- (/ l 2) (/ 1 10)) h) :velocity (0 0))
  (restitution rod ledge 0)
  (simulate :states 2))
