;;;; src/report/presentation.lisp -- the presentation step: each reported quantity written as a textbook would.
;;;;
;;;; Not a change to what is solved: a PRESENTER takes a solved expression and gives an
;;;; expression of the same value that reads well. Maxima does the algebra (candidate forms:
;;;; ratsimp, factor, sums grouped into factorable parts, trigsimp; the coefficients of a
;;;; polynomial in tau); forms.lisp arranges each candidate in the conventional order (the
;;;; scenario's masses first, then its parameters as declared, functions, then tau); the
;;;; smallest wins. Internal names become readable (the simulator's arc length is s), and
;;;; atan(cos x / sin x) becomes pi/2 - x where the assumptions put x in (0, pi). Every
;;;; presented form is checked against the solved one at admissible points (numbers that
;;;; satisfy the scenario's assumptions); should one ever differ, the solved form is shown
;;;; instead: a wrong closed form is never printed.

(in-package #:ames.report)

(defclass presenter ()
  ((scenario :initarg :scenario :reader presenter-scenario)
   (bridge :initarg :bridge :reader presenter-bridge)
   (values :initarg :values :initform '() :reader presenter-values
           :documentation "Alist (PARAMETER . NUMBER) for numbers beside the formulas.")
   (renamings :initarg :renamings :initform '() :reader presenter-renamings
              :documentation "Alist (INTERNAL-VARIABLE . DISPLAY-SYMBOL), e.g. the
simulator's arc length to s.")
   (cache :initform (make-hash-table :test 'equal) :reader presenter-cache)
   (points :initform nil :accessor presenter-points
           :documentation "Admissible points for the numeric check, made on first use."))
  (:documentation "The presentation step for one scenario's history: see PRESENT."))

(defparameter +arc-length+ (find-symbol "ARC-LENGTH" '#:ames.simulator)
  "The simulator's arc-length variable, named s in reports.")

(defparameter +arc-speed+ (find-symbol "ARC-SPEED" '#:ames.simulator)
  "The simulator's variable for the speed along a curve, named s' in reports.")

(defun display-symbol (base scenario)
  "A fresh symbol printed BASE (\"s\"), or BASE1, BASE2 ... when a parameter of SCENARIO
already has that name."
  (let ((taken (mapcar (lambda (p) (symbol-name (scenario-parameter-name p)))
                       (scenario-parameters scenario))))
    (loop for suffix from 0
          for name = (if (zerop suffix) base (format nil "~A~D" base suffix))
          unless (member name taken :test #'string-equal)
            return (make-symbol name))))

(defun make-presenter (history bridge)
  "The PRESENTER for HISTORY, asking BRIDGE (call within the scenario's assumptions)."
  (let ((scenario (history-scenario history)))
    (make-instance 'presenter
                   :scenario scenario :bridge bridge
                   :values (history-parameter-values history)
                   :renamings (list (cons +arc-length+ (display-symbol "S" scenario))
                                    (cons +arc-speed+ (display-symbol "S'" scenario))))))

(defun call-with-presenter (history bridge function)
  "Call FUNCTION with a PRESENTER for HISTORY, within the scenario's assumptions in BRIDGE.
When the run's time is up (its budget's, or a signal's: see AMES.BASE:BUDGET-TIME-LEFT)
Maxima is not asked: FUNCTION is called outside the assumptions, and the presenter's
requests fall back to the forms as solved."
  (flet ((without-maxima () (funcall function (make-presenter history bridge))))
    (let ((left (budget-time-left)))
      (if (and left (<= left 0))
          (without-maxima)
          (handler-case
              (ames.maxima:with-assumptions (bridge (scenario-assumption-relations
                                                     (history-scenario history)))
                (funcall function (make-presenter history bridge)))
            (ames.maxima:maxima-budget-exceeded () (without-maxima)))))))

(defun arc-length-symbol (presenter)
  "The symbol that names the arc length in PRESENTER's reports."
  (cdr (assoc +arc-length+ (presenter-renamings presenter))))

(defun mass-parameters (scenario)
  "The parameters that appear in a body's mass, in order of declaration."
  (let ((in-masses (loop for body in (scenario-bodies scenario)
                         append (expression-variables (or (scenario-body-mass body) 0)))))
    (remove-if-not (lambda (name) (member name in-masses))
                   (mapcar #'scenario-parameter-name (scenario-parameters scenario)))))

(defun symbol-key-function (presenter)
  "The sort key of a name in PRESENTER's arrangement: masses, other parameters as
declared, quantity terms (a_x), other names, s, then tau."
  (let* ((scenario (presenter-scenario presenter))
         (masses (mass-parameters scenario))
         (parameters (mapcar #'scenario-parameter-name (scenario-parameters scenario)))
         (variables (mapcar #'cdr (presenter-renamings presenter))))
    (lambda (name)
      (cond ((member name masses) (list 2 (position name masses)))
            ((member name parameters) (list 3 (position name parameters)))
            ((quantity-term-p name) (list 4 (princ-to-string name)))
            ((eq name 'tau) (list 7 0))
            ((member name variables) (list 6 (position name variables)))
            (t (list 5 (symbol-name name)))))))

(defun presenter-arrangement (presenter &optional variable)
  "The ARRANGEMENT forms.lisp uses for PRESENTER, sums ordered by powers of VARIABLE."
  (make-arrangement
   :symbol-key (symbol-key-function presenter)
   :variable variable
   :negative-p (lambda (expression) (proven-sign-p presenter '< expression))
   :nonnegative-p (lambda (expression) (proven-sign-p presenter '>= expression))))

(defvar *cheap-signs* nil
  "True while PROVEN-SIGN-P asks only for a cheap proof (ames.algebra:CHEAP-PROOF): where
a form is presented that no result depends on and whose terms' signs the full proof
mostly fails on (the facts assumed from the given values).")

(defun proven-sign-p (presenter relation expression)
  "True when the bridge proves (RELATION EXPRESSION 0) under the scenario's assumptions
(remembered in PRESENTER's cache); false when it does not or cannot. Under *CHEAP-SIGNS*,
by a cheap proof only, and a failed one is not remembered (a full proof may still come)."
  (let ((key (list relation expression)))
    (multiple-value-bind (known found) (gethash key (presenter-cache presenter))
      (cond (found known)
            (*cheap-signs*
             (let ((proven (handler-case (eq :true (ames.algebra:cheap-proof
                                                    (presenter-bridge presenter)
                                                    (list relation expression 0)))
                             (ames.maxima:maxima-condition () nil))))
               (when proven (setf (gethash key (presenter-cache presenter)) t))
               proven))
            (t (setf (gethash key (presenter-cache presenter))
                     (handler-case (let ((ames.algebra:*combined-bounds-wanted* nil))
                                     ;; a form's arrangement is not worth the costliest proofs
                                     (ames.algebra:holds-p (presenter-bridge presenter)
                                                           (list relation expression 0)))
                       (ames.maxima:maxima-condition () nil))))))))

(defun present-cheaply (presenter relation)
  "RELATION presented (PRESENT-RELATION) with the signs of its terms asked of cheap proofs
only (*CHEAP-SIGNS*), and without remembering the forms of its sides: for the facts
assumed from the given values, whose terms' signs the full proofs mostly fail on."
  (let ((*cheap-signs* t)
        (cache (presenter-cache presenter))
        (sides (and (consp relation) (relation-operator-p (first relation))
                    (list (list (relation-lhs relation) nil) (list (relation-rhs relation) nil)))))
    (let ((before (mapcar (lambda (key) (multiple-value-list (gethash key cache))) sides)))
      (prog1 (present-relation presenter relation)
        ;; a side presented here is presented again, with full proofs, where else it shows
        (loop for key in sides
              for (value found) in before
              do (if found (setf (gethash key cache) value) (remhash key cache)))))))

;;; Rewrites the assumptions justify

(defun holds-under-assumptions-p (presenter relation)
  "True when the bridge proves RELATION under the scenario's assumptions."
  (handler-case (ames.algebra:holds-p (presenter-bridge presenter) relation)
    (ames.maxima:maxima-condition () nil)))

(defun complementary-angles (presenter expression)
  "EXPRESSION with atan(cos x / sin x) written pi/2 - x where 0 < x < pi is proven, and
atan(sin x / cos x) written x where -pi/2 < x < pi/2 is."
  (labels ((walk (x)
             (if (or (atom x) (quantity-term-p x))
                 x
                 (let ((x (cons (first x) (mapcar #'walk (rest x)))))
                   (or (and (eq (first x) 'atan) (null (cddr x))
                            (let ((ratio (second x)))
                              (and (consp ratio) (eq (first ratio) '/) (= 3 (length ratio))
                                   (consp (second ratio)) (consp (third ratio))
                                   (equal (rest (second ratio)) (rest (third ratio)))
                                   (let ((angle (second (second ratio))))
                                     (case (first (second ratio))
                                       (cos (and (eq (first (third ratio)) 'sin)
                                                 (holds-under-assumptions-p presenter `(> ,angle 0))
                                                 (holds-under-assumptions-p presenter `(< ,angle pi))
                                                 `(- (/ pi 2) ,angle)))
                                       (sin (and (eq (first (third ratio)) 'cos)
                                                 (holds-under-assumptions-p presenter `(> ,angle (- (/ pi 2))))
                                                 (holds-under-assumptions-p presenter `(< ,angle (/ pi 2)))
                                                 angle)))))))
                       x)))))
    (walk expression)))

;;; The numeric check

(defun admissible-points (presenter)
  "A few alists (NAME . DOUBLE-FLOAT) over the scenario's parameters that satisfy its
assumptions (checked numerically), with tau and s in (0, 2): the given values first."
  (or (presenter-points presenter)
      (setf (presenter-points presenter)
            (let* ((scenario (presenter-scenario presenter))
                   (names (mapcar #'scenario-parameter-name (scenario-parameters scenario)))
                   (facts (scenario-assumption-relations scenario))
                   (state (sb-ext:seed-random-state 1994))
                   (points '()))
              (flet ((admissible-p (point)
                       (every (lambda (fact)
                                (let ((difference (expression-value
                                                   (list '- (relation-lhs fact) (relation-rhs fact)) point)))
                                  (and (realp difference)
                                       (ecase (first fact)
                                         ((> >=) (> difference 1d-9))
                                         ((< <=) (< difference -1d-9))
                                         (= (< (abs difference) 1d-9))
                                         (/= (> (abs difference) 1d-9))))))
                              facts))
                     (extended (point)
                       (list* (cons 'tau (+ 0.1d0 (random 1.5d0 state)))
                              (cons (arc-length-symbol presenter) (+ 0.1d0 (random 1.5d0 state)))
                              point)))
                (let ((given (append (presenter-values presenter) (scenario-parameter-values scenario))))
                  (when (every (lambda (n) (assoc n given)) names)
                    (let ((point (report-floats (mapcar (lambda (n) (assoc n given)) names))))
                      (when (and (= (length point) (length names)) (admissible-p point))
                        (push (extended point) points)))))
                (loop repeat 200 while (< (length points) 4)
                      do (let ((point (mapcar (lambda (n) (cons n (+ 0.05d0 (random 1.5d0 state)))) names)))
                           (when (admissible-p point) (push (extended point) points))))
                (nreverse points))))))

(defun numerically-same-p (presenter a b)
  "NIL when A and B surely differ at an admissible point (both defined there, relative
difference above 1e-7), else true."
  (dolist (point (admissible-points presenter) t)
    (let ((x (expression-value a point)) (y (expression-value b point)))
      (when (and (realp x) (realp y)
                 (> (abs (- x y)) (* 1d-7 (max 1d0 (abs x) (abs y)))))
        (return nil)))))

;;; Presenting

(defun renamed (presenter expression)
  "EXPRESSION with the simulator's internal variables replaced by their display names."
  (substitute-expressions (presenter-renamings presenter) expression))

(defun best-form (presenter expression variable)
  "The smallest arranged candidate of EXPRESSION (already renamed)."
  (let ((arrangement (presenter-arrangement presenter variable))
        (best nil) (best-size nil))
    (dolist (candidate (ames.maxima:presentation-candidates (presenter-bridge presenter) expression) best)
      (let* ((arranged (arrange candidate arrangement))
             (size (form-size arranged)))
        (when (or (null best) (< size best-size))
          (setf best arranged best-size size))))))

(defun polynomial-form (presenter coefficients variable)
  "The arranged sum of the presented COEFFICIENTS times powers of VARIABLE, constant first."
  (let ((terms (loop for coefficient in coefficients
                     for degree from 0
                     for shown = (present presenter coefficient)
                     unless (eql shown 0)
                       collect (if (zerop degree)
                                   shown
                                   (list '* shown (if (= degree 1) variable (list 'expt variable degree)))))))
    (cond ((null terms) 0)
          ((null (rest terms)) (arrange (first terms) (presenter-arrangement presenter variable)))
          (t (arrange (cons '+ terms) (presenter-arrangement presenter variable))))))

(defun present (presenter expression &key (variable 'tau))
  "EXPRESSION (arithmetic, as solved) written as a textbook would: an expression of the
algebra of the same value, a polynomial in VARIABLE grouped by its powers (constant
first), common factors pulled out, shorter trigonometric forms, factors in the
scenario's conventional order, internal names made readable. Non-arithmetic data is
returned as it is. Maxima's failures leave the renamed solved form."
  (if (not (valid-expression-p expression :kind :arithmetic))
      expression
      (let ((key (list expression variable)))
        (multiple-value-bind (known found) (gethash key (presenter-cache presenter))
          (if found
              known
              (setf (gethash key (presenter-cache presenter))
                    (let* ((plain (renamed presenter expression))
                           (shown (handler-case (present-renamed presenter plain variable)
                                    (ames.maxima:maxima-condition () plain))))
                      (if (numerically-same-p presenter plain shown) shown plain))))))))

(defun present-renamed (presenter expression variable)
  "PRESENT's work on the renamed EXPRESSION: the assumptions' rewrites, then a polynomial
in VARIABLE or the best candidate."
  (let* ((rewritten (complementary-angles presenter expression))
         (coefficients (and variable (not (free-of-p variable rewritten))
                            (ames.maxima:polynomial-coefficients (presenter-bridge presenter)
                                                                 rewritten variable))))
    (cond ((realp rewritten) rewritten)
          ((or (variable-symbol-p rewritten) (constant-symbol-p rewritten)) rewritten)
          (coefficients (polynomial-form presenter coefficients variable))
          (t (best-form presenter rewritten variable)))))

(defun present-relation (presenter relation)
  "RELATION (REL LHS RHS), or a logical form, with each side presented."
  (cond ((and (consp relation) (relation-operator-p (first relation)))
         (list (first relation) (present presenter (relation-lhs relation))
               (present presenter (relation-rhs relation))))
        ((and (consp relation) (logical-operator-p (first relation)))
         (cons (first relation) (mapcar (lambda (r) (present-relation presenter r)) (rest relation))))
        (t (present presenter relation))))

(defun numeric (presenter expression)
  "The number EXPRESSION (as solved) takes under the presenter's values, or NIL."
  (let ((values (presenter-values presenter)))
    (and values (valid-expression-p expression :kind :arithmetic)
         (let ((value (expression-value expression values)))
           (cond ((integerp value) value)
                 (t (report-float value)))))))

(defun numeric-polynomial (presenter expression &optional (variable 'tau))
  "EXPRESSION under the presenter's values as an arranged polynomial in VARIABLE with
numeric coefficients (0.9152 + 2.1 tau^2), a number when it is free of VARIABLE, or NIL."
  (let ((values (presenter-values presenter)))
    (when (and values (valid-expression-p expression :kind :arithmetic))
      (if (free-of-p variable expression)
          (numeric presenter expression)
          (let ((coefficients (handler-case (ames.maxima:polynomial-coefficients
                                             (presenter-bridge presenter) expression variable)
                                (ames.maxima:maxima-condition () nil))))
            (when coefficients
              (let ((numbers (mapcar (lambda (c) (numeric presenter c)) coefficients)))
                (when (every #'report-float numbers)
                  (arrange (cons '+ (loop for n in numbers for degree from 0
                                          unless (zerop n)
                                            collect (list '* (report-float n)
                                                          (list 'expt variable degree))))
                           (presenter-arrangement presenter variable))))))))))
