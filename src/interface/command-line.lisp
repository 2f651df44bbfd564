;;;; src/interface/command-line.lisp -- reading bin/ames's command line: the usage text, the
;;;; options and their values (numbers, settings p=v, seconds), the usage error, and the
;;;; limits the options set. What is run with them, and the exit codes, are cli.lisp's.

(in-package #:ames)

(define-condition usage-error (ames-error) ()
  (:documentation "The command line is malformed. DATUM is the offending argument.")
  (:report (lambda (condition stream)
             (format stream "~A~@[: ~A~]" (ames-error-detail condition)
                     (ames-error-datum condition)))))

(defparameter *usage*
  "Usage: ames run FILE... [--format text|sexp|latex|json|html] [--svg OUT.svg] [--numeric]
                 [--set PARAM=VALUE ...] [--time-limit SECONDS] [--maxima-timeout SECONDS]
                 [--all-branches] [--verbose] [--jobs N]
       ames explain FILE... [--state N] [--numeric] [--set PARAM=VALUE ...]
       ames check FILE... [--numeric] [--set PARAM=VALUE ...]
       ames --version | ames help | ames run --help
  Simulate every scenario in each FILE (- for the standard input; a pipe or a device
  too) and print a report. On a terminal, a line on the standard error per state done.
  --format text   a report for people, state by state (the default)
  --format sexp   one readable s-expression per scenario (see the scenario language page)
  --format latex  a LaTeX fragment per scenario (formulas through Maxima's tex)
  --format json   the s-expression's content as JSON, one line per scenario
  --format html   one self-contained page: pictures, timelines, typeset formulas
  --standalone    with --format latex: one whole LaTeX document (for pdflatex)
  --svg OUT.svg   also draw each scenario (OUT-NAME.svg when the run has several)
  --numeric       use the scenario's (:value N) defaults as parameter values
  --all-branches  where the values select a branch of a fork, simulate the others too
  --set p=v ...   give parameter p the number v (an integer, ratio or decimal), over its
                  default; numeric values are then printed beside the closed forms, and
                  a fact the assumptions leave open but the values decide is used and
                  reported. Values that break a declared assumption are an error.
  --time-limit S  the wall time one scenario and its report may take, in seconds
                  (default 300); a run over it prints the states that finished (exit 3)
  --maxima-timeout S  the time one Maxima request may take, in seconds (default 20)
  --no-check      skip the self-check (under values, every state's closed form, end and
                  printed numbers are checked numerically before printing; the report
                  says which states were)
  --verbose       print error messages in full (long ones are otherwise cut short)
  --jobs N        run the files in N processes at once (each with its own Maxima);
                  reports in the files' order, the exit code the worst of them
  check           run each scenario through AMES and through the witness (Siconos,
                  witness/siconos_driver.py) and print both side by side with a verdict
                  (exit 0 agree, 4 a disagreement or a crash, 1 refused or not witnessed)
  explain         why each state's contacts and modes hold, where its equations
                  come from, and why it ends when it does (or only state N)
Exit codes: 0 complete, 1 a scenario error, 2 usage, 3 a run (or a branch) that ended
ambiguous or undecided, or stopped by its time limit, 5 a self-check failed (1 wins
over 5, 5 over 3); 130 and 143 when SIGINT or SIGTERM stopped the run (the states that
finished are printed)."
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
  "Parse one --set argument \"NAME=VALUE\" into (NAME-STRING . NUMBER): a rational, or
a double-float for a value with pi or in degrees (see set-values.lisp); signal
USAGE-ERROR naming TEXT when it is malformed."
  (let ((position (position #\= text)))
    (unless (and position (plusp position))
      (error 'usage-error :datum text :detail "--set takes PARAM=VALUE"))
    (let ((value (parse-set-value (subseq text (1+ position)))))
      (unless value
        (error 'usage-error :datum text :detail "--set needs a number after ="))
      (cons (subseq text 0 position) value))))

(defun parse-seconds (option text)
  "The positive number of seconds TEXT writes (as PARSE-DECIMAL reads it), for OPTION;
signal USAGE-ERROR naming TEXT when it is not one."
  (let ((value (and text (parse-decimal text))))
    (unless (and value (plusp value) (<= value (* 365 24 3600)))
      (error 'usage-error :datum (or text option)
                          :detail (format nil "~A takes a positive number of seconds" option)))
    value))

(defun check-command-word (arguments)
  "Check the command word, the first of ARGUMENTS. Returns the parsed command line
(:COMMAND :HELP or :VERSION) when the command asks for the usage or the version, else
NIL: a command to parse further. Signals USAGE-ERROR when there is no command or an
unknown one."
  (let ((command (first arguments)))
    (cond ((null command) (error 'usage-error :detail "no command given"))
          ((member command '("help" "--help" "-h") :test #'string=)
           (list :command :help))
          ((member command '("version" "--version") :test #'string=)
           (list :command :version))
          ((intersection (rest arguments) '("--help" "-h") :test #'string=)
           ;; run --help, explain -h: the usage, whatever else is given
           (list :command :help))
          ((not (member command '("run" "explain" "check") :test #'string=))
           (error 'usage-error :datum command :detail "unknown command")))))

(defun parse-option (command argument rest)
  "Parse the command line's ARGUMENT, given to COMMAND, with its values from REST, the
arguments after it. Returns three values: the option's key (NIL when ARGUMENT is a
file), its value (for :SETTINGS, the list of settings given) and the arguments after
its values. Signals USAGE-ERROR on an unknown option or a malformed value."
  (flet ((option (key value) (values key value rest)))
    (cond ((string= argument "--format")
           (let ((value (pop rest)))
             (option :format
                     (or (find value *report-formats* :test #'string-equal)
                         (error 'usage-error :datum value
                                             :detail "--format takes text, sexp, latex, json or html")))))
          ((string= argument "--svg")
           (let ((svg (pop rest)))
             (when (or (null svg) (eql 0 (search "--" svg)))
               (error 'usage-error :datum argument :detail "--svg takes the picture's file name"))
             (option :svg svg)))
          ((string= argument "--numeric") (option :numeric t))
          ((string= argument "--all-branches") (option :all-branches t))
          ((string= argument "--set")
           (unless (and rest (find #\= (first rest)))
             (error 'usage-error :datum argument :detail "--set takes PARAM=VALUE"))
           (option :settings
                   (loop while (and rest (find #\= (first rest))
                                    (not (eql 0 (search "--" (first rest)))))
                         collect (parse-setting (pop rest)))))
          ((and (string= command "explain") (string= argument "--state"))
           (let ((value (and rest (parse-decimal (pop rest)))))
             (unless (and (integerp value) (>= value 0))
               (error 'usage-error :datum argument :detail "--state takes a state's index"))
             (option :state value)))
          ((string= argument "--time-limit")
           (option :time-limit (parse-seconds argument (pop rest))))
          ((string= argument "--maxima-timeout")
           (option :maxima-timeout (parse-seconds argument (pop rest))))
          ((string= argument "--verbose") (option :verbose t))
          ((string= argument "--standalone") (option :standalone t))
          ((string= argument "--no-check") (option :no-check t))
          ((eql 0 (search "--" argument))
           (error 'usage-error :datum argument :detail "unknown option"))
          (t (option nil nil)))))

(defun parse-command-line (arguments)
  "Parse ARGUMENTS (strings, without the program name) into a plist (:COMMAND :FILES
:FORMAT :SETTINGS :SVG :STATE :NUMERIC :TIME-LIMIT :MAXIMA-TIMEOUT :VERBOSE
:ALL-BRANCHES); the two
limits are NIL when not given. Signals USAGE-ERROR on anything malformed."
  (let ((command (first arguments)) (files '()) (options (list :format :text :settings '())))
    (let ((shortcut (check-command-word arguments)))
      (when shortcut (return-from parse-command-line shortcut)))
    (loop with rest = (rest arguments)
          while rest
          do (let ((argument (pop rest)))
               (multiple-value-bind (key value after) (parse-option command argument rest)
                 (setf rest after)
                 (case key
                   ((nil) (push argument files))
                   (:settings (setf (getf options :settings)
                                    (append (getf options :settings) value)))
                   (t (setf (getf options key) value))))))
    (when (null files) (error 'usage-error :detail "run needs at least one scenario file"))
    (list :command (cond ((string= command "explain") :explain)
                         ((string= command "check") :check)
                         (t :run))
          :files (nreverse files) :format (getf options :format)
          :settings (getf options :settings) :svg (getf options :svg)
          :state (getf options :state) :numeric (getf options :numeric)
          :time-limit (getf options :time-limit) :maxima-timeout (getf options :maxima-timeout)
          :verbose (getf options :verbose)
          :standalone (getf options :standalone) :no-check (getf options :no-check)
          :all-branches (getf options :all-branches))))

(defun command-line-limits (options)
  "The LIMITS for the parsed command line OPTIONS: *LIMITS* with its time limit and
Maxima timeout replaced by those given."
  (let ((limits *limits*))
    (when (getf options :time-limit)
      (setf limits (change-limits limits :time-limit (getf options :time-limit))))
    (when (getf options :maxima-timeout)
      (setf limits (change-limits limits :maxima-timeout (getf options :maxima-timeout))))
    limits))
