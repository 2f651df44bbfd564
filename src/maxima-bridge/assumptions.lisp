;;;; src/maxima-bridge/assumptions.lisp -- scoped assumptions (Maxima contexts) and the sign facts Maxima misses.
;;;;
;;;; Each WITH-ASSUMPTIONS scope is one Maxima context made with supcontext and ended with
;;;; killcontext, so facts never leak out of their scope. Maxima does not use the range of
;;;; an angle to find the sign of its sine or cosine (with 0 < a < pi/2, is(cos(a) > 0) is
;;;; unknown), so the bridge derives those facts itself from the numeric bounds of each
;;;; variable (exactly, see angles.lisp) and assumes them too. The frames are kept in the bridge, so a restarted
;;;; Maxima process gets them replayed.

(in-package #:ames.maxima)

;;; Facts as Maxima can assume them

(defun negate-condition (condition)
  "The prefix condition saying the opposite of CONDITION."
  (let ((operator (expression-operator condition))
        (arguments (expression-arguments condition)))
    (case operator
      (= (list* '/= arguments)) (/= (list* '= arguments))
      (< (list* '>= arguments)) (>= (list* '< arguments))
      (> (list* '<= arguments)) (<= (list* '> arguments))
      (not (first arguments))
      (and (list* 'or (mapcar #'negate-condition arguments)))
      (or (list* 'and (mapcar #'negate-condition arguments))))))

(defun flatten-facts (facts)
  "FACTS with conjunctions spread out and negations pushed inward."
  (loop for fact in facts
        append (case (expression-operator fact)
                 (and (flatten-facts (expression-arguments fact)))
                 (not (flatten-facts (list (negate-condition (second fact)))))
                 (t (list fact)))))

(defun fact-to-maxima (table fact)
  "The Maxima form of the relation FACT, as assume() takes it (= and /= become
equal() and notequal())."
  (let ((form (to-maxima table fact :kind :condition)))
    (case (expression-operator fact)
      (= (apply #'mform +equal+ (mform-arguments form)))
      (/= (apply #'mform +notequal+ (mform-arguments form)))
      (t form))))

;;; Deriving trigonometric sign facts from numeric bounds

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

(defun subject-p (x)
  "True for what a bound can be about: a variable or a quantity term."
  (or (variable-symbol-p x) (quantity-term-p x)))

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

;;; Scopes

(defun current-assumptions (bridge)
  "The facts in force in BRIDGE, outermost scope first, as they were given (derived
facts not included)."
  (loop for frame in (reverse (bridge-frames bridge))
        append (assumption-frame-facts frame)))

(defun frame-setup-form (frame)
  "The Maxima request that opens FRAME's context and assumes its facts."
  (let ((facts (assumption-frame-maxima-facts frame)))
    (mlist (list* (mform (wire "$SUPCONTEXT") (assumption-frame-context frame))
                  (when facts (list (apply #'mform (wire "$ASSUME") facts)))))))

(defun replay-assumptions (bridge)
  "Open again, in a fresh Maxima process, every active frame of BRIDGE."
  (dolist (frame (reverse (bridge-frames bridge)))
    (multiple-value-bind (status data) (round-trip bridge (list :eval (frame-setup-form frame)))
      (unless (eq status :ok)
        (discard-process bridge)
        (error 'maxima-process-died
               :datum (assumption-frame-facts frame)
               :detail (format nil "replaying assumptions failed: ~S ~S" status data))))))

(defun pop-frame (bridge frame)
  "Leave FRAME (the innermost) and kill its Maxima context. When Maxima cannot do that,
the process is discarded: a new one is built from the remaining frames."
  (setf (bridge-frames bridge) (remove frame (bridge-frames bridge)))
  (when (bridge-alive-p bridge)
    (let ((parent (if (bridge-frames bridge)
                      (assumption-frame-context (first (bridge-frames bridge)))
                      +initial-context+)))
      (handler-case
          (maxima-request bridge (mform (wire "$AMES_POP_CONTEXT")
                                        (assumption-frame-context frame) parent)
                          :cache nil)
        (maxima-condition () (discard-process bridge))))))

(defun call-with-assumptions (bridge facts thunk)
  "Call THUNK with FACTS (a list of relations in prefix algebra, e.g.
((> mp 0) (> a 0) (< a (/ pi 2)))) assumed in BRIDGE's Maxima, in a scope of their own
that ends when THUNK returns or exits; scopes nest. Adds the sign facts of sin, cos and
tan that follow from numeric bounds (0 < a < pi/2 gives sin a > 0, cos a > 0, tan a > 0).
A fact with a product of square roots of negative radicands is told to Maxima with
real roots (sqrt(A) sqrt(B) = -sqrt(-A) sqrt(-B) for A, B < 0). Returns THUNK's values.
Signals UNTRANSLATABLE-EXPRESSION for a fact outside the algebra, MAXIMA-ERROR when
Maxima cannot assume a fact (a disjunction, say), and INCONSISTENT-ASSUMPTIONS naming
the fact that contradicts the facts in force; its restart RETRACT-ASSUMPTION calls THUNK
under the other facts."
  (unless (listp facts)
    (error 'untranslatable-expression :datum facts :expression facts
                                      :detail "assumptions must be a list of relations"))
  (dolist (fact facts) (check-translatable fact :condition))
  (let* ((table (bridge-names bridge))
         (outer (current-assumptions bridge))
         (already (derived-sign-facts outer))
         (derived (remove-if (lambda (fact) (member fact already :test #'equal))
                             (derived-sign-facts (append outer facts))))
         (flat (flatten-facts facts))
         ;; Derived facts go first, so that a contradiction is laid at a given fact.
         (sources (append derived flat))
         ;; Maxima is told facts with real square roots only (see REALIFIED-RELATION)
         (assumed (append derived
                          (mapcar (lambda (fact)
                                    (if (product-root-radicands fact)
                                        (realified-relation bridge fact)
                                        fact))
                                  flat)))
         (frame (make-assumption-frame (fresh-context-name table) facts
                                       (mapcar (lambda (fact) (fact-to-maxima table fact))
                                               assumed)))
         (answer (let ((opened nil))
                   (unwind-protect
                        (prog1 (maxima-request bridge (frame-setup-form frame)
                                               :cache nil :datum facts)
                          (setf opened t))
                     ;; A failed set-up may have left the context open in Maxima.
                     (unless opened (pop-frame bridge frame)))))
         (verdicts (and (rest (mlist-items answer)) (mlist-items (second (mlist-items answer)))))
         (position (position +inconsistent+ verdicts)))
    (push frame (bridge-frames bridge))
    (when position
      (pop-frame bridge frame)
      (let ((culprit (nth position sources)))
        (restart-case
            (error 'inconsistent-assumptions :fact culprit :datum facts
                                             :detail "Maxima's assume() says inconsistent")
          (retract-assumption ()
            :report (lambda (stream)
                      (format stream "Retract ~S and go on with the other facts." culprit))
            (return-from call-with-assumptions
              (call-with-assumptions bridge (remove-offending-fact culprit facts) thunk))))))
    (unwind-protect (funcall thunk)
      (pop-frame bridge frame))))

(defun remove-offending-fact (culprit facts)
  "FACTS without CULPRIT (or without the conjunction or negation that contains it)."
  (remove-if (lambda (fact) (member culprit (flatten-facts (list fact)) :test #'equal))
             facts))

(defmacro with-assumptions ((bridge facts) &body body)
  "Run BODY with FACTS assumed in BRIDGE's Maxima: see CALL-WITH-ASSUMPTIONS."
  `(call-with-assumptions ,bridge ,facts (lambda () ,@body)))
