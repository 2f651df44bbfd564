;;;; src/simulator/state-numbers.lisp -- the numbers beside the formulas: each state's start,
;;;; duration, final positions and velocities under the history's parameter values, each the
;;;; value of the formula it is printed beside (ANALYSE-HISTORY calls ADD-NUMERIC-VALUES
;;;; after a run).

(in-package #:ames.simulator)

(defun numeric-duration (bridge state values)
  "STATE's duration as a number under VALUES, or NIL."
  (let ((duration (state-duration state)))
    (cond ((keywordp duration) nil)
          ((closed-form-time-p duration) (numeric-or-nil bridge duration values))
          ((eq (first duration) :no-closed-form)
           (numeric-travel-time bridge (getf (rest duration) :speed-squared)
                                (getf (rest duration) :from-arc-length)
                                (getf (rest duration) :to-arc-length) values)))))

(defun numeric-start (bridge state values clock)
  "STATE's start time as a number under VALUES: the value of its start formula when it
has one (a state after an accumulation of impacts starts where the series sums, not
after the durations of the states printed before it), else CLOCK, the numbers of the
durations before it summed (after a state whose end has no closed form)."
  (let ((start (state-start state)))
    (cond ((realp start) start)
          ((and start (not (keywordp start)) (closed-form-time-p start))
           (or (numeric-or-nil bridge start values) clock))
          (t clock))))

(defun add-numeric-values (history bridge &optional (clock 0))
  "When HISTORY has parameter values, record in each state (STATE-NUMBERS, a plist) the
numeric start, duration and final positions and velocities, each the value of the
formula it is printed beside. CLOCK is the number at which its first state starts (a
branch continued from a fork starts later), or NIL."
  (let ((values (history-parameter-values history)))
    (unless values
      (add-travel-time-numbers history bridge))
    (when values
      (dolist (state (history-states history))
        (flet ((numbers-of (alist)
                 (mapcar (lambda (entry)
                           (list (first entry)
                                 (mapcar (lambda (x) (numeric-or-nil bridge x values)) (second entry))))
                         alist)))
          (let ((duration (numeric-duration bridge state values)))
            (setf clock (numeric-start bridge state values clock))
            (setf (state-numbers state)
                  (list :start clock
                        :duration (or duration (state-duration state))
                        :final-positions (numbers-of (state-final-positions state))
                        :final-velocities (numbers-of (state-final-velocities state))
                        :period (let ((periodic (state-periodic state)))
                                  (and periodic (numeric-or-nil bridge (getf periodic :period) values)))))
            (add-rotation-numbers bridge state values)
            (setf clock (and clock (realp duration) (+ clock duration)))))))))

(defun add-travel-time-numbers (history bridge)
  "In a HISTORY whose scenario has no parameters (its values are written in it, so no
other number is recorded: the formulas are the numbers), record as each state's
STATE-NUMBERS (:DURATION N) the number of a duration with no closed form (a travel-time
integral), which no formula gives: the self-check, the reports and the witness need it."
  (when (null (scenario-parameters (history-scenario history)))
    (dolist (state (history-states history))
      (let ((duration (state-duration state)))
        (when (and (consp duration) (eq (first duration) :no-closed-form)
                   (null (state-numbers state)))
          (let ((number (numeric-duration bridge state '())))
            (when number
              (setf (state-numbers state) (list :duration number)))))))))
