;;;; src/check/claims.lisp -- one state's claims checked numerically.
;;;;
;;;; CHECK-STATE (self-check.lisp) takes a state and the run's parameter values, and
;;;; returns how its claims fare: its equations of motion (the rates the knowledge base's model gives, recorded
;;;; as :CHECK-MODEL in the state's analysis) are integrated from the state's start by
;;;; INTEGRATE-RK4 on a fine grid up to the claimed end (or a horizon, for a state that
;;;; lasts forever), and
;;;;   - the closed-form positions and velocities (in TAU, or over the arc length along a
;;;;     curve) are compared with the integration at several times, the final positions
;;;;     and velocities at the end (relative 1e-8, with an absolute floor near zero: 1e-11
;;;;     of the largest such value in the state; for the velocities of a state at rest to
;;;;     double precision, of the largest position over the span; for a state integrated
;;;;     numerically, at least its integrator's error per step: COMPARISON-SCALE);
;;;;   - every termination condition's event function is evaluated on the grid: none may
;;;;     fire before the claimed end, and one that names the claimed end event must fire
;;;;     at the claimed time;
;;;;   - the model's equations, with the solved quantities put in, are evaluated at four
;;;;     points of the integration (relative 1e-8 of the size of their parts);
;;;;   - (self-check.lisp) the numbers the report prints beside the state's start, duration
;;;;     and final values are compared with their formulas' values (relative 1e-8).
;;;; Nothing here reads the closed-form solution to compute what it compares with.

(in-package #:ames.check)

(defparameter *relative-tolerance* 1d-8 "How far a closed form may be from the integration.")
(defparameter *grid-points* 240 "The grid of times on which events are searched.")
(defparameter *comparison-points* 8 "How many times of the grid the motion is compared at.")

(defstruct (check-failure (:constructor make-check-failure (claim discrepancy &optional detail)))
  "A claim that failed: CLAIM names it, DISCREPANCY is how far off it is (a number: the
relative error, or the time by which an event comes earlier), DETAIL says more."
  claim discrepancy detail)

(defun near-p (a b scale &optional (tolerance *relative-tolerance*))
  "True when A and B agree within TOLERANCE relative to their size, or to SCALE near zero."
  (<= (abs (- a b)) (* tolerance (max (abs a) (abs b) scale))))

(defun relative-error (a b scale)
  "|A - B| relative to their size (or to SCALE near zero)."
  (/ (abs (- a b)) (max (abs a) (abs b) scale 1d-300)))

(defstruct (setup (:constructor %make-setup))
  "A state ready to check: TERMS (its state terms), VARIABLES (TERMS, TAU and the
parameters), PARAMETERS (their values, doubles), RATES (a function of a state vector and
a time), Y0 the start, MODEL the recorded :CHECK-MODEL."
  terms variables parameters rates y0 model (cache (make-hash-table :test #'equal))
  ;; a function of a state vector and a time: the rates' round-off scales (ROUND-OFF-FORM)
  rate-scales)

(defun compiled (setup expression)
  "EXPRESSION as a function of a state vector and a time (see COMPILE-NUMERIC), compiled
once per SETUP."
  (or (gethash expression (setup-cache setup))
      (setf (gethash expression (setup-cache setup)) (compile-in-setup setup expression))))

(defun compile-in-setup (setup expression)
  "EXPRESSION compiled over SETUP's variables (see COMPILED)."
  (let ((function (compile-numeric expression (setup-variables setup)))
        (parameters (setup-parameters setup))
        (n (length (setup-terms setup))))
    (lambda (y time)
      (let ((v (make-array (+ n 1 (length parameters)))))
        (replace v y)
        (setf (svref v n) (coerce time 'double-float))
        (replace v parameters :start1 (1+ n))
        (funcall function v)))))

(defun make-setup (model values)
  "The SETUP of a state's MODEL under the parameter VALUES (alist name -> number), or
NIL (and a reason) when its start has no value."
  (let* ((terms (mapcar #'car (getf model :rates)))
         (setup (%make-setup :terms terms :model model
                             :variables (append terms (list 'tau) (mapcar #'car values))
                             :parameters (map 'simple-vector (lambda (e) (coerce (cdr e) 'double-float)) values)))
         (rate-functions (mapcar (lambda (entry) (compiled setup (cdr entry))) (getf model :rates)))
         (scale-functions (mapcar (lambda (entry) (compiled setup (round-off-form (cdr entry))))
                                  (getf model :rates)))
         (y0 (map 'simple-vector (lambda (term)
                                   (value-under (cdr (assoc term (getf model :initial) :test #'equal)) values))
                  terms)))
    (when (some #'null y0)
      (return-from make-setup (values nil "a state variable has no value at the start")))
    (setf (setup-y0 setup) y0
          (setup-rates setup) (lambda (y time)
                                (map 'simple-vector (lambda (f) (funcall f y time)) rate-functions))
          (setup-rate-scales setup) (lambda (y time)
                                      (map 'simple-vector (lambda (f) (funcall f y time)) scale-functions)))
    setup))

(defun safe (function y time)
  "FUNCTION's value at Y and TIME, or NIL where it has none."
  (handler-case (funcall function y time)
    (arithmetic-error () nil)))

(defun tau-form-p (motion)
  "True when MOTION, a body's reported position or velocity, is a pair of expressions in TAU."
  (and (consp motion) (= 2 (length motion))
       (every (lambda (c) (or (realp c) (valid-expression-p c :kind :arithmetic))) motion)))

(defun body-motion-values (setup body what y time)
  "BODY's integrated position (WHAT :POSITION) or velocity (:VELOCITY), a list of doubles."
  (mapcar (lambda (c) (funcall (compiled setup c) y time))
          (getf (second (assoc body (getf (setup-model setup) :bodies))) what)))

(defun motion-scale (setup samples what)
  "The largest absolute coordinate of the bodies' integrated positions or velocities."
  (loop for (time . y) in samples
        maximize (loop for (body) in (getf (setup-model setup) :bodies)
                       maximize (reduce #'max (mapcar #'abs (body-motion-values setup body what y time))))))

(defparameter *rest-round-off* 1d-12
  "A state whose velocities, over its whole span, move no body by more than this part of
its coordinates is at rest to double precision: its velocities are round-off.")

(defun comparison-scale (setup samples what &optional state)
  "The absolute floor near zero of the comparison of positions or velocities (WHAT):
1e-3 of the largest such value. When the state is at rest to double precision (see
*REST-ROUND-OFF*: the start values of an equilibrium, rounded to doubles, drift by
round-off), a velocity's floor is the largest position over the span: a velocity below
it moves no body beyond the tolerance of the positions. A STATE integrated numerically
(no closed form) claims its values only to its integrator's absolute error per step,
*NUMERIC-TOLERANCE* times (1 + the largest value): a value that crosses zero there (a
velocity at a turning point) is compared with at least that floor."
  (let ((scale (motion-scale setup samples what))
        (span (- (car (car (last samples))) (car (first samples)))))
    (when (and (eq what :velocity) (plusp span))
      (let ((positions (motion-scale setup samples :position)))
        (when (< (* scale span) (* *rest-round-off* positions))
          (setf scale (/ positions span)))))
    (max (* 1d-3 (max 1d-9 scale))
         (if (and state (state-numeric-trajectory state))
             (/ (* *numeric-tolerance* (+ 1 scale)) *relative-tolerance*)
             0d0))))

(defun closed-motion (setup body motion)
  "BODY's reported MOTION (position or velocity) as two expressions the setup can
evaluate: in TAU as it is, or, reported over the arc length along a curve (:ON-PATH (X Y)
:ARC-LENGTH S), with S the body's arc-length state term (so that the integrated arc
length gives the claimed place and velocity); NIL when it is neither."
  (cond ((tau-form-p motion) motion)
        ((and (consp motion) (eq (first motion) :on-path))
         (let ((term (getf (second (assoc body (getf (setup-model setup) :bodies))) :arc-length))
               (variable (getf (cddr motion) :arc-length)))
           (and term variable (tau-form-p (second motion))
                (mapcar (lambda (c) (substitute-expressions (list (cons variable term)) c))
                        (second motion)))))))

(defun turning-point-speed-p (state what claimed numeric scale &optional reported)
  "True when the velocity (WHAT :VELOCITY) of a periodic STATE, or one REPORTED over the
arc length (:ON-PATH ...), has no closed-form value where the integration gives it as
zero within SCALE: at a turning point the closed form over the arc length is the root of
the energy integral, which rounding leaves a hair below zero (the speed there is zero, as
claimed; a state ending where its body turns is checked at that end)."
  (and (null claimed) (eq what :velocity)
       (or (state-periodic state) (and (consp reported) (eq (first reported) :on-path)))
       (<= (abs numeric) scale)))

(defun compare-motion (setup state samples)
  "Failures of STATE's closed-form motion (in TAU, or over the arc length) at several
grid SAMPLES: for each body and coordinate, the worst time."
  (let ((failures '()) (stride (max 1 (floor (1- (length samples)) *comparison-points*))))
    (loop for (what reported) in (list (list :position (state-positions state))
                                       (list :velocity (state-velocities state)))
          for scale = (comparison-scale setup samples what state)
          do (loop for (body) in (getf (setup-model setup) :bodies)
                   for closed = (closed-motion setup body (body-entry reported body))
                   when closed
                     do (loop for c in closed
                              for axis in '(:x :y)
                              for function = (compiled setup c)
                              for worst = nil
                              do (loop for (time . y) in samples
                                       for k from 0
                                       when (and (plusp k) (zerop (mod k stride)))
                                         do (let ((claimed (safe function y time))
                                                  (numeric (nth (position axis '(:x :y))
                                                                (body-motion-values setup body what y time))))
                                              (unless (or (and claimed (near-p claimed numeric scale))
                                                          (turning-point-speed-p state what claimed numeric scale
                                                                                 (body-entry reported body)))
                                                (let ((off (if claimed (relative-error claimed numeric scale) :no-value)))
                                                  (when (or (null worst) (not (realp off))
                                                            (and (realp (first worst)) (> off (first worst))))
                                                    (setf worst (list off time claimed numeric)))))))
                                 (when worst
                                   (destructuring-bind (off time claimed numeric) worst
                                     (push (make-check-failure
                                            (format nil "~(~A~) ~(~A~)_~(~A~) at tau = ~A" body what axis (number-string time))
                                            off
                                            (format nil "closed form ~A, integration ~A"
                                                    (number-string claimed) (number-string numeric)))
                                           failures))))))
    (nreverse failures)))

(defun plain-text (datum)
  "DATUM written without package prefixes: symbols by their lower-case names."
  (cond ((keywordp datum) (format nil ":~(~A~)" (symbol-name datum)))
        ((and datum (symbolp datum)) (string-downcase (symbol-name datum)))
        ((consp datum)
         (format nil "(~{~A~^ ~})" (loop for cell on datum
                                         collect (plain-text (car cell))
                                         unless (listp (cdr cell)) collect (format nil ". ~A" (plain-text (cdr cell))))))
        ((null datum) "()")
        (t (princ-to-string datum))))

(defun datum-string (datum)
  "DATUM written briefly (see PLAIN-TEXT), cut at 80 characters."
  (let ((text (plain-text datum)))
    (if (> (length text) 80) (concatenate 'string (subseq text 0 77) "...") text)))

(defun number-string (x)
  "X (a real or NIL) written briefly for a report: 10 significant digits."
  (if (realp x)
      (let ((*read-default-float-format* 'double-float))
        (string-trim " " (format nil "~,10G" x)))
      "none"))

(defun compare-final (setup state samples values)
  "Failures of STATE's final positions and velocities against the integration at the end
of SAMPLES."
  (let ((failures '()) (end (car (car (last samples)))) (y (cdr (car (last samples)))))
    (loop for (what finals) in (list (list :position (state-final-positions state))
                                     (list :velocity (state-final-velocities state)))
          for scale = (comparison-scale setup samples what state)
          do (loop for (body) in (getf (setup-model setup) :bodies)
                   for final = (body-entry finals body)
                   when final
                     do (loop for c in final for axis in '(:x :y)
                              for numeric in (body-motion-values setup body what y end)
                              for claimed = (value-under c values)
                              unless (or (and claimed (near-p claimed numeric scale))
                                         (turning-point-speed-p state what claimed numeric scale
                                                                (body-entry (state-velocities state) body)))
                                do (push (make-check-failure
                                          (format nil "final ~(~A~) ~(~A~)_~(~A~)" what body axis)
                                          (if claimed (relative-error claimed numeric scale) :no-value)
                                          (format nil "claimed ~A, integration ~A at tau = ~A"
                                                  (number-string claimed) (number-string numeric) (number-string end)))
                                         failures))))
    (nreverse failures)))

;;; The model's equations, satisfied by the solved quantities along the motion

(defun subexpressions (expression &optional (limit 200))
  "EXPRESSION and its compound subexpressions, at most LIMIT of them, outermost first."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (< (length found) limit))
                 (push x found)
                 (unless (quantity-term-p x) (mapc #'walk (rest x))))))
      (walk expression))
    (nreverse found)))

(defun equation-residual (setup equation y time)
  "For EQUATION (LHS RHS), (values RESIDUAL SCALE) at Y and TIME: LHS - RHS and the
largest magnitude among both sides and their parts (what the residual is measured
against); NIL where a side has no value. Signals UNEVALUABLE as COMPILED does."
  (destructuring-bind (lhs rhs) equation
    (let ((left (safe (compiled setup lhs) y time))
          (right (safe (compiled setup rhs) y time)))
      (when (and left right)
        ;; the scale: the largest value of any part of the equation (terms that cancel
        ;; leave a residual of their own size's rounding)
        (values (- left right)
                (reduce #'max (mapcar (lambda (term) (abs (or (safe (compiled setup term) y time) 0d0)))
                                      (append (subexpressions lhs) (subexpressions rhs)))
                        :initial-value (max (abs left) (abs right))))))))

(defun compare-equations (setup samples)
  "Failures of the model's equations (the state's :CHECK-MODEL :EQUATIONS) at four
SAMPLES along the integration, relative 1e-8 of their terms' size; and the numbers of
equations verified and in all (an equation with a term the check cannot evaluate is not
verified)."
  (let* ((equations (getf (setup-model setup) :equations))
         (n (length samples))
         (points (remove-duplicates (list (first samples) (nth (floor n 3) samples)
                                          (nth (floor (* 2 n) 3) samples) (car (last samples)))))
         (failures '()) (verified 0))
    (dolist (equation equations)
      (handler-case
          (let ((worst nil))
            (dolist (sample points)
              (multiple-value-bind (residual scale) (equation-residual setup equation (cdr sample) (car sample))
                (when (and residual (> (abs residual) (* *relative-tolerance* scale)))
                  (let ((off (/ (abs residual) (max scale 1d-300))))
                    (when (or (null worst) (> off (first worst)))
                      (setf worst (list off (car sample))))))))
            (incf verified)
            (when worst
              (push (make-check-failure (format nil "the model equation ~A = ~A at tau = ~A"
                                                (datum-string (first equation)) (datum-string (second equation))
                                                (number-string (second worst)))
                                        (first worst)
                                        "the solved quantities do not satisfy it")
                    failures)))
        (unevaluable () nil)))
    (values (nreverse failures) verified (length equations))))
