;;;; scenarios/block-sliding-down-rough-incline.lisp -- a block on a rough incline too steep to stick slides down and off.
;;;;
;;;; The incline and the block are those of block-on-incline.lisp (a fixed right triangle
;;;; of height h and angle a, slope length L = h / sin a; a square block of side b < h
;;;; sitting flat on the middle of its slope, at rest), with Coulomb friction between
;;;; them: MU-K = MU-S = mu, and tan a > mu (too steep to stick).
;;;;
;;;; Expected results (textbook):
;;;;   State 0: contact block-incline, face on face, sliding down.
;;;;     Normal force N = m g cos a; kinetic friction mu m g cos a up the slope (the
;;;;     contact's unit tangent points uphill: reported value + mu m g cos a).
;;;;     Acceleration along the slope g (sin a - mu cos a), downhill:
;;;;       A_block = g (sin a - mu cos a) (cos a, -sin a).
;;;;     It slides (L + b)/2 until its uphill bottom corner passes the foot of the slope:
;;;;       t1 = sqrt((h / sin a + b) / (g (sin a - mu cos a))),
;;;;     (:leaves block incline :endpoint), with speed g (sin a - mu cos a) t1.
;;;;   State 1: free fall from there, acceleration (0, -g), forever.

(scenario block-sliding-down-rough-incline
  "A block at rest on a rough incline with tan a > mu slides down and off its foot."
  (parameters (m :positive) (g :positive)
              (h :positive) (a (> a 0) (< a (/ pi 2)))
              (b (> b 0) (< b h))
              (mu :positive (< mu (tan a))))
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
  (friction block incline :static mu)
  (simulate :states 3))
