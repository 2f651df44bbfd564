;;;; src/scenario/inertia.lisp -- a rotating body's moment of inertia from its shape (issue 23,
;;;; scenario-language.md "Rotation": :inertia :uniform and :ring).
;;;;
;;;; The moment of inertia about the body's reference point, which for a rotating body is
;;;; its centre of mass, as an expression of the algebra (mass times a factor of the
;;;; shape; constant factors folded to exact numbers where the shape's coordinates are):
;;;;   (circle R)      :uniform  m R^2 / 2 (a uniform disc)     :ring  m R^2 (a hoop)
;;;;   (polygon ...)   :uniform  the uniform lamina: with c_i = x_i y_(i+1) - x_(i+1) y_i,
;;;;                   I = m (sum c_i (x_i^2 + x_i x_(i+1) + x_(i+1)^2 + y_i^2 + y_i y_(i+1)
;;;;                   + y_(i+1)^2)) / (6 sum c_i)  (the second moment of area about the
;;;;                   origin, over the area; a w by h rectangle gives m (w^2 + h^2) / 12)
;;;;   (segment A B)   :uniform  a thin uniform rod: m |B - A|^2 / 12
;;;; :uniform needs the reference point at the shape's centroid (the polygon's centroid of
;;;; area, the rod's midpoint): CENTROID gives it, and the validator rejects a shape whose
;;;; centroid is not at the origin (numbers), or hands the fact to the semantic checks.
;;;; Other shapes (a point, an outline, an arc, a half-plane) have no :uniform inertia here.

(in-package #:ames.scenario)

(defun folded (expression)
  "EXPRESSION, or its exact value when it has one (a rational)."
  (multiple-value-bind (value exact) (expression-value expression)
    (if (and value exact (rationalp value)) value expression)))

(defun product (&rest factors)
  "The product of FACTORS as an expression: constant factors folded, factors 1 left out."
  (let* ((factors (mapcar #'folded factors))
         (numbers (remove-if-not #'rationalp factors))
         (others (remove-if #'rationalp factors))
         (coefficient (reduce #'* numbers)))
    (cond ((zerop coefficient) 0)
          ((null others) coefficient)
          ((= coefficient 1) (if (rest others) (cons '* others) (first others)))
          (t (list* '* coefficient others)))))

(defun polygon-edges (polygon)
  "The edges of the checked POLYGON as a list of (A B), A to B counter-clockwise."
  (let ((vertices (rest polygon)))
    (loop for (a . rest) on vertices
          collect (list a (if rest (first rest) (first vertices))))))

(defun edge-cross (a b)
  "x_a y_b - x_b y_a as an expression."
  `(- (* ,(first a) ,(second b)) (* ,(first b) ,(second a))))

(defun polygon-area-sum (polygon)
  "The sum of the edges' cross products (twice the signed area) as an expression."
  (cons '+ (loop for (a b) in (polygon-edges polygon) collect (edge-cross a b))))

(defun centroid (shape)
  "The centroid of SHAPE in its own frame, (X Y) as expressions (folded where exact): of
a polygon's area, of a segment (its midpoint), of a circle (its centre, the origin);
NIL for other shapes."
  (case (shape-kind shape)
    (:circle (list 0 0))
    (:segment (destructuring-bind (a b) (rest shape)
                (list (folded `(/ (+ ,(first a) ,(first b)) 2))
                      (folded `(/ (+ ,(second a) ,(second b)) 2)))))
    (:polygon
     (let ((area (polygon-area-sum shape)))
       (flet ((moment (key)
                (folded `(/ (+ ,@(loop for (a b) in (polygon-edges shape)
                                       collect `(* (+ ,(funcall key a) ,(funcall key b))
                                                   ,(edge-cross a b))))
                            (* 3 ,area)))))
         (list (moment #'first) (moment #'second)))))))

(defun polygon-inertia-factor (polygon)
  "I / m of the uniform lamina POLYGON about its own origin (see this file's header)."
  (folded
   `(/ (+ ,@(loop for (a b) in (polygon-edges polygon)
                  collect (destructuring-bind ((xa ya) (xb yb)) (list a b)
                            `(* ,(edge-cross a b)
                                (+ (expt ,xa 2) (* ,xa ,xb) (expt ,xb 2)
                                   (expt ,ya 2) (* ,ya ,yb) (expt ,yb 2))))))
       (* 6 ,(polygon-area-sum polygon)))))

(defun shape-inertia (shape mass kind)
  "The moment of inertia about its reference point of a body of MASS and SHAPE (checked):
KIND :UNIFORM (a uniform lamina, disc or rod) or :RING (a hoop: circles only). NIL when
the shape has no such inertia (the caller says why)."
  (ecase kind
    (:ring (when (eq (shape-kind shape) :circle)
             (product mass `(expt ,(second shape) 2))))
    (:uniform
     (case (shape-kind shape)
       (:circle (product 1/2 mass `(expt ,(second shape) 2)))
       (:polygon (product mass (polygon-inertia-factor shape)))
       (:segment (destructuring-bind (a b) (rest shape)
                   (product 1/12 mass `(+ (expt (- ,(first b) ,(first a)) 2)
                                          (expt (- ,(second b) ,(second a)) 2)))))))))
