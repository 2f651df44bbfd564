;;;; src/interface/cli.lisp -- the command line: bin/ames run FILE... [--format text|sexp|latex|json|html] [--svg FILE] [--numeric] [--set p=v ...]
;;;;
;;;; Exit codes, so that a script can tell a finished run from one that stopped:
;;;;   0  every scenario ran to its end (a run that branched ran every branch to its end);
;;;;   1  a scenario error (a defective scenario or file, values that break an assumption,
;;;;      a failure of the simulation); the other scenarios of the files still run;
;;;;   2  a usage error (nothing is run);
;;;;   3  every scenario was valid, but a run (or a branch of it) ended ambiguous or
;;;;      undecided: the assumptions (and the values, if any) did not decide what comes next.
;;;; When a run has both an error and an undecided scenario, the status is 1.

(in-package #:ames)

(defconstant +exit-complete+ 0 "Exit status: every scenario ran to its end.")
(defconstant +exit-scenario-error+ 1 "Exit status: a scenario (or file) had an error.")
(defconstant +exit-usage+ 2 "Exit status: the command line is malformed.")
(defconstant +exit-undecided+ 3
  "Exit status: a run ended ambiguous or undecided (and no scenario had an error).")

(define-condition usage-error (ames-error) ()
  (:documentation "The command line is malformed. DATUM is the offending argument.")
  (:report (lambda (condition stream)
             (format stream "~A~@[: ~A~]" (ames-error-detail condition)
                     (ames-error-datum condition)))))

(defparameter *usage*
  "Usage: ames run FILE... [--format text|sexp|latex|json|html] [--svg OUT.svg] [--numeric]
                [--set PARAM=VALUE ...]
       ames explain FILE... [--state N] [--numeric] [--set PARAM=VALUE ...]
  Simulate every scenario in each FILE and print a report.
  --format text   a report for people, state by state (the default)
  --format sexp   one readable s-expression per scenario (see the scenario language page)
  --format latex  a LaTeX fragment per scenario (formulas through Maxima's tex)
  --format json   the s-expression's content as JSON, one line per scenario
  --format html   one self-contained page: pictures, timelines, typeset formulas
  --svg OUT.svg   also draw each scenario (OUT-NAME.svg when the run has several)
  --numeric       use the scenario's (:value N) defaults as parameter values
  --set p=v ...   give parameter p the number v (an integer, ratio or decimal), over its
                  default; numeric values are then printed beside the closed forms, and
                  a fact the assumptions leave open but the values decide is used and
                  reported. Values that break a declared assumption are an error.
  explain         why each state's contacts and modes hold, where its equations
                  come from, and why it ends when it does (or only state N)
Exit codes: 0 complete, 1 a scenario error, 2 usage, 3 a run (or a branch) that ended
ambiguous or undecided (1 wins when both happen)."
  "The text printed for `ames help` and after a usage error.")

(defun parse-decimal (text)
  "The exact rational written by TEXT: an integer (\"-3\"), a ratio (\"981/100\") or a
decimal (\"9.81\", \"1e-3\", \"2.5E2\"). NIL when TEXT is none of these. Never calls the
Lisp reader."
  (let ((scanner (load-time-value
                  (cl-ppcre:create-scanner
                   "^([+-]?)(\\d*)(?:\\.(\\d*))?(?:[eE]([+-]?\\d{1,4}))?$|^([+-]?\\d+)/(\\d+)$"))))
    (multiple-value-bind (match groups) (cl-ppcre:scan-to-strings scanner text)
      (cond ((null match) nil)
            ((aref groups 4)
             (let ((denominator (parse-integer (aref groups 5))))
               (and (plusp denominator) (/ (parse-integer (aref groups 4)) denominator))))
            (t
             (let ((sign (if (equal (aref groups 0) "-") -1 1))
                   (whole (aref groups 1))
                   (fraction (or (aref groups 2) ""))
                   (exponent (if (aref groups 3) (parse-integer (aref groups 3)) 0)))
               (when (and (string= whole "") (string= fraction ""))
                 (return-from parse-decimal nil))
               (* sign
                  (/ (parse-integer (concatenate 'string "0" whole fraction))
                     (expt 10 (length fraction)))
                  (expt 10 exponent))))))))

(defun parse-setting (text)
  "Parse one --set argument \"NAME=VALUE\" into (NAME-STRING . RATIONAL); signal
USAGE-ERROR naming TEXT when it is malformed."
  (let ((position (position #\= text)))
    (unless (and position (plusp position))
      (error 'usage-error :datum text :detail "--set takes PARAM=VALUE"))
    (let ((value (parse-decimal (subseq text (1+ position)))))
      (unless value
        (error 'usage-error :datum text :detail "--set needs a number after ="))
      (cons (subseq text 0 position) value))))

(defun parse-command-line (arguments)
  "Parse ARGUMENTS (strings, without the program name) into a plist (:COMMAND :FILES
:FORMAT :SETTINGS :SVG :STATE :NUMERIC). Signals USAGE-ERROR on anything malformed."
  (let ((command (first arguments)) (files '()) (format :text) (settings '()) (svg nil)
        (state nil) (numeric nil))
    (cond ((null command) (error 'usage-error :detail "no command given"))
          ((member command '("help" "--help" "-h") :test #'string=)
           (return-from parse-command-line (list :command :help)))
          ((not (member command '("run" "explain") :test #'string=))
           (error 'usage-error :datum command :detail "unknown command")))
    (loop with rest = (rest arguments)
          while rest
          do (let ((argument (pop rest)))
               (cond ((string= argument "--format")
                      (let ((value (pop rest)))
                        (setf format
                              (or (find value *report-formats* :test #'string-equal)
                                  (error 'usage-error :datum value
                                                      :detail "--format takes text, sexp, latex, json or html")))))
                     ((string= argument "--svg")
                      (setf svg (pop rest))
                      (when (or (null svg) (eql 0 (search "--" svg)))
                        (error 'usage-error :datum argument :detail "--svg takes the picture's file name")))
                     ((string= argument "--numeric")
                      (setf numeric t))
                     ((string= argument "--set")
                      (unless (and rest (find #\= (first rest)))
                        (error 'usage-error :datum argument :detail "--set takes PARAM=VALUE"))
                      (loop while (and rest (find #\= (first rest))
                                       (not (eql 0 (search "--" (first rest)))))
                            do (push (parse-setting (pop rest)) settings)))
                     ((and (string= command "explain") (string= argument "--state"))
                      (let ((value (and rest (parse-decimal (pop rest)))))
                        (unless (and (integerp value) (>= value 0))
                          (error 'usage-error :datum argument :detail "--state takes a state's index"))
                        (setf state value)))
                     ((eql 0 (search "--" argument))
                      (error 'usage-error :datum argument :detail "unknown option"))
                     (t (push argument files)))))
    (when (null files) (error 'usage-error :detail "run needs at least one scenario file"))
    (list :command (if (string= command "explain") :explain :run)
          :files (nreverse files) :format format
          :settings (nreverse settings) :svg svg :state state :numeric numeric)))

(defun main (arguments)
  "The entry point of bin/ames: run the command in ARGUMENTS (a list of strings) and quit
with the status RUN-FILES returns (0 complete, 1 a scenario error, 3 a run ended
ambiguous or undecided), or 2 on a usage error."
  (let ((status
          (handler-case
              (let ((options (parse-command-line arguments)))
                (case (getf options :command)
                  (:help (write-string *usage*) (terpri) +exit-complete+)
                  (:explain (explain-files (getf options :files) :state (getf options :state)
                                           :settings (getf options :settings)
                                           :numeric (getf options :numeric)))
                  (:run (let ((*package* (find-package '#:ames-scenario)))
                          (run-files (getf options :files)
                                     :format (getf options :format)
                                     :settings (getf options :settings)
                                     :numeric (getf options :numeric)
                                     :svg (getf options :svg)
                                     :stream *standard-output*)))))
            (usage-error (condition)
              (format *error-output* "ames: ~A~%~A~%" condition *usage*)
              +exit-usage+))))
    (finish-output *standard-output*)
    (finish-output *error-output*)
    (uiop:quit status)))

(defun explain-files (files &key state settings numeric (stream *standard-output*))
  "Explain every scenario of each of FILES (see EXPLAIN), or only the state STATE.
SETTINGS and NUMERIC give parameter values as for RUN-FILES. Returns the exit status:
0, or 1 when a scenario could not be explained."
  (let ((status 0))
    (dolist (file files status)
      (handler-case
          (dolist (history (run-file file :settings settings :numeric numeric))
            (explain history :state state :stream stream))
        (ames-error (condition)
          (setf status 1)
          (format *error-output* "~&ames: ~A~%" condition))))))

(defun undecided-history-p (history)
  "True when HISTORY, or a branch of one of its forks, ended without deciding what
comes next: its outcome is :AMBIGUOUS or :UNDECIDED. At a fork whose branch the run's
values select (:SELECTED T), only that branch counts."
  (labels ((undecided-outcome-p (outcome) (member outcome '(:ambiguous :undecided)))
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

(defun simulate-with-values (scenario bridge values)
  "Simulate SCENARIO with the checked parameter VALUES (an alist (PARAMETER . NUMBER)),
stopping at an ambiguity that cannot be branched on; the facts the values decided
outside the simulator's own transitions (geometric checks) are added to the history's
notes as :ASSUMED, with :STATE NIL."
  (ames.maxima:with-parameter-values (values)
    (let ((history (handler-bind ((ambiguous-transition #'stop-simulation))
                     (simulate scenario :bridge bridge :parameter-values values))))
      (dolist (fact (ames.maxima:facts-from-values))
        (unless (member fact (getf (history-notes history) :assumed)
                        :key (lambda (entry) (getf entry :fact)) :test #'equal)
          (push (list :state nil :fact fact) (getf (history-notes history) :assumed))))
      history)))

(defun run-files (files &key (format :text) settings numeric (stream *standard-output*) svg
                          (bridge (current-bridge)))
  "Simulate every scenario of each of FILES and print each history on STREAM in FORMAT
(:TEXT, :SEXP, :LATEX, :JSON or :HTML, one page at the end), and, when SVG (a file
name) is given, draw each to it (see AMES.REPORT:FINISH-REPORT). SETTINGS is an alist
(PARAMETER-NAME . NUMBER); with NUMERIC, the scenarios' (:value N) defaults are used
too, SETTINGS overriding them; the values are checked against every assumption (see
RUN-PARAMETER-VALUES). A defective scenario or file is reported on *ERROR-OUTPUT* and
the others still run. Returns the exit status: +EXIT-COMPLETE+ (0) when every scenario
ran to its end, +EXIT-SCENARIO-ERROR+ (1) when any had an error, else +EXIT-UNDECIDED+
(3) when any (or a branch of one) ended ambiguous or undecided."
  (let ((error-seen nil) (undecided-seen nil)
        (output (make-report-output format stream :svg svg :bridge bridge)))
    (flet ((report-error (condition)
             (setf error-seen t)
             (format *error-output* "~&ames: ~A~%" condition)))
      (dolist (file files)
        (multiple-value-bind (scenarios conditions) (read-scenario-file file :on-error :collect)
          (mapc #'report-error conditions)
          (dolist (scenario scenarios)
            (handler-case
                (let* ((values (run-parameter-values scenario :settings settings :numeric numeric))
                       (history (simulate-with-values scenario bridge values)))
                  (when (undecided-history-p history)
                    (setf undecided-seen t))
                  (report-history output history))
              (ames-error (condition) (report-error condition))))))
      (handler-case (finish-report output)
        (ames-error (condition) (report-error condition))))
    (cond (error-seen +exit-scenario-error+)
          (undecided-seen +exit-undecided+)
          (t +exit-complete+))))

(defun run-file (pathname &key settings numeric (bridge (current-bridge)))
  "Simulate every scenario of the file PATHNAME and return their SIMULATION-HISTORYs.
SETTINGS and NUMERIC give parameter values as for RUN-FILES, checked against every
assumption. A scenario that ends ambiguously stops there (its history says so). Signals
SCENARIO-ERROR for a defective scenario (PARAMETER-VALUE-ERROR for values that break an
assumption), with the restart SKIP-SCENARIO."
  (let ((histories '()))
    (dolist (scenario (read-scenario-file pathname) (nreverse histories))
      (restart-case
          (push (simulate-with-values scenario bridge
                                      (run-parameter-values scenario :settings settings
                                                                     :numeric numeric))
                histories)
        (skip-scenario ()
          :report "Skip this scenario and go on with the next one."
          nil)))))
