;;;; src/simulator/numeric.lisp -- the numeric integrator: for motions with no closed form, under
;;;; parameter values (--set), a Dormand-Prince 5(4) integration of the state's ODEs with event
;;;; detection.
;;;;
;;;; A group of bodies whose ODEs are neither constant, nor linear with a closed form, nor
;;;; one degree of freedom along a curve (a particle on a sliding hemisphere, a body around
;;;; a fixed mass) has no closed form in time. With numbers for the parameters its state
;;;; variables are integrated numerically, every termination condition that depends on
;;;; them is watched along the way, and the first to fire ends the state at a numeric
;;;; time, located by bisection. Without numbers, the state's end cannot be found: the
;;;; run stops, saying so (NO-CLOSED-FORM).

(in-package #:ames.simulator)

(define-condition no-closed-form (simulation-error) ()
  (:documentation "A state's motion has no closed form and no parameter values were given
to integrate it numerically. DATUM names the bodies."))

;;; A small compiler from the prefix algebra to closures over a vector of doubles

(defun numeric-function (expression symbols)
  "A function of a simple-vector of doubles (the values of SYMBOLS, in order) returning
EXPRESSION's value as a double, or signalling ARITHMETIC-ERROR where it has none.
EXPRESSION may hold numbers, PI and SYMBOLS only."
  (labels ((compile-form (x)
             (cond ((realp x) (let ((value (coerce x 'double-float))) (lambda (v) (declare (ignore v)) value)))
                   ((eq x 'pi) (lambda (v) (declare (ignore v)) pi))
                   ((symbolp x)
                    (let ((index (position x symbols)))
                      (unless index
                        (error 'unsupported-situation :datum x
                                                      :detail "A numeric integration met a symbol with no value."))
                      (lambda (v) (svref v index))))
                   (t (let ((args (mapcar #'compile-form (rest x))))
                        (flet ((unary (f) (let ((a (first args))) (lambda (v) (funcall f (funcall a v))))))
                          (case (first x)
                            (+ (lambda (v) (let ((s 0d0)) (dolist (a args s) (incf s (funcall a v))))))
                            (* (lambda (v) (let ((s 1d0)) (dolist (a args s) (setf s (* s (funcall a v)))))))
                            (- (if (rest args)
                                   (lambda (v) (- (funcall (first args) v)
                                                  (let ((s 0d0)) (dolist (a (rest args) s) (incf s (funcall a v))))))
                                   (unary #'-)))
                            (/ (if (rest args)
                                   (lambda (v) (/ (funcall (first args) v)
                                                  (let ((s 1d0)) (dolist (a (rest args) s) (setf s (* s (funcall a v)))))))
                                   (unary #'/)))
                            (expt (let ((base (first args)) (power (second args))
                                        (integer (and (integerp (third x)) (third x))))
                                    (if integer
                                        (lambda (v) (expt (funcall base v) integer))
                                        (lambda (v) (real-power (funcall base v) (funcall power v))))))
                            (sqrt (unary (lambda (a) (if (minusp a) (error 'floating-point-invalid-operation) (sqrt a)))))
                            (abs (unary #'abs))
                            (exp (unary #'exp))
                            (log (unary (lambda (a) (if (plusp a) (log a) (error 'floating-point-invalid-operation)))))
                            (sin (unary #'sin)) (cos (unary #'cos)) (tan (unary #'tan))
                            (sinh (unary #'sinh)) (cosh (unary #'cosh)) (tanh (unary #'tanh))
                            (asin (unary (lambda (a) (if (<= -1 a 1) (asin a) (error 'floating-point-invalid-operation)))))
                            (acos (unary (lambda (a) (if (<= -1 a 1) (acos a) (error 'floating-point-invalid-operation)))))
                            (atan (if (rest args)
                                      (let ((y (first args)) (x (second args)))
                                        (lambda (v) (atan (funcall y v) (funcall x v))))
                                      (unary #'atan)))
                            (t (error 'unsupported-situation
                                      :datum x :detail "A numeric integration met an operator it cannot evaluate.")))))))))
    (compile-form expression)))

(defun real-power (base power)
  "BASE^POWER for doubles, real or an arithmetic error."
  (cond ((plusp base) (expt base power))
        ((and (zerop base) (plusp power)) 0d0)
        (t (error 'floating-point-invalid-operation))))

;;; Dormand-Prince 5(4)

(defparameter *numeric-tolerance* 1d-10
  "The relative (and absolute) error per step the numeric integrator aims at.")

(defparameter *numeric-step-limit* 200000
  "The most steps one numeric state may take before the run stops, undecided.")

(defun dopri-step (rates y h)
  "One Dormand-Prince step of size H from the state vector Y: the fifth-order result
and an error estimate (a double). RATES maps a state vector to its derivative vector."
  (let* ((n (length y))
         (c '((1/5) (3/40 9/40) (44/45 -56/15 32/9) (19372/6561 -25360/2187 64448/6561 -212/729)
              (9017/3168 -355/33 46732/5247 49/176 -5103/18656)
              (35/384 0 500/1113 125/192 -2187/6784 11/84)))
         (b5 '(35/384 0 500/1113 125/192 -2187/6784 11/84 0))
         (b4 '(5179/57600 0 7571/16695 393/640 -92097/339200 187/2100 1/40))
         (ks (list (funcall rates y))))
    (flet ((combine (coefficients)
             (let ((result (copy-seq y)))
               (loop for a in coefficients for k in ks
                     do (dotimes (i n) (incf (svref result i) (* h (coerce a 'double-float) (svref k i)))))
               result)))
      (dolist (row c)
        (setf ks (append ks (list (funcall rates (combine row))))))
      (let ((y5 (combine b5)) (y4 (combine b4)) (err 0d0))
        (dotimes (i n)
          (let ((scale (+ *numeric-tolerance* (* *numeric-tolerance* (max (abs (svref y i)) (abs (svref y5 i)))))))
            (setf err (max err (/ (abs (- (svref y5 i) (svref y4 i))) scale)))))
        (values y5 err)))))

(defun integrate-until (rates y0 events &key (start-step 1d-3))
  "Integrate from the state vector Y0 at time 0 until one of EVENTS fires. EVENTS is a
list of functions of (STATE TIME) returning a double that is >= 0 while the event has
not happened (NIL where undefined). Returns (values TIME STATE INDEX SAMPLES): the time
and state where event INDEX first crosses below zero, located by bisection, and the
accepted steps as (TIME . STATE). NIL for TIME when the step limit is reached first, or
when the state or the step overflows the doubles (a motion that goes on forever with no
event: the steps grow without bound)."
  (let ((y y0) (time 0d0) (h start-step) (samples (list (cons 0d0 y0)))
        (before (mapcar (lambda (event) (funcall event y0 0d0)) events)))
    (loop repeat *numeric-step-limit*
          do (multiple-value-bind (next err)
                 (handler-case (dopri-step rates y h)
                   (floating-point-overflow ()
                     (return-from integrate-until (values nil y nil (nreverse samples)))))
               (if (> err 1d0)
                   (setf h (* h (max 0.1d0 (* 0.9d0 (expt err -1/5)))))
                   (let* ((after (mapcar (lambda (event) (funcall event next (+ time h))) events))
                          (fired (loop for b in before for a in after for i from 0
                                       when (and b a (>= b 0) (< a 0)) collect i)))
                     (loop while fired
                           do (multiple-value-bind (at state index) (locate-event rates y time h events fired)
                                (let ((value (funcall (nth index events) state at))
                                      (start (nth index before)))
                                  ;; a jump below zero is no event (a gap gated by its
                                  ;; face's extent: numeric-roots.lisp, JUMP-BELOW-ZERO-P)
                                  (if (and value (> (abs value) (* 1d-6 (max 1d0 (abs start)))))
                                      (setf fired (remove index fired))
                                      (return-from integrate-until
                                        (values at state index (nreverse (cons (cons at state) samples))))))))
                     (setf y next time (+ time h) before after)
                     (push (cons time y) samples)
                     (setf h (* h (min 5d0 (* 0.9d0 (expt (max err 1d-10) -1/5)))))))))
    (values nil y nil (nreverse samples))))

(defun locate-event (rates y time h events fired)
  "The first of the FIRED events within the step of size H from Y at TIME, by bisection:
(values TIME STATE INDEX)."
  (let ((low 0d0) (high h) (index (first fired)))
    (loop repeat 60
          do (let* ((middle (/ (+ low high) 2))
                    (state (dopri-step rates y middle))
                    (crossed (find-if (lambda (i)
                                        (let ((value (funcall (nth i events) state (+ time middle))))
                                          (and value (< value 0))))
                                      fired)))
               (if crossed
                   (setf high middle index crossed)
                   (setf low middle))))
    (values (+ time high) (dopri-step rates y high) index)))

;;; The numeric groups of a state

(defun run-numbers-known-p (run)
  "True when every parameter of the run has a number: values were given (--set,
--numeric), or the scenario has no parameters at all (its values are written in it)."
  (or (run-values run) (null (scenario-parameters (run-scenario run)))))

(defun numeric-bindings (run)
  "The run's parameter values as an alist parameter -> double (none for a scenario
without parameters), or signal NO-CLOSED-FORM when parameters have no values."
  (if (run-numbers-known-p run)
      (mapcar (lambda (entry) (cons (car entry) (coerce (cdr entry) 'double-float)))
              (run-values run))
      (error 'no-closed-form
             :datum (free-body-names run)
             :detail "The state's motion has no closed form; give the parameters numbers (--set) to integrate it numerically.")))

(defun numeric-expression (run groups expression terms)
  "EXPRESSION (over state terms, TAU and parameters) ready for NUMERIC-FUNCTION over
TERMS' symbols and TAU: the state terms of closed-form groups replaced by their motion,
the parameters by their values, TERMS by their symbols."
  (substitute-expressions
   (append (mapcar (lambda (term) (cons term (state-symbol term))) terms)
           (mapcar (lambda (entry) (cons (car entry) (cdr entry))) (numeric-bindings run)))
   (motion-value (remove :numeric groups :key #'group-kind) expression)))

(defun safe-value (function vector)
  "FUNCTION's value on VECTOR, or NIL where it has none."
  (handler-case (funcall function vector)
    (arithmetic-error () nil)))

(defun numeric-event-functions (run solved groups terms condition)
  "The event functions (see INTEGRATE-UNTIL) of the termination CONDITION over the
numeric TERMS: one per part of an OR."
  (let* ((relation (ames.engine:termination-condition-relation condition))
         (meeting (relation-meeting run solved relation))   ; guarded-meetings.lisp
         (symbols (append (mapcar #'state-symbol terms) (list 'tau))))
    (flet ((compiled (expression)
             (numeric-function (numeric-expression run groups (over-state-terms run solved expression) terms)
                               symbols))
           (vector-of (state time) (concatenate 'simple-vector state (vector time))))
      (if meeting
          (let* ((gap (compiled (ames.geometry:meeting-gap meeting)))
                 (margins (loop for r in (ames.geometry:meeting-extent meeting)
                                unless (eq (first r) 'or) collect (compiled (extent-margin r)))))
            (list (lambda (state time)
                    (let* ((v (vector-of state time)) (g (safe-value gap v)))
                      (and g (if (every (lambda (m) (let ((x (safe-value m v))) (and x (>= x -1d-9)))) margins)
                                 g
                                 (max g 1d-300)))))))
          (loop for part in (if (eq (first relation) 'or) (rest relation) (list relation))
                collect (let ((f (compiled (violation-function part))))
                          ;; the relation holds when F < 0: F itself is the event value
                          (lambda (state time) (safe-value f (vector-of state time)))))))))

(defun numeric-candidates (run solved groups conditions horizon)
  "Integrate the state's :NUMERIC groups until the first of CONDITIONS (those that
depend on them) fires, or until HORIZON (a number: the earliest closed-form candidate,
or NIL). Returns the CANDIDATEs that fire then (none when HORIZON comes first) and
records each numeric group's end state and samples."
  (let* ((numeric (remove :numeric groups :key #'group-kind :test-not #'eq))
         (terms (loop for g in numeric append (group-terms g)))
         (symbols (append (mapcar #'state-symbol terms) (list 'tau)))
         (rate-functions (mapcar (lambda (term)
                                   (numeric-function
                                    (numeric-expression run groups (cdr (assoc term (solved-model-rates solved)
                                                                              :test #'equal))
                                                        terms)
                                    symbols))
                                 terms))
         (rates (lambda (state)
                  (let ((v (concatenate 'simple-vector state (vector 0d0))))
                    (map 'simple-vector (lambda (f)
                                          (handler-case (funcall f v)
                                            (arithmetic-error ()
                                              (error 'simulation-error :datum terms
                                                     :detail "The numeric integration left the region where the motion is defined."))))
                         rate-functions))))
         (y0 (map 'simple-vector
                  (lambda (term)
                    (coerce (or (numeric-or-nil (run-bridge run) (cdr (assoc term (solved-model-initial solved) :test #'equal))
                                                (run-values run))
                                (error 'no-closed-form :datum term :detail "No numeric initial value."))
                            'double-float))
                  terms))
         (owners '()) (events '()))
    (dolist (condition conditions)
      (dolist (event (numeric-event-functions run solved groups terms condition))
        (push condition owners) (push event events)))
    (when horizon
      (push nil owners)
      (push (let ((h (coerce horizon 'double-float))) (lambda (state time) (declare (ignore state)) (- h time))) events))
    (setf owners (nreverse owners) events (nreverse events))
    ;; the ODEs are autonomous in the numeric terms, but a closed-form group's motion
    ;; may enter an event: events get the time explicitly
    (multiple-value-bind (time state index samples) (integrate-until rates y0 events)
      (unless time
        (error 'simulation-error :datum terms
                                 :detail (format nil "No event within ~D steps of the numeric integration (or before its steps overflowed)."
                                                 *numeric-step-limit*)))
      (dolist (group numeric)
        (setf (group-end-state group)
              (mapcar (lambda (term) (cons term (svref state (position term terms :test #'equal))))
                      (group-terms group))
              (group-samples group)
              (list :terms terms :end-time time
                    :samples (mapcar (lambda (sample) (cons (car sample) (coerce (cdr sample) 'list)))
                                     samples))))
      (let ((condition (nth index owners)))
        (if condition
            (let ((rate (numeric-approach-rate (nth index events) rates state time condition)))
              (when (and rate (corner-at-face-end-p run solved groups terms condition state time))
                ;; the corner meets the fixed body's vertex: along the adjoining face it
                ;; slides onto it, no impact (face-end-corners.lisp)
                (if (eq (face-end-verdict run solved groups terms condition rate rates state time)
                        :slides-on)
                    (setf rate nil)
                    (error 'unsupported-situation
                           :datum (condition-event condition nil)
                           :detail "A corner is reached at a speed at the end of a state integrated numerically exactly at an end of the face, moving into the adjoining face too (or beside it): a corner striking the fixed body's vertex is not modelled.")))
              (list (make-candidate condition (condition-event condition rate) time :rate rate)))
            '())))))

(defun corner-at-face-end-p (run solved groups terms condition state time)
  "True when CONDITION is a corner's guarded meeting (guarded-meetings.lisp) whose place
along the face is, in STATE at TIME, within round-off (1e-9) of one of the face's ends:
a corner reaching a face at its very end, where the neighbouring face may hold it."
  (let ((meeting (and (guarded-relation-parts (ames.engine:termination-condition-relation condition))
                      (relation-meeting run solved (ames.engine:termination-condition-relation condition))))
        (symbols (append (mapcar #'state-symbol terms) (list 'tau)))
        (vector (concatenate 'simple-vector state (vector time))))
    (and meeting
         (loop for r in (ames.geometry:meeting-extent meeting)
               thereis (and (not (eq (first r) 'or))
                            (let ((value (safe-value (numeric-function
                                                   (numeric-expression run groups
                                                                       (over-state-terms run solved (extent-margin r))
                                                                       terms)
                                                   symbols)
                                                  vector)))
                              (and value (<= (abs value) 1d-9))))))))

(defun numeric-approach-rate (event rates state time condition)
  "The rate (exact, from the double) at which the contact of CONDITION, whose event
function EVENT (of the state vector and time) fired at TIME in STATE, is reached, when
the bodies clearly approach (a central difference along the motion, RATES, below -1e-6):
an impact; NIL for another condition, or a meeting at no clear speed (a contact)."
  (let ((relation (ames.engine:termination-condition-relation condition)))
    (flet ((approach ()
             (let* ((epsilon 1d-7)
                    (velocity (funcall rates state))
                    (ahead (map 'simple-vector (lambda (y d) (+ y (* epsilon d))) state velocity))
                    (behind (map 'simple-vector (lambda (y d) (- y (* epsilon d))) state velocity))
                    (g1 (funcall event ahead (+ time epsilon)))
                    (g0 (funcall event behind (- time epsilon))))
               (when (and g0 g1)
                 (let ((rate (/ (- g1 g0) (* 2 epsilon))))
                   (and (< rate -1d-6) (rational-of rate)))))))
      (cond ((gap-relation-contact relation) (approach))
            ;; a corner reached at a clear speed (guarded-meetings.lisp): its impact is
            ;; resolved from the state's end put back exactly on the contacts held through
            ;; it (corner-snapping.lisp and its neighbours), or refused where one is not
            ;; (held-contacts.lisp)
            ((guarded-relation-parts relation) (approach))))))
