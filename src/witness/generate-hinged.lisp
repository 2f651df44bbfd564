;;;; src/witness/generate-hinged.lisp -- random scenarios with rotating bodies held by
;;;; hinges, corners and wound ropes: a rod or a disc hinged at a point and swinging (a
;;;; physical pendulum, periodic), a ladder against a wall on a smooth floor (it leaves the
;;;; wall) or on a rough one (it stays), a yo-yo unwinding, an Atwood machine over a
;;;; massive pulley (ropes wound on a hinged disc). The witness (siconos_rotation.py,
;;;; Moreau-Jean, first order) models a rotating body with three degrees of freedom, a
;;;; hinge as an equality relation, a wound rope as a unilateral relation on x + R theta.
;;;;
;;;; Angles are whole degrees written into the bodies ((deg K)); every value satisfies its
;;;; family's assumptions (the swing stays below the top, the ladder's friction holds it,
;;;; the bodies of the Atwood machine stay clear of the pulley until the first lands).

(in-package #:ames.witness)

(defun polar-text (length degrees)
  "The point LENGTH (an expression) along the direction (deg DEGREES), as text."
  (format nil "((* ~A (cos (deg ~D))) (* ~A (sin (deg ~D))))" length degrees length degrees))

(defun family-hinged-swing (name)
  "A uniform rod (hinged at one end or at a point between its end and its centre) or a
disc or hoop (hinged at a point of its rim or inside it), released at rest at an angle,
or launched from hanging straight down with less than the energy to go over the top:
it swings between two turning points (AMES: one periodic state)."
  (let* ((rod (zerop (random 2 *random*)))
         (l (random-ratio 1/2 2)) (r (random-ratio 1/10 1/2 20))
         ;; the hinge at distance k from the centre (own frame (-k 0)): the centre hangs
         ;; at angle theta from the hinge, the body's own x axis along it
         (k (if rod (pick "(/ l 2)" "(/ l 3)" "(/ l 4)") (pick "r" "(/ r 2)")))
         (g (random-ratio 5 15))
         (launched (zerop (random 3 *random*)))
         (theta (if launched -90 (pick (random-ratio -170 -95 1) (random-ratio -85 10 1))))
         (omega (if launched
                    ;; below the top: (1/2) I_hinge w^2 < 2 m g d with d the distance to
                    ;; the centre; a safe fraction of the rod's bound sqrt(6 g / l) (k = l/2)
                    ;; or of the least bound over the shapes, sqrt(g / r)
                    (* (random-ratio 1/5 3/5 20) (rational (sqrt (float (if rod (/ (* 3 g) l) (/ g r) ) 1d0))))
                    0))
         (shape (if rod
                    "(segment ((- (/ l 2)) 0) ((/ l 2) 0))"
                    "(circle r)"))
         (inertia (if rod :uniform (pick :uniform :ring))))
    (scenario-text name "A body hinged at a point swings under gravity."
                   (parameters-text 'g g 'm (random-ratio 1/2 3) (if rod 'l 'r) (if rod l r))
                   (list (format nil "(body swing :mass m :inertia ~(~S~) :shape ~A :position ~A :angle (deg ~D) :velocity ~A :angular-velocity ~A)"
                                 inertia shape (polar-text k theta) theta
                                 (if launched (format nil "((* ~A ~A) 0)" (float-free omega) k) "(0 0)")
                                 (float-free omega))
                         (format nil "(hinge pin :body swing :at ((- ~A) 0))" k))
                   1)))

(defun float-free (x)
  "X, a rational, as text (a short rational: numerator and denominator below 10^6)."
  (let ((q (rationalize (float x 1d0))))
    (if (< (max (abs (numerator q)) (denominator q)) 1000000)
        (format nil "~A" q)
        (format nil "~A" (/ (round (* x 10000)) 10000)))))

(defun family-ladder (name)
  "A uniform ladder against a frictionless wall, at rest at an angle a with the floor
whose cosine and sine are rational (a Pythagorean triple: a = atan(b / c)): on a
frictionless floor it slides and leaves the wall (:lift-off ladder wall) when its top has
dropped to 2/3 of its height (one state: the fall after has no closed form); on a floor
rough enough (mu >= 1 / (2 tan a), with a margin) it stays. (At an angle such as 51
degrees, AMES's closed forms carry cos(43 pi/60) + cos(17 pi/60), which Maxima does not
see to be 0: it refuses, witness/disagreements/refused-ladder-51-degrees.lisp.)"
  (destructuring-bind (c b h) (pick '(3 4 5) '(4 3 5) '(5 12 13) '(12 5 13) '(8 15 17) '(15 8 17)
                                    '(20 21 29) '(21 20 29) '(7 24 25))
    (let ((rough (zerop (random 3 *random*)))
          (mu (* (pick 6/5 3/2 2) (/ c (* 2 b)))))
      (scenario-text name "A ladder against a wall."
                     (parameters-text 'g (random-ratio 5 15) 'm (random-ratio 1/2 3) 'l (random-ratio 1/2 4))
                     (list (floor-text)
                           "(body wall :fixed t :shape (half-plane (0 0) (0 1)))"
                           (format nil "(body ladder :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0)) :position ((* ~A l) (* ~A l)) :angle (- pi (atan ~A)) :velocity (0 0))"
                                   (/ c (* 2 h)) (/ b (* 2 h)) (/ b c))
                           (if rough (format nil "(friction ladder floor :static ~A)" mu) ""))
                     1))))

(defun until-text (text until)
  "TEXT (a scenario of SCENARIO-TEXT) with its (simulate ...) replaced by
\(simulate :states 2 :until UNTIL)."
  (let ((at (search "(simulate" text)))
    (format nil "~A(simulate :states 2 :until ~A))~%" (subseq text 0 at) until)))

(defun family-yoyo (name)
  "A yo-yo (a disc of radius R, inertia :uniform or a number below m R^2) whose string,
wound on its axle of radius r, goes straight up to the ceiling from its left or its right
side: released at rest, or already falling with the matching spin, it falls at
g / (1 + I / (m r^2)) until the scenario's time limit."
  (let* ((big-r (random-ratio 1/20 1/4 40)) (r (* big-r (random-ratio 1/5 4/5 20)))
         (m (random-ratio 1/5 2 20)) (side (pick 1 -1))
         (v (pick 0 0 (random-ratio 1/4 2)))
         (top (random-ratio 1 3)))
    (until-text
     (scenario-text name "A yo-yo falls as its string unwinds."
                    (parameters-text 'g (random-ratio 5 15) 'm m 'big-r big-r 'r r 'top top)
                    (list "(body ceiling :fixed t :shape (half-plane (0 top) (1 top)))"
                          (format nil "(body yoyo :mass m :inertia ~A :shape (circle big-r) :position (0 0) :velocity (0 ~A) :angular-velocity ~A)"
                                  (pick ":uniform" (format nil "(* ~A m (expt big-r 2))" (random-ratio 1/4 1 20)))
                                  (- v) (float-free (/ (* side v) r)))
                          (format nil "(rope string :length top :through ((ceiling (~A top)) (yoyo (~A 0) :wound)))"
                                  (if (= side 1) "r" "(- r)") (if (= side 1) "r" "(- r)")))
                    1)
     (random-ratio 1/4 1))))

(defun family-wound-atwood (name)
  "An Atwood machine over a massive pulley: a disc (inertia a number, :uniform or :ring)
hinged at its centre at height top, a weight hanging from a rope wound on each side; the
heavier one falls to the floor (one state: the landing ends it), the other rising clear
of the pulley."
  (let* ((m1 (random-ratio 1/2 3)) (m2 (random-ratio 1/2 3))
         (big-r (random-ratio 1/10 1/2 20))
         (h1 (random-ratio 1/2 2)) (h2 (random-ratio 1/2 2))
         (top (+ h1 h2 big-r (random-ratio 1/2 2))))
    (when (= m1 m2) (setf m2 (+ m1 1/4)))
    (scenario-text name "An Atwood machine over a massive pulley."
                   (parameters-text 'g (random-ratio 5 15) 'm1 m1 'm2 m2 'big-m (random-ratio 1/2 3)
                                    'big-r big-r 'h1 h1 'h2 h2 'top top)
                   (list (floor-text)
                         (format nil "(body pulley :mass big-m :inertia ~A :shape (circle big-r) :position (0 top) :velocity (0 0))"
                                 (pick ":uniform" ":ring" (format nil "(* ~A big-m (expt big-r 2))" (random-ratio 1/4 1 20))))
                         "(hinge axle :body pulley :at (0 0))"
                         "(body left :mass m1 :shape point :position ((- big-r) h1) :velocity (0 0))"
                         "(body right :mass m2 :shape point :position (big-r h2) :velocity (0 0))"
                         "(rope rope-1 :length (- top h1) :through ((left (0 0)) (pulley ((- big-r) 0) :wound)))"
                         "(rope rope-2 :length (- top h2) :through ((right (0 0)) (pulley (big-r 0) :wound)))")
                   1)))

(defparameter *hinged-families*
  '((:hinged-swing . family-hinged-swing) (:ladder . family-ladder)
    (:yoyo . family-yoyo) (:wound-atwood . family-wound-atwood))
  "The families of bodies turning on hinges, against corners and on wound ropes, added to
*FAMILIES* and *ROTATION-FAMILIES*.")

(dolist (entry *hinged-families*)
  (unless (assoc (car entry) *rotation-families*)
    (setf *rotation-families* (append *rotation-families* (list entry))))
  (unless (assoc (car entry) *families*)
    (setf *families* (append *families* (list entry)))))
