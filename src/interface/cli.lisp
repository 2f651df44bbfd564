;;;; src/interface/cli.lisp -- the command line: bin/ames run FILE... [--format text|sexp|latex|json|html] [--svg FILE] [--set p=v ...]

(in-package #:ames)

(define-condition usage-error (ames-error) ()
  (:documentation "The command line is malformed. DATUM is the offending argument.")
  (:report (lambda (condition stream)
             (format stream "~A~@[: ~A~]" (ames-error-detail condition)
                     (ames-error-datum condition)))))

(defparameter *usage*
  "Usage: ames run FILE... [--format text|sexp|latex|json|html] [--svg OUT.svg] [--set PARAM=VALUE ...]
                [--jobs N]
       ames explain FILE... [--state N] [--set PARAM=VALUE ...]
  Simulate every scenario in each FILE and print a report.
  --format text   a report for people, state by state (the default)
  --format sexp   one readable s-expression per scenario (see the scenario language page)
  --format latex  a LaTeX fragment per scenario (formulas through Maxima's tex)
  --format json   the s-expression's content as JSON, one line per scenario
  --format html   one self-contained page: pictures, timelines, typeset formulas
  --svg OUT.svg   also draw each scenario (OUT-NAME.svg when the run has several)
  --set p=v ...   give parameter p the number v (an integer, ratio or decimal); numeric
                  values are then printed beside the closed forms
  --jobs N        run the files in N processes at once (each with its own Maxima);
                  reports in the files' order, the exit code the worst of them
  explain         why each state's contacts and modes hold, where its equations
                  come from, and why it ends when it does (or only state N)
Exit codes: 0 success, 1 a scenario error, 2 usage."
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
:FORMAT :SETTINGS :SVG :STATE). Signals USAGE-ERROR on anything malformed."
  (let ((command (first arguments)) (files '()) (format :text) (settings '()) (svg nil)
        (state nil))
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
          :settings (nreverse settings) :svg svg :state state)))

(defun main (arguments)
  "The entry point of bin/ames: run the command in ARGUMENTS (a list of strings) and quit
with 0 on success, 1 when any scenario had an error, 2 on a usage error."
  (let ((status
          (handler-case
              (multiple-value-bind (jobs arguments) (jobs-option arguments)
                (let ((options (parse-command-line arguments)))
                  (case (getf options :command)
                    (:help (write-string *usage*) (terpri) 0)
                    (:explain (explain-files (getf options :files) :state (getf options :state)
                                             :settings (getf options :settings)))
                    (:run (if jobs
                              (run-jobs jobs options)
                              (let ((*package* (find-package '#:ames-scenario)))
                                (run-files (getf options :files)
                                           :format (getf options :format)
                                           :settings (getf options :settings)
                                           :svg (getf options :svg)
                                           :stream *standard-output*)))))))
            (usage-error (condition)
              (format *error-output* "ames: ~A~%~A~%" condition *usage*)
              2))))
    (finish-output *standard-output*)
    (finish-output *error-output*)
    (uiop:quit status)))

(defun explain-files (files &key state settings (stream *standard-output*))
  "Explain every scenario of each of FILES (see EXPLAIN), or only the state STATE.
Returns the exit status: 0, or 1 when a scenario could not be explained."
  (let ((status 0))
    (dolist (file files status)
      (handler-case
          (dolist (history (run-file file :settings settings))
            (explain history :state state :stream stream))
        (ames-error (condition)
          (setf status 1)
          (format *error-output* "~&ames: ~A~%" condition))))))

(defun run-files (files &key (format :text) settings (stream *standard-output*) svg
                          (bridge (current-bridge)))
  "Simulate every scenario of each of FILES and print each history on STREAM in FORMAT
(:TEXT, :SEXP, :LATEX, :JSON or :HTML, one page at the end), and, when SVG (a file
name) is given, draw each to it (see AMES.REPORT:FINISH-REPORT). SETTINGS is an alist
(PARAMETER-NAME . NUMBER). A defective scenario or file is reported on *ERROR-OUTPUT*
and the others still run. Returns the exit status: 0 when every scenario ran, 1 when any
had an error."
  (let ((status 0)
        (output (make-report-output format stream :svg svg :bridge bridge)))
    (flet ((report-error (condition)
             (setf status 1)
             (format *error-output* "~&ames: ~A~%" condition)))
      (dolist (file files)
        (multiple-value-bind (scenarios conditions) (read-scenario-file file :on-error :collect)
          (mapc #'report-error conditions)
          (dolist (scenario scenarios)
            (handler-case
                (let ((history (handler-bind ((ambiguous-transition #'stop-simulation))
                                 (simulate scenario :bridge bridge :parameter-values settings))))
                  (report-history output history))
              (ames-error (condition) (report-error condition))))))
      (handler-case (finish-report output)
        (ames-error (condition) (report-error condition))))
    status))

(defun run-file (pathname &key settings (bridge (current-bridge)))
  "Simulate every scenario of the file PATHNAME and return their SIMULATION-HISTORYs.
A scenario that ends ambiguously stops there (its history says so). Signals
SCENARIO-ERROR for a defective scenario, with the restart SKIP-SCENARIO."
  (let ((histories '()))
    (dolist (scenario (read-scenario-file pathname) (nreverse histories))
      (restart-case
          (push (handler-bind ((ambiguous-transition #'stop-simulation))
                  (simulate scenario :bridge bridge :parameter-values settings))
                histories)
        (skip-scenario ()
          :report "Skip this scenario and go on with the next one."
          nil)))))
