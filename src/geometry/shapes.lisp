;;;; src/geometry/shapes.lisp -- shape objects, the parser of scenario shape forms, validation.
;;;;
;;;; A shape is given in its body's own frame, relative to the body's reference point:
;;;;   point                                  a particle
;;;;   (circle R)                             disc of radius R centred on the reference point
;;;;   (polygon (X Y) ...)                    closed polygon, vertices counter-clockwise
;;;;   (outline PIECE ...)                    closed counter-clockwise boundary of
;;;;        (line (X1 Y1) (X2 Y2)) and (arc :center (CX CY) :radius R :from A1 :to A2)
;;;;        pieces; an arc turns counter-clockwise when A2 > A1 (a convex bulge) and
;;;;        clockwise when A2 < A1 (a concave bite)
;;;;   (segment (X1 Y1) (X2 Y2))              thin one-sided surface, solid on its left
;;;;   (arc :center C :radius R :from A1 :to A2 [:solid :inside|:outside])
;;;;                                          thin circular track from A1 counter-clockwise
;;;;                                          to A2 (0 < A2 - A1 <= 2 PI); the solid is inside
;;;;                                          the circle by default (a dome), outside for a bowl
;;;;   (half-plane (X1 Y1) (X2 Y2))           everything left of the line from the first
;;;;                                          point through the second
;;;; Coordinates are prefix expressions over parameters. PARSE-SHAPE validates: every
;;;; fault signals INVALID-SHAPE naming the form; facts that depend on parameters are
;;;; decided through the bridge (UNDECIDABLE-GEOMETRIC-FACT when they cannot be).
;;;;
;;;; Feature names (used to say which parts of two bodies touch):
;;;;   point: (:point)   circle: (:circle)
;;;;   polygon: (:vertex I) and (:edge I), edge I running from vertex I to vertex I+1
;;;;   outline: (:vertex I) where piece I starts, (:edge I) a line piece, (:arc I) an arc
;;;;   segment: (:edge 0), its ends (:vertex 0) and (:vertex 1)
;;;;   arc track: (:arc 0), its ends (:vertex 0) at A1 and (:vertex 1) at A2
;;;;   half-plane: (:edge 0)
;;;; Indices count from 0 in the order written.

(in-package #:ames.geometry)

(defclass shape ()
  ((form :initarg :form :reader shape-form
         :documentation "The scenario form the shape was parsed from.")
   (boundary :initarg :boundary :initform '() :reader shape-boundary
             :documentation "The boundary pieces, solid on their left, in order.")
   (convex :initarg :convex :initform nil :reader shape-convex-p
           :documentation "True when the solid is convex (decided when parsed)."))
  (:documentation "A rigid body's shape in its own frame."))

(defclass point-shape (shape) ()
  (:documentation "A particle."))

(defclass circle-shape (shape)
  ((radius :initarg :radius :reader shape-radius))
  (:documentation "A disc of RADIUS centred on the reference point."))

(defclass polygon-shape (shape)
  ((vertices :initarg :vertices :reader shape-vertices))
  (:documentation "A simple polygon with counter-clockwise VERTICES."))

(defclass outline-shape (shape) ()
  (:documentation "A closed counter-clockwise boundary of line and arc pieces."))

(defclass segment-shape (shape) ()
  (:documentation "A thin one-sided straight surface, solid on its left."))

(defclass arc-shape (shape)
  ((solid :initarg :solid :reader shape-solid-side
          :documentation ":INSIDE (a dome) or :OUTSIDE (a bowl)."))
  (:documentation "A thin circular track."))

(defclass half-plane-shape (shape) ()
  (:documentation "An unbounded solid: everything left of a directed line."))

(defgeneric shape-kind (shape)
  (:documentation "The kind of SHAPE: :POINT :CIRCLE :POLYGON :OUTLINE :SEGMENT :ARC or
:HALF-PLANE.")
  (:method ((s point-shape)) :point)
  (:method ((s circle-shape)) :circle)
  (:method ((s polygon-shape)) :polygon)
  (:method ((s outline-shape)) :outline)
  (:method ((s segment-shape)) :segment)
  (:method ((s arc-shape)) :arc)
  (:method ((s half-plane-shape)) :half-plane))

(defun shape-surface-p (shape)
  "True for the thin or unbounded shapes (segment, arc track, half-plane): surfaces that
are never the observer of a pair unless both bodies are surfaces."
  (member (shape-kind shape) '(:segment :arc :half-plane)))

(defun shape-closed-p (shape)
  "True when SHAPE's boundary is a closed curve (circle, polygon, outline)."
  (member (shape-kind shape) '(:circle :polygon :outline)))

(defmethod print-object ((shape shape) stream)
  (print-unreadable-object (shape stream :type t)
    (format stream "~S" (shape-form shape))))

;;; Parsing helpers

(defun invalid-shape (form datum detail &rest arguments)
  "Signal INVALID-SHAPE about DATUM in the shape FORM."
  (error 'invalid-shape :shape form :datum datum
                        :detail (apply #'format nil detail arguments)))

(defun head-is (x name)
  "True when X is a symbol named NAME (in whatever package the scenario was read)."
  (and (symbolp x) x (string= (symbol-name x) name)))

(defun parse-coordinate (form expression)
  "EXPRESSION checked (a parameter expression) and normalized."
  (handler-case (normalize-expression
                 (check-expression expression :kind :arithmetic :allow-terms nil))
    (malformed-expression (condition)
      (invalid-shape form expression "a coordinate is not an expression of parameters: ~A"
                     (ames-error-detail condition)))))

(defun parse-point (form x)
  "The vector written as (X Y) in FORM."
  (unless (and (consp x) (alexandria:proper-list-p x) (= (length x) 2))
    (invalid-shape form x "a point must be written (X Y)"))
  (vec (parse-coordinate form (first x)) (parse-coordinate form (second x))))

(defun parse-keywords (form arguments allowed)
  "The plist ARGUMENTS checked: only ALLOWED keywords, each once, each with a value."
  (unless (and (alexandria:proper-list-p arguments) (evenp (length arguments)))
    (invalid-shape form arguments "keyword arguments must come in pairs"))
  (loop for (key value) on arguments by #'cddr
        do (unless (member key allowed)
             (invalid-shape form key "unknown keyword; expected one of ~{~S~^ ~}" allowed))
           (when (> (count key arguments) 1)
             (invalid-shape form key "keyword given twice")))
  arguments)

(defun required-keyword (form arguments key)
  (let ((tail (member key arguments)))
    (unless (and tail (evenp (position key arguments)))
      (invalid-shape form form "missing ~S" key))
    (second tail)))

(defun check-positive-radius (decider form radius)
  (case (sign-of decider radius)
    (:zero (invalid-shape form radius "zero radius"))
    (:negative (invalid-shape form radius "negative radius"))))

(defun check-distinct-points (decider form a b datum what)
  (when (vector-equal-p decider a b)
    (invalid-shape form datum "~A: its two points coincide" what)))

;;; Arc helpers

(defun parse-arc-arguments (form arguments allowed)
  "Centre, radius, from and to angles of an arc form's keyword ARGUMENTS."
  (parse-keywords form arguments allowed)
  (let ((center (parse-point form (required-keyword form arguments :center)))
        (radius (parse-coordinate form (required-keyword form arguments :radius)))
        (from (parse-coordinate form (required-keyword form arguments :from)))
        (to (parse-coordinate form (required-keyword form arguments :to))))
    (values center radius from to)))

;;; The shapes

(defun parse-shape (form &key bridge)
  "The SHAPE described by the scenario shape FORM (see the file header for the syntax).
BRIDGE is the Maxima bridge used to decide facts that depend on parameters (call under
ames.maxima:with-assumptions for the scenario's assumptions); NIL is enough for numeric
shapes. Signals INVALID-SHAPE (naming the form and the fault) for a malformed or
degenerate shape and UNDECIDABLE-GEOMETRIC-FACT when a needed fact cannot be decided."
  (let ((decider (ensure-decider bridge form)))
    (cond ((or (head-is form "POINT") (and (consp form) (head-is (car form) "POINT")
                                           (null (cdr form))))
           (make-instance 'point-shape :form form :convex t))
          ((not (and (consp form) (alexandria:proper-list-p form) (symbolp (car form))))
           (invalid-shape form form "not a shape: expected point, (circle R), (polygon ...), (outline ...), (segment ...), (arc ...) or (half-plane ...)"))
          ((head-is (car form) "CIRCLE") (parse-circle decider form))
          ((head-is (car form) "POLYGON") (parse-polygon decider form))
          ((head-is (car form) "OUTLINE") (parse-outline decider form))
          ((head-is (car form) "SEGMENT") (parse-segment decider form))
          ((head-is (car form) "ARC") (parse-arc-track decider form))
          ((head-is (car form) "HALF-PLANE") (parse-half-plane decider form))
          (t (invalid-shape form (car form) "unknown shape")))))

(defun parse-circle (decider form)
  (unless (= (length form) 2)
    (invalid-shape form form "a circle is written (circle R)"))
  (let ((radius (parse-coordinate form (second form))))
    (check-positive-radius decider form radius)
    (make-instance 'circle-shape
                   :form form :radius radius :convex t
                   :boundary (list (make-arc-piece (vec 0 0) radius 0 (e* 2 'pi) :ccw
                                                   :name '(:circle) :full t)))))

(defun parse-segment (decider form)
  (unless (= (length form) 3)
    (invalid-shape form form "a segment is written (segment (X1 Y1) (X2 Y2))"))
  (let ((a (parse-point form (second form))) (b (parse-point form (third form))))
    (check-distinct-points decider form a b form "degenerate segment")
    (make-instance 'segment-shape :form form :convex t
                                  :boundary (list (make-line-piece a b :name '(:edge 0))))))

(defun parse-half-plane (decider form)
  (unless (= (length form) 3)
    (invalid-shape form form "a half-plane is written (half-plane (X1 Y1) (X2 Y2))"))
  (let ((a (parse-point form (second form))) (b (parse-point form (third form))))
    (check-distinct-points decider form a b form "degenerate half-plane")
    (make-instance 'half-plane-shape
                   :form form :convex t
                   :boundary (list (make-line-piece a b :name '(:edge 0) :infinite t)))))

(defun parse-arc-track (decider form)
  (let ((arguments (rest form)))
    (multiple-value-bind (center radius from to)
        (parse-arc-arguments form arguments '(:center :radius :from :to :solid))
      (let ((solid (or (getf arguments :solid) :inside)))
        (unless (member solid '(:inside :outside))
          (invalid-shape form solid ":solid must be :inside or :outside"))
        (check-positive-radius decider form radius)
        (let ((sweep (e- to from)))
          (unless (positive-p decider sweep)
            (invalid-shape form form "the arc must turn counter-clockwise from :from to :to (:to greater than :from)"))
          (unless (fact-holds-p decider (list '<= sweep (e* 2 'pi)))
            (invalid-shape form form "the arc turns more than a full circle"))
          (let ((full (fact-holds-p decider (list '= sweep (e* 2 'pi)))))
            (make-instance 'arc-shape
                           :form form :solid solid :convex (eq solid :inside)
                           :boundary (list (if (eq solid :inside)
                                               (make-arc-piece center radius from to :ccw
                                                               :name '(:arc 0) :full full)
                                               (make-arc-piece center radius to from :cw
                                                               :name '(:arc 0) :full full))))))))))

(defun polygon-signed-area (vertices)
  "Twice the signed area of the polygon VERTICES (positive when counter-clockwise)."
  (apply #'e+ (loop for (a b) on (append vertices (list (first vertices)))
                    while b collect (cross a b))))

(defun parse-polygon (decider form)
  (let ((vertices (mapcar (lambda (x) (parse-point form x)) (rest form))))
    (when (< (length vertices) 3)
      (invalid-shape form form "a polygon needs at least three vertices"))
    (let* ((n (length vertices))
           (edges (loop for (a b) on (append vertices (list (first vertices)))
                        for i from 0
                        while b
                        collect (make-line-piece a b :name (list :edge i)))))
      (unless (= n 3)
        (loop for (a b) on (append vertices (list (first vertices)))
              for (written next) on (append (rest form) (list (second form)))
              while b
              do (check-budget form)
                 (check-distinct-points decider form a b (list written next) "repeated vertex")))
      (case (sign-of decider (polygon-signed-area vertices))
        (:negative (invalid-shape form form "the vertices run clockwise; list them counter-clockwise"))
        (:zero (invalid-shape form form "the polygon has no area")))
      (let ((convex (or (= n 3) (check-closed-boundary decider form edges))))
        (make-instance 'polygon-shape :form form :vertices vertices
                                      :convex convex :boundary edges)))))

(defun parse-outline-piece (decider form piece index)
  (cond ((and (consp piece) (head-is (car piece) "LINE"))
         (unless (= (length piece) 3)
           (invalid-shape form piece "a line piece is written (line (X1 Y1) (X2 Y2))"))
         (let ((a (parse-point form (second piece))) (b (parse-point form (third piece))))
           (check-distinct-points decider form a b piece "degenerate line piece")
           (make-line-piece a b :name (list :edge index))))
        ((and (consp piece) (head-is (car piece) "ARC"))
         (multiple-value-bind (center radius from to)
             (parse-arc-arguments form (rest piece) '(:center :radius :from :to))
           (check-positive-radius decider form radius)
           (let ((sweep (e- to from)))
             (when (zero-p decider sweep)
               (invalid-shape form piece "the arc piece has no length (:from = :to)"))
             (let ((sense (if (positive-p decider sweep) :ccw :cw)))
               (unless (fact-holds-p decider (list '<= (if (eq sense :ccw) sweep (e- sweep))
                                                   (e* 2 'pi)))
                 (invalid-shape form piece "the arc piece turns more than a full circle"))
               (make-arc-piece center radius from to sense
                               :name (list :arc index)
                               :full (fact-holds-p decider
                                                   (list '= (if (eq sense :ccw) sweep (e- sweep))
                                                         (e* 2 'pi))))))))
        (t (invalid-shape form piece "an outline piece is (line ...) or (arc ...)"))))

(defun outline-signed-area (pieces)
  "Twice the signed area enclosed by the closed chain of PIECES (Green's formula)."
  (apply #'e+
         (loop for piece in pieces
               collect (etypecase piece
                         (line-piece (cross (line-piece-start piece) (line-piece-end piece)))
                         (arc-piece
                          ;; chord term plus the circular segment between chord and arc
                          (let ((phi (arc-signed-sweep piece)) (r (arc-piece-radius piece)))
                            (e+ (cross (piece-start piece) (piece-end piece))
                                (e* (esquare r) (e- phi (esin phi))))))))))

(defun parse-outline (decider form)
  (let ((pieces (loop for piece in (rest form) for i from 0
                      collect (parse-outline-piece decider form piece i))))
    (when (null pieces)
      (invalid-shape form form "an outline needs at least one piece"))
    (loop for (a b) on (append pieces (list (first pieces)))
          for (written next) on (append (rest form) (list (second form)))
          while b
          do (check-budget form)
             (unless (vector-equal-p decider (piece-end a) (piece-start b))
               (invalid-shape form (list written next)
                              "the pieces do not join: one ends where the next does not start")))
    (case (sign-of decider (outline-signed-area pieces))
      (:negative (invalid-shape form form "the outline runs clockwise; write it counter-clockwise"))
      (:zero (invalid-shape form form "the outline encloses no area")))
    (let ((convex (check-closed-boundary decider form pieces)))
      (make-instance 'outline-shape :form form :convex convex :boundary pieces))))

(defun check-closed-boundary (decider form pieces)
  "Check that the closed chain PIECES does not fold back on itself or cross itself;
return true when it bounds a convex solid (every arc convex, every corner turning left).
Linear but for the crossings, found in O(n log n) for numeric line pieces (see
boundary.lisp). Signals INVALID-SHAPE, UNDECIDABLE-GEOMETRIC-FACT, or BUDGET-EXCEEDED
when the run's deadline passes."
  (let* ((pieces (coerce pieces 'vector)) (n (length pieces)) (convex t))
    (flet ((piece (i) (aref pieces (mod i n))))
      (dotimes (i n)
        (check-budget form)
        (let ((t-in (piece-end-tangent (piece i))) (t-out (piece-start-tangent (piece (1+ i)))))
          (case (sign-of decider (cross t-in t-out))
            (:negative (setf convex nil))
            (:zero (when (negative-p decider (dot t-in t-out))
                     (invalid-shape form (shape-piece-form form i)
                                    "the boundary folds back on itself at the end of this piece"))))))
      (when (some (lambda (p) (and (arc-piece-p p) (eq (arc-piece-sense p) :cw))) pieces)
        (setf convex nil))
      (when (> n 3)
        (let ((crossing (boundary-crossing decider pieces)))
          (when crossing
            (invalid-shape form (mapcar (lambda (i) (shape-piece-form form i)) crossing)
                           "the boundary crosses itself"))))
      ;; adjacent pieces may only share their joint
      (when (>= n 2)
        (dotimes (i n)
          (check-budget form)
          (let ((common (piece-intersections decider (piece i) (piece (1+ i)))))
            (when (> (length common) (if (= n 2) 2 1))
              (invalid-shape form (shape-piece-form form i)
                             "the boundary overlaps itself near this piece")))))
      convex)))

(defun shape-piece-form (form index)
  "The written form of piece INDEX of a polygon or outline FORM, for error reports."
  (if (head-is (car form) "POLYGON")
      (list (nth index (rest form)) (nth (mod (1+ index) (length (rest form))) (rest form)))
      (nth index (rest form))))

;;; Sizes (for choosing the observer)

(defun shape-area (shape)
  "The area of SHAPE as an expression; :INFINITE for a half-plane, 0 for thin shapes."
  (ecase (shape-kind shape)
    ((:point :segment :arc) 0)
    (:circle (e* 'pi (esquare (shape-radius shape))))
    (:polygon (e* 1/2 (polygon-signed-area (shape-vertices shape))))
    (:outline (e* 1/2 (outline-signed-area (shape-boundary shape))))
    (:half-plane :infinite)))
