;;;; scenarios/incline-and-hanging-mass.lisp -- a particle on a fixed 3-4-5 incline tied by a rope,
;;;; over a pulley on the slope's line just beyond its top, to a hanging mass.
;;;;
;;;; Expected results: with sin a = 3/5 and the hanging mass m2 = m1 sin a + e heavier than
;;;; the pull along the slope needs, the particle accelerates up the slope at
;;;; g (m2 - 3 m1/5)/(m1 + m2) = g e/(m1 + m2), the hanging mass down as fast, the tension is
;;;; 8 g m1 m2 / (5 (m1 + m2)) (that is m1 m2 g (1 + sin a)/(m1 + m2)), and the particle, 5/2
;;;; below the top along the slope, reaches the top corner after sqrt(5 (m1 + m2)/(g e)):
;;;; (:leaves particle incline :endpoint).

(scenario incline-and-hanging-mass
  "A particle on an incline pulled up by a hanging mass over a pulley."
  (parameters (m1 :positive (:value 1)) (e :positive (:value 2/5)) (g :positive (:value 981/100)))
  (gravity g)
  (body incline :fixed t :shape (polygon (0 0) (4 0) (4 3)))
  (body particle :mass m1 :position (2 3/2) :velocity (0 0) :shape point)
  (body weight :mass (+ (* 3/5 m1) e) :position (22/5 1) :velocity (0 0) :shape point)
  (pulley top :on incline :at (22/5 33/10))
  (rope line :length 53/10 :through ((particle (0 0)) top (weight (0 0))))
  (simulate :states 1))
