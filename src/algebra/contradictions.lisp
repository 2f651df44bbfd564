;;;; src/algebra/contradictions.lisp -- a relation proven to contradict the facts in force.
;;;;
;;;; A fork's branch assumes a fact that the assumptions and the facts of the forks above
;;;; it may already exclude without DECIDE seeing it: under f l3 - mb g (l1 - l2) < 0 (B
;;;; falls), P = (l1 - l2)^2 (mb g (3 l1 + l2) - f l3) + 2 ma g l3^2 (l1 + l2) <= 0 has no
;;;; admissible point, though neither fact alone decides P's sign in Maxima (P is too large
;;;; for the order substitution). Both facts are linear in f with coefficients of opposite
;;;; signs: s1 = c1 f + r1 >= 0 and s2 = c2 f + r2 > 0 with c1 > 0 > c2 give, with the
;;;; positive multipliers -c2 and c1, the combination -c2 s1 + c1 s2 = c1 r2 - c2 r1 = K,
;;;; free of f, which is > 0 wherever both hold (Farkas's lemma in one variable). When K <= 0
;;;; is proven under the facts in force (K < 0 when neither fact is strict), no admissible
;;;; point satisfies both: the relation contradicts them. Sound: the multipliers' signs and
;;;; K's are proven, and the combination is an identity (no division). An equation counts
;;;; as the two inequalities s >= 0 and -s >= 0. First, admissible points are drawn: one
;;;; that satisfies the relation shows it is consistent, and nothing is asked of Maxima.

(in-package #:ames.algebra)

(defparameter *most-contradicting-facts* 8
  "The most facts in force linear in one variable that CONTRADICTS-FACTS-P pairs with the
relation.")

(defun relation-witnessed-p (bridge relation)
  "True when RELATION surely holds at a point that surely satisfies the facts in force."
  (let ((found nil))
    (call-with-admissible-points bridge relation
                                 (lambda (point)
                                   (setf found (eq (condition-truth relation point) :true))))
    found))

(defun slacks (relation)
  "RELATION (> >= < <= =) as a list of (S STRICT): it says each S > 0 (STRICT) or S >= 0
(an equation: S >= 0 and -S >= 0). NIL for another operator."
  (if (eq (expression-operator relation) '=)
      (let ((difference `(- ,(relation-lhs relation) ,(relation-rhs relation))))
        (list (list difference nil) (list `(- ,difference) nil)))
      (multiple-value-bind (slack strict) (slack-of relation)
        (and slack (list (list slack strict))))))

(defun proven-sign (bridge x)
  "1 or -1 when X is proven positive or negative under the facts in force, else NIL."
  (cond ((realp x) (cond ((plusp x) 1) ((minusp x) -1)))
        ((eq :true (decide bridge (list '> x 0))) 1)
        ((eq :true (decide bridge (list '< x 0))) -1)))

(defun slack-parts (bridge slack variable)
  "(C R) with SLACK = C VARIABLE + R, C nonzero and both free of VARIABLE, or NIL."
  (let ((coefficients (linear-coefficients bridge slack variable)))
    (and coefficients (list (second coefficients) (first coefficients)))))

(defun opposing-slacks-contradict-p (bridge first second)
  "True when the slacks FIRST and SECOND, entries (C R STRICT SIGN) with C of proven sign
SIGN (opposite signs), cannot both hold: the combination |C2| S1 + |C1| S2 = K, free of
the variable, is proven <= 0 (< 0 when neither is strict)."
  (destructuring-bind ((c1 r1 strict1 sign1) (c2 r2 strict2 sign2)) (list first second)
    (declare (ignore sign2))
    ;; with C1 > 0 > C2: K = -C2 R1 + C1 R2; with C1 < 0 < C2: K = C2 R1 - C1 R2
    (let* ((k (simplified bridge (if (plusp sign1)
                                     `(+ (* -1 ,c2 ,r1) (* ,c1 ,r2))
                                     `(- (* ,c2 ,r1) (* ,c1 ,r2)))
                          :ratsimp))
           (goal (list (if (or strict1 strict2) '<= '<) k 0)))
      (and (not (relation-refuted-p bridge goal))
           (eq :true (decide bridge goal))))))

(defun contradicts-facts-p (bridge relation)
  "True when RELATION (> >= < <= =) is proven to hold at no point that satisfies the facts
in force, by two facts linear in one variable with coefficients of opposite signs (see
the file header): RELATION's own and one fact in force. NIL when it is seen to hold at
an admissible point, or when no such pair proves it."
  (when (and (slacks relation) (not (relation-witnessed-p bridge relation)))
    (let ((facts (remove-if-not (lambda (fact) (slacks fact))
                                (flatten-facts (current-assumptions bridge)))))
      (dolist (variable (remove-if-not #'variable-symbol-p (expression-variables relation)) nil)
        (let ((mentioning (remove-if (lambda (fact) (free-of-p variable fact)) facts)))
          (when (<= 1 (length mentioning) *most-contradicting-facts*)
            (flet ((entries (relation)
                     (loop for (slack strict) in (slacks relation)
                           for parts = (slack-parts bridge slack variable)
                           for sign = (and parts (proven-sign bridge (first parts)))
                           when sign collect (append parts (list strict sign)))))
              (let ((own (entries relation)))
                (when own
                  (dolist (fact mentioning)
                    (dolist (other (entries fact))
                      (dolist (mine own)
                        (when (and (/= (fourth mine) (fourth other))
                                   (opposing-slacks-contradict-p bridge mine other))
                          (return-from contradicts-facts-p t))))))))))))))
