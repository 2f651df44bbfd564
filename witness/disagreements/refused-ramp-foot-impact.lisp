;;;; refused-ramp-foot-impact.lisp -- AMES refuses (honestly) a particle that slides down a
;;;; ramp standing on the floor and hits the floor at the ramp's foot with e > 0 (with e = 0
;;;; it runs): "No set of contacts and modes is consistent at the start of the state."
;;;; The witness (Siconos) has the particle bounce off the floor at the foot, leaving the
;;;; ramp. Found by make crosscheck (family ramp: about half of them, every e > 0).

(scenario ramp-1 "A particle slides down a ramp onto the floor." (gravity 45/4) (restitution 1)
 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body ramp :fixed t :shape (polygon (0 0) (9/4 0) (0 7/4)))
 (body particle :mass 1 :position ((/ 9/4 2) (/ 7/4 2)) :velocity (0 0) :shape point)
 (simulate :states 3))
