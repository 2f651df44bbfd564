;;;; src/algebra/imaginary-radicands.lisp -- relations with products of square roots of
;;;; negative radicands, decided in real terms.
;;;;
;;;; Maxima takes the square root of a negative number for an imaginary one, so a product
;;;; sqrt(A) sqrt(B) with A, B < 0 (a real number, -sqrt(A B)) makes it find a relation
;;;; complex or a fact inconsistent. DECIDE hands such relations here (through
;;;; DECIDE-WITH-IMAGINARY-RADICANDS); RADICALS.LISP rewrites facts with REALIFIED-RELATION.

(in-package #:ames.algebra)

(defun product-root-radicands (expression)
  "The radicands of the square roots that stand, two or more together, as factors of
one product or quotient somewhere in EXPRESSION, each once."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (when (member (expression-operator x) '(* /))
                   (let ((radicands (loop for (factor) in (nth-value 1 (product-parts x))
                                          for radicand = (square-root-radicand factor)
                                          when radicand collect radicand)))
                     (when (rest radicands)
                       (dolist (radicand radicands) (pushnew radicand found :test #'equal)))))
                 (mapc #'walk (expression-arguments x)))))
      (walk expression))
    (nreverse found)))

(defun imaginary-radicands (bridge relation)
  "The radicands of RELATION's products of square roots (see PRODUCT-ROOT-RADICANDS)
that are proven negative: there sqrt(A) sqrt(B) = -sqrt(A B) is real, but Maxima's
sign() takes the square root of a radicand it cannot see is negative for a nonnegative
number, and one it sees is negative for an imaginary one. A radicand sign() finds
nonnegative is not asked further."
  (loop for radicand in (product-root-radicands relation)
        for signs = (handler-case (maxima-signs bridge radicand :datum relation)
                      (maxima-error () nil))
        when (and (not (only-signs-p signs :positive :zero))
                  (member :negative signs)
                  (eq :true (decide bridge (list '< radicand 0))))
          collect radicand))

(defun realified (expression radicands)
  "EXPRESSION with each product or quotient holding an even number of square roots of
the negative RADICANDS written with real roots: sqrt(A) sqrt(B) = -sqrt(-A) sqrt(-B) and
sqrt(A) / sqrt(B) = sqrt(-A) / sqrt(-B) for A, B < 0 (i i = -1, i / i = 1). A product
with an odd number of them, which is not real, is left as it is."
  (labels ((walk (x)
             (cond ((or (atom x) (quantity-term-p x)) x)
                   ((member (expression-operator x) '(* /))
                    (multiple-value-bind (coefficient factors) (product-parts x)
                      (let ((turns 0))
                        (let ((rewritten
                                (loop for (factor . power) in factors
                                      for radicand = (square-root-radicand factor)
                                      collect (if (and radicand (member radicand radicands :test #'equal))
                                                  (progn (incf turns power)
                                                         (cons (list 'sqrt (list '- (walk radicand))) power))
                                                  (cons (walk factor) power)))))
                          (if (evenp turns)
                              (product-expression (if (= 2 (mod turns 4)) (- coefficient) coefficient)
                                                  rewritten)
                              (cons (expression-operator x) (mapcar #'walk (expression-arguments x))))))))
                   (t (cons (expression-operator x) (mapcar #'walk (expression-arguments x)))))))
    (walk expression)))

(defun realified-relation (bridge relation)
  "RELATION (a relation or logical form) with its products of square roots of negative
radicands written with real roots (see REALIFIED), or RELATION itself when it has none:
Maxima takes the square root of a negative for an imaginary number, and so finds such a
relation complex, or a fact about it inconsistent."
  (let ((radicands (imaginary-radicands bridge relation)))
    (if radicands (realified relation radicands) relation)))

(defun decide-with-imaginary-radicands (bridge relation)
  "RELATION, which has products of square roots of negative radicands (see
IMAGINARY-RADICANDS), decided in real terms: written with real roots where the products
hold an even number of them (REALIFIED), and asked of DECIDE. Where a product holds an
odd number (an imaginary part, which only a sum such as Cardano's formula for a cubic's
root can make real again), from the signs of its parts and through squares; :FALL-BACK
when that decides nothing, for DECIDE-RELATION's usual strategies."
  (let* ((radicands (imaginary-radicands bridge relation))
         (real (realified relation radicands)))
    (if (and (not (equal real relation)) (null (product-root-radicands-among real radicands)))
        (decide bridge real)
        (let* ((*imaginary-radicands* radicands)
               (prover (prover-for bridge))
               (verdict (relation-verdict (expression-operator relation)
                                          (expression-signs prover (relation-difference relation) :top t))))
          (when (eq verdict :unknown)
            (setf verdict (handler-case (decide-by-squares prover relation)
                            ((or maxima-timeout maxima-error) () :unknown))))
          (if (eq verdict :unknown) :fall-back verdict)))))

(defun product-root-radicands-among (expression radicands)
  "The RADICANDS still under a square root in EXPRESSION."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (let ((radicand (square-root-radicand x)))
                   (when (and radicand (member radicand radicands :test #'equal))
                     (pushnew radicand found :test #'equal)))
                 (mapc #'walk (expression-arguments x)))))
      (walk expression))
    found))
