;;;; scenarios/rod-hinged-strikes-floor.lisp -- a uniform rod hinged at one end, released
;;;; horizontal at the height l/2 above a floor, swings down until its free end strikes the
;;;; floor (an impact of a rotating body while a hinge holds it).
;;;;
;;;; Expected results (textbook): the free end reaches the floor at the angle -pi/6 with
;;;; omega = -sqrt(3 g / (2 l)) (energy: the centre has dropped l/4); the hinge keeps the pin
;;;; still through the impact, so the restitution on the end's normal velocity gives
;;;; omega' = -e omega; the floor's impulse is m (1 + e) sqrt(2 g l) / 3 (angular momentum
;;;; about the pin, (m l^2 / 3) (omega' - omega) = (l cos(pi/6)) J), and the impact dissipates
;;;; (1 - e^2) of the kinetic energy m g l / 4. One state: the rod's swing back after the
;;;; bounce is integrated numerically.

(scenario rod-hinged-strikes-floor
  "A rod hinged at one end swings down onto the floor and bounces."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1))
              (e :positive (< e 1) (:value 1/2)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
            :position ((/ l 2) (/ l 2)) :velocity (0 0))
  (hinge pin :body rod :at ((- (/ l 2)) 0))
  (restitution rod floor e)
  (simulate :states 1))
