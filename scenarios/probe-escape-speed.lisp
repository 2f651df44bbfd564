;;;; scenarios/probe-escape-speed.lisp -- a probe launched straight up from a fixed planet
;;;; under universal gravitation, below and above the escape speed sqrt(2 G M / r).
;;;;
;;;; Expected results: along the line of centres (s the distance from the planet's centre)
;;;; the energy integral is s'^2 = v0^2 - 2 G M (1/r - 1/s). Below the escape speed the
;;;; probe turns where that vanishes, at s = 2 G M r / (2 G M - r v0^2) (11.43 with the
;;;; defaults), and falls back to collide with the planet at s = r with speed v0, after the
;;;; same time again. Above it, s'^2 stays above v0^2 - 2 G M / r > 0: the probe escapes and
;;;; the state lasts forever.

(scenario probe-below-escape-speed
  "A probe launched straight up from a planet's surface too slowly to escape."
  (parameters (m :positive (:value 1)) (big-m :positive (:value 1000)) (big-g :positive (:value 1))
              (r :positive (:value 10))
              (v0 :positive (:value 5)))
  (gravitation big-g)
  (body planet :mass big-m :fixed t :position (0 0) :shape (circle r))
  (body probe :mass m :position (0 r) :velocity (0 v0) :shape point)
  (simulate :states 2))

(scenario probe-above-escape-speed
  "A probe launched straight up from a planet's surface fast enough to escape."
  (parameters (m :positive (:value 1)) (big-m :positive (:value 1000)) (big-g :positive (:value 1))
              (r :positive (:value 10))
              (v0 :positive (> v0 (sqrt (/ (* 2 big-g big-m) r))) (:value 20)))
  (gravitation big-g)
  (body planet :mass big-m :fixed t :position (0 0) :shape (circle r))
  (body probe :mass m :position (0 r) :velocity (0 v0) :shape point)
  (simulate :states 2))
