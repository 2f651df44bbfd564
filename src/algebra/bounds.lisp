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
  (let ((intervals '()))
    (dolist (fact (flatten-facts facts) (nreverse intervals))
      (multiple-value-bind (subject side bound) (fact-bound fact)
        (when subject
          (let ((entry (or (assoc subject intervals :test #'equal)
                           (let ((new (list subject nil))) (push new intervals) new))))
            (when (member side '(:lower :both))
              (setf (second entry) (tighter-bound (second entry) bound :lower)))
            (when (member side '(:upper :both))
              (setf (cddr entry) (tighter-bound (cddr entry) bound :upper)))))))))

(defun derived-sign-facts (facts)
  "The sign facts about sin, cos and tan of each subject that follow from the numeric
bounds in FACTS (0 < a < pi/2 gives sin a > 0, cos a > 0 and tan a > 0), read off the
exact ranges of angles.lisp."
  (angle-sign-facts (flatten-facts facts)))

(setf *derived-facts* 'derived-sign-facts)
