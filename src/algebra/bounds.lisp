;;;; src/algebra/bounds.lisp -- the numeric bounds facts put on a subject, and the sign facts of angles they give.
;;;;
;;;; Maxima does not use the range of an angle to find the sign of its sine or cosine, so
;;;; the facts a scope assumes are completed with the sign facts that follow from each
;;;; subject's numeric bounds (read off exactly in angles.lisp); the bridge calls
;;;; DERIVED-SIGN-FACTS through its hook *DERIVED-FACTS*.

(in-package #:ames.algebra)

(defun constant-value (expression)
  "The double-float value of EXPRESSION when it is made of numbers and PI only, else NIL."
  (labels ((value (x)
             (cond ((realp x) (coerce x 'double-float))
                   ((eq x 'pi) pi)
                   ((and (consp x) (arithmetic-operator-p (car x)))
                    (let ((arguments (mapcar #'value (cdr x))))
                      (when (every #'realp arguments)
                        (let ((result (apply-operator (car x) arguments)))
                          (and (realp result) (coerce result 'double-float))))))
                   (t nil)))
           (apply-operator (operator arguments)
             (handler-case
                 (case operator
                   (+ (apply #'+ arguments)) (- (apply #'- arguments))
                   (* (apply #'* arguments)) (/ (apply #'/ arguments))
                   (expt (expt (first arguments) (second arguments)))
                   (sqrt (sqrt (first arguments))) (exp (exp (first arguments)))
                   (abs (abs (first arguments)))
                   (log (log (first arguments)))
                   (sin (sin (first arguments))) (cos (cos (first arguments)))
                   (tan (tan (first arguments))) (asin (asin (first arguments)))
                   (acos (acos (first arguments)))
                   (atan (apply #'atan arguments)))
               (arithmetic-error () nil))))
    (value expression)))

(defstruct (bound (:constructor make-bound (value open)))
  "One end of an interval: a double-float VALUE, OPEN when the end is excluded."
  value open)

(defun fact-bound (fact)
  "When the relation FACT bounds a subject by a constant, return the subject, :LOWER or
:UPPER (or :BOTH for =), and the BOUND; else NIL."
  (let ((operator (expression-operator fact)))
    (when (member operator '(< > <= >= =))
      (let* ((lhs (relation-lhs fact)) (rhs (relation-rhs fact))
             (flip (and (not (subject-p lhs)) (subject-p rhs)))
             (subject (if flip rhs lhs))
             (value (constant-value (if flip lhs rhs))))
        (when (and (subject-p subject) value)
          (let ((operator (if flip
                              (ecase operator (< '>) (> '<) (<= '>=) (>= '<=) (= '=))
                              operator)))
            (ecase operator
              (> (values subject :lower (make-bound value t)))
              (>= (values subject :lower (make-bound value nil)))
              (< (values subject :upper (make-bound value t)))
              (<= (values subject :upper (make-bound value nil)))
              (= (values subject :both (make-bound value nil))))))))))

(defun tighter-bound (old new side)
  "The tighter of the bounds OLD (maybe NIL) and NEW on SIDE (:LOWER or :UPPER)."
  (cond ((null old) new)
        ((= (bound-value old) (bound-value new))
         (if (bound-open new) new old))
        ((eq side :lower) (if (> (bound-value new) (bound-value old)) new old))
        (t (if (< (bound-value new) (bound-value old)) new old))))

(defun subject-intervals (facts)
  "An alist (SUBJECT LOWER . UPPER) of the numeric bounds FACTS put on each subject."
  (let ((intervals '())
        (entries (make-hash-table :test #'equal)))
    (dolist (fact (flatten-facts facts) (nreverse intervals))
      (multiple-value-bind (subject side bound) (fact-bound fact)
        (when subject
          (let ((entry (or (gethash subject entries)
                           (let ((new (list subject nil)))
                             (push new intervals)
                             (setf (gethash subject entries) new)))))
            (when (member side '(:lower :both))
              (setf (second entry) (tighter-bound (second entry) bound :lower)))
            (when (member side '(:upper :both))
              (setf (cddr entry) (tighter-bound (cddr entry) bound :upper)))))))))

(defun derived-sign-facts (facts)
  "The sign facts about sin, cos and tan of each subject that follow from the numeric
bounds in FACTS (0 < a < pi/2 gives sin a > 0, cos a > 0 and tan a > 0), read off the
exact ranges of angles.lisp, and the squares of bounds by square roots (see
SQUARED-ROOT-FACTS)."
  (let ((flat (flatten-facts facts)))
    (append (angle-sign-facts flat) (squared-root-facts flat))))

(defun squared-root-facts (facts)
  "For each fact of FACTS bounding a quantity X by a square root, X < sqrt(Y) with X > 0
among FACTS, or X > sqrt(Y), the same bound squared, X^2 < Y or X^2 > Y (D X^2 < N
for Y = N / D with D > 0 among FACTS): Maxima's assume() does not square it (v0 < sqrt(2
G M / r) leaves the sign of r v0^2 - 2 G M open)."
  (flet ((positive-p (x) (or (and (realp x) (plusp x))
                             (member (list '> x 0) facts :test #'equal)
                             (member (list '< 0 x) facts :test #'equal)))
         (root-p (x) (and (consp x) (eq (first x) 'sqrt) (= (length x) 2))))
    (loop for fact in facts
          for (op a b) = (and (consp fact) (= (length fact) 3) fact)
          for (x root upper) = (cond ((and (member op '(< <=)) (root-p b)) (list a b t))
                                     ((and (member op '(> >=)) (root-p a)) (list b a t))
                                     ((and (member op '(> >=)) (root-p b)) (list a b nil))
                                     ((and (member op '(< <=)) (root-p a)) (list b a nil)))
          when (and root (or (not upper) (positive-p x)))
            collect (let ((relation (if upper (if (member op '(< >)) '< '<=) (if (member op '(< >)) '> '>=)))
                          (radicand (second root)))
                      ;; a quotient N / D with D > 0: D X^2 against N, which Maxima's sign()
                      ;; reads (it does not multiply through)
                      (if (and (consp radicand) (eq (first radicand) '/) (= (length radicand) 3)
                               (positive-p (third radicand)))
                          (list relation `(* ,(third radicand) (expt ,x 2)) (second radicand))
                          (list relation `(expt ,x 2) radicand))))))

(setf *derived-facts* 'derived-sign-facts)
