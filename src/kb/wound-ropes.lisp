;;;; src/kb/wound-ropes.lisp -- a rope wound on a turning disc (scenario-language.md, "Rotation"):
;;;; a yo-yo's string, the ropes of a massive pulley.
;;;;
;;;; A rope end (B (X Y) :wound) winds the rope on the circle about the disc B's centre C
;;;; through its point (X Y): radius R = |(X Y)|. The rope's piece from its neighbouring
;;;; point P leaves that circle at the tangent point T, of the two the one on the side of
;;;; (X Y) (turned by B's starting angle), and B turning pays the rope out or winds it in
;;;; without slipping. With w = P - C and l = sqrt(|w|^2 - R^2) the straight length,
;;;;   T - C = d = (R^2 w - SENSE R l k x w) / |w|^2,
;;;;   the unit vector from P toward T is u = -(l w + SENSE R k x w) / |w|^2,
;;;; where SENSE = +1 when turning B counter-clockwise pays the rope out, -1 when clockwise:
;;;; the sign of p0 x w0, p0 the wound point turned by B's starting angle, at the scenario's
;;;; start. Turning B by dtheta pays out SENSE R dtheta, so the rope's length, the sum of
;;;; its straight pieces, counts the wound piece as
;;;;   l - SENSE R (theta - theta0)        (theta0: B's angle at the scenario's start)
;;;; (the rope's :length L is its straight length when B is at theta0: the scenario
;;;; language's L runs to the tangent point, the rope wound beyond it not counted). The
;;;; tension acts on B at T along u's opposite (toward P): its moment about C is
;;;; d x (T (-u)) = SENSE R T, the virtual work of the length's angle term.
;;;;
;;;; The entities (made by ropes.lisp's ROPE-ENTITIES):
;;;;   (rope R ... :wound T :winding-indicator I)   I = p0 x w0, over the
;;;;                                          parameters: its sign is SENSE
;;;;   (wound-rope-segment S :rope R :from A :to B :disc D :radius R :start-angle THETA0)
;;;;                                          one of :FROM and :TO is (D (X Y)), D's point
;;;; The ROPE-WINDING component decides SENSE once per state from I (a fact over the
;;;; parameters) and asserts (rope-winding R :sense SENSE), 0 for a rope wound on no disc;
;;;; the rope's components (ropes.lisp) take SENSE from it. The wound piece defines the
;;;; span quantities of its segment (span-length: the length above, span-direction: from
;;;; :FROM toward :TO, span-acceleration) while P keeps moving along the line of u
;;;; relative to C (T then stays put relative to C, d the value the state starts with);
;;;; a piece that swings off that line (the tangent point wandering round the disc) is not
;;;; modelled: its state ends with (:turns S) and the next is refused.
;;;; One wound end per rope (a rope wound on two discs is refused). At an impact:
;;;; wound-rope-impacts.lisp.

(in-package #:ames.kb)

;;; The rotation core's quantity terms of a disc

(defun disc-angle (disc) "The angle term of the rotating body DISC." `(angle ,disc))
(defun disc-angular-velocity (disc) "DISC's angular velocity term." `(angvel ,disc))
(defun disc-angular-acceleration (disc) "DISC's angular acceleration term." `(angacc ,disc))

;;; The entities

(defun wound-segment-of (rope segments)
  "The name among SEGMENTS (the scenario ROPE's, in order) of the piece that ends wound on
a disc, or NIL. Signals UNMODELLED-SITUATION for a rope wound at both ends."
  (let ((ends (ames.scenario:scenario-rope-wound-ends rope)))
    (when (rest ends)
      (error 'unmodelled-situation
             :datum (ames.scenario:scenario-rope-name rope)
             :detail (format nil "The rope ~(~A~) is wound on a disc at both ends; a rope wound at one end only is modelled."
                             (ames.scenario:scenario-rope-name rope))))
    (case (first ends)
      (:first (first segments))
      (:last (car (last segments))))))

(defun rotated (vector angle)
  "VECTOR (X Y) turned counter-clockwise by ANGLE, as expressions."
  (if (eql angle 0)
      vector
      (destructuring-bind (x y) vector
        (list `(- (* (cos ,angle) ,x) (* (sin ,angle) ,y)) `(+ (* (sin ,angle) ,x) (* (cos ,angle) ,y))))))

(defun scenario-start-point (scenario point)
  "Where POINT, (BODY (X Y)), is at the start of SCENARIO (the offset turned by the body's
starting angle when it rotates)."
  (let* ((body (ames.scenario:find-scenario-body (point-body point) scenario))
         (position (or (ames.scenario:scenario-body-position body) '(0 0)))
         (offset (if (ames.scenario:scenario-body-inertia body)
                     (rotated (point-offset point) (ames.scenario:scenario-body-angle body))
                     (point-offset point))))
    (mapcar (lambda (p x) `(+ ,p ,x)) position offset)))

(defun wound-ends (rope points)
  "The wound point (D (X Y)) of the scenario ROPE through POINTS (resolved) and the point
next to it along the rope."
  (if (eq (first (ames.scenario:scenario-rope-wound-ends rope)) :first)
      (values (first points) (second points))
      (values (car (last points)) (car (last points 2)))))

(defun wound-rope-properties (scenario rope points)
  "The properties a ROPE wound on a disc adds to its entity: :WINDING-INDICATOR, p0 x w0 at
the scenario's start (see the file header)."
  (multiple-value-bind (wound neighbour) (wound-ends rope points)
    (let* ((disc (ames.scenario:find-scenario-body (point-body wound) scenario))
           (p0 (rotated (point-offset wound) (ames.scenario:scenario-body-angle disc)))
           (centre (scenario-start-point scenario (list (point-body wound) '(0 0))))
           (w0 (mapcar (lambda (p c) `(- ,p ,c)) (scenario-start-point scenario neighbour) centre)))
      (list :winding-indicator (ames.geometry:cross p0 w0)))))

(defun wound-segment-entity (scenario rope segment index from to)
  "The WOUND-ROPE-SEGMENT entity SEGMENT of the scenario ROPE, its INDEXth piece, from the
point FROM to the point TO, one of them wound."
  (let* ((wound (if (eq (first (ames.scenario:scenario-rope-wound-ends rope)) :first) from to))
         (disc (point-body wound))
         (offset (point-offset wound)))
    (list 'wound-rope-segment segment :rope (ames.scenario:scenario-rope-name rope) :index index
          :from from :to to :disc disc
          :radius `(sqrt (+ (expt ,(first offset) 2) (expt ,(second offset) 2)))
          :start-angle (ames.scenario:scenario-body-angle
                        (ames.scenario:find-scenario-body disc scenario)))))

;;; The wound piece's geometry

(defun wound-segment-p (situation segment)
  "True when the rope SEGMENT ends wound on a disc."
  (eq (ames.engine:entity-kind (entity-named situation segment)) 'wound-rope-segment))

(defun wound-piece (situation segment)
  "(values NEIGHBOUR DISC RADIUS TOWARD-DISC-P) of the wound SEGMENT: the point at its
other end, the disc, the radius, and whether the segment runs from NEIGHBOUR to the disc."
  (let* ((entity (entity-named situation segment))
         (disc (entity-property entity :disc))
         (from (entity-property entity :from))
         (to (entity-property entity :to)))
    (if (eq (point-body to) disc)
        (values from disc (entity-property entity :radius) t)
        (values to disc (entity-property entity :radius) nil))))

(defun wound-vector (situation segment head)
  "w = P - C over the quantity HEAD (POS, INITIAL-POS, VEL or ACC): from the wound SEGMENT's
disc centre to its neighbouring point."
  (multiple-value-bind (neighbour disc) (wound-piece situation segment)
    (span-difference situation (list disc '(0 0)) neighbour head)))

(defun wound-turn (situation segment sense head)
  "SENSE R times the disc's turn since the scenario's start (HEAD :ANGLE), its angular
velocity (:RATE) or acceleration (:ACCELERATION): the rope the disc has paid out."
  (multiple-value-bind (neighbour disc radius) (wound-piece situation segment)
    (declare (ignore neighbour))
    (if (eql sense 0)
        0
        `(* ,sense ,radius
            ,(ecase head
               (:angle `(- ,(disc-angle disc)
                           ,(entity-property (entity-named situation segment) :start-angle)))
               (:rate (disc-angular-velocity disc))
               (:acceleration (disc-angular-acceleration disc)))))))

(defun straight-length (w radius)
  "sqrt(|w|^2 - R^2): the tangent's length from the point at w from the centre."
  `(sqrt (- ,(ames.geometry:dot w w) (expt ,radius 2))))

(defun wound-direction (situation segment sense)
  "u, the unit vector from the wound SEGMENT's neighbouring point toward its tangent point
at the start of the state: -(l w + SENSE R k x w) / |w|^2."
  (multiple-value-bind (neighbour disc radius) (wound-piece situation segment)
    (declare (ignore neighbour disc))
    (let* ((w (wound-vector situation segment 'initial-pos))
           (l (straight-length w radius))
           (kw (list `(- ,(second w)) (first w)))
           (w2 (ames.geometry:dot w w)))
      (mapcar (lambda (a b) `(- (/ (+ (* ,l ,a) (* ,sense ,radius ,b)) ,w2))) w kw))))

(defun wound-piece-length (situation segment sense)
  "The wound piece's length while it keeps its starting direction, less the rope the disc
has paid out: l0 + (w0 - w).u - SENSE R (theta - theta0)."
  (multiple-value-bind (neighbour disc radius) (wound-piece situation segment)
    (declare (ignore neighbour disc))
    (let ((w0 (wound-vector situation segment 'initial-pos))
          (w (wound-vector situation segment 'pos)))
      `(- (+ ,(straight-length w0 radius)
             ,(ames.geometry:dot (mapcar (lambda (a b) `(- ,a ,b)) w0 w)
                                 (wound-direction situation segment sense)))
          ,(wound-turn situation segment sense :angle)))))

(defun wound-piece-length-now (situation segment sense)
  "The wound piece's length from the positions and the disc's angle (exact whatever its
direction): sqrt(|w|^2 - R^2) - SENSE R (theta - theta0)."
  (multiple-value-bind (neighbour disc radius) (wound-piece situation segment)
    (declare (ignore neighbour disc))
    `(- ,(straight-length (wound-vector situation segment 'pos) radius)
        ,(wound-turn situation segment sense :angle))))

(defun wound-piece-rate-now (situation segment sense)
  "The rate of WOUND-PIECE-LENGTH-NOW: w.w' / sqrt(|w|^2 - R^2) - SENSE R omega."
  (multiple-value-bind (neighbour disc radius) (wound-piece situation segment)
    (declare (ignore neighbour disc))
    (let ((w (wound-vector situation segment 'pos)))
      `(- (/ ,(ames.geometry:dot w (wound-vector situation segment 'vel)) ,(straight-length w radius))
          ,(wound-turn situation segment sense :rate)))))

(defun register-wound-rope-templates (kb)
  "Register in KB the template functions of ropes wound on discs."
  (flet ((reg (head function documentation)
           (register-template kb head function :documentation documentation)))
    (reg 'winding-indicator
         (lambda (situation rope) (entity-property (entity-named situation rope) :winding-indicator))
         "p0 x w0 of a rope wound on a disc: its sign is the rope's winding sense.")
    (reg 'wound-piece-length #'wound-piece-length
         "A wound piece's length along its starting direction, less the rope paid out.")
    (reg 'wound-piece-acceleration
         (lambda (situation segment sense)
           `(- ,(ames.geometry:dot (wound-vector situation segment 'acc)
                                   (mapcar (lambda (x) `(- ,x)) (wound-direction situation segment sense)))
               ,(wound-turn situation segment sense :acceleration)))
         "The second derivative of that length: -(a_P - a_C).u - SENSE R alpha.")
    (reg 'wound-piece-direction
         (lambda (situation segment sense axis)
           (let ((u (wound-direction situation segment sense)))
             (axis-component (if (nth-value 3 (wound-piece situation segment)) u (mapcar (lambda (x) `(- ,x)) u))
                             axis)))
         "A component of the wound piece's unit vector from its :FROM end toward its :TO end.")
    (reg 'wound-piece-transverse-rate
         (lambda (situation segment sense)
           (ames.geometry:cross (wound-direction situation segment sense) (wound-vector situation segment 'vel)))
         "The neighbouring point's velocity relative to the disc's centre across the piece.")
    (reg 'wound-piece-offset
         (lambda (situation segment sense)
           (ames.geometry:cross (wound-direction situation segment sense)
                                (mapcar (lambda (a b) `(- ,a ,b))
                                        (wound-vector situation segment 'pos)
                                        (wound-vector situation segment 'initial-pos))))
         "How far the neighbouring point has moved across the piece relative to the centre.")
    (reg 'wound-piece-radius
         (lambda (situation segment) (nth-value 2 (wound-piece situation segment)))
         "The radius a wound piece leaves its disc at.")))

(defun register-wound-rope-refusals (kb)
  "Register in KB the templates that refuse what wound ropes do not model."
  (flet ((reg (head function documentation)
           (register-template kb head function :documentation documentation)))
    (reg 'wound-piece-swings
         (lambda (situation segment)
           ;; the datum is the user's rope, not the piece (an entity of the simulator's)
           (let ((rope (entity-property (entity-named situation segment) :rope)))
             (error 'unmodelled-situation
                    :datum rope
                    :detail (format nil "The rope ~(~A~) swings off its line where it leaves the disc ~(~A~) it is wound on: its tangent point wanders round the disc. Only a wound rope that keeps its direction is modelled."
                                    rope (entity-property (entity-named situation segment) :disc)))))
         "Signals UNMODELLED-SITUATION: a wound rope's piece swings.")
    (reg 'winding-undecided
         (lambda (situation rope)
           (declare (ignore situation))
           (error 'unmodelled-situation
                  :datum rope
                  :detail (format nil "The rope ~(~A~) is wound on a disc at a point in line with the disc's centre and the rope's next point: which side of the disc it leaves is not said."
                                  rope)))
         "Signals UNMODELLED-SITUATION: a wound rope's side is not told.")))

(register-wound-rope-templates *mechanics*)
(register-wound-rope-refusals *mechanics*)

;;; The components

(defcomponent unwound-rope (:knowledge-base *mechanics*)
  "A rope wound on no disc has no winding sense (0)."
  (:arguments (?rope :entity rope :where (:wound nil)))
  (:assert (rope-winding ?rope :sense 0)))

(defcomponent rope-winding (:knowledge-base *mechanics*)
  "A rope wound on a disc is paid out by the disc turning counter-clockwise (sense +1) or
clockwise (-1): the sign of p0 x w0 at the scenario's start, p0 the wound point from the
centre and w0 the rope's next point from the centre (a fact over the parameters)."
  (:arguments (?rope :entity rope :where (:wound t)))
  (:mode :pays-out-counter-clockwise
   (:entry (> (winding-indicator ?rope) 0))
   (:assert (rope-winding ?rope :sense 1)))
  (:mode :pays-out-clockwise
   (:entry (< (winding-indicator ?rope) 0))
   (:assert (rope-winding ?rope :sense -1)))
  (:mode :side-not-told
   (:entry (= (winding-indicator ?rope) 0))
   (:equations (= (winding-undecided ?rope) 0))))

(defcomponent wound-rope-piece (:knowledge-base *mechanics*)
  "The piece of a rope that leaves a disc it is wound on: its length counts the rope the
disc has paid out, its direction is the tangent's from the neighbouring point (see the
file header). Modelled while the neighbouring point moves along that line relative to
the disc's centre; swinging off it ends the state, (:turns S)."
  (:arguments (?rope :entity rope)
              (?sense :belief (rope-winding ?rope :sense ?sense))
              (?segment :entity wound-rope-segment :where (:rope ?rope)))
  (:mode :fixed-direction
   (:entry (<= (expt (wound-piece-transverse-rate ?segment ?sense) 2) 0))
   (:equations (= (span-length ?segment) (wound-piece-length ?segment ?sense))
               (= (span-direction ?segment :x) (wound-piece-direction ?segment ?sense :x))
               (= (span-direction ?segment :y) (wound-piece-direction ?segment ?sense :y))
               (= (span-acceleration ?segment) (wound-piece-acceleration ?segment ?sense)))
   (:transition :to :swinging :when (> (expt (wound-piece-offset ?segment ?sense) 2) 0)
                :event (:turns ?segment)))
  (:mode :swinging
   (:entry (> (expt (wound-piece-transverse-rate ?segment ?sense) 2) 0))
   (:equations (= (wound-piece-swings ?segment) 0))))

(defcomponent wound-rope-tension (:knowledge-base *mechanics*)
  "A taut rope's wound piece pulls its neighbouring point's body toward the disc and the
disc toward that body with the rope's tension; on the disc it acts at the tangent point,
its moment about the centre SENSE R T."
  (:arguments (?rope :entity rope)
              (?sense :belief (rope-winding ?rope :sense ?sense))
              (?segment :entity wound-rope-segment
                        :where (:rope ?rope :from (?body1 ?_) :to (?body2 ?_) :disc ?disc)))
  (:activation (:believes (taut ?rope)))
  (:assert (force (tension ?segment ?body1) :type tension :from ?body2 :on ?body1)
           (force (tension ?segment ?body2) :type tension :from ?body1 :on ?body2)
           (acts-at (tension ?segment ?disc) :on ?disc))
  (:equations (= (force-x (tension ?segment ?body1)) (* (tension ?rope) (span-direction ?segment :x)))
              (= (force-y (tension ?segment ?body1)) (* (tension ?rope) (span-direction ?segment :y)))
              (= (force-x (tension ?segment ?body2)) (- (* (tension ?rope) (span-direction ?segment :x))))
              (= (force-y (tension ?segment ?body2)) (- (* (tension ?rope) (span-direction ?segment :y))))
              (= (moment-of (tension ?segment ?disc)) (* ?sense (wound-piece-radius ?segment) (tension ?rope)))))
