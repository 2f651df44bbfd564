;;;; src/algebra/vanishing-witnesses.lisp -- a strict inequality E > 0 (or E < 0) whose E
;;;; has a square-root factor, sqrt(X), that surely vanishes at an admissible point: no
;;;; sound proof of it exists, and HOLDS-P says so without asking Maxima.
;;;;
;;;; The numeric witnesses (witnesses.lisp) cannot evaluate E where X < 0 (it is not real
;;;; there), so where X takes both signs they see E > 0 hold at some admissible points and
;;;; never fail: a root of a quadratic whose leading coefficient's sign is undecided,
;;;; sqrt(-c0/c2), is the costliest case (every strategy of DECIDE tried, each failing).
;;;; When X is surely positive at one admissible point and surely negative at another,
;;;; and X and E / sqrt(X) are surely defined and real on the whole segment between them,
;;;; every fact holding there too (CONTINUOUS-AND-ADMISSIBLE-BETWEEN-P), then X vanishes
;;;; at an admissible point on the segment (intermediate values), where E is 0: E > 0 and
;;;; E < 0 both fail there. Only a proof counts for HOLDS-P; DECIDE, which must tell
;;;; :FALSE from :UNKNOWN, does not use this.

(in-package #:ames.algebra)

(defun square-root-factors (expression)
  "Each way of writing EXPRESSION, as written, as REST * sqrt(X): a list of (X . REST),
from sqrt(X) or X^(1/2) itself (REST 1), and from each such factor of a product, or of
the numerator of a quotient, or of a negated expression (REST EXPRESSION with that
factor written 1)."
  (flet ((within (part rebuild)
           (mapcar (lambda (entry) (cons (car entry) (funcall rebuild (cdr entry))))
                   (square-root-factors part))))
    (cond ((atom expression) '())
          ((and (eq (expression-operator expression) 'sqrt) (= (length expression) 2))
           (list (cons (second expression) 1)))
          ((and (eq (expression-operator expression) 'expt) (eql (third expression) 1/2))
           (list (cons (second expression) 1)))
          ((eq (expression-operator expression) '*)
           (loop for tail on (rest expression)
                 for factor = (first tail)
                 for before = (ldiff (rest expression) tail)
                 for after = (rest tail)
                 append (within factor (lambda (rest) `(* ,@before ,rest ,@after)))))
          ((and (eq (expression-operator expression) '-) (= (length expression) 2))
           (within (second expression) (lambda (rest) `(- ,rest))))
          ((and (eq (expression-operator expression) '/) (cddr expression))
           (within (second expression) (lambda (rest) `(/ ,rest ,@(cddr expression)))))
          (t '()))))

(defun vanishing-square-root-p (bridge expression)
  "True when EXPRESSION, REST * sqrt(X) (one of SQUARE-ROOT-FACTORS), surely vanishes at
a point that satisfies the facts in force: X surely positive at one admissible point and
surely negative at another, X and REST surely defined and real, and every fact surely
holding, on the whole segment between them. NIL proves nothing. Asks Maxima nothing."
  (let ((factors (square-root-factors expression)))
    (when factors
      (let ((found (make-array (length factors) :initial-element nil)))
        ;; FOUND holds, for each factor, (POSITIVE-POINT . NEGATIVE-POINT) of its radicand
        (let ((facts (call-with-admissible-points
                      bridge (list '> expression 0)
                      (lambda (point)
                        (loop for (radicand . nil) in factors
                              for i from 0
                              for entry = (or (aref found i) (setf (aref found i) (cons nil nil)))
                              for ball = (expression-ball radicand point)
                              do (case (and ball (ball-sign ball))
                                   (:positive (unless (car entry) (setf (car entry) point)))
                                   (:negative (unless (cdr entry) (setf (cdr entry) point)))))
                        nil))))
          (loop for (radicand . rest) in factors
                for (positive . negative) across found
                thereis (and positive negative
                             (continuous-and-admissible-between-p radicand facts positive negative)
                             (continuous-and-admissible-between-p rest facts positive negative))))))))

(defun strict-relation-vanishing-p (bridge relation)
  "True when RELATION is E > 0, E < 0, 0 > E or 0 < E with E surely vanishing at an
admissible point (VANISHING-SQUARE-ROOT-P): it fails there, and has no sound proof."
  (and (consp relation)
       (member (expression-operator relation) '(> <))
       (= (length relation) 3)
       (let ((lhs (relation-lhs relation)) (rhs (relation-rhs relation)))
         (cond ((eql rhs 0) (vanishing-square-root-p bridge lhs))
               ((eql lhs 0) (vanishing-square-root-p bridge rhs))))))
