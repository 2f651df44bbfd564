;;;; scenarios/block-sticking-on-rough-incline.lisp -- a block at rest on a rough incline steep enough to need friction, not too steep to stick.
;;;;
;;;; The incline and the block are those of block-on-incline.lisp (a fixed right triangle
;;;; of height h and angle a; a square block of side b sitting flat on the middle of its
;;;; slope, at rest), with Coulomb friction between them: MU-S = mu, MU-K = muk <= mu,
;;;; and tan a < mu. Here muk < tan a is allowed: sliding down with kinetic friction
;;;; would then be consistent too, but a pair that can stick does not start sliding.
;;;;
;;;; Expected results (textbook):
;;;;   State 0: contact block-incline, face on face, static.
;;;;     Normal force N = m g cos a; friction m g sin a up the slope (the contact's unit
;;;;     tangent points uphill, so the reported value is + m g sin a); no motion:
;;;;     acceleration (0, 0), forever. End event: none.

(scenario block-sticking-on-rough-incline
  "A block at rest on a rough incline sticks when tan a < mu."
  (parameters (m :positive) (g :positive)
              (h :positive) (a (> a 0) (< a (/ pi 2)))
              (b (> b 0) (< b h))
              (mu :positive (> mu (tan a)))
              (muk :positive (<= muk mu)))
  (gravity g)
  (body incline :fixed t :position (0 0)
                :shape (polygon (0 0) ((/ h (tan a)) 0) (0 h)))
  (body block :mass m
              :position ((/ h (* 2 (tan a))) (/ h 2))
              :velocity (0 0)
              :shape (polygon ((- (* (/ b 2) (cos a))) (* (/ b 2) (sin a)))
                              ((* (/ b 2) (cos a)) (- (* (/ b 2) (sin a))))
                              ((+ (* (/ b 2) (cos a)) (* b (sin a)))
                               (+ (- (* (/ b 2) (sin a))) (* b (cos a))))
                              ((+ (- (* (/ b 2) (cos a))) (* b (sin a)))
                               (+ (* (/ b 2) (sin a)) (* b (cos a))))))
  (friction block incline :static mu :kinetic muk)
  (simulate :states 3))
