;;;; src/simulator/numeric-roots.lisp -- under parameter values, the time a termination condition
;;;; fires over a closed-form motion whose root Maxima cannot give (a number).
;;;;
;;;; A closed form in TAU may meet a condition at a time with no elementary closed form: a ball
;;;; falling against linear drag reaches the ground at a Lambert W, against quadratic drag where
;;;; ln cosh equals a constant (solve() may find the root but cannot prove it the earliest). The
;;;; condition is then undecided; under parameter values (--set, --numeric) its event function
;;;; (the one the numeric integrator watches: numeric.lisp) is followed along the closed-form
;;;; motion itself, on a grid of times growing geometrically from 1e-6 by 0.1% a step (about
;;;; 23,000 evaluations up to 1e6), and the first crossing below zero is located by bisection:
;;;; the candidate's time is that number. Only a root Maxima could not give is looked for so
;;;; ((:EARLIEST-ROOT-OF ...)): an undecided sign is the run's branch, as before. A crossing that starts and ends between two grid
;;;; times (a grazing dip) is missed, as by the numeric integrator's own event search. No
;;;; crossing up to the grid's end (or where the function stops having a value) leaves the
;;;; condition undecided, as before.

(in-package #:ames.simulator)

(defparameter *numeric-root-grid* '(1d-6 1.001d0 1d6)
  "The grid of times a numeric root search follows: (FIRST RATIO LAST).")

(defun first-crossing-time (function)
  "The first time > 0 at which FUNCTION (of a double time, a double or NIL where undefined)
goes from >= 0 to < 0, located by bisection to double precision, or NIL."
  (destructuring-bind (first ratio last) *numeric-root-grid*
    (let ((previous 0d0) (before (funcall function 0d0)))
      (loop for time = first then (* time ratio)
            while (<= time last)
            do (let ((value (funcall function time)))
                 (cond ((null value) (return nil))
                       ((and before (>= before 0) (< value 0))
                        (let ((low previous) (high time))
                          (loop repeat 200
                                while (< low (* high (- 1 1d-15)))
                                do (let* ((middle (/ (+ low high) 2)) (v (funcall function middle)))
                                     (if (and v (< v 0)) (setf high middle) (setf low middle))))
                          (return high))))
                 (setf previous time before value))))))

(defun numeric-root-candidate (run solved groups condition)
  "Under the run's parameter values, a CANDIDATE for CONDITION (over closed-form GROUPS)
at the first time its event function crosses below zero, or NIL (no values, no crossing
found, or no event function)."
  (when (and (run-values run) (numeric-root-allowed-p run condition))
    (let* ((functions (handler-case (numeric-event-functions run solved groups '() condition)
                        (ames-error () nil)))
           (empty (vector))
           (times (loop for f in functions
                        for time = (first-crossing-time
                                    (lambda (time) (handler-case (funcall f empty time)
                                                     (error () nil))))
                        when time collect time)))
      (when times
        (let* ((time (reduce #'min times))
               (rate (crossing-rate run solved groups condition time)))
          (if (and rate (eq (approach-kind run rate) :impact))
              (make-candidate condition (condition-event condition rate) time :rate rate)
              (make-candidate condition (condition-event condition nil) time)))))))

(defun numeric-root-allowed-p (run condition)
  "True unless CONDITION meets a locus the state's end could not be put on exactly: a
contact other than a straight one between two shapes (a curve, or a point attached to a
body), where the body found at a rounded time would sit off the locus."
  (let* ((relation (ames.engine:termination-condition-relation condition))
         (contact (gap-relation-contact relation)))
    (or (null contact)
        (and (eq (first relation) '=)
             (null (locus-kind run contact))
             (member (ames.geometry:contact-kind (contact-geometry run contact)) '(:segment :line))))))

(defun snapped-to-contacts (run fired positions)
  "The final POSITIONS (alist body -> (X Y)) with each observer of a straight contact that
a FIRED candidate meets at a numeric time (NUMERIC-ROOT-CANDIDATE) put exactly on the
contact's line (its rounded place projected onto it), so that the next state finds the
contact."
  (dolist (candidate fired positions)
    (let ((contact (and (floatp (candidate-time candidate)) (candidate-condition candidate)
                        (gap-relation-contact (ames.engine:termination-condition-relation
                                               (candidate-condition candidate))))))
      (when (and contact (numeric-root-allowed-p run (candidate-condition candidate)))
        (destructuring-bind (observer obstacle) (contact-bodies run contact)
          (let* ((geometry (contact-geometry run contact))
                 (base (second (assoc obstacle positions)))
                 (start (ames.geometry:contact-point geometry 0))
                 (tangent (ames.geometry:contact-unit-tangent geometry 0))
                 (q (vec- (second (assoc observer positions)) base))
                 (s (tidy run (vec-dot (vec- q start) tangent)))
                 (on (mapcar (lambda (x) (tidy run x)) (vec+ base (vec+ start (vec-scale s tangent))))))
            (unless (body-fixed-p run observer)
              (setf positions (mapcar (lambda (entry) (if (eq (first entry) observer) (list observer on) entry))
                                      positions)))))))))

(defun crossing-rate (run solved groups condition time)
  "For a CONDITION that names an impact event, the rate at which its function (a contact's
gap, or the violation function) crosses zero at the numeric TIME, as a number; else NIL."
  (when (ames.engine:termination-condition-impact condition)
    (let* ((relation (ames.engine:termination-condition-relation condition))
           (contact (gap-relation-contact relation))
           (function (cond (contact (ames.geometry:meeting-gap (contact-meeting-terms run solved contact)))
                           ((member (first relation) '(< <= > >=)) (violation-function relation))))
           (over-time (and function (motion-value groups (over-state-terms run solved function)))))
      (and over-time
           (numeric-or-nil (run-bridge run) (at-time (time-derivative over-time) (rational-of time))
                           (run-values run))))))

(defun end-value-or-number (run expression time)
  "EXPRESSION, a closed form at a state's end TIME, as END-VALUE makes it; at a numeric TIME
(a root found under values: a double), its number under the run's values instead (exact,
as a numeric state's end values are), so that nothing prints a formula of a rounded time."
  (let ((number (and (floatp time) (numeric-or-nil (run-bridge run) expression (run-values run)))))
    (if number (rational-of number) (end-value run expression))))

(defun closed-form-candidate (run solved groups involved condition)
  "CONDITION's candidate over the closed-form INVOLVED groups (:CONSTANT, :LINEAR,
:SPEED-LINE): TAU-CANDIDATE's answer (SPEED-LINE-CANDIDATE's over one :SPEED-LINE group);
where it is undecided and the run has parameter values, the numeric root."
  (multiple-value-bind (result fact not-before)
      (if (and (null (rest involved)) (eq (group-kind (first involved)) :speed-line))
          (speed-line-candidate run solved groups (first involved) condition)
          (tau-candidate run solved groups condition))
    (or (and (eq result :unknown) (root-not-found-p fact)
             (numeric-root-candidate run solved groups condition))
        (values result fact not-before))))

(defun root-not-found-p (fact)
  "True when the undecided FACT says that Maxima found no provable root, (:EARLIEST-ROOT-OF
...), rather than naming a sign the assumptions leave open (a fact to branch on, whose
branches have closed forms)."
  (and (consp fact) (eq (first fact) :earliest-root-of)))
