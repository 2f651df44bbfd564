;;;; src/scenario/rotation.lisp -- validating the rotation section of the language (issue 23;
;;;; scenario-language.md, "Rotation"): a body's :inertia, :angle and :angular-velocity, the
;;;; (hinge NAME :body B :at (X Y)) clause, a force's :at, a rope's :wound end, and the
;;;; queries (angle B), (angular-velocity B), (angular-acceleration B), (hinge-force H).
;;;;
;;;; Choices where the language page is silent (what a teacher would expect):
;;;; - Only a body with an :inertia rotates. :angle and :angular-velocity without one are an
;;;;   error (the body would silently keep its orientation); so are :inertia on a fixed or
;;;;   driven body, on a particle (shape POINT) and on a half-plane.
;;;; - :inertia takes a value (an expression, positive), :uniform (inertia.lisp: a disc, a
;;;;   polygon lamina, a segment as a thin rod) or :ring (circles only). A value for a disc
;;;;   may not exceed m r^2 (all the mass on the rim): checked where the numbers or the
;;;;   assumptions decide it. :uniform needs the reference point at the centroid: an error
;;;;   names the centroid (numbers), or the fact goes to the semantic checks (symbols).
;;;; - A hinge pins a rotating body (one hinge per body: two would fix it) to the fixed
;;;;   frame; its point may lie outside the body's shape (a disc on a light rigid arm).
;;;;   The body's start velocity must leave the pin at rest: v + omega k x R(theta0) p = 0.
;;;; - A force's :at is a point of a rotating body (on a translating body it would change
;;;;   nothing, and writing it means the author expects a torque: an error says to give
;;;;   the body an :inertia); it must lie in the body's shape (on its boundary or inside),
;;;;   decided for numbers (circles and polygons) and, for a disc, by the assumptions.
;;;; - A rope end (B (X Y) :wound), first or last, winds the rope on a rotating disc B (a
;;;;   (circle R) shape: a drum, a yo-yo's axle or rim) on the circle about B's centre
;;;;   through (X Y), whose radius may not be 0 nor exceed R. Of the two tangents from the
;;;;   rope's neighbouring point, the rope leaves the circle at the one on the side of
;;;;   (X Y) (so (X Y) at the circle's leftmost point hangs the rope down its left side).
;;;; - (segment A B) with an :inertia is a thin rod (the textbook ladder or pendulum rod):
;;;;   :uniform gives m |B - A|^2 / 12 about its midpoint, which must be its reference point.
;;;; - (angle B), (angular-velocity B), (angular-acceleration B), (angular-momentum B) (about
;;;;   the origin) name a rotating body,
;;;;   (hinge-force H) a hinge (a vector: (x (hinge-force H)), (y ...)); a value query's WHEN
;;;;   may be (reaches QUANTITY VALUE) (canonical (:reaches QUANTITY VALUE), queries.lisp).
;;;; - Until the simulator rotates bodies, SCENARIO-AWAITING (rotation-checks.lisp) lists what
;;;;   a scenario asks that AMES cannot do yet, and SIMULATE refuses such a scenario with an
;;;;   UNSUPPORTED-SITUATION naming it (never runs a rotating body as a translating one).

(in-package #:ames.scenario)

(defclass scenario-hinge ()
  ((name :initarg :name :reader scenario-hinge-name)
   (body :initarg :body :reader scenario-hinge-body
         :documentation "The symbol of the rotating body pinned.")
   (point :initarg :point :reader scenario-hinge-point
          :documentation "(X Y): the pinned point, in the body's own frame."))
  (:documentation "A hinge: the point of a rotating body pinned to the fixed frame."))

(defmethod print-object ((hinge scenario-hinge) stream)
  (print-unreadable-object (hinge stream :type t)
    (prin1 (scenario-hinge-name hinge) stream)))

(defun scenario-hinges (scenario) "The SCENARIO-HINGEs." (scenario-extension scenario :hinges))

(defun find-scenario-hinge (name scenario)
  "The SCENARIO-HINGE of SCENARIO named NAME (compared by name), or NIL."
  (find name (scenario-hinges scenario) :key #'scenario-hinge-name :test #'same-name-p))

(defun scenario-body-rotating-p (body)
  "True when BODY rotates (it has an :inertia)."
  (and (scenario-body-inertia body) t))

(defun scenario-rotating-bodies (scenario)
  "The bodies of SCENARIO that rotate, in order of declaration."
  (remove-if-not #'scenario-body-rotating-p (scenario-bodies scenario)))

;;; A body's keys

(defun checked-inertia (validation x shape mass)
  "The moment of inertia that the :inertia value X of a body of SHAPE and MASS gives, and
its kind (:VALUE, :UNIFORM or :RING) as a second value."
  (case (shape-kind shape)
    (:point (reject validation 'scenario-syntax-error x
                    "a particle (shape point) does not rotate: give the body a shape with an ~
                     extent, such as (circle R) or a polygon, to give it an :inertia"))
    (:half-plane (reject validation 'scenario-syntax-error x
                         "an unbounded half-plane cannot rotate")))
  (cond ((member x '(:uniform :ring))
         (let ((inertia (shape-inertia shape mass x)))
           (unless inertia
             (reject validation 'scenario-syntax-error x
                     "~S is the inertia of ~:[a uniform disc, polygon or segment (a rod)~;a ~
                      hoop, a (circle R) shape~]; give this ~(~A~)'s inertia as a value"
                     x (eq x :ring) (shape-kind shape)))
           (when (eq x :uniform) (check-numeric-centroid validation x shape))
           (values inertia x)))
        ((keywordp x)
         (reject validation 'scenario-syntax-error x
                 ":inertia takes a value, :uniform or :ring, not ~S" x))
        (t (let ((inertia (checked-expression validation x)))
             (check-positive-constant validation inertia "a moment of inertia"
                                      'scenario-expression-error)
             (values inertia :value)))))

(defun nonzero-number-p (expression)
  "True when EXPRESSION is a constant whose value is decidedly not 0."
  (multiple-value-bind (value exact) (expression-value expression)
    (and value (member (compare-values value exact 0 t) '(:less :greater)) t)))

(defun check-numeric-centroid (validation datum shape)
  "Signal SCENARIO-SHAPE-ERROR when the numbers show that SHAPE's centroid is not its
reference point (:uniform needs it there)."
  (let ((centroid (centroid shape)))
    (when (some #'nonzero-number-p centroid)
      (reject validation 'scenario-shape-error datum
              "with :inertia :uniform the body's reference point is its centre of mass, the ~
               shape's centroid; this shape's centroid is at ~A in its own frame: give its ~
               points relative to the centroid (shift them by ~A)"
              (show centroid) (show (mapcar (lambda (c) (folded `(- ,c))) centroid))))))

(defun checked-rotation (validation arguments shape mass fixed driven)
  "The rotation initargs (:INERTIA :INERTIA-KIND :ANGLE :ANGULAR-VELOCITY) of a body whose
keyword ARGUMENTS (an alist) are given, or NIL for a body that translates only. Signals a
SCENARIO-ERROR naming the key at fault (see this file's header)."
  (let ((inertia (assoc :inertia arguments))
        (angle (assoc :angle arguments))
        (omega (assoc :angular-velocity arguments)))
    (cond ((null inertia)
           (let ((orphan (or angle omega)))
             (when orphan
               (reject validation 'scenario-syntax-error (cdr orphan)
                       "~(~S~) is for a body that rotates: give the body an :inertia (a value, ~
                        :uniform or :ring); without one it translates only" (car orphan))))
           nil)
          ((or fixed driven)
           (reject validation 'scenario-syntax-error (cdr inertia)
                   "a ~:[driven~;fixed~] body does not rotate: it takes no :inertia" fixed))
          (t (multiple-value-bind (value kind) (checked-inertia validation (cdr inertia) shape mass)
               (list :inertia value :inertia-kind kind
                     :angle (if angle (checked-expression validation (cdr angle)) 0)
                     :angular-velocity (if omega (checked-expression validation (cdr omega)) 0)))))))

;;; The hinge clause and a rope's wound end

(defun checked-hinge (validation clause)
  "The SCENARIO-HINGE that a (hinge NAME :body B :at (X Y)) clause declares (its body's
rotation is checked with the whole scenario, by CHECK-ROTATION)."
  (let* ((name (cdr (declared validation (second clause))))
         (what (format nil "hinge ~A" (symbol-name name))))
    (enter validation what clause)
    (let ((arguments (checked-keywords validation (cddr clause) '(:body :at) what)))
      (required validation arguments clause '(:body :at) "the hinge")
      (make-instance 'scenario-hinge
                     :name name
                     :body (checked-body-name validation (keyword-value :body arguments) what)
                     :point (checked-vector validation (keyword-value :at arguments) ":at")))))

(defun wound-end-p (x)
  "True when the rope end X is written (BODY (X Y) :wound)."
  (and (proper-list-p x) (= (length x) 3) (keyword-named-p (third x) "WOUND")))

(defun checked-rope-end (validation x what)
  "The rope end X, (BODY (X Y)) or (BODY (X Y) :wound), as an attachment (BODY (X Y)), and
true as a second value when it is wound."
  (if (wound-end-p x)
      (values (checked-attachment validation (butlast x) what) t)
      (values (checked-attachment validation x what) nil)))

;;; A rotating body's shape at its start angle (for the geometry, once rotation runs)

(defun turned (point angle)
  "POINT (X Y) turned counter-clockwise by ANGLE about the origin, as expressions."
  (if (eql angle 0)
      point
      (destructuring-bind (x y) point
        (list (folded `(- (* (cos ,angle) ,x) (* (sin ,angle) ,y)))
              (folded `(+ (* (sin ,angle) ,x) (* (cos ,angle) ,y)))))))

(defun turned-shape (shape angle)
  "The checked SHAPE (own frame) turned counter-clockwise by ANGLE about its reference
point: the points of a polygon, segment or half-plane turned, an arc's or outline's
centres turned and angles shifted by ANGLE; a circle and a point unchanged."
  (flet ((arc (piece)
           (destructuring-bind (word &key center radius from to (solid nil solid-p)) piece
             (append (list word :center (turned center angle) :radius radius
                           :from (folded `(+ ,from ,angle)) :to (folded `(+ ,to ,angle)))
                     (and solid-p (list :solid solid))))))
    (if (eql angle 0)
        shape
        (ecase (shape-kind shape)
          ((:point :circle) shape)
          ((:polygon :segment :half-plane)
           (cons (first shape) (mapcar (lambda (p) (turned p angle)) (rest shape))))
          (:arc (arc shape))
          (:outline (cons (first shape)
                          (mapcar (lambda (piece)
                                    (if (eq (first piece) 'ames-scenario:line)
                                        (list (first piece) (turned (second piece) angle)
                                              (turned (third piece) angle))
                                        (arc piece)))
                                  (rest shape))))))))

(defun scenario-body-start-shape (body)
  "BODY's shape as it stands at the start: turned by its :angle (its own shape for a body
that does not rotate). What the geometry's checks at the start (overlaps) must see."
  (turned-shape (scenario-body-shape body) (scenario-body-angle body)))
