;;;; scenarios/rods-set-moving-by-a-push-or-a-fall.lisp -- a rod standing tilted on a smooth
;;;; floor released from rest, and a free rod (no gravity) pushed sideways at one end by a
;;;; constant force: neither motion has a closed form in time; the instant of release does.
;;;;
;;;; Source type: the textbook's "initial reaction" problems (first-year rotational
;;;; dynamics: Newton's law for the centre and the torque about it, at the instant of
;;;; release, when the angular velocity is still 0). Expected results (textbook):
;;;;   rod of length l tilted b from the vertical on a smooth floor: the centre falls
;;;;     straight down; at release the floor pushes N = m g / (1 + 3 sin^2 b), the centre
;;;;     accelerates at -3 g sin^2 b / (1 + 3 sin^2 b), the rod at alpha = -6 g sin b / (l (1
;;;;     + 3 sin^2 b)); it lands flat with its centre at sqrt(3 g l cos b / 4) (energy: m g
;;;;     (l/2) cos b = (2/3) m v^2), turning at 2 v / l;
;;;;   free rod pushed at its end by f, perpendicular: a = f / m, alpha = 6 f / (m l)
;;;;     (torque f l/2 over m l^2/12); as it turns, the force keeping its direction,
;;;;     omega^2 = 12 f sin(theta) / (m l).
;;;; Without values AMES answers the instant of release and says the rest has no closed
;;;; form (exit 3); --numeric integrates it.

(scenario rod-released-tilted-on-a-smooth-floor
  "A uniform rod standing tilted on a frictionless floor falls flat."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1))
              (b (> b 0) (< b (/ pi 2)) (:value (deg 30))))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
        :position ((* (/ l 2) (sin b)) (* (/ l 2) (cos b))) :angle (- (/ pi 2) b) :velocity (0 0))
  (query floor-push-at-release (value (normal-force rod floor) :at (start 0)))
  (query alpha-at-release (value (angular-acceleration rod) :at (start 0)))
  (query fall-at-release (value (y (acceleration rod)) :at (start 0)))
  (simulate :states 1))

(scenario free-rod-pushed-at-one-end
  "A uniform rod floating free is pushed sideways at one end by a constant force."
  (parameters (m :positive (:value 2)) (l :positive (:value 1)) (f :positive (:value 3)))
  (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
            :position (0 0) :velocity (0 0))
  (force push :on rod :at ((/ l 2) 0) :value (0 f))
  (query alpha-at-start (value (angular-acceleration rod) :at (start 0)))
  (query acceleration-at-start (value (acceleration rod) :at (start 0)))
  (simulate :states 1 :until 1))
