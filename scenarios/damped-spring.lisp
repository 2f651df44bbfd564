;;;; scenarios/damped-spring.lisp -- a block on a horizontal spring in a viscous medium: the
;;;; damped harmonic oscillator m x'' + c x' + k x = 0.
;;;;
;;;; Expected results: with x the stretch from rest length and the block pulled out by a and
;;;; released, the discriminant c^2 - 4 m k decides the motion: under-damped (c^2 < 4 m k),
;;;; x = a exp(-c t / (2 m)) (cos(w t) + c sin(w t) / (2 m w)), w = sqrt(4 m k - c^2) / (2 m);
;;;; critically damped (c^2 = 4 m k) and over-damped (c^2 > 4 m k) otherwise. The assumptions
;;;; here do not decide it: the run branches three ways. Pulled out by a < l0, the block never
;;;; reaches the wall point (released from rest, the stretch never exceeds a): the spring
;;;; never shrinks to zero length.

(scenario damped-spring
  "A block on a spring in a viscous medium, pulled out and released."
  (parameters (m :positive (:value 1)) (k :positive (:value 4)) (c :positive (:value 1/2))
              (l0 :positive (:value 1)) (a :positive (< a l0) (:value 1/5)) (g :positive (:value 981/100)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :position (-1 0) :shape point)
  (body block :mass m :position ((+ l0 a) 0) :velocity (0 0) :shape point)
  (spring s :from (wall (1 0)) :to (block (0 0)) :stiffness k :rest-length l0)
  (drag oil :on block :linear c)
  (simulate :states 2))
