;;;; scenarios/disc-down-incline.lisp -- a disc (a circle body that does not rotate: it slides)
;;;; released on the slope of a fixed incline slides down and reaches the floor.

(scenario disc-down-incline
  "A disc slides from rest down a fixed frictionless incline onto the floor."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (h :positive (:value 2)) (r :positive (:value 1/10))
              (a (> a 0) (< a (/ pi 2)) (:value 1/2)))
  (gravity g)
  (body floor   :fixed t :shape (half-plane (1 0) (0 0)))
  (body incline :fixed t :position (0 0)
                :shape (polygon (0 0) ((/ h (tan a)) 0) (0 h)))
  ;; half-way down the slope, its centre r off the slope along the slope's normal
  (body disc :mass m :velocity (0 0) :shape (circle r)
             :position ((+ (/ h (* 2 (tan a))) (* r (sin a))) (+ (/ h 2) (* r (cos a)))))
  (simulate :states 3))
