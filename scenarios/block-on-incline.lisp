;;;; scenarios/block-on-incline.lisp -- a square block slides down a fixed frictionless incline.
;;;;
;;;; The incline is a fixed right triangle (0 0) (h/tan a, 0) (0 h): its slope, of angle
;;;; a, descends toward +x, from (0 h) to (h/tan a, 0); its length is L = h / sin a.
;;;; The block is a square of side b, tilted to sit flat on the slope (bodies translate
;;;; and do not rotate). Its reference point is the middle of its bottom face; with
;;;; u = (cos a, -sin a) the downhill direction and n = (sin a, cos a) the slope's
;;;; outward normal, its vertices are -(b/2)u, (b/2)u, (b/2)u + b n, -(b/2)u + b n
;;;; (counter-clockwise). It starts at rest with its bottom face centred on the middle
;;;; of the slope, (h/(2 tan a), h/2): face on face, away from any vertex. b < h < L,
;;;; so the face lies within the slope.
;;;;
;;;; Expected results (textbook):
;;;;   State 0: contact block-incline, face on face.
;;;;     Acceleration along the slope g sin a, downhill:
;;;;       A_block = (g sin a cos a, -g sin^2 a)
;;;;     Normal force N = m g cos a.
;;;;     The face-on-face contact lasts until the block's uphill bottom corner passes
;;;;     the foot of the slope, after sliding (L + b)/2 along it:
;;;;       t1 = sqrt((L + b) / (g sin a)) = sqrt((h / sin a + b) / (g sin a)),
;;;;     with speed g sin a t1. End event: the block leaves the end of the incline
;;;;     (:leaves block incline :endpoint).
;;;;   State 1: free fall (projectile) from there, acceleration (0, -g), forever
;;;;     (nothing lies below).

(scenario block-on-incline
  "A square block slides from rest down a fixed frictionless incline."
  (parameters (m :positive) (g :positive)
              (h :positive) (a (> a 0) (< a (/ pi 2)))
              (b (> b 0) (< b h)))
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
  (simulate :states 3))
