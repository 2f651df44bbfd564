;;;; src/check/self-check.lisp -- a history's claims checked before they are printed.
;;;;
;;;; SELF-CHECK-HISTORY runs under parameter values (--set, --numeric): every state of the
;;;; run's path (at a fork, the branch the values select) is checked by CHECK-STATE, and
;;;; every number printed beside a formula (a state's start, duration and final values,
;;;; the queries' answers) against that formula's value. The result goes in the history's
;;;; notes as :SELF-CHECK, a plist
;;;;   :CHECKED   the indices of the states whose motion and end were checked;
;;;;   :UNCHECKED ((:STATE INDEX :REASON TEXT) ...): states that could not be (a fork, a
;;;;              state lasting no time, no value for its model under the values ...);
;;;;   :NUMBERS   (CHECKED TOTAL): the printed numbers compared with their formulas;
;;;;   :EQUATIONS (VERIFIED TOTAL): the states' model equations evaluated with the solved
;;;;              quantities along the integration (the solve checked);
;;;;   :FAILURES  ((:STATE INDEX :CLAIM TEXT :DISCREPANCY X :DETAIL TEXT) ...), INDEX NIL
;;;;              for a query's answer;
;;;;   :CHOSEN    ((PARAMETER . NUMBER) ...), when the run left parameters without a value
;;;;              that the check gave one (see CHECK-VALUES);
;;;; or (:SKIPPED T) under --no-check.
;;;; A failure is a defect of AMES: the command line exits with a status of its own.

(in-package #:ames.check)

(defvar *self-check* t
  "When true (the default), runs under parameter values are self-checked (--no-check
makes it NIL).")

(defparameter *number-tolerance* 1d-8
  "How far a printed number may be from its formula's value, relative.")

(defun duration-number (state values)
  "STATE's claimed duration as a number: its formula's value under VALUES; for a
duration with no closed form, the number the run found (see the simulator's notes); NIL
when there is none; :FOREVER."
  (let ((duration (state-duration state))
        (numeric (state-numbers state)))
    (cond ((eq duration :forever) :forever)
          ((realp duration) duration)
          ((or (keywordp duration) (and (consp duration) (keywordp (first duration))))
           (let ((n (getf numeric :duration)))
             (and (realp n) n)))
          (t (handler-case (value-under duration values)
               (unevaluable () nil))))))

(defun period-number (state values)
  "The period of a periodic STATE (its notes' :PERIODIC (:PERIOD EXPR ...), see the
scenario language's \"Oscillation and turning points\") under VALUES, or NIL."
  (let ((periodic (state-periodic state)))
    (and (consp periodic) (getf periodic :period)
         (handler-case (value-under (getf periodic :period) values)
           (unevaluable () nil)))))

(defun check-state (state values &key (horizon 1d0))
  "Check STATE's motion and end under VALUES (see claims.lisp and events.lisp): a plist
(:STATUS S :REASON R :FAILURES F :EQUATIONS (VERIFIED TOTAL)), S one of :CHECKED,
:UNCHECKED (R says why) and :FAILED. A state lasting forever is checked up to HORIZON; a periodic one over its
period, at whose end it must be back where it started, its turning points allowed."
  (let ((model (getf (state-analysis state) :check-model))
        (duration (duration-number state values))
        (periodic (state-periodic state)))
    (flet ((unchecked (reason) (return-from check-state (list :status :unchecked :reason reason))))
      (cond ((state-branches state) (unchecked "the fork there has no period of motion; the branch the values select is checked"))
            ((null model) (unchecked "no model recorded"))
            ((getf model :uncompared)
             (unchecked (format nil "the motion of ~{~A~^, ~} is no state variable of its model"
                                (mapcar #'plain-text (getf model :uncompared)))))
            ((null duration) (unchecked "its duration has no number"))
            ((and (realp duration) (zerop duration)) (unchecked "it lasts no time"))
            ((and periodic (not (period-number state values))) (unchecked "its period has no number")))
      (handler-case
          (multiple-value-bind (setup reason) (make-setup model values)
            (unless setup (unchecked reason))
            (let* ((*rate-scales* (setup-rate-scales setup))
                   (end (if (eq duration :forever) nil (coerce duration 'double-float)))
                   (period (and periodic (null end) (period-number state values)))
                   (samples (let ((*error-sum* 0d0))
                              (prog1 (integrate-grid (setup-rates setup) (setup-y0 setup)
                                                     (or end period (coerce horizon 'double-float)) *grid-points*)
                                (when (and (plusp *error-sum*) (> *error-sum* (* 1/10 *relative-tolerance*)))
                                  ;; the rates' round-off (ROUND-OFF-FLOOR) bounds the steps
                                  (unchecked (format nil "the round-off of its rates limits the integration to ~,1,,,,,'eE"
                                                     *error-sum*))))))
                   ;; a periodic state's closed form describes one swing, from one turning
                   ;; point to the next (the way back is its mirror): compared over it
                   (failures (append (compare-motion setup state
                                                     (if period (first-swing samples period) samples))
                                     (and end (compare-final setup state samples values))
                                     (and period (compare-period setup samples period)))))
              (multiple-value-bind (event-failures reason)
                  (check-events setup state samples end :turning-points-allowed (and period t))
                (multiple-value-bind (equation-failures verified total) (compare-equations setup samples)
                  (setf failures (append failures event-failures equation-failures))
                  (append (cond (failures (list :status :failed :failures failures))
                                (reason (list :status :unchecked :reason reason))
                                (t (list :status :checked)))
                          (list :equations (list verified total)))))))
        (unevaluable (condition)
          (unchecked (format nil "cannot evaluate ~A" (datum-string (ames-error-datum condition)))))
        (integration-failed (condition)
          (unchecked (ames-error-detail condition)))))))

(defun first-swing (samples period)
  "The SAMPLES (TIME . Y) of a periodic state up to half its PERIOD: one swing."
  (remove-if (lambda (sample) (> (car sample) (* 0.5d0 period (+ 1 1d-9)))) samples))

(defun compare-period (setup samples period)
  "Failures of a periodic state's claim: after PERIOD (the end of SAMPLES) every state
variable is back at its start."
  (let ((y0 (cdr (first samples))) (y1 (cdr (car (last samples)))) (scales (state-scales samples)))
    (loop for term in (setup-terms setup)
          for i from 0
          unless (near-p (svref y0 i) (svref y1 i) (* 1d-3 (svref scales i)))
            collect (make-check-failure (format nil "the period: ~A back at its start after ~A"
                                                (datum-string term) (number-string period))
                                        (relative-error (svref y0 i) (svref y1 i) (* 1d-3 (svref scales i)))
                                        (format nil "start ~A, after a period ~A" (number-string (svref y0 i)) (number-string (svref y1 i)))))))

(defun printed-numbers (state)
  "The numbers the report prints beside STATE's formulas: a list of (LABEL NUMBER FORMULA)."
  (let ((numeric (state-numbers state)))
    (append
     (let ((start (getf numeric :start)))
       (and (realp start) (not (realp (state-start state)))
            (list (list "start time" start (state-start state)))))
     ;; the number the report prints beside the duration (see the report's view)
     (let ((duration (getf numeric :duration)))
       (and (realp duration) (not (realp (state-duration state)))
            (not (keywordp (state-duration state)))
            (not (and (consp (state-duration state)) (keywordp (first (state-duration state)))))
            (list (list "duration" duration (state-duration state)))))
     (loop for (key formulas) in (list (list :final-positions (state-final-positions state))
                                       (list :final-velocities (state-final-velocities state)))
           append (loop for (body numbers) in (getf numeric key)
                        for formula = (body-entry formulas body)
                        append (loop for n in numbers for f in formula for axis in '(:x :y)
                                     when (and (realp n) (not (realp f)))
                                       collect (list (format nil "~(~A ~A~)_~(~A~)"
                                                             (if (eq key :final-positions) "final position of" "final velocity of")
                                                             body axis)
                                                     n f)))))))

(defun check-number (label number formula values)
  "NIL when NUMBER is FORMULA's value under VALUES; a CHECK-FAILURE when not; :UNCHECKED
when the formula has no value here."
  (let ((value (handler-case (value-under formula values) (unevaluable () :unevaluable))))
    (cond ((or (null value) (eq value :unevaluable)) :unchecked)
          ((near-p value (coerce number 'double-float) 0d0 *number-tolerance*) nil)
          (t (make-check-failure (format nil "the number printed for the ~A" label)
                                 (relative-error value (coerce number 'double-float) 0d0)
                                 (format nil "printed ~A, its formula ~A is ~A"
                                         (number-string number) (datum-string formula) (number-string value)))))))

(defun checked-path (states)
  "STATES along the run's path: at a fork, the selected branch's states follow it."
  (loop for state in states
        collect state
        append (let ((selected (find-if (lambda (b) (getf b :selected)) (state-branches state))))
                 (and selected (checked-path (getf selected :states))))))

(defun answer-numbers (history)
  "The answers printed with a number: (LABEL NUMBER FORMULA) for each scalar one."
  (loop for (name value . options) in (history-answers history)
        for number = (getf options :numeric)
        when (and (realp number) (not (realp value)) (valid-expression-p value :kind :arithmetic))
          collect (list (format nil "answer ~(~A~)" name) number value)))

(defparameter *generic-values* '(1.234d0 1.357d0 1.414d0 1.573d0 1.618d0 1.732d0 1.877d0 1.953d0)
  "The values the self-check gives, in turn, to parameters the run has no value for (see
CHECK-VALUES): unremarkable numbers, distinct so that no two parameters coincide.")

(defun check-values (history)
  "The parameter values the self-check uses for HISTORY: the run's, and for each
parameter without one whose only assumptions are that it is positive (or non-negative),
a generic value -- the run's claims are made for every such value, so any one of them
tests them. Returns (values ALIST CHOSEN), CHOSEN the generic entries."
  (let* ((scenario (history-scenario history))
         (values (history-parameter-values history))
         (relations (ames.scenario:scenario-assumption-relations scenario))
         (generic *generic-values*)
         (chosen '()))
    (dolist (parameter (ames.scenario:scenario-parameters scenario))
      (let ((name (ames.scenario:scenario-parameter-name parameter)))
        (when (and generic (not (assoc name values))
                   (every (lambda (relation)
                            (or (free-of-p name relation)
                                (and (member (first relation) '(> >=)) (eq (second relation) name)
                                     (eql (third relation) 0))))
                          relations))
          (push (cons name (pop generic)) chosen))))
    (values (append values (reverse chosen)) (reverse chosen))))

(defun failure-entry (index failure)
  "The plist the history's notes keep for FAILURE of state INDEX (NIL: an answer)."
  (list :state index :claim (check-failure-claim failure)
        :discrepancy (check-failure-discrepancy failure) :detail (check-failure-detail failure)))

(defun numbers-known-p (history)
  "True when every number of HISTORY's claims is known: it has parameter values, or its
scenario has no parameters at all (a problem given in numbers)."
  (or (history-parameter-values history)
      (null (ames.scenario:scenario-parameters (history-scenario history)))))

(defun self-check-history (history)
  "Check HISTORY's claims under its parameter values (see the file header) and record the
result in its notes as :SELF-CHECK. Does nothing when numbers are not known (see
NUMBERS-KNOWN-P) or when *SELF-CHECK* is NIL. Returns the result plist, or NIL."
  (let ((values (numbers-known-p history)))
    (when (and values (not *self-check*))
      (setf (getf (history-notes history) :self-check) (list :skipped t)))
    (when (and *self-check* values)
      (handler-case (check-history-claims history)
        ;; a value beyond double precision (a default of 10^400): no numeric check can be
        ;; made, and the report says so instead of ending
        (floating-point-overflow ()
          (setf (getf (history-notes history) :self-check)
                (list :not-made "a number beyond double precision")))))))

(defun check-history-claims (history)
  "The body of SELF-CHECK-HISTORY: check every state of HISTORY's path and every printed
number, and record the result in its notes as :SELF-CHECK."
  (multiple-value-bind (values chosen) (check-values history)
      (let ((checked '()) (unchecked '()) (failures '()) (numbers-checked 0) (numbers 0) (clock 0d0)
            (equations (list 0 0)))
        (flet ((number-check (index entry)
                 (destructuring-bind (label number formula) entry
                   (incf numbers)
                   (let ((result (check-number label number formula values)))
                     (cond ((null result) (incf numbers-checked))
                           ((check-failure-p result)
                            (incf numbers-checked)
                            (push (failure-entry index result) failures)))))))
          (dolist (state (checked-path (history-states history)))
            (let* ((index (state-index state))
                   (start (getf (state-numbers state) :start))
                   (result (check-state state values
                                        :horizon (max 1d0 (* 2 (if (realp start) start clock))))))
              (when (realp start) (setf clock (coerce start 'double-float)))
              (let ((counts (getf result :equations)))
                (when counts (setf equations (mapcar #'+ equations counts))))
              (ecase (getf result :status)
                (:checked (push index checked))
                (:unchecked (push (list :state index :reason (getf result :reason)) unchecked))
                (:failed (dolist (f (getf result :failures))
                           (push (failure-entry index f) failures))))
              (dolist (entry (printed-numbers state)) (number-check index entry))))
          (dolist (entry (answer-numbers history)) (number-check nil entry)))
        (setf (getf (history-notes history) :self-check)
              (append (list :checked (nreverse checked) :unchecked (nreverse unchecked)
                            :numbers (list numbers-checked numbers) :equations equations
                            :failures (nreverse failures))
                      (and chosen (list :chosen chosen)))))))

(defun self-check-result (history)
  "The :SELF-CHECK plist of HISTORY's notes, or NIL when it was not checked."
  (getf (history-notes history) :self-check))

(defun self-check-failed-p (history)
  "True when HISTORY's self-check found a claim that is wrong."
  (and (getf (self-check-result history) :failures) t))
