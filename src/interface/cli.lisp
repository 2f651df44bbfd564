;;;; src/interface/cli.lisp -- the command line: bin/ames run|explain FILE... [--format F] [--svg FILE] [--numeric] [--set p=v ...] [--time-limit S] [--maxima-timeout S] [--verbose] [--no-check]
;;;;
;;;; Exit codes, so that a script can tell a finished run from one that stopped:
;;;;   0  every scenario ran to its end (a run that branched ran every branch to its end);
;;;;   1  a scenario error (a defective scenario or file, values that break an assumption,
;;;;      a failure of the simulation); the other scenarios of the files still run;
;;;;   2  a usage error (nothing is run);
;;;;   3  every scenario was valid, but a run (or a branch of it) ended ambiguous or
;;;;      undecided: the assumptions (and the values, if any) did not decide what comes next.
;;;;      A run stopped by its --time-limit counts as undecided (its finished states printed).
;;;;   5  a self-check failed: under parameter values a claim AMES was about to print (a
;;;;      closed form, a state's end, a number beside its formula) disagrees with AMES's
;;;;      independent numeric check (see src/check/); the report names the claim. A defect.
;;;; When a run has both an error and an undecided scenario, the status is 1; 1 wins over
;;;; 5, and 5 over 3.
;;;;   130, 143  SIGINT, SIGTERM stopped the run (see signals.lisp).
;;;;   141  the reader of the standard output went away (bin/ames run x | head).

(in-package #:ames)

(defconstant +exit-complete+ 0 "Exit status: every scenario ran to its end.")
(defconstant +exit-scenario-error+ 1 "Exit status: a scenario (or file) had an error.")
(defconstant +exit-usage+ 2 "Exit status: the command line is malformed.")
(defconstant +exit-undecided+ 3
  "Exit status: a run ended ambiguous or undecided (and no scenario had an error).")
(defconstant +exit-check-failed+ 5
  "Exit status: a self-check found a wrong claim (and no scenario had an error).")

(defconstant +broken-pipe-status+ 141
  "The exit status when the reader of the standard output went away (a shell's status for
a process ended by SIGPIPE).")

(defun main (arguments)
  "The entry point of bin/ames: run the command in ARGUMENTS (a list of strings) and quit
with the status RUN-FILES returns (0 complete, 1 a scenario error, 3 a run ended
ambiguous or undecided), or 2 on a usage error; with --jobs N, the worst status of the
child processes (RUN-JOBS). When the standard output is a pipe whose reader went away
(bin/ames run x | head), stop quietly with status +BROKEN-PIPE-STATUS+. SIGINT and
SIGTERM stop the run with the states that finished printed, and status 130 or 143 (see
signals.lisp)."
  (install-stop-handlers)
  (let ((status
          (handler-case
              (multiple-value-bind (jobs arguments) (jobs-option arguments)
                (let* ((options (parse-command-line arguments))
                       (ames.check:*self-check* (not (getf options :no-check)))
                       (*all-branches* (getf options :all-branches)))
                  (case (getf options :command)
                    (:help (write-string *usage*) (terpri) +exit-complete+)
                    (:version (write-line (version-text)) +exit-complete+)
                    (:explain (explain-files (getf options :files) :state (getf options :state)
                                             :settings (getf options :settings)
                                             :numeric (getf options :numeric)
                                             :limits (command-line-limits options)))
                    (:check (check-files (getf options :files) :settings (getf options :settings)
                                         :numeric (getf options :numeric)
                                         :limits (command-line-limits options)))
                    (:run (if jobs
                              (run-jobs jobs options)
                              (let ((*package* (find-package '#:ames-scenario))
                                    (*latex-standalone* (getf options :standalone)))
                                ;; Maxima loads while the scenarios are read and checked
                                (ames.maxima:prestart-bridge (current-bridge))
                                (call-with-progress
                                 (lambda ()
                                  (run-files (getf options :files)
                                           :format (getf options :format)
                                           :settings (getf options :settings)
                                           :numeric (getf options :numeric)
                                           :svg (getf options :svg)
                                           :limits (command-line-limits options)
                                           :verbose (getf options :verbose)
                                           :stream *standard-output*)))))))))
            (usage-error (condition)
              (format *error-output* "ames: ~A~%~A~%" condition *usage*)
              +exit-usage+)
            (sb-int:broken-pipe ()
              (sb-ext:exit :code +broken-pipe-status+ :abort t)))))
    (handler-case (progn (finish-output *standard-output*)
                         (finish-output *error-output*))
      (sb-int:broken-pipe ()
        (sb-ext:exit :code +broken-pipe-status+ :abort t)))
    (uiop:quit (finish-stopped-process status))))

(defun explain-files (files &key state settings numeric (stream *standard-output*)
                               (limits *limits*))
  "Explain every scenario of each of FILES (see EXPLAIN), or only the state STATE, each
run within a budget of LIMITS. SETTINGS and NUMERIC give parameter values as for
RUN-FILES. Returns the exit status: 0, or 1 when a scenario could not be explained."
  (let ((status 0))
    (dolist (file files status)
      (handler-case
          (dolist (history (run-file file :settings settings :numeric numeric :limits limits))
            (explain history :state state :stream stream))
        (ames-error (condition)
          (setf status 1)
          (print-error-message condition))
        ;; the output is gone (a closed pipe): nothing more can be reported
        (stream-error (condition) (error condition))
        ;; a defect of AMES is reported as RUN-FILES reports it, not as a backtrace
        (error (condition)
          (setf status 1)
          (print-error-message (make-condition 'internal-error :datum condition)))))))

(defun undecided-history-p (history)
  "True when HISTORY, or a branch of one of its forks, ended without deciding what
comes next: its outcome is :AMBIGUOUS or :UNDECIDED, or :FAILED (a branch that could
not be simulated). At a fork whose branch the run's values select (:SELECTED T), only
that branch counts."
  (labels ((undecided-outcome-p (outcome) (member outcome '(:ambiguous :undecided :failed)))
           (counted-branches (branches)
             (let ((selected (find-if (lambda (branch) (getf branch :selected)) branches)))
               (if selected (list selected) branches)))
           (undecided-states-p (states)
             (some (lambda (state)
                     (some (lambda (branch)
                             (or (undecided-outcome-p (getf branch :outcome))
                                 (undecided-states-p (getf branch :states))))
                           (counted-branches (state-branches state))))
                   states)))
    (and (or (undecided-outcome-p (history-outcome history))
             (undecided-states-p (history-states history)))
         t)))

(defun run-files (files &key (format :text) settings numeric (stream *standard-output*) svg
                          (bridge (current-bridge)) (limits *limits*) verbose)
  "Simulate every scenario of each of FILES, each by RUN-SCENARIO (a fresh bridge state,
a budget of LIMITS, by default *LIMITS*), and print each history on STREAM in FORMAT
(:TEXT, :SEXP, :LATEX, :JSON or :HTML, one page at the end), and, when SVG (a file
name) is given, draw each to it (see AMES.REPORT:FINISH-REPORT). SETTINGS is an alist
(PARAMETER-NAME . NUMBER); with NUMERIC, the scenarios' (:value N) defaults are used
too, SETTINGS overriding them; the values are checked against every assumption (see
RUN-PARAMETER-VALUES). A defective scenario or file, and a run that fails, are reported
on *ERROR-OUTPUT*, naming the file, the scenario and the line; the others still run (a
Lisp error that is no AMES-ERROR, a defect of AMES, is reported as an INTERNAL-ERROR).
Long messages are cut short unless VERBOSE. Returns the exit status: +EXIT-COMPLETE+
(0) when every scenario ran to its end, +EXIT-SCENARIO-ERROR+ (1) when any had an
error, else +EXIT-CHECK-FAILED+ (5) when a self-check found a wrong claim, else
+EXIT-UNDECIDED+ (3) when any (or a branch of one) ended ambiguous or undecided."
  (let ((error-seen nil) (undecided-seen nil) (check-failed nil)
        (*full-reports* (or verbose *full-reports*))
        (output (make-report-output format stream :svg svg :bridge bridge)))
    (flet ((report-error (condition)
             (setf error-seen t)
             (print-error-message condition)))
      (dolist (file files)
        (when *stop-requested* (return))
        (multiple-value-bind (scenarios conditions) (read-file-within-time file limits)
          (mapc #'report-error conditions)
          (dolist (scenario scenarios)
            (when *stop-requested* (return))
            (when numeric (note-symbolic-parameters scenario settings))
            (multiple-value-bind (undecided failed-check)
                (run-and-report-scenario scenario output #'report-error
                                         :bridge bridge :settings settings :numeric numeric
                                         :limits limits :stream stream)
              (when undecided (setf undecided-seen t))
              (when failed-check (setf check-failed t))))))
      (handler-case (call-within-time-left (lambda () (finish-report output))
                                           limits (get-internal-real-time) nil)
        (ames-error (condition) (report-error condition))))
    (cond (error-seen +exit-scenario-error+)
          (check-failed +exit-check-failed+)
          (undecided-seen +exit-undecided+)
          (t +exit-complete+))))

(defun run-and-report-scenario (scenario output report-error &key bridge settings numeric limits stream)
  "Run SCENARIO (see RUN-SCENARIO) and report its history to OUTPUT within LIMITS'
time. Returns (values UNDECIDED CHECK-FAILED): whether the run ended undecided (or was
stopped by its time) and whether its self-check found a wrong claim. An AMES-ERROR, an
exhausted heap or a Lisp error (a defect of AMES: an INTERNAL-ERROR) goes to
REPORT-ERROR and returns NIL; a closed output stream is signalled on."
  (handler-case
      (let* ((start (get-internal-real-time))
             (history (run-scenario scenario :bridge bridge :settings settings
                                             :numeric numeric :limits limits))
             (stopped (stopped-by-time history))
             (failed-check (ames.check:self-check-failed-p history)))
        (when failed-check
          (format *error-output* "~&ames: ~A: the self-check found a wrong claim (a defect of AMES; see the report's SELF-CHECK FAILED lines)~%"
                  (string-downcase (symbol-name (scenario-name scenario)))))
        (when (and stopped (not *stop-requested*))
          (print-error-message
           (format nil "~@[~A: ~]the time limit of ~A s was exceeded; ~[no state had finished~;~
                        the 1 state that finished is printed~:;the ~:*~D states that ~
                        finished are printed~]"
                   (scenario-name scenario) (budget-exceeded-limit stopped)
                   (length (history-states history)))))
        (call-within-time-left (lambda () (report-history output history))
                               limits start (scenario-name scenario)
                               :quiet stopped)
        (finish-output stream)
        (values (or (and stopped t) (undecided-history-p history)) failed-check))
    (ames-error (condition)
      ;; a run a signal stopped before its first state: MAIN says so, once
      (unless (typep condition 'run-stopped)
        (funcall report-error condition))
      nil)
    ;; the output is gone (a closed pipe): nothing more can be reported
    (stream-error (condition) (error condition))
    ;; the heap is exhausted: say so, and go on (the run's garbage is freed)
    (storage-condition (condition)
      (let ((exhausted (make-condition 'memory-exhausted :datum condition)))
        (setf (ames-error-context exhausted) (run-error-context scenario exhausted))
        (funcall report-error exhausted))
      nil)
    ;; a defect of AMES in one scenario does not lose the others
    (error (condition)
      (let ((internal (make-condition 'internal-error :datum condition)))
        (setf (ames-error-context internal) (run-error-context scenario internal))
        (funcall report-error internal))
      nil)))

(defun run-file (pathname &key settings numeric (bridge (current-bridge)) (limits *limits*))
  "Simulate every scenario of the file PATHNAME, each by RUN-SCENARIO (a fresh bridge
state, a budget of LIMITS, by default *LIMITS*), and return their SIMULATION-HISTORYs.
SETTINGS and NUMERIC give parameter values as for RUN-FILES, checked against every
assumption. A scenario that ends ambiguously stops there (its history says so). Signals SCENARIO-ERROR for a defective scenario, and the
errors of a run (named by their context: file, scenario, line), with the restart
SKIP-SCENARIO; BUDGET-EXCEEDED when a run goes over its budget; PARAMETER-VALUES-ERROR
for SETTINGS that are not an alist of names and numbers."
  (let ((histories '()))
    (dolist (scenario (read-scenario-file pathname) (nreverse histories))
      (restart-case
          (push (run-scenario scenario :bridge bridge :settings settings :numeric numeric
                                         :limits limits)
                histories)
        (skip-scenario ()
          :report "Skip this scenario and go on with the next one."
          nil)))))
