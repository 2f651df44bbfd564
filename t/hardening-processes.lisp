;;;; t/hardening-processes.lisp -- issue 27 and 25 (the command line): limits that hold for
;;;; the whole run, signals, pipes and devices, --version and --help, progress, too little
;;;; memory. Several tests spawn bin/ames; each keeps to a few seconds.

(in-package #:ames.tests)

(in-suite hardening)

;;; Limits that hold for the whole run

(test the-maxima-timeout-reaches-the-simulation
  "--maxima-timeout (the limits' MAXIMA-TIMEOUT) is the timeout every request of the run
gets (it was the bridge's own 20 s: the simulation ran under the default limits)."
  (let ((seen '()))
    (sb-int:encapsulate 'ames.maxima::configured-timeout 'hardening-spy
                        (lambda (function bridge)
                          (let ((timeout (funcall function bridge)))
                            (pushnew timeout seen)
                            timeout)))
    (unwind-protect
         (hardening-run *spring-pushed-into-floor*
                        :limits (ames.base:make-limits :time-limit 60 :maxima-timeout 17))
      (sb-int:unencapsulate 'ames.maxima::configured-timeout 'hardening-spy))
    (is (equal '(17) seen) "the requests had the timeouts ~A" seen)))

(test a-time-limit-covers-the-report-and-keeps-the-finished-states
  "The particle on a sphere on the floor needs far more than 3 s (simulation and
report): with --time-limit 3 the run ends within the limit and a few seconds. When the
simulation was cut short, the states that finished are printed, the standard error says
so and the status is 3; when it finished (a quiet machine) but its report ran out of
time, the report is written without Maxima and the standard error says that."
  (let ((start (get-internal-real-time)))
    (multiple-value-bind (status output errors)
        (report-in-format (uiop:read-file-string (scenario-path "particle-on-sphere-on-floor"))
                          :text :limits (ames.base:make-limits :time-limit 3))
      (let ((seconds (ames::seconds-since start)))
        (is (< seconds 9) "the run took ~,1F s" seconds))
      (is (search "State 0" output))
      (if (eql 3 status)
          (progn
            (is (search "Outcome: stopped" output))
            (is (search "time limit of 3 s was exceeded" errors) "~A" errors)
            (is (search "that finished" errors)))
          (progn
            (is (eql 0 status))
            (is (search "ran out while the report was written" errors) "~A" errors))))))

;;; Signals: the run stops with its finished states, its status, and no process left

(defun process-children (pid)
  "The process ids whose parent is PID."
  (let ((text (uiop:run-program (list "pgrep" "-P" (princ-to-string pid))
                                :output :string :ignore-error-status t)))
    (mapcar #'parse-integer (uiop:split-string (string-trim '(#\Newline #\Space) text)
                                               :separator '(#\Newline)))))

(defun process-alive-p (pid)
  "True when a process PID exists (and is no zombie)."
  (let ((stat (format nil "/proc/~D/stat" pid)))
    (and (probe-file stat)
         (not (search ") Z" (ignore-errors (uiop:read-file-string stat)))))))

(defun run-and-signal (signal seconds &rest arguments)
  "Run bin/ames with ARGUMENTS, send it SIGNAL (a number) after SECONDS; return its exit
code, its standard output, its standard error, and the processes it had started
(its children and theirs) at the time of the signal."
  (let* ((program (namestring (merge-pathnames "bin/ames" (asdf:system-source-directory "ames"))))
         (out (uiop:tmpize-pathname (merge-pathnames "ames-signal-out" (uiop:temporary-directory))))
         (err (uiop:tmpize-pathname (merge-pathnames "ames-signal-err" (uiop:temporary-directory))))
         (process (sb-ext:run-program program arguments :wait nil :output out :error err
                                                        :if-output-exists :supersede
                                                        :if-error-exists :supersede)))
    (unwind-protect
         (progn
           (sleep seconds)
           (let* ((pid (sb-ext:process-pid process))
                  (children (process-children pid))
                  (descendants (append children (mapcan #'process-children children))))
             (sb-ext:process-kill process signal)
             (sb-ext:process-wait process)
             (values (sb-ext:process-exit-code process)
                     (uiop:read-file-string out) (uiop:read-file-string err)
                     descendants)))
      (sb-ext:process-close process)
      (uiop:delete-file-if-exists out)
      (uiop:delete-file-if-exists err))))

(defun count-of (part text)
  "How many times PART occurs in TEXT."
  (loop for start = 0 then (+ position (length part))
        for position = (search part text :start2 start)
        while position count t))

(test sigterm-and-sigint-stop-the-run-with-its-finished-states
  "SIGTERM ends a run with 143, SIGINT with 130: one line says so, the states that
finished are printed, and no process of the run (Maxima) is left."
  (dolist (case '((15 143 "SIGTERM") (2 130 "SIGINT")))
    (destructuring-bind (signal expected name) case
      (multiple-value-bind (code output errors descendants)
          (run-and-signal signal 3 "run" (scenario-path "two-blocks-in-corner"))
        (is (eql expected code) "~A: status ~A, ~A" name code errors)
        (is (search (format nil "stopped by ~A" name) errors) "~A" errors)
        (is (= 1 (count-of "stopped by" errors)) "not one line: ~A" errors)
        ;; the run's history, with the states that finished (none when the signal came
        ;; before the run had checked its scenario, as it may on a loaded machine)
        (is (or (zerop (length output))
                (and (search "Outcome: stopped" output) (search "stopped by" output)))
            "~A" output)
        (is (plusp (length descendants)) "no Maxima was running")
        (sleep 0.5)
        (is (notany #'process-alive-p descendants) "processes left: ~A" descendants)))))

(test sigterm-under-jobs-stops-the-workers-and-their-maxima
  "Under --jobs 2, SIGTERM to the parent stops both workers and their Maxima; the status
is 143 and the workers' finished states are printed."
  (multiple-value-bind (code output errors descendants)
      (run-and-signal 15 4 "run" (scenario-path "two-blocks-in-corner")
                      (scenario-path "two-blocks-in-corner-segment-wall") "--jobs" "2")
    (is (eql 143 code) "status ~A, ~A" code errors)
    (is (= 1 (count-if (lambda (line) (search "stopped by" line))
                       (uiop:split-string errors :separator '(#\Newline))))
        "not one line: ~A" errors)
    ;; each worker prints its stopped run (or nothing, when stopped before its first check)
    (is (<= (count-of "Outcome: stopped" output) 2) "~A" output)
    (is (>= (length descendants) 2) "the workers were not running: ~A" descendants)
    (sleep 0.5)
    (is (notany #'process-alive-p descendants) "processes left: ~A" descendants)))

;;; Inputs that are not plain files

(defun bin-ames-shell (command)
  "Run the shell COMMAND with $AMES the checkout's bin/ames and $DROP a quick scenario
file; return its exit code (the last command's), its standard output and error."
  (let ((drop (write-scenario-text *drop-text*)))
    (unwind-protect
         (multiple-value-bind (output errors code)
             (uiop:run-program (list "bash" "-c" command)
                               :output :string :error-output :string :ignore-error-status t
                               :environment (list (format nil "AMES=~A" (namestring (merge-pathnames "bin/ames" (asdf:system-source-directory "ames"))))
                                                  (format nil "DROP=~A" drop)
                                                  (format nil "PATH=~A" (uiop:getenv "PATH"))
                                                  (format nil "HOME=~A" (uiop:getenv "HOME"))))
           (values code output errors))
      (delete-file drop))))

(test pipes-devices-and-the-standard-input-are-read-to-their-end
  "A scenario read from -, /dev/stdin or a pipe (<(cat f)) runs as the file does; empty
input, a directory and a missing file are errors (status 1); /dev/zero is refused
naming the limit of scenario text; a named pipe without a writer waits no longer than
--time-limit."
  (dolist (command '("$AMES run - < $DROP" "$AMES run /dev/stdin < $DROP"
                     "$AMES run <(cat $DROP)" "cat $DROP | $AMES run -"))
    (multiple-value-bind (code output errors) (bin-ames-shell command)
      (is (eql 0 code) "~A: ~A ~A" command code errors)
      (is (search "Scenario drop" output) "~A: ~A" command output)))
  (dolist (case '(("$AMES run - < /dev/null" "empty") ("$AMES run /tmp" "Is a directory")
                  ("$AMES run /nonexistent/x.lisp" "No such file")
                  ("$AMES run /dev/zero" "4,194,304 characters")))
    (destructuring-bind (command text) case
      (multiple-value-bind (code output errors) (bin-ames-shell command)
        (declare (ignore output))
        (is (eql 1 code) "~A: ~A" command code)
        (is (search text errors) "~A: ~A" command errors))))
  (let ((start (get-internal-real-time)))
    (multiple-value-bind (code output errors)
        (bin-ames-shell "d=$(mktemp -d); mkfifo $d/p; $AMES run $d/p --time-limit 1; s=$?; rm -r $d; exit $s")
      (declare (ignore output))
      (is (eql 1 code))
      (is (search "within the time limit" errors) "~A" errors)
      (is (< (ames::seconds-since start) 8)))))

;;; The command line: --version, run --help, progress on a terminal

(test version-help-and-progress
  "--version prints AMES's version (status 0); run --help and explain -h print the usage
(status 0); with progress on (a terminal), each finished state gets one line on the
standard error."
  (is (eq :version (getf (ames::parse-command-line '("--version")) :command)))
  (is (eq :help (getf (ames::parse-command-line '("run" "x.lisp" "--help")) :command)))
  (is (eq :help (getf (ames::parse-command-line '("explain" "-h")) :command)))
  (multiple-value-bind (code output) (run-bin-ames "--version")
    (is (eql 0 code))
    (is (search (format nil "AMES ~A" (asdf:component-version (asdf:find-system "ames"))) output)))
  (multiple-value-bind (code output) (run-bin-ames "run" "--help")
    (is (eql 0 code))
    (is (search "Usage: ames run" output)))
  (let* ((errors (make-string-output-stream))
         (histories (let ((*error-output* errors))
                      (ames::call-with-progress
                       (lambda () (hardening-run *spring-pushed-into-floor*)) :progress t)))
         (lines (remove "" (uiop:split-string (get-output-stream-string errors)
                                              :separator '(#\Newline))
                        :test #'string=)))
    (is (= (length (ames:history-states (first histories))) (length lines)) "~A" lines)
    (is (search "pushed-into-floor: state 0 finished" (first lines)) "~A" lines)))

;;; Too little memory

(test too-little-virtual-memory-is-said-plainly
  "Under ulimit -v 1.2 GB, bin/ames says which limit is too low and exits 4 (SBCL alone
would stop with \"Can't allocate\"); the condition that reports an exhausted heap says
so (exhausting the heap itself is too slow for the suite)."
  (multiple-value-bind (code output errors) (bin-ames-shell "ulimit -v 1200000; $AMES run $DROP")
    (declare (ignore output))
    (is (eql 4 code))
    (is (search "ulimit -v 1200000" errors) "~A" errors)
    (is (not (search "Can't allocate" errors))))
  (let ((message (princ-to-string (make-condition 'ames::memory-exhausted
                                                  :datum (make-condition 'storage-condition)))))
    (is (search "ran out of memory" message))))

(test numeric-without-defaults-says-so
  "--numeric on a scenario whose parameters have no (:value N) default names those that
stay symbolic (a --set value counts as a value)."
  (let* ((*package* (find-package '#:ames-scenario))
         (scenario (first (ames:read-scenarios-from-string *drop-text*)))
         (text (with-output-to-string (*error-output*)
                 (ames::note-symbolic-parameters scenario '(("g" . 10))))))
    (is (search "m, h have no (:value N) default" text) "~A" text)
    (is (not (search " g," text)))
    (is (string= "" (with-output-to-string (*error-output*)
                      (ames::note-symbolic-parameters scenario '(("g" . 10) ("m" . 1) ("h" . 2))))))))

(test jobs-workers-do-not-outlive-a-killed-parent
  "Under --jobs 2, a parent killed with SIGKILL (no handler runs) leaves no worker and no
Maxima behind: each worker watches its parent and stops when it is gone."
  (multiple-value-bind (code output errors descendants)
      (run-and-signal 9 4 "run" (scenario-path "two-blocks-in-corner")
                      (scenario-path "two-blocks-in-corner-segment-wall") "--jobs" "2")
    (declare (ignore code output errors))
    (is (>= (length descendants) 2) "the workers were not running: ~A" descendants)
    (loop repeat 80 while (some #'process-alive-p descendants) do (sleep 0.1))
    (is (notany #'process-alive-p descendants) "processes left: ~A" descendants)
    (dolist (pid (remove-if-not #'process-alive-p descendants))
      (ignore-errors (sb-unix:unix-kill pid 9)))))
