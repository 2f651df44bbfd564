;;;; src/algebra/real-roots.lisp -- a root solve() writes with square roots is a time only
;;;; when it is real: every radicand proven non-negative.
;;;;
;;;; Maxima's sign() takes sqrt(D) for a non-negative number whatever D's sign, and its
;;;; solve() writes the roots of a quadratic factor as (-b -+ sqrt(D))/(2a) without %i
;;;; when D's sign is not known to be negative. A gap closed along a tangent is a square,
;;;; (y - top)^2, whose double roots are those of y = top: under top > 2 h they are complex
;;;; (the body never climbs that high), yet sign() found (v + sqrt(v^2 - 2 g top))/g
;;;; positive, and the search took a complex number for the time of a contact (atwood
;;;; machine with a bouncing mass). A root from solve() counts as found only when each
;;;; radicand of an even root in it is proven non-negative under the facts in force; else
;;;; it is left undecided (and dropped only when its imaginary part is decidedly not zero,
;;;; NON-REAL-P), so that the search answers :UNKNOWN and the square-free retry
;;;; (repeated-roots.lisp), whose quadratic reads the discriminant's sign, is tried.
;;;; The same flaw took sqrt(-(mb (l1 - l2)^2 + ma l3^2)) / sqrt(mb g (l2 - l1) + f l3) for
;;;; a time in the two blocks in a corner (real only when the push is too weak); the run
;;;; now branches on the push's sign at once, not through the slope at that root.

(in-package #:ames.algebra)

(defun even-root-radicands (expression)
  "The radicands of the even roots in EXPRESSION (sqrt(A), A^(p/q) with q even), inner
ones included, each once, outermost first."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (compound-expression-p x) (not (quantity-term-p x)))
                 (let ((radicand (case (expression-operator x)
                                   (sqrt (second x))
                                   (expt (let ((power (third x)))
                                           (and (rationalp power)
                                                (evenp (denominator power))
                                                (second x)))))))
                   (when radicand (pushnew radicand found :test #'equal)))
                 (mapc #'walk (expression-arguments x)))))
      (walk expression))
    (nreverse found)))

(defun proven-real-p (bridge expression)
  "True when EXPRESSION (prefix algebra, free of %i) is proven real under the facts in
force in BRIDGE: each radicand of an even root in it (EVEN-ROOT-RADICANDS) proven
non-negative (HOLDS-P; a constant one by exact intervals, through DECIDE). NIL when one
is not: Maxima's sign() takes sqrt(D) for a non-negative real whatever D's sign, so a
sign it gives such an EXPRESSION proves nothing. Signals what DECIDE signals, but for an
untranslatable radicand (NIL)."
  (every (lambda (radicand)
           (if (realp radicand)
               (>= radicand 0)
               (handler-case (holds-p bridge (list '>= radicand 0))
                 (untranslatable-expression () nil))))
         (even-root-radicands expression)))

(defun proven-real-root-p (search offset)
  "True when the root form OFFSET (a root solve() gave, free of %i) is proven real under
the facts in force (PROVEN-REAL-P of its expression). NIL when it is not, or OFFSET
does not translate."
  (let* ((bridge (search-bridge search))
         (expression (handler-case (root-form-expression bridge offset)
                       (untranslatable-result () (return-from proven-real-root-p nil)))))
    (proven-real-p bridge expression)))
