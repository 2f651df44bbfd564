;;;; src/witness/model.lisp -- from a validated scenario with values to the witness's model.
;;;;
;;;; The model is the JSON object read by witness/siconos_driver.py (see its docstring):
;;;; the free bodies with their masses, shapes, initial state and constant forces, the
;;;; fixed bodies as faces (a half-plane one infinite face, a segment one finite face, a
;;;; polygon its edges), gravity, the coefficients of restitution, springs and ropes over
;;;; pulleys (points given by body index and offset, or fixed points), and for rotating
;;;; bodies (rotation.lisp) their inertia, angle and angular velocity, the hinges, the wound
;;;; rope ends, the forces at points and the angles the queries ask about; arcs, circles,
;;;; gravitation and bumpers in model-curved.lisp; a body's linear and quadratic drag
;;;; coefficients (summed over its drags). What the witness cannot model (outlines, driven
;;;; bodies) is refused with WITNESS-UNSUPPORTED, never approximated.

(in-package #:ames.witness)

(define-condition witness-unsupported (ames-error) ()
  (:documentation "The scenario has something the witness cannot model. DATUM is that
thing; DETAIL says why."))

(defun unsupported (datum control &rest arguments)
  "Signal WITNESS-UNSUPPORTED for DATUM with the detail CONTROL/ARGUMENTS."
  (error 'witness-unsupported :datum datum :detail (apply #'format nil control arguments)))

(defparameter +unsupported-words+
  '(:driven :outline)
  "Words of the scenario language that name what the witness does not model.")

(defun check-modelled (form)
  "Signal WITNESS-UNSUPPORTED when the scenario FORM uses a word of
+UNSUPPORTED-WORDS+ (as a keyword or a clause or shape name)."
  (labels ((walk (x)
             (cond ((symbolp x)
                    (let ((word (find (symbol-name x) +unsupported-words+
                                      :key #'symbol-name :test #'string-equal)))
                      (when word (unsupported x "the witness does not model ~(~A~)" word))))
                   ((consp x) (walk (car x)) (when (listp (cdr x)) (mapc #'walk (cdr x)))))))
    ;; the first two elements are SCENARIO and the name, the description is a string
    (mapc #'walk (cdddr form))))

(defun value-of (expression values what)
  "The double-float value of EXPRESSION under VALUES; WITNESS-UNSUPPORTED naming WHAT
when it has none."
  (let ((value (expression-value expression values)))
    (unless value (unsupported expression "~A has no numeric value under the values given" what))
    (coerce value 'double-float)))

(defun point-of (point values what)
  (list (value-of (first point) values what) (value-of (second point) values what)))

(defun shape-model (body values)
  "The driver's shape of the free BODY: point, circle or polygon (own frame)."
  (let ((shape (scenario-body-shape body)))
    (case (shape-kind shape)
      (:point '(("kind" . "point")))
      (:circle `(("kind" . "circle") ("r" . ,(value-of (second shape) values "a radius"))))
      (:polygon `(("kind" . "polygon")
                  ("vertices" . (:array ,@(mapcar (lambda (p) (cons :array (point-of p values "a vertex")))
                                                  (rest shape))))))
      (:segment (if (scenario-body-rotating-p body)
                    `(("kind" . "segment")
                      ("vertices" . (:array ,@(mapcar (lambda (p) (cons :array (point-of p values "an end")))
                                                      (rest shape)))))
                    (unsupported (scenario-body-name body) "the witness models moving segments as rotating rods only")))
      (t (unsupported (scenario-body-name body) "the witness models moving points, discs and polygons only")))))

(defun offset-point (point origin values)
  (mapcar #'+ (point-of point values "a vertex") origin))

(defun face-model (a b infinite)
  `(("a" . (:array ,@a)) ("b" . (:array ,@b)) ("infinite" . ,(if infinite :true :false))))

(defun obstacle-faces (body values)
  "The faces (world frame) of the fixed BODY."
  (let ((shape (scenario-body-shape body))
        (origin (point-of (scenario-body-position body) values "a position")))
    (case (shape-kind shape)
      (:point '())                      ; a fixed point (a pulley's support) has no face
      ((:arc :circle) '())              ; model-curved.lisp: OBSTACLE-ARCS
      (:half-plane (list (face-model (offset-point (second shape) origin values)
                                     (offset-point (third shape) origin values) t)))
      (:segment (list (face-model (offset-point (second shape) origin values)
                                  (offset-point (third shape) origin values) nil)))
      (:polygon (let ((points (mapcar (lambda (p) (offset-point p origin values)) (rest shape))))
                  (loop for (a . rest) on points
                        collect (face-model a (if rest (first rest) (first points)) nil))))
      (t (unsupported (scenario-body-name body) "the witness models fixed polygons, segments and half-planes only")))))

(defun body-force (scenario body values)
  "The sum of the constant forces on BODY that act at its reference point."
  (let ((fx 0d0) (fy 0d0))
    (dolist (force (scenario-forces scenario) (list fx fy))
      (when (and (eq (scenario-force-body force) (scenario-body-name body))
                 (null (scenario-force-point force)))
        (destructuring-bind (x y) (point-of (scenario-force-value force) values "a force")
          (incf fx x) (incf fy y))))))

(defun body-drag (scenario body values)
  "The drag entry of BODY's model: its linear coefficient B (F = -B v) and its quadratic
coefficient C (F = -C |v| v), each the sum of its drags of that law; none without drag."
  (let ((linear 0d0) (quadratic 0d0) (any nil))
    (dolist (data (scenario-kb-clauses scenario))
      (when (and (eq (first data) :drag) (eq (getf (cddr data) :on) (scenario-body-name body)))
        (setf any t)
        (let ((c (value-of (getf (cddr data) :coefficient) values "a drag coefficient")))
          (ecase (getf (cddr data) :law)
            (:linear (incf linear c))
            (:quadratic (incf quadratic c))))))
    (and any `(("drag" . (("linear" . ,linear) ("quadratic" . ,quadratic)))))))

(defun model-point (scenario body-name point values)
  "The driver's POINT of BODY-NAME's point POINT (own frame): a free body's index and
offset, or a fixed body's point in the world."
  (let ((body (find-scenario-body body-name scenario))
        (offset (point-of point values "an attachment point")))
    (if (scenario-body-fixed-p body)
        `(("point" . (:array ,@(mapcar #'+ offset (point-of (scenario-body-position body) values "a position")))))
        `(("body" . ,(position body (scenario-moving-bodies scenario)))
          ("offset" . (:array ,@offset))))))

(defun springs-model (scenario values)
  (loop for spring in (remove-if-not #'scenario-spring-to (scenario-springs scenario)) ; bumpers: model-curved
        for (a-body a-point) = (scenario-spring-from spring)
        for (b-body b-point) = (scenario-spring-to spring)
        collect `(("name" . ,(string-downcase (scenario-spring-name spring)))
                  ("k" . ,(value-of (scenario-spring-stiffness spring) values "a stiffness"))
                  ("rest" . ,(if (scenario-spring-rest-length spring)
                                 (value-of (scenario-spring-rest-length spring) values "a rest length")
                                 :null))
                  ("a" . ,(model-point scenario a-body a-point values))
                  ("b" . ,(model-point scenario b-body b-point values)))))

(defun ropes-model (scenario values)
  (loop for rope in (scenario-ropes scenario)
        for through = (scenario-rope-through rope)
        collect `(("name" . ,(string-downcase (scenario-rope-name rope)))
                  ("length" . ,(value-of (scenario-rope-length rope) values "a rope's length"))
                  ("points" . (:array ,@(loop for point in through
                                              for (body where) = (rope-point-position scenario point)
                                              for wound = (or (and (eq point (first through))
                                                                   (member :first (scenario-rope-wound-ends rope)))
                                                              (and (eq point (car (last through)))
                                                                   (member :last (scenario-rope-wound-ends rope))))
                                              collect (append (model-point scenario body where values)
                                                              (and wound '(("wound" . :true)))
                                                              ;; a fixed point's body: a piece closing there
                                                              ;; is (:strikes-pulley HOLDER BODY)
                                                              (and (scenario-body-fixed-p (find-scenario-body body scenario))
                                                                   `(("holder" . ,(string-downcase body)))))))))))

(defun scenario-model (scenario values t-end &key samples)
  "The witness's model (an alist for MODEL-JSON) of the validated SCENARIO with the
parameter VALUES (an alist (PARAMETER . NUMBER)), simulated from 0 to T-END, the state
reported at the times SAMPLES too. Signals WITNESS-UNSUPPORTED for what the witness
cannot model."
  (check-modelled (scenario-form scenario))
  (let ((default 0) (pairs '()))
    (dolist (entry (scenario-restitutions scenario))
      (destructuring-bind (a b e) entry
        (if a
            (push `(:array ,(string-downcase a) ,(string-downcase b) ,(value-of e values "a restitution")) pairs)
            (setf default (value-of e values "a restitution")))))
    `(("t_end" . ,(coerce t-end 'double-float))
      ("gravity" . ,(if (scenario-gravity scenario) (value-of (scenario-gravity scenario) values "gravity") 0d0))
      ("default_restitution" . ,(coerce default 'double-float))
      ("restitution" . (:array ,@pairs))
      ("bodies" . (:array ,@(loop for body in (scenario-moving-bodies scenario)
                                  collect `(("name" . ,(string-downcase (scenario-body-name body)))
                                            ("mass" . ,(value-of (scenario-body-mass body) values "a mass"))
                                            ("q" . (:array ,@(point-of (scenario-body-position body) values "a position")))
                                            ("v" . (:array ,@(point-of (scenario-body-velocity body) values "a velocity")))
                                            ("shape" . ,(shape-model body values))
                                            ("force" . (:array ,@(body-force scenario body values)))
                                            ,@(body-drag scenario body values)
                                            ,@(body-rotation-model scenario body values)))))
      ("springs" . (:array ,@(springs-model scenario values)))
      ("friction" . (:array ,@(loop for friction in (scenario-frictions scenario)
                                    for (a b) = (scenario-friction-bodies friction)
                                    collect `(:array ,(string-downcase a) ,(string-downcase b)
                                                     ,(value-of (scenario-friction-static friction) values "a friction coefficient")
                                                     ,(value-of (scenario-friction-kinetic friction) values "a friction coefficient")))))
      ("ropes" . (:array ,@(ropes-model scenario values)))
      ,@(rotation-model scenario values)
      ("obstacles" . (:array ,@(loop for body in (scenario-fixed-bodies scenario)
                                     collect `(("name" . ,(string-downcase (scenario-body-name body)))
                                               ("faces" . (:array ,@(obstacle-faces body values)))
                                               ("arcs" . (:array ,@(obstacle-arcs body values)))))))
      ,@(curved-model-entries scenario values samples))))

(defun write-json (value stream)
  "Write VALUE as JSON: an alist with string keys is an object, (:ARRAY ...) an array,
:TRUE/:FALSE booleans, strings and reals as themselves (reals as decimals)."
  (cond ((eq value :true) (write-string "true" stream))
        ((eq value :null) (write-string "null" stream))
        ((eq value :false) (write-string "false" stream))
        ((stringp value)
         (write-char #\" stream)
         (loop for c across value
               do (when (member c '(#\" #\\)) (write-char #\\ stream))
                  (write-char c stream))
         (write-char #\" stream))
        ((integerp value) (format stream "~D" value))
        ((realp value)
         (let ((x (coerce value 'double-float)))
           (write-string (substitute #\e #\d (let ((*read-default-float-format* 'single-float))
                                               (prin1-to-string x)))
                         stream)))
        ((and (consp value) (eq (first value) :array))
         (write-char #\[ stream)
         (loop for (item . rest) on (rest value)
               do (write-json item stream) (when rest (write-char #\, stream)))
         (write-char #\] stream))
        ((listp value)
         (write-char #\{ stream)
         (loop for ((key . item) . rest) on value
               do (write-json key stream) (write-char #\: stream) (write-json item stream)
                  (when rest (write-char #\, stream)))
         (write-char #\} stream))
        (t (error "cannot write ~S as JSON" value))))

(defun model-json (model)
  "The JSON text of MODEL (see SCENARIO-MODEL)."
  (with-output-to-string (stream) (write-json model stream)))
