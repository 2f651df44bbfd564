;;;; scenarios/particle-off-raised-ramp.lisp -- a particle slides down a ramp whose foot is raised, off its end, and falls.
;;;;
;;;; A fixed ramp, the quadrilateral (0 0) (l 0) (l h0) (0 h0 + l tan a), stands on a fixed
;;;; floor (y <= 0): its top face, of angle a, descends toward +x and ends at (l, h0), a
;;;; height h0 above the floor, where a vertical face drops to the floor. A particle
;;;; starts at rest in the middle of the top face, (l/2, h0 + l tan(a) / 2).
;;;; (Once the simulator stopped here as ambiguous, missing the fact
;;;; sqrt(2 h0 + l tan a)/(sin a sqrt g) <= sqrt(l)/(sqrt(cos a) sqrt(sin a) sqrt g), which
;;;; is false for every h0 > 0: issue 9.)
;;;;
;;;; Expected results (textbook):
;;;;   State 0: contact particle-ramp on the top face; acceleration g sin a down the slope,
;;;;     A = (g sin a cos a, -g sin^2 a). Sliding (l/2)/cos a to the end of the face takes
;;;;       t1 = sqrt(l / (g sin a cos a)),
;;;;     before the particle could reach the floor's level along the slope's line (at
;;;;     sqrt(2 h0 + l tan a) / (sin a sqrt g), later since h0 > 0): (:leaves particle
;;;;     ramp :endpoint), at (l, h0), with speed v = sqrt(g l tan a) along (cos a, -sin a).
;;;;   State 1: a projectile from (l, h0): A = (0, -g); it lands on the floor after
;;;;       t2 = (sqrt(v^2 sin^2 a + 2 g h0) - v sin a) / g,
;;;;     at x = l + v cos a t2: (:collision particle floor), which ends the run.

(scenario particle-off-raised-ramp
  "A particle slides down a ramp whose foot is raised h0 above the floor, off its end, and falls."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (h0 :positive (:value 1)) (l :positive (:value 2))
              (a (> a 0) (< a (/ pi 2)) (:value 1/2)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body ramp :fixed t :position (0 0)
             :shape (polygon (0 0) (l 0) (l h0) (0 (+ h0 (* l (tan a))))))
  (body particle :mass m :position ((/ l 2) (+ h0 (/ (* l (tan a)) 2))) :velocity (0 0)
                 :shape point)
  (simulate :states 3))
