;;;; refused-raised-ramp-quotient-by-zero.lisp -- (fixed: now agrees) AMES stopped with "Maxima failed:
;;;; `quotient' by `zero'" on a particle at rest on a raised ramp (slope rising 3/2 over 1,
;;;; foot 3 above the floor); the witness has it leave the ramp's end and land on the
;;;; floor. Found by make crosscheck (family raised-ramp, several seeds).

(scenario raised-ramp-26 "A particle slides off a raised ramp and falls to the floor." (gravity 9)
 (restitution 0) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body ramp :fixed t :shape (polygon (0 0) (1 0) (1 3) (0 (+ 3 3/2))))
 (body particle :mass 1 :position ((/ 1 2) (+ 3 (/ 3/2 2))) :velocity (0 0) :shape point)
 (simulate :states 3))
