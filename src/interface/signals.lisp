;;;; src/interface/signals.lisp -- SIGTERM and SIGINT end a run as its time limit would, and each
;;;; scenario's time limit covers its report.
;;;;
;;;; A signal (kill, Ctrl-C) sets AMES.BASE:*STOP-REQUESTED*: from then on every budget's
;;;; deadline has passed. The scenario running is interrupted as its time limit would
;;;; interrupt it (an asynchronous BUDGET-EXCEEDED), so its history holds the states that
;;;; finished (RUN-SCENARIO); it is reported without asking Maxima (the presenter falls
;;;; back to the forms as solved), no further scenario is started, and MAIN ends with
;;;; one line naming the signal and the conventional status 128 + its number (130 for
;;;; SIGINT, 143 for SIGTERM), after stopping Maxima. A second signal ends the process at
;;;; once. Under --jobs the parent passes SIGTERM on to its workers, waits for them (each
;;;; stops its own Maxima and prints its finished states), and prints what they printed.
;;;;
;;;; The time limit of a scenario covers its report too (REPORT-WITHIN-TIME): the report
;;;; gets the time the run left; when that runs out, the report is made again without
;;;; Maxima. A run stopped by its time limit is reported (its finished states) with one
;;;; line on the standard error, and the exit status is 3 (undecided) at least.

(in-package #:ames)

(defparameter *stop-signals* '((:sigint . 2) (:sigterm . 15))
  "The signals that stop a run, with their numbers.")

(defvar *main-thread* nil
  "The thread bin/ames runs its command in, which a stop signal interrupts.")

(defun stop-signal-status (name)
  "The exit status of a process stopped by the signal NAME: 128 + its number."
  (+ 128 (cdr (assoc name *stop-signals*))))

(define-condition run-stopped (budget-exceeded) ()
  (:documentation "A signal (*STOP-REQUESTED*) stopped the scenario run in progress: a
BUDGET-EXCEEDED of its time, so that the run ends as its time limit would end it. DETAIL
names the signal.")
  (:report (lambda (condition stream)
             (format-report stream "~@[The run of ~A: ~]~A"
                            (let ((subject (budget-exceeded-subject condition)))
                              (and subject (not (ames-error-context condition))
                                   (princ-to-string subject)))
                            (ames-error-detail condition)))))

(defun stop-running-scenario ()
  "In the main thread, when a scenario run is in progress (a budget is running), end it
as its time limit would (with a RUN-STOPPED)."
  (when *budget*
    (error 'run-stopped :quantity :time :limit (current-time-limit) :asynchronous t
                        :subject (budget-subject *budget*)
                        :detail (format nil "stopped by ~A" *stop-requested*))))

(defun exit-at-once (name)
  "Stop Maxima and end the process with NAME's status, now (a second signal)."
  (ignore-errors (when *bridge* (ames.maxima:close-bridge *bridge*)))
  (sb-ext:exit :code (stop-signal-status name) :abort t))

(defvar *stop-requested-at* nil
  "The internal real time of the first stop signal, or NIL.")

(defun request-stop (name)
  "The handler of the signal NAME (:SIGINT, :SIGTERM): the first asks the run to stop
(see this file's header), a second one more than a second later ends the process at
once (one within a second is the same stop reaching a --jobs worker twice: from the
terminal's Ctrl-C and from its parent)."
  (if *stop-requested*
      (when (> (get-internal-real-time)
               (+ *stop-requested-at* internal-time-units-per-second))
        (exit-at-once *stop-requested*))
      (progn
        (setf *stop-requested* name
              *stop-requested-at* (get-internal-real-time))
        (let ((thread *main-thread*))
          (when (and thread (sb-thread:thread-alive-p thread))
            (sb-thread:interrupt-thread thread #'stop-running-scenario))))))

(defun install-stop-handlers ()
  "Make SIGINT and SIGTERM stop the run (REQUEST-STOP), from the current thread; in a
--jobs worker, the parent's end too (WATCH-JOB-PARENT)."
  (setf *main-thread* sb-thread:*current-thread*)
  (watch-job-parent)
  (sb-sys:enable-interrupt sb-unix:sigint
                           (lambda (signal info context)
                             (declare (ignore signal info context))
                             (request-stop :sigint)))
  (sb-sys:enable-interrupt sb-unix:sigterm
                           (lambda (signal info context)
                             (declare (ignore signal info context))
                             (request-stop :sigterm))))

(defparameter *job-parent-variable* "AMES_JOB_PARENT"
  "The environment variable that tells a --jobs worker its parent's process id.")

(defun parent-process-id ()
  "The process id of this process's parent (getppid(2))."
  (sb-alien:alien-funcall (sb-alien:extern-alien "getppid" (function sb-alien:int))))

(defun watch-job-parent ()
  "In a --jobs worker (see *JOB-PARENT-VARIABLE*), a thread that stops the run as SIGTERM
would when the parent is gone (killed with SIGKILL, say), so that no worker and no
Maxima outlive it."
  (let* ((text (sb-ext:posix-getenv *job-parent-variable*))
         (parent (and text (parse-integer text :junk-allowed t))))
    (when parent
      (sb-thread:make-thread
       (lambda ()
         (loop (sleep 1)
               (unless (eql (parent-process-id) parent)
                 (request-stop :sigterm)
                 (return))))
       :name "AMES job parent watch"))))

(defun finish-stopped-process (status)
  "STATUS, or, when a signal asked the run to stop, say so in one line, stop Maxima and
return the signal's status."
  (let ((name *stop-requested*))
    (if (null name)
        status
        (progn
          (ignore-errors (when *bridge* (ames.maxima:close-bridge *bridge*)))
          (ignore-errors
           (format *error-output* "~&ames: stopped by ~A; the states that finished are printed~%"
                   name)
           (finish-output *error-output*))
          (stop-signal-status name)))))

;;; The time limit covers the report

(defun seconds-since (start)
  "The seconds of wall time since the internal real time START."
  (/ (- (get-internal-real-time) start) internal-time-units-per-second))

(defun call-without-maxima (thunk)
  "Call THUNK as if the run's time were up: the reports ask Maxima nothing."
  (let ((*stop-requested* (or *stop-requested* :time-limit)))
    (funcall thunk)))

(defun call-within-time-left (thunk limits start subject &key quiet)
  "Call THUNK within what is left, since the internal real time START, of the time limit
of LIMITS; when nothing is left, or it runs out, call THUNK again without Maxima (see
CALL-WITHOUT-MAXIMA), and, unless QUIET, say so on the standard error, naming SUBJECT.
THUNK must write nothing until it has succeeded."
  (let* ((time-limit (limits-time-limit limits))
         (left (and time-limit (- time-limit (seconds-since start)))))
    (flet ((fall-back ()
             (unless (or quiet *stop-requested*)
               (print-error-message
                (format nil "note: ~@[~A: ~]the time limit of ~A s ran out while the report was ~
                             written; its formulas are written as solved, not rearranged for print"
                        subject time-limit)))
             (call-without-maxima thunk)))
      (cond ((or *stop-requested* (and left (<= left 0))) (fall-back))
            ((null left) (funcall thunk))
            (t (handler-case
                   (call-with-budget thunk :limits (change-limits limits :time-limit left)
                                           :subject subject)
                 (budget-exceeded (condition)
                   (if (eq (budget-exceeded-quantity condition) :time)
                       (fall-back)
                       (error condition)))))))))

(defun read-file-within-time (file limits)
  "READ-SCENARIO-FILE of FILE, collecting its errors, within the time limit of LIMITS (a
named pipe without a writer waits no longer): (values SCENARIOS CONDITIONS), a
BUDGET-EXCEEDED among the conditions when the time ran out."
  (handler-case
      (call-with-budget (lambda () (read-scenario-file file :on-error :collect))
                        :limits limits :subject file)
    (budget-exceeded (condition) (values '() (list condition)))))

(defun stopped-by-time (history)
  "The BUDGET-EXCEEDED that stopped HISTORY's run (its time limit, or a signal), or NIL."
  (let ((condition (getf (history-notes history) :stopped-by)))
    (and (typep condition 'budget-exceeded)
         (eq (budget-exceeded-quantity condition) :time)
         condition)))
