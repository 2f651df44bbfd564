;;;; scenarios/block-launched-up-rough-incline.lisp -- a block launched up a rough incline stops, then sticks or slides back.
;;;;
;;;; A fixed incline without end (a half-plane whose surface descends toward +x at angle a
;;;; through the origin) and a square block of side b sitting flat on it, its reference
;;;; point the middle of its bottom face, at the origin, launched uphill with speed v0.
;;;; Coulomb friction between them, MU-K = MU-S = mu. Whether tan a < mu or tan a > mu is
;;;; left open: the default values (a = 1/2, tan a = 0.546, mu = 1/5) say tan a > mu.
;;;;
;;;; Expected results (textbook; u = (cos a, -sin a) the downhill direction):
;;;;   State 0: contact block-incline, face on face, sliding uphill.
;;;;     N = m g cos a; kinetic friction mu m g cos a downhill.
;;;;     Acceleration g (sin a + mu cos a) downhill: A = g (sin a + mu cos a) u.
;;;;     The block stops at t1 = v0 / (g (sin a + mu cos a)), after travelling
;;;;     d = v0^2 / (2 g (sin a + mu cos a)) uphill: (:stops-sliding block incline).
;;;;   State 1, when tan a < mu: static at rest forever; friction m g sin a uphill.
;;;;   State 1, when tan a > mu: it slides back down with acceleration
;;;;     g (sin a - mu cos a) u, friction mu m g cos a uphill, forever.
;;;;   With the assumptions alone, which of the two is undecided: the run names the
;;;;   missing fact (the sign of m g (sin a - mu cos a)) at the start of state 1.

(scenario block-launched-up-rough-incline
  "A block launched up a rough incline stops, then sticks or slides back."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (a (> a 0) (< a (/ pi 2)) (:value 1/2))
              (b :positive (:value 1))
              (v0 :positive (:value 2))
              (mu :positive (:value 1/5)))
  (gravity g)
  (body incline :fixed t :shape (half-plane ((cos a) (- (sin a))) (0 0)))
  (body block :mass m :position (0 0)
              :velocity ((- (* v0 (cos a))) (* v0 (sin a)))
              :shape (polygon ((- (* (/ b 2) (cos a))) (* (/ b 2) (sin a)))
                              ((* (/ b 2) (cos a)) (- (* (/ b 2) (sin a))))
                              ((+ (* (/ b 2) (cos a)) (* b (sin a)))
                               (+ (- (* (/ b 2) (sin a))) (* b (cos a))))
                              ((+ (- (* (/ b 2) (cos a))) (* b (sin a)))
                               (+ (* (/ b 2) (sin a)) (* b (cos a))))))
  (friction block incline :static mu)
  (simulate :states 3))
