;;;; scenarios/disc-at-30-degrees.lisp -- a disc slides down a fixed 30 degree incline toward the floor.
;;;;
;;;; The incline is the fixed triangle (0 0) (sqrt(3) k, 0) (0 k) on a fixed floor
;;;; (y <= 0): its slope, of angle pi/6, descends toward +x from (0, k) to its foot
;;;; (sqrt(3) k, 0). A disc of radius r starts at rest touching the slope at a distance h
;;;; (along the slope) above the foot: its centre is that point plus r (1/2, sqrt(3)/2).
;;;; 0 < h < k keeps the contact point on the slope; r < h keeps the disc clear of the
;;;; floor ((2 - sqrt 3) r < h is what it needs).
;;;; (Once the simulator stopped here as ambiguous, missing the fact
;;;; 2 sqrt(h + (sqrt(3) - 2) r)/sqrt(g) <= 2 sqrt(h)/sqrt(g): issue 9.)
;;;;
;;;; Expected results (textbook):
;;;;   State 0: contact disc-incline; acceleration g/2 down the slope,
;;;;     A = (sqrt(3) g / 4, -g / 4), N = sqrt(3) m g / 2.
;;;;     The disc meets the floor when its centre is r above it, having slid
;;;;     h - (2 - sqrt 3) r along the slope:
;;;;       t1 = 2 sqrt(h + (sqrt(3) - 2) r) / sqrt(g),
;;;;     before its contact point reaches the foot (at 2 sqrt(h) / sqrt(g)):
;;;;     (:collision disc floor), which ends the run.

(scenario disc-at-30-degrees
  "A disc slides down a fixed 30 degree incline toward the floor."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (k :positive (:value 2))
              (h (> h 0) (< h k) (:value 1)) (r (> r 0) (< r h) (:value 1/4)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body incline :fixed t :shape (polygon (0 0) ((* (sqrt 3) k) 0) (0 k)))
  (body disc :mass m
             :position ((+ (* (sqrt 3) k) (- (/ (* (sqrt 3) h) 2)) (/ r 2))
                        (+ (/ h 2) (/ (* (sqrt 3) r) 2)))
             :velocity (0 0) :shape (circle r))
  (simulate :states 2))
