;;;; src/algebra/square-orders.lisp -- declared bounds carried through monotone maps.
;;;;
;;;; A bound declared on a positive parameter, v0 < sqrt(g r) or mu < tan a, says just as
;;;; much about its square: x -> x^2 is increasing on [0, oo), so 0 < V < E gives
;;;; V^2 < E^2 (and 0 < E < V gives E^2 < V^2). A relation in which V appears only
;;;; through even powers, such as v0^2 - g r > 0 or sin^2 a - mu^2 cos^2 a > 0, is then
;;;; decided with V^2 written as E^2 - D (or E^2 + D), D > 0 fresh: g r - D - g r < 0 at
;;;; once; tan^2 a is written sin^2 a / cos^2 a, so that the sines and cosines cancel.
;;;; Sound: every admissible V^2 is such an E^2 -/+ D. This is the last strategy of the
;;;; order substitution (orders.lisp), tried when the plain orderings decide nothing.

(in-package #:ames.algebra)

(defun even-powers-only-p (variable expression)
  "True when VARIABLE occurs in EXPRESSION, and only as (EXPT VARIABLE N) with N even."
  (let ((found nil))
    (labels ((walk (x)
               (cond ((eq x variable) (return-from even-powers-only-p nil))
                     ((and (consp x) (eq (first x) 'expt) (eq (second x) variable)
                           (integerp (third x)) (evenp (third x)) (plusp (third x)))
                      (setf found t))
                     ((and (consp x) (not (quantity-term-p x))) (mapc #'walk (rest x))))))
      (walk expression))
    found))

(defun substitute-square (variable square expression)
  "EXPRESSION with each (EXPT VARIABLE 2K) written as (EXPT SQUARE K)."
  (labels ((walk (x)
             (cond ((and (consp x) (eq (first x) 'expt) (eq (second x) variable)
                         (integerp (third x)) (evenp (third x)))
                    (if (= (third x) 2) square (list 'expt square (/ (third x) 2))))
                   ((and (consp x) (not (quantity-term-p x))) (cons (first x) (mapcar #'walk (rest x))))
                   (t x))))
    (walk expression)))

(defun squared-bound (bridge expression)
  "EXPRESSION^2 simplified, a tangent's square written sin^2/cos^2; NIL when Maxima
cannot."
  (let ((square (handler-case (simplify bridge (list 'expt expression 2) :strategy :full)
                  ((or untranslatable-result maxima-error) () nil))))
    (and square
         (labels ((walk (x)
                    (cond ((and (consp x) (eq (first x) 'tan))
                           (list '/ (list 'sin (second x)) (list 'cos (second x))))
                          ((and (consp x) (not (quantity-term-p x))) (cons (first x) (mapcar #'walk (rest x))))
                          (t x))))
           (walk square)))))

(defun positive-p (bridge expression)
  "True when EXPRESSION is proven positive (without the order substitution)."
  (let ((*substituting-orders* t))
    (eq :true (decide bridge (list '> expression 0)))))

(defun square-orders (bridge relation)
  "The orders (V^2 E^2 SIGN WEAK) that the facts in force give on the squares of the
positive variables of RELATION which RELATION has only in even powers (see the file
header)."
  (loop for fact in (current-assumptions bridge)
        for operator = (expression-operator fact)
        for sign = (case operator ((> >=) 1) ((< <=) -1))
        for lhs = (and sign (relation-lhs fact))
        for rhs = (and sign (relation-rhs fact))
        for alone = (cond ((null sign) nil)
                          ((variable-symbol-p lhs) (list lhs rhs sign))
                          ((variable-symbol-p rhs) (list rhs lhs (- sign))))
        for variable = (first alone)
        for bound = (second alone)
        when (and alone (not (numberp bound)) (free-of-p variable bound)
                  (even-powers-only-p variable relation)
                  (positive-p bridge variable) (positive-p bridge bound))
          collect (let ((square (squared-bound bridge bound)))
                    (and square (list variable square (third alone) (and (member operator '(>= <=)) t))))
            into orders
        finally (return (remove nil orders))))

(defun decide-by-square-orders (bridge relation)
  "RELATION decided with the square of a bounded positive variable written as its
bound's square plus or minus a fresh positive excess (see the file header), each such
fact alone: :TRUE, :FALSE or :UNKNOWN."
  (dolist (order (square-orders bridge relation) :unknown)
    (destructuring-bind (variable square sign weak) order
      (let* ((*substituting-orders* t)
             (delta (order-excess-name bridge (list 'expt variable 2)))
             (rewritten (substitute-square variable (list '+ square (list '* sign delta)) relation))
             (verdict (handler-case
                          (call-with-assumptions bridge (list (list (if weak '>= '>) delta 0))
                                                 (lambda () (decide bridge rewritten)))
                        (maxima-error () :unknown))))
        (unless (eq verdict :unknown)
          (return verdict))))))
