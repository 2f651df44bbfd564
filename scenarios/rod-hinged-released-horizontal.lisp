;;;; scenarios/rod-hinged-released-horizontal.lisp -- a uniform rod hinged at
;;;; one end, released horizontal, swings down (a physical pendulum).
;;;;
;;;; Expected results (textbook): energy, m g (l/2) = (1/2) (m l^2 / 3) omega^2, gives the
;;;; angular speed sqrt(3 g / l) at the bottom (clockwise: omega = -sqrt(3 g / l)), and the
;;;; hinge there pulls up with (5/2) m g (the weight plus the centripetal m omega^2 l / 2);
;;;; at release the angular acceleration is -3 g / (2 l) and the hinge holds m g / 4.
;;;; The swing is periodic: (:turns rod) at the horizontal on the other side, the angle
;;;; between 0 and -pi with the period 4 sqrt(2 l / (3 g)) K(1/2) (a simple pendulum of
;;;; length 2 l / 3 released at 90 degrees). AMES reports the one state along the angle as
;;;; :duration :forever with :periodic (src/kb/turning.lisp, src/simulator/turns.lisp).

(scenario rod-hinged-released-horizontal
  "A uniform rod hinged at one end swings down from the horizontal."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1)))
  (gravity g)
  (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
            :position ((/ l 2) 0) :velocity (0 0))
  (hinge pin :body rod :at ((- (/ l 2)) 0))
  (query omega-at-bottom (value (angular-velocity rod) :at (reaches (angle rod) (- (/ pi 2)))))
  (query hinge-at-bottom (value (y (hinge-force pin)) :at (reaches (angle rod) (- (/ pi 2)))))
  (simulate :states 2))
