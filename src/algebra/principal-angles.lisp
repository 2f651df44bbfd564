;;;; src/algebra/principal-angles.lisp -- atan of the tangent of an angle on the principal
;;;; branch is that angle.
;;;;
;;;; Solving for a turning point or an angle where a condition fires often gives
;;;; atan(sin b / cos b) (the arctangent of a tangent), where a physicist reads b: a disc
;;;; hinged at its rim, released at b, turns back at the angle -2 atan(sin b / cos b).
;;;; Maxima's sign() does not simplify atan(tan b), so whether the swing passes -b was not
;;;; decided. atan(tan x) = x holds exactly when -pi/2 < x < pi/2; each one-argument atan
;;;; whose argument is proven equal to tan x for one angle x proven inside that interval is
;;;; replaced by x, and the relation decided afresh (an identity, so the verdict stands).

(in-package #:ames.algebra)

(defun trigonometric-angles (expression)
  "The distinct arguments of sin, cos and tan in EXPRESSION."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (when (member (expression-operator x) '(sin cos tan))
                   (pushnew (first (expression-arguments x)) found :test #'equal))
                 (mapc #'walk (expression-arguments x)))))
      (walk expression))
    found))

(defun principal-angle-of (bridge atan-form)
  "The angle x when ATAN-FORM, (atan ARG), has ARG = tan x for the one angle x its
argument holds, with -pi/2 < x < pi/2 proven; else NIL."
  (let* ((argument (first (expression-arguments atan-form)))
         (angles (trigonometric-angles argument)))
    (when (and angles (null (rest angles)))
      (let ((x (first angles)))
        (and (holds-p bridge `(< (- (/ pi 2)) ,x))
             (holds-p bridge `(< ,x (/ pi 2)))
             (equivalent-p bridge argument `(/ (sin ,x) (cos ,x)))
             x)))))

(defun arctangents-of-tangents (expression)
  "The one-argument atan forms of EXPRESSION whose argument holds a trigonometric
function, innermost first."
  (one-argument-atans expression #'trigonometric-angles)) ; atan-orders.lisp

(defun decide-by-principal-angles (prover relation)
  "A reasoning step: each atan(tan x) of RELATION with x on the principal branch written
x (see the file header), the relation decided afresh. :UNKNOWN when there is none."
  (let* ((bridge (prover-bridge prover))
         (bindings (loop for form in (arctangents-of-tangents relation)
                         for angle = (principal-angle-of bridge form)
                         when angle collect (cons form angle))))
    (if (null bindings)
        :unknown
        (decide bridge (substitute-subexpressions bindings relation)))))
