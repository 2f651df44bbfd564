;;;; scenarios/rod-and-disc-pendulums.lisp -- physical pendulums: a uniform rod hinged at one
;;;; end released at an angle b below the horizontal, and a uniform disc hinged at a point of
;;;; its rim released at an angle b from the vertical.
;;;;
;;;; Source type: the textbook's physical pendulum (first-year mechanics; energy with the
;;;; moment of inertia about the pivot, parallel axes). Expected results (textbook):
;;;;   rod (I about the hinge m l^2 / 3): at the bottom omega = -sqrt(3 g (1 - sin b) / l),
;;;;     the hinge pulls up with m g + m omega^2 l / 2 = m g (5 - 3 sin b) / 2; at release
;;;;     alpha = -3 g cos b / (2 l) and the hinge force (-3 m g sin b cos b / 4,
;;;;     m g (1 + 3 sin^2 b) / 4); it swings between the angles -b and b - pi with the period
;;;;     4 sqrt(2 l / (3 g)) K(k^2), k = sin(theta0 / 2), theta0 = pi/2 - b the amplitude
;;;;     from the vertical;
;;;;   disc (I about the rim point 3 m r^2 / 2, the equivalent length 3 r / 2): the period
;;;;     4 sqrt(3 r / (2 g)) K(sin^2(b/2)), 2 pi sqrt(3 r / (2 g)) for small b; at the
;;;;     bottom omega = -2 sqrt(g (1 - cos b) / (3 r));
;;;;   rod hinged at its lower end, upright, nudged at w0 (counter-clockwise): it turns over
;;;;     and over (no turning point), omega^2 = w0^2 + 3 g / l horizontal, w0^2 + 6 g / l at
;;;;     the bottom, where the hinge pulls up with m g + m omega^2 l / 2 = 4 m g + m l w0^2 / 2.

(scenario rod-hinged-released-at-an-angle
  "A uniform rod hinged at one end swings down from an angle b below the horizontal."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1))
              (b (> b 0) (< b (/ pi 2)) (:value (deg 30))))
  (gravity g)
  (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
            :position ((* (/ l 2) (cos b)) (- (* (/ l 2) (sin b)))) :angle (- b) :velocity (0 0))
  (hinge pin :body rod :at ((- (/ l 2)) 0))
  (query omega-at-bottom (value (angular-velocity rod) :at (reaches (angle rod) (- (/ pi 2)))))
  (query hinge-at-bottom (value (y (hinge-force pin)) :at (reaches (angle rod) (- (/ pi 2)))))
  (query alpha-at-release (value (angular-acceleration rod) :at (start 0)))
  (query hinge-at-release (value (hinge-force pin) :at (start 0)))
  (simulate :states 2))

(scenario disc-hinged-at-its-rim
  "A uniform disc hinged at a point of its rim swings from an angle b."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (r :positive (:value 1/5))
              (b (> b 0) (< b (/ pi 2)) (:value 1/10)))
  (gravity g)
  (body disc :mass m :inertia :uniform :shape (circle r)
        :position ((* r (sin b)) (- (* r (cos b)))) :velocity (0 0))
  (hinge pin :body disc :at ((- (* r (sin b))) (* r (cos b))))
  (query omega-at-bottom (value (angular-velocity disc) :at (reaches (angle disc) (- b))))
  (simulate :states 2))

(scenario rod-nudged-from-upright
  "A uniform rod hinged at its lower end, upright, nudged with angular velocity w0, turns over."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1))
              (w0 :positive (:value 1/10)))
  (gravity g)
  (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
            :position (0 (/ l 2)) :angle (/ pi 2) :velocity ((- (* w0 (/ l 2))) 0) :angular-velocity w0)
  (hinge pin :body rod :at ((- (/ l 2)) 0))
  (query omega-horizontal (value (angular-velocity rod) :at (reaches (angle rod) pi)))
  (query omega-bottom (value (angular-velocity rod) :at (reaches (angle rod) (* 3/2 pi))))
  (query hinge-bottom (value (y (hinge-force pin)) :at (reaches (angle rod) (* 3/2 pi))))
  (simulate :states 2))
