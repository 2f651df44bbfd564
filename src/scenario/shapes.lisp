;;;; src/scenario/shapes.lisp -- validating shapes.

(in-package #:ames.scenario)

;;; ------------------------------------------------------------------------------------
;;; Shapes

(defparameter +shape-words+
  (mapcar #'car +shape-kinds+)
  "The words that begin a shape form.")

(defun shape-word (x)
  "The AMES-SCENARIO shape word named like X, or NIL."
  (language-word x +shape-words+))

(defun shape-reject (validation datum control &rest arguments)
  "Signal SCENARIO-SHAPE-ERROR."
  (apply #'reject validation 'scenario-shape-error datum control arguments))

(defun checked-point (validation x what)
  "X, a point (X Y) of a shape, checked."
  (checked-vector validation x what :class 'scenario-shape-error))

(defun numeric-point (point)
  "The numeric coordinates of POINT as (values X Y EXACT), or NIL."
  (multiple-value-bind (x x-exact) (expression-value (first point))
    (multiple-value-bind (y y-exact) (expression-value (second point))
      (and x y (values x y (and x-exact y-exact))))))

(defun points-coincide-p (a b)
  "True when the points A and B are the same form, or numerically the same."
  (or (equal a b)
      (multiple-value-bind (ax ay a-exact) (numeric-point a)
        (multiple-value-bind (bx by b-exact) (numeric-point b)
          (and ax bx
               (eq (compare-values ax a-exact bx b-exact) :equal)
               (eq (compare-values ay a-exact by b-exact) :equal))))))

(defun check-distinct-points (validation shape a b)
  "Signal SCENARIO-SHAPE-ERROR when the points A and B of SHAPE coincide."
  (when (points-coincide-p a b)
    (shape-reject validation shape "the points ~A and ~A coincide" (show a) (show b))))

(defun checked-polygon (validation shape)
  "(polygon (X Y) ...) checked: three vertices or more, no vertex repeated next to
itself, counter-clockwise when the vertices are numbers."
  (let ((vertices (loop for vertex in (rest shape)
                        for i from 1
                        collect (checked-point validation vertex
                                               (format nil "vertex ~D of the polygon" i)))))
    (when (< (length vertices) 3)
      (shape-reject validation shape "a polygon needs three vertices or more"))
    (loop for (a b) on (append vertices (list (first vertices)))
          while b
          do (check-distinct-points validation shape a b))
    (let ((area 0) (exact t))
      (loop for (a b) on (append vertices (list (first vertices)))
            while b
            do (multiple-value-bind (ax ay a-exact) (numeric-point a)
                 (multiple-value-bind (bx by b-exact) (numeric-point b)
                   (unless (and ax bx) (return-from checked-polygon
                                         (cons 'ames-scenario:polygon vertices)))
                   (setf exact (and exact a-exact b-exact))
                   (incf area (- (* ax by) (* bx ay))))))
      (case (compare-values area exact 0 t)
        (:less (shape-reject validation shape
                             "the polygon's vertices run clockwise; list them counter-clockwise: ~A"
                             (show (counter-clockwise-polygon
                                    (cons (first shape) vertices)))))
        (:equal (shape-reject validation shape "the polygon has no area"))))
    (cons 'ames-scenario:polygon vertices)))

(defun checked-arc (validation shape &key piece)
  "(arc :center (CX CY) :radius R :from A1 :to A2 [:solid :inside/:outside]) checked
and completed with its :solid side (default :inside); with PIECE true (a piece of an
outline), without :solid."
  (let* ((what (if piece "an arc piece of an outline" "an arc"))
         (arguments (checked-keywords validation (rest shape)
                                      (if piece
                                          '(:center :radius :from :to)
                                          '(:center :radius :from :to :solid))
                                      what :class 'scenario-shape-error)))
    (dolist (key '(:center :radius :from :to))
      (unless (assoc key arguments)
        (shape-reject validation shape "~A needs ~S" what key)))
    (let ((center (checked-point validation (keyword-value :center arguments) "the arc's :center"))
          (radius (checked-expression validation (keyword-value :radius arguments)))
          (from (checked-expression validation (keyword-value :from arguments)))
          (to (checked-expression validation (keyword-value :to arguments)))
          (solid (keyword-value :solid arguments :inside)))
      (unless (member solid '(:inside :outside))
        (shape-reject validation shape ":solid takes :inside or :outside, not ~A" (show solid)))
      (check-positive-constant validation radius "the arc's radius" 'scenario-shape-error)
      (multiple-value-bind (a1 a1-exact) (expression-value from)
        (multiple-value-bind (a2 a2-exact) (expression-value to)
          (when (and a1 a2)
            (unless (eq (compare-values a2 a2-exact a1 a1-exact) :greater)
              (shape-reject validation shape
                            "the arc's :to must exceed its :from (it runs counter-clockwise)"))
            (when (eq (compare-values (- a2 a1) (and a1-exact a2-exact) (* 2 pi) nil) :greater)
              (shape-reject validation shape "the arc turns more than a full circle")))))
      (append (list 'ames-scenario:arc :center center :radius radius :from from :to to)
              (unless piece (list :solid solid))))))

(defun arc-end-point (arc angle-key)
  "The numeric point of ARC (a checked arc) at its ANGLE-KEY (:FROM or :TO) end, as
a list (X Y NIL) (NIL: not exact), or NIL when not numeric."
  (destructuring-bind (cx cy) (getf (rest arc) :center)
    (let* ((radius (getf (rest arc) :radius))
           (angle (getf (rest arc) angle-key))
           (x (expression-value `(+ ,cx (* ,radius (cos ,angle)))))
           (y (expression-value `(+ ,cy (* ,radius (sin ,angle))))))
      (and x y (list x y nil)))))

(defun piece-end (piece end)
  "The numeric point (X Y EXACT) where the checked outline PIECE starts (END :START)
or ends (:END), or NIL when it is not numeric."
  (if (eq (first piece) 'ames-scenario:line)
      (multiple-value-bind (x y exact) (numeric-point (if (eq end :start) (second piece) (third piece)))
        (and x (list x y exact)))
      (arc-end-point piece (if (eq end :start) :from :to))))

(defun numeric-points-differ-p (a b)
  "True when the numeric points A and B, each (X Y EXACT), are clearly apart."
  (destructuring-bind (ax ay a-exact) a
    (destructuring-bind (bx by b-exact) b
      (and (or (member (compare-values ax a-exact bx b-exact) '(:less :greater))
               (member (compare-values ay a-exact by b-exact) '(:less :greater)))
           t))))

(defun checked-outline (validation shape)
  "(outline PIECE ...) checked: line and arc pieces, end to end where numbers tell."
  (when (null (rest shape))
    (shape-reject validation shape "an outline needs at least one piece"))
  (let ((pieces
          (loop for piece in (rest shape)
                for i from 1
                collect (let ((kind (and (consp piece) (proper-list-p piece)
                                         (language-word (car piece)
                                                        '(ames-scenario:line ames-scenario:arc)))))
                          (case kind
                            (ames-scenario:line
                             (unless (= (length piece) 3)
                               (shape-reject validation piece "a line piece is (line (X1 Y1) (X2 Y2))"))
                             (let ((a (checked-point validation (second piece) "a line's start"))
                                   (b (checked-point validation (third piece) "a line's end")))
                               (check-distinct-points validation piece a b)
                               (list 'ames-scenario:line a b)))
                            (ames-scenario:arc (checked-arc validation piece :piece t))
                            (t (shape-reject validation piece
                                             "piece ~D of the outline is not (line ...) or (arc ...)"
                                             i)))))))
    (loop for (previous next) on (append pieces (list (first pieces)))
          while next
          do (let ((end (piece-end previous :end))
                   (start (piece-end next :start)))
               (when (and end start (numeric-points-differ-p end start))
                 (shape-reject validation shape
                               "the outline's pieces do not meet end to end: ~A ends at ~
                                (~A ~A) but ~A starts at (~A ~A)" (show previous)
                               (first end) (second end) (show next)
                               (first start) (second start)))))
    (cons 'ames-scenario:outline pieces)))

(defun checked-shape (validation x)
  "The shape form X checked and rewritten with AMES-SCENARIO's words. Signals
SCENARIO-SHAPE-ERROR for a bad form (and the expression errors for its coordinates)."
  (let ((kinds "point, (circle R), (polygon (X Y) ...), (outline PIECE ...), ~
                (segment (X1 Y1) (X2 Y2)), (arc :center (CX CY) :radius R :from A1 :to A2) ~
                or (half-plane (X1 Y1) (X2 Y2))"))
    (cond ((and (atom x) (eq (shape-word x) 'ames-scenario:point)) 'ames-scenario:point)
          ((not (and (consp x) (proper-list-p x) (shape-word (car x))))
           (shape-reject validation x "~A is not a shape; a shape is ~A" (show x) kinds))
          (t
           (ecase (shape-word (car x))
             (ames-scenario:point
              (shape-reject validation x "a point shape is the bare word POINT"))
             (ames-scenario:circle
              (unless (= (length x) 2)
                (shape-reject validation x "a circle is (circle R)"))
              (let ((radius (checked-expression validation (second x))))
                (check-positive-constant validation radius "a circle's radius"
                                         'scenario-shape-error)
                (list 'ames-scenario:circle radius)))
             (ames-scenario:polygon (checked-polygon validation x))
             (ames-scenario:outline (checked-outline validation x))
             ((ames-scenario:segment ames-scenario:half-plane)
              (unless (= (length x) 3)
                (shape-reject validation x "~(~A~) takes two points: (~:*~(~A~) (X1 Y1) (X2 Y2))"
                              (shape-word (car x))))
              (let ((a (checked-point validation (second x) "the first point"))
                    (b (checked-point validation (third x) "the second point")))
                (check-distinct-points validation x a b)
                (list (shape-word (car x)) a b)))
             (ames-scenario:arc (checked-arc validation x)))))))
