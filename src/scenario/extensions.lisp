;;;; src/scenario/extensions.lisp -- the clauses of forces that depend on where the bodies are:
;;;; springs and bumpers, pulleys and ropes, universal gravitation (thesis 3.3.2).
;;;;
;;;;   (spring NAME :from (BODY1 (X1 Y1)) :to (BODY2 (X2 Y2)) :stiffness K [:rest-length L0])
;;;;   (spring NAME :from (BODY (X Y)) :toward (DX DY) :stiffness K :rest-length L0)   ; a bumper
;;;;   (pulley NAME :on BODY :at (X Y))
;;;;   (rope NAME :length L :through ((BODY1 (X1 Y1)) PULLEY ... (BODY2 (X2 Y2))))
;;;;   (gravitation G)
;;;;
;;;; Choices where the language page is silent:
;;;; - Springs, pulleys and ropes are named in the namespace that parameters, bodies and
;;;;   forces share. A spring's two ends are on two different bodies. A rope runs over any
;;;;   number of pulleys, each at most once.
;;;; - An attached spring's rest length defaults to the distance between its attachment
;;;;   points at the start (an expression over the bodies' :positions). A bumper needs
;;;;   :rest-length, and its :toward may not be (0 0); it is normalized.
;;;; - :stiffness, :rest-length, :length and the gravitational constant must be positive
;;;;   when they are numbers (symbolic ones are the assumptions' business).
;;;; - (gravitation G) appears at most once; it acts between every two bodies that have a
;;;;   :mass and are not both fixed (a fixed body with a :mass attracts: a particle around a
;;;;   fixed sun).

(in-package #:ames.scenario)

(defclass scenario-spring ()
  ((name :initarg :name :reader scenario-spring-name)
   (from :initarg :from :reader scenario-spring-from
         :documentation "(BODY (X Y)): the first attachment point, in BODY's frame.")
   (to :initarg :to :initform nil :reader scenario-spring-to
       :documentation "(BODY (X Y)): the second attachment point, or NIL for a bumper.")
   (toward :initarg :toward :initform nil :reader scenario-spring-toward
           :documentation "A bumper's direction (DX DY) from its attachment to its free end.")
   (stiffness :initarg :stiffness :reader scenario-spring-stiffness)
   (rest-length :initarg :rest-length :reader scenario-spring-rest-length))
  (:documentation "An ideal massless spring (Hooke's law): attached at both ends, or a
bumper with a free end that only pushes."))

(defclass scenario-pulley ()
  ((name :initarg :name :reader scenario-pulley-name)
   (body :initarg :body :reader scenario-pulley-body)
   (point :initarg :point :reader scenario-pulley-point
          :documentation "(X Y) in the body's frame."))
  (:documentation "An ideal, massless, frictionless pulley: a point of a body."))

(defclass scenario-rope ()
  ((name :initarg :name :reader scenario-rope-name)
   (length :initarg :length :reader scenario-rope-length)
   (through :initarg :through :reader scenario-rope-through
            :documentation "The rope's points in order: (BODY (X Y)) at the ends, pulley
names between.")
   (wound :initarg :wound :initform '() :reader scenario-rope-wound-ends
          :documentation "The ends wound on a rotating disc (:wound): a list of :FIRST and
:LAST (see rotation.lisp)."))
  (:documentation "A massless, inextensible rope over pulleys."))

(defun scenario-extension (scenario key)
  "The entry KEY of SCENARIO's extensions plist."
  (getf (scenario-extensions scenario) key))

(defun scenario-springs (scenario) "The SCENARIO-SPRINGs." (scenario-extension scenario :springs))
(defun scenario-pulleys (scenario) "The SCENARIO-PULLEYs." (scenario-extension scenario :pulleys))
(defun scenario-ropes (scenario) "The SCENARIO-ROPEs." (scenario-extension scenario :ropes))
(defun scenario-gravitation (scenario)
  "The gravitational constant of the (gravitation G) clause, or NIL."
  (scenario-extension scenario :gravitation))

(defun scenario-spring-bumper-p (spring)
  "True when SPRING is a bumper (one end free)."
  (null (scenario-spring-to spring)))

(defun find-scenario-pulley (name scenario)
  "The SCENARIO-PULLEY of SCENARIO named NAME (compared by name), or NIL."
  (find name (scenario-pulleys scenario) :key #'scenario-pulley-name :test #'same-name-p))

(defun rope-point-position (scenario point)
  "A rope's POINT, (BODY (X Y)) or a pulley's name, as (BODY (X Y))."
  (if (consp point)
      point
      (let ((pulley (find-scenario-pulley point scenario)))
        (list (scenario-pulley-body pulley) (scenario-pulley-point pulley)))))

;;; Checking the clauses

(defun checked-attachment (validation x what)
  "X, an attachment point (BODY (X Y)), checked: (BODY-SYMBOL (X Y))."
  (unless (and (proper-list-p x) (= (length x) 2))
    (reject validation 'scenario-syntax-error x
            "~A is an attachment point (BODY (X Y)), not ~A" what (show x)))
  (list (checked-body-name validation (first x) what)
        (checked-vector validation (second x) (format nil "the point of ~A" what))))

(defun required (validation arguments clause keys what)
  "Signal MISSING-PROPERTY-ERROR when one of KEYS is absent from ARGUMENTS."
  (let ((missing (remove-if (lambda (key) (assoc key arguments)) keys)))
    (when missing
      (reject validation 'missing-property-error clause "~A has no ~{~S~^, ~}" what missing))))

(defun checked-positive (validation x what)
  "X checked as an expression that is positive when it is a number."
  (let ((e (checked-expression validation x)))
    (check-positive-constant validation e what 'scenario-expression-error)
    e))

(defun body-position-of (bodies body)
  "The :position of BODY among the checked BODIES."
  (scenario-body-position (find body bodies :key #'scenario-body-name)))

(defun start-distance (bodies from to)
  "The distance at the start between the attachment points FROM and TO."
  (flet ((at (point)
           (mapcar (lambda (p x) (list '+ p x)) (body-position-of bodies (first point)) (second point))))
    (let ((a (at from)) (b (at to)))
      (list 'sqrt (list '+ (list 'expt (list '- (first b) (first a)) 2)
                        (list 'expt (list '- (second b) (second a)) 2))))))

(defun checked-spring (validation clause bodies)
  "The SCENARIO-SPRING that a (spring NAME ...) clause declares."
  (let* ((name (cdr (declared validation (second clause))))
         (what (format nil "spring ~A" (symbol-name name))))
    (enter validation what clause)
    (let ((arguments (checked-keywords validation (cddr clause)
                                       '(:from :to :toward :stiffness :rest-length) what)))
      (required validation arguments clause '(:from :stiffness) "the spring")
      (let ((to (assoc :to arguments)) (toward (assoc :toward arguments)))
        (when (eq (and to t) (and toward t))
          (reject validation 'scenario-syntax-error clause
                  "a spring has either :to (attached at both ends) or :toward (a bumper)"))
        (when (and toward (not (assoc :rest-length arguments)))
          (reject validation 'missing-property-error clause "a bumper needs its :rest-length")))
      (let* ((from (checked-attachment validation (keyword-value :from arguments) ":from"))
             (to (and (assoc :to arguments)
                      (checked-attachment validation (keyword-value :to arguments) ":to")))
             (toward (and (assoc :toward arguments)
                          (checked-vector validation (keyword-value :toward arguments) ":toward"))))
        (when (and to (eq (first from) (first to)))
          (reject validation 'scenario-syntax-error clause
                  "a spring joins two different bodies"))
        (when (and toward (zero-vector-p toward))
          (reject validation 'scenario-expression-error (keyword-value :toward arguments)
                  "a bumper's direction :toward cannot be (0 0)"))
        (make-instance 'scenario-spring
                       :name name :from from :to to :toward toward
                       :stiffness (checked-positive validation (keyword-value :stiffness arguments)
                                                    "a stiffness")
                       :rest-length (if (assoc :rest-length arguments)
                                        (checked-positive validation
                                                          (keyword-value :rest-length arguments)
                                                          "a rest length")
                                        (start-distance bodies from to)))))))

(defun checked-pulley (validation clause)
  "The SCENARIO-PULLEY that a (pulley NAME :on BODY :at (X Y)) clause declares."
  (let* ((name (cdr (declared validation (second clause))))
         (what (format nil "pulley ~A" (symbol-name name))))
    (enter validation what clause)
    (let ((arguments (checked-keywords validation (cddr clause) '(:on :at) what)))
      (required validation arguments clause '(:on :at) "the pulley")
      (make-instance 'scenario-pulley
                     :name name :body (checked-body-name validation (keyword-value :on arguments) what)
                     :point (checked-vector validation (keyword-value :at arguments) ":at")))))

(defun checked-rope (validation clause)
  "The SCENARIO-ROPE that a (rope NAME :length L :through (...)) clause declares."
  (let* ((name (cdr (declared validation (second clause))))
         (what (format nil "rope ~A" (symbol-name name))))
    (enter validation what clause)
    (let ((arguments (checked-keywords validation (cddr clause) '(:length :through) what)))
      (required validation arguments clause '(:length :through) "the rope")
      (let ((through (keyword-value :through arguments)))
        (unless (and (proper-list-p through) (>= (length through) 2))
          (reject validation 'scenario-syntax-error through
                  ":through lists the rope's end, its pulleys and its other end"))
        (multiple-value-bind (first first-wound)
            (checked-rope-end validation (first through) "the rope's first end")
         (multiple-value-bind (last last-wound)
             (checked-rope-end validation (car (last through)) "the rope's last end")
        (let* (
               (middle (mapcar (lambda (x)
                                 (let ((declaration (declared validation x)))
                                   (unless (and declaration (eq (car declaration) :pulley))
                                     (reject validation 'undeclared-symbol-error x
                                             "~A is not a declared pulley" (show x)))
                                   (cdr declaration)))
                               (butlast (rest through))))
               (points (append (list first) middle (list last))))
          (when (/= (length middle) (length (remove-duplicates middle)))
            (reject validation 'scenario-syntax-error through "the rope runs over a pulley twice"))
          (make-instance 'scenario-rope
                         :name name
                         :length (checked-positive validation (keyword-value :length arguments)
                                                   "a rope's length")
                         :through points
                         :wound (append (and first-wound '(:first)) (and last-wound '(:last)))))))))))

(defun checked-gravitation (validation clauses)
  "The constant of the (gravitation G) clause among CLAUSES, or NIL."
  (let ((clause (single-clause validation 'ames-scenario:gravitation clauses)))
    (when clause
      (unless (= (length clause) 2)
        (reject validation 'scenario-syntax-error clause
                "gravitation takes one constant: (gravitation G)"))
      (checked-positive validation (second clause) "the gravitational constant"))))

(defun checked-extensions (validation sorted bodies)
  "The extensions plist (:SPRINGS :PULLEYS :ROPES :GRAVITATION :KB-CLAUSES) of the SORTED clauses
(an alist WORD -> clauses, as SORTED-CLAUSES makes it), the checked BODIES given."
  (flet ((clauses (word) (cdr (assoc word sorted))))
    (let ((pulleys (mapcar (lambda (c) (checked-pulley validation c))
                           (clauses 'ames-scenario:pulley))))
      (list :springs (mapcar (lambda (c) (checked-spring validation c bodies))
                             (clauses 'ames-scenario:spring))
            :pulleys pulleys
            :ropes (mapcar (lambda (c) (checked-rope validation c))
                           (clauses 'ames-scenario:rope))
            :gravitation (checked-gravitation validation (clauses 'ames-scenario:gravitation))
            :hinges (mapcar (lambda (c) (checked-hinge validation c))
                            (clauses 'ames-scenario:hinge))
            :kb-clauses (checked-kb-clauses validation sorted bodies)))))
