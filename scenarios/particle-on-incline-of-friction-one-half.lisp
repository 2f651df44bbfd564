;;;; scenarios/particle-on-incline-of-friction-one-half.lisp -- a particle at rest on an
;;;; incline whose static friction coefficient is the number 1/2 (kinetic 1/4): the angle
;;;; alone decides whether it slides.
;;;;
;;;; Expected results (textbook): the particle sticks while m g sin a <= mu_s m g cos a,
;;;; tan a <= 1/2; the run forks on 2 sin a - cos a (sin a - cos a / 2 times 2):
;;;;   2 sin a - cos a > 0: it slides down at g (sin a - cos a / 4) along the slope, a
;;;;     distance h / (2 sin a) (from half height to the foot), arriving at
;;;;     t1 = sqrt(4 h / (g sin a (4 sin a - cos a))), then flies off (free fall);
;;;;   2 sin a - cos a < 0: it stays, held by static friction m g sin a, for ever;
;;;;   2 sin a - cos a = 0, the boundary a = atan(1/2) (sin a = 1/sqrt 5, cos a = 2/sqrt 5):
;;;;     static friction just holds it, F = m g / sqrt 5, N = 2 m g / sqrt 5, at x = h.
;;;; The boundary's angle is the one root of 2 sin a - cos a in 0 < a < pi/2, found with
;;;; half angles (src/algebra/one-angle-cells.lisp); the sliding branch's later order of
;;;; events is decided under the branch's own fact in the angle alone.

(scenario particle-on-incline-of-friction-one-half
  "A particle at rest on an incline of static friction 1/2 slides when tan a > 1/2."
  (parameters (m :positive) (g :positive)
              (h :positive) (a (> a 0) (< a (/ pi 2))))
  (gravity g)
  (body incline :fixed t :position (0 0)
                :shape (polygon (0 0) ((/ h (tan a)) 0) (0 h)))
  (body particle :mass m :shape point
                 :position ((/ h (* 2 (tan a))) (/ h 2))
                 :velocity (0 0))
  (friction particle incline :static 1/2 :kinetic 1/4)
  (simulate :states 2))
