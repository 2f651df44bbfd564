;;;; t/hardening-fuzz.lisp -- issue 27's fuzz: extension clauses with values that are not
;;;; physics, hostile names in every output format, and bin/ames under signals and pipes.
;;;;
;;;; OUTPUT-FUZZ-FIGURES: each case takes a scenario of scenarios/, gives it a hostile name
;;;; and description (a line break, \input and \def, ESC, BEL, DEL, a C1 control, < & " ')
;;;; and, one case in two, a random extension clause (friction, restitution, a spring or a
;;;; bumper, a pulley and a rope, gravitation, a query) with values from a list of the
;;;; plausible and the absurd (-1, 0, 2, 1e300, a parameter, (- g)...). The scenario is read
;;;; and validated, run within a small budget, and then written in every format; the checks:
;;;;   :MALFORMED-JSON  a JSON report that Python's json module refuses (target 0)
;;;;   :MALFORMED-SVG   a picture that is not well-formed XML (target 0)
;;;;   :LATEX-INJECTION a LaTeX report with \input, \def or \write in it (target 0)
;;;;   :RAW-CONTROL     a report but sexp carrying a raw control character (target 0)
;;;;   :FORMAT-FAILED   a format that ended in a condition (target 0)
;;;;   :OTHER, :HANGS   as in the whole-path fuzz (target 0)
;;;; PROCESS-FUZZ-FIGURES: bin/ames on a quick scenario file read through a random kind of input
;;;; (-, /dev/stdin, <(cat f), a named pipe with a writer, one without, /dev/null), and,
;;;; one run in two, a SIGTERM or SIGINT after a random delay to a long one; the checks: the status is
;;;; the one expected (0/1/3 when the run ended by itself, 130/143 after a signal), a
;;;; stopped run says so in one line, no process of the run is left, and a run read
;;;; through a pipe prints what the file prints.

(in-package #:ames.tests)

(in-suite hardening)

(defparameter *output-fuzz-test-forms* 4
  "How many output fuzz cases `make test` runs (`make fuzz` runs FUZZ_OUTPUT_FORMS).")

(defparameter *process-fuzz-test-runs* 3
  "How many process fuzz runs `make test` runs (`make fuzz` runs FUZZ_PROCESS_RUNS).")

(defparameter *hostile-name-parts*
  (list (string #\Newline) "\\input{/etc/passwd}" "\\def\\x{}" "^^M\\write18{ls}"
        (string (code-char 27)) "[31m" (string (code-char 7)) (string (code-char 127))
        (string (code-char 133)) "<script>" "&amp;" "\"" "'" "%" "$" "#" "_" "~" "}{")
  "Pieces of a hostile scenario name or description.")

(defparameter *fuzz-values*
  '("-1" "0" "1/2" "1" "2" "-1/3" "1e300" "(- g)" "(* 2 g)" "(/ 1 0)" "(sqrt -1)")
  "The values an extension clause gets: plausible, out of range, malformed.")

(defun fresh-directory (prefix)
  "The pathname of a new, empty temporary directory named after PREFIX."
  (loop (let ((directory (uiop:ensure-directory-pathname
                          (merge-pathnames (format nil "~A-~36R" prefix (random (expt 36 8)
                                                                                (make-random-state t)))
                                           (uiop:temporary-directory)))))
          (unless (probe-file directory)
            (ensure-directories-exist directory)
            (return directory)))))

(defun hostile-text (state &key (pieces 4))
  "A string of a few letters and PIECES pieces of *HOSTILE-NAME-PARTS*."
  (with-output-to-string (out)
    (write-string "fuzz" out)
    (loop repeat pieces
          do (write-string (random-element *hostile-name-parts* state) out)
             (write-char (code-char (+ 97 (random 26 state))) out))))

(defun bar-symbol-text (text)
  "TEXT written as a |symbol| of the scenario language (| and \\ escaped)."
  (with-output-to-string (out)
    (write-char #\| out)
    (loop for c across text
          do (when (member c '(#\| #\\)) (write-char #\\ out))
             (write-char c out))
    (write-char #\| out)))

(defun string-literal-text (text)
  "TEXT written as a string of the scenario language (\" and \\ escaped)."
  (with-output-to-string (out)
    (write-char #\" out)
    (loop for c across text
          do (when (member c '(#\" #\\)) (write-char #\\ out))
             (write-char c out))
    (write-char #\" out)))

(defun random-extension-clause (text state)
  "A random extension clause over the bodies and parameters of the scenario TEXT."
  (let* ((bodies (or (cl-ppcre:all-matches-as-strings "(?<=\\(body )[^\\s()]+" text)
                     (list "nobody")))
         (parameters (cl-ppcre:all-matches-as-strings "(?<=\\()[a-z][a-z0-9-]*(?= :positive)" text))
         (values (append *fuzz-values* parameters)))
    (flet ((body () (random-element bodies state))
           (value () (random-element values state)))
      (ecase (random 7 state)
        (0 (format nil "(friction ~A ~A :static ~A :kinetic ~A)" (body) (body) (value) (value)))
        (1 (if (zerop (random 2 state))
               (format nil "(restitution ~A)" (value))
               (format nil "(restitution ~A ~A ~A)" (body) (body) (value))))
        (2 (format nil "(spring fuzz-spring :from (~A (0 0)) :to (~A (~A 0)) :stiffness ~A~@[ :rest-length ~A~])"
                   (body) (body) (value) (value) (and (zerop (random 2 state)) (value))))
        (3 (format nil "(spring fuzz-bumper :from (~A (0 0)) :toward (~A 1) :stiffness ~A :rest-length ~A)"
                   (body) (value) (value) (value)))
        (4 (format nil "(pulley fuzz-wheel :on ~A :at (0 ~A)) (rope fuzz-rope :length ~A :through ((~A (0 0)) fuzz-wheel (~A (0 0))))"
                   (body) (value) (value) (body) (body)))
        (5 (format nil "(gravitation ~A)" (value)))
        (6 (format nil "(query ~A (value (x ~A) :at (:end 0)))"
                   (random-element (list "fuzz-query" (body)) state) (body)))))))

(defun hostile-scenario-text (text state)
  "The scenario TEXT with a hostile name and description, and one time in two a random
extension clause before its closing parenthesis. Second value: whether a clause was added."
  (let* ((named (cl-ppcre:regex-replace "^\\(scenario\\s+[^\\s()\";]+(\\s+\"(?:[^\"\\\\]|\\\\.)*\")?"
                                        text
                                        (format nil "(scenario ~A ~A"
                                                (bar-symbol-text (hostile-text state))
                                                (string-literal-text (hostile-text state :pieces 6)))))
         (extended (zerop (random 2 state)))
         (end (position #\) named :from-end t)))
    (values (if (and extended end)
                (concatenate 'string (subseq named 0 end) " " (random-extension-clause text state)
                             (subseq named end))
                named)
            extended)))

(defun python-check-files (kind paths)
  "The PATHS (of KIND :json, every non-empty line an object, or :xml) that Debian's
Python refuses, in one run of Python."
  (when paths
    (let* ((program (ecase kind
                      (:json "import json,sys
for p in sys.argv[1:]:
    try:
        [json.loads(l) for l in open(p, encoding='utf-8').read().splitlines() if l.strip()]
    except Exception:
        print(p)")
                      (:xml "import sys, xml.dom.minidom as m
for p in sys.argv[1:]:
    try:
        m.parse(p)
    except Exception:
        print(p)")))
           (output (uiop:run-program (list* "/usr/bin/python3" "-c" program paths)
                                     :output :string :ignore-error-status t)))
      (remove "" (uiop:split-string output :separator '(#\Newline)) :test #'string=))))

(defun render-every-format (history bridge limits)
  "HISTORY written in every format, within the time limit of LIMITS, as a plist FORMAT ->
text (or the condition a format ended in): :TEXT :SEXP :LATEX :JSON :HTML :SVG."
  (flet ((render (function)
           (handler-case
               (ames::call-within-time-left
                (lambda () (with-output-to-string (out) (funcall function out)))
                limits (get-internal-real-time) nil :quiet t)
             (error (condition) condition))))
    (list :text (render (lambda (out) (ames.report:print-history-text history out :bridge bridge)))
          :sexp (render (lambda (out) (ames.report:print-history-sexp history out)))
          :latex (render (lambda (out) (ames.report:print-history-latex history out :bridge bridge)))
          :json (render (lambda (out) (ames.report:print-history-json history out)))
          :html (render (lambda (out) (ames.report:print-history-html (list history) out :bridge bridge)))
          :svg (render (lambda (out) (ames.report:print-history-svg history out))))))

(defun check-rendered (rendered case directory)
  "Check the plist RENDERED (see RENDER-EVERY-FORMAT) of fuzz CASE: return a list of
(KEY DESCRIPTION) for each failure, and the JSON and SVG files written into DIRECTORY
for Python (as two more values)."
  (let ((failures '()) (json nil) (svg nil))
    (loop for (format text) on rendered by #'cddr
          do (cond ((not (stringp text))
                    (push (list :format-failed (format nil "case ~D: ~(~A~) ended in ~A" case format
                                                       (type-of text)))
                          failures))
                   (t
                    (when (and (not (eq format :sexp)) (raw-control-characters-p text))
                      (push (list :raw-control (format nil "case ~D: ~(~A~) has a raw control character"
                                                       case format))
                            failures))
                    (when (and (eq format :latex)
                               (some (lambda (command) (search command text))
                                     '("\\input" "\\def" "\\write")))
                      (push (list :latex-injection (format nil "case ~D: the LaTeX runs user text" case))
                            failures))
                    (when (member format '(:json :svg))
                      (let ((path (merge-pathnames (format nil "case-~D.~(~A~)" case format) directory)))
                        (with-open-file (out path :direction :output :if-exists :supersede
                                                  :external-format :utf-8)
                          (write-string text out))
                        (if (eq format :json)
                            (setf json (namestring path))
                            (setf svg (namestring path))))))))
    (values failures json svg)))

(defun output-fuzz-figures (forms &key (seed *fuzz-seed*) (limits *fuzz-limits*))
  "Run FORMS output fuzz cases (see the file header); return the figures as a plist with
:FAILURES."
  (let* ((state (sb-ext:seed-random-state (+ seed 27)))
         (seeds (scenario-seed-texts))
         (bridge (ames.maxima:make-bridge))
         (directory (fresh-directory "ames-output-fuzz"))
         (figures (list :forms 0 :extended 0 :ames-errors 0 :histories 0 :formats-checked 0
                        :malformed-json 0 :malformed-svg 0 :latex-injection 0 :raw-control 0
                        :format-failed 0 :other 0 :hangs 0))
         (failures '()) (json-files '()) (svg-files '()))
    (ensure-directories-exist directory)
    (flet ((note (key &optional description)
             (incf (getf figures key))
             (when description (push description failures))))
      (unwind-protect
           (let ((hang-seconds (+ (limits-time-limit limits) ames.base::*backstop-grace*
                                  *fuzz-hang-margin*)))
             (dotimes (case forms)
               (multiple-value-bind (text extended) (hostile-scenario-text (random-element seeds state) state)
                 (note :forms)
                 (when extended (note :extended))
                 (let* ((start (get-internal-real-time))
                        (outcome (fuzz-outcome
                                  (lambda ()
                                    (let* ((*package* (find-package '#:ames-scenario))
                                           (scenario (first (ames:read-scenarios-from-string text))))
                                      (ames:run-scenario scenario :bridge bridge :limits limits
                                                                  :numeric t)))
                                  (* 3 hang-seconds))))
                   (cond ((or (eq outcome :hang) (> (seconds-since start) hang-seconds))
                          (note :hangs (format nil "case ~D: a hang" case))
                          (ames.maxima:reset-bridge bridge :restart t))
                         ((typep outcome 'ames:simulation-history)
                          (note :histories)
                          (multiple-value-bind (problems json svg)
                              (check-rendered (render-every-format outcome bridge limits) case directory)
                            (incf (getf figures :formats-checked) 6)
                            (when json (push json json-files))
                            (when svg (push svg svg-files))
                            (loop for (key description) in problems do (note key description))))
                         ((typep outcome 'ames-error) (note :ames-errors))
                         (t (note :other (format nil "case ~D: ~A" case (type-of outcome)))))))))
        (dolist (path (python-check-files :json json-files))
          (note :malformed-json (format nil "~A is not JSON" path)))
        (dolist (path (python-check-files :xml svg-files))
          (note :malformed-svg (format nil "~A is not well-formed XML" path)))
        (ames.maxima:close-bridge bridge)
        (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore)))
    (append figures (list :failures (nreverse failures)))))

(defun print-output-fuzz-figures (figures &optional (stream *standard-output*))
  "Print the output fuzz FIGURES."
  (format stream "~&Output fuzz: ~D hostile scenarios (~D with an extension clause added): ~
                  ~D AMES-ERRORs, ~D histories, ~D reports checked; ~D malformed JSON, ~
                  ~D malformed SVG, ~D LaTeX injections, ~D raw control characters, ~
                  ~D formats that failed, ~D other conditions, ~D hangs~%~{  ~A~%~}"
          (getf figures :forms) (getf figures :extended) (getf figures :ames-errors)
          (getf figures :histories) (getf figures :formats-checked)
          (getf figures :malformed-json) (getf figures :malformed-svg)
          (getf figures :latex-injection) (getf figures :raw-control)
          (getf figures :format-failed) (getf figures :other) (getf figures :hangs)
          (getf figures :failures)))

(defun output-fuzz-clean-p (figures)
  "True when the output fuzz FIGURES meet every target."
  (every (lambda (key) (zerop (getf figures key)))
         '(:malformed-json :malformed-svg :latex-injection :raw-control :format-failed
           :other :hangs)))

;;; bin/ames under signals and through pipes

(defparameter *process-fuzz-inputs*
  '(:file :dash :dev-stdin :process-substitution :fifo :fifo-without-writer :dev-null)
  "The kinds of input the process fuzz reads a scenario file through.")

(defun input-command (kind file directory)
  "The shell command running $AMES on FILE read through the input KIND."
  (ecase kind
    (:file (format nil "$AMES run ~A" file))
    (:dash (format nil "$AMES run - < ~A" file))
    (:dev-stdin (format nil "cat ~A | $AMES run /dev/stdin" file))
    (:process-substitution (format nil "$AMES run <(cat ~A)" file))
    (:fifo (format nil "mkfifo ~Ap; (cat ~A > ~Ap &); $AMES run ~Ap" directory file directory directory))
    (:fifo-without-writer (format nil "mkfifo ~Aq; $AMES run ~Aq --time-limit 1" directory directory))
    (:dev-null "$AMES run /dev/null")))

(defun process-tree (pid)
  "PID's descendants, depth first."
  (let ((children (process-children pid)))
    (append children (mapcan #'process-tree children))))

(defparameter *quick-scenario-names*
  '("block-on-incline" "projectile-off-table" "blocks-colliding"
    "block-sliding-on-rough-floor")
  "Scenario files that run in seconds: the process fuzz reads them through pipes.")

(defparameter *slow-scenario-names* '("two-blocks-in-corner" "two-blocks-in-corner-segment-wall")
  "Scenario files that run long: the process fuzz stops them with a signal.")

(defun process-fuzz-case (state expected)
  "One process fuzz run (see the file header), EXPECTED a hash table of each quick
file's output run as a file: a list of failure descriptions (empty when it went right),
and the kind of input and the signal used."
  (let* ((kind (random-element *process-fuzz-inputs* state))
         (signal (and (member kind '(:file :dash :process-substitution))
                      (zerop (random 2 state))
                      (random-element '(2 15) state)))
         (file (scenario-path (random-element (if signal *slow-scenario-names* *quick-scenario-names*)
                                              state)))
         (expected-output (and (not signal)
                               (or (gethash file expected)
                                   (setf (gethash file expected) (bin-ames-output "run" file)))))
         (delay (+ 0.3 (random 4.0 state)))
         (directory (fresh-directory "ames-process-fuzz"))
         (out (merge-pathnames "out" directory))
         (err (merge-pathnames "err" directory))
         (failures '()))
    (ensure-directories-exist directory)
    (unwind-protect
         (let* ((command (input-command kind file (namestring directory)))
                (process (sb-ext:run-program
                          "/bin/bash" (list "-c" command) :wait nil :output out :error err
                          :environment (list (format nil "AMES=~A" (namestring (merge-pathnames "bin/ames" (asdf:system-source-directory "ames"))))
                                             (format nil "PATH=~A" (uiop:getenv "PATH"))
                                             (format nil "HOME=~A" (uiop:getenv "HOME")))))
                (descendants '()))
           (if signal
               (progn
                 (sleep delay)
                 (setf descendants (cons (sb-ext:process-pid process)
                                         (process-tree (sb-ext:process-pid process))))
                 ;; the signal goes to bin/ames (the image bash started), as kill would send it
                 (let ((ames (find-if (lambda (pid)
                                        (search "ames-image"
                                                (or (ignore-errors (uiop:read-file-string
                                                                    (format nil "/proc/~D/cmdline" pid)))
                                                    "")))
                                      descendants)))
                   (if ames
                       (sb-posix-kill ames signal)
                       (setf signal nil))))
               (loop repeat 200 while (sb-ext:process-alive-p process)
                     do (setf descendants (union descendants (process-tree (sb-ext:process-pid process))))
                        (sleep 0.05)))
           (sb-ext:process-wait process)
           (let ((code (sb-ext:process-exit-code process))
                 (output (uiop:read-file-string out))
                 (errors (uiop:read-file-string err)))
             (cond ((and signal (member code '(130 143)))
                    (unless (eql code (+ 128 signal))
                      (push (format nil "~(~A~) signal ~D: status ~D" kind signal code) failures))
                    (unless (= 1 (count-if (lambda (line) (search "stopped by" line))
                                           (uiop:split-string errors :separator '(#\Newline))))
                      (push (format nil "~(~A~) signal ~D: no one line saying so: ~A" kind signal errors)
                            failures)))
                   ((member kind '(:fifo-without-writer :dev-null))
                    (unless (eql code 1)
                      (push (format nil "~(~A~): status ~D, not 1" kind code) failures)))
                   ((not (member code '(0 1 3)))
                    (push (format nil "~(~A~)~@[ signal ~D~]: status ~D" kind signal code) failures))
                   ((and (null signal) (not (string= output expected-output)))
                    (push (format nil "~(~A~): the output differs from the file's" kind) failures)))
             (sleep 0.3)
             (let ((left (remove-if-not #'process-alive-p descendants)))
               (when left
                 (push (format nil "~(~A~)~@[ signal ~D~]: processes left: ~A" kind signal left) failures)
                 (dolist (pid left) (ignore-errors (sb-posix-kill pid 9)))))))
      (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore))
    (values failures kind signal)))

(defun sb-posix-kill (pid signal)
  "Send SIGNAL to the process PID."
  (sb-unix:unix-kill pid signal))

(defun process-fuzz-figures (runs &key (seed *fuzz-seed*))
  "Run RUNS process fuzz cases (see the file header) over scenarios/; the figures as a
plist with :FAILURES."
  (let* ((state (sb-ext:seed-random-state (+ seed 143)))
         (expected (make-hash-table :test 'equal))
         (figures (list :runs 0 :signalled 0 :failed 0))
         (kinds '()) (failures '()))
    (dotimes (i runs)
      (progn
        (multiple-value-bind (problems kind signal)
            (process-fuzz-case state expected)
          (incf (getf figures :runs))
          (when signal (incf (getf figures :signalled)))
          (let ((entry (assoc kind kinds))) (if entry (incf (cdr entry)) (push (cons kind 1) kinds)))
          (when problems
            (incf (getf figures :failed))
            (setf failures (append failures (list (format nil "run ~D: ~{~A~^; ~}"
                                                           i problems))))))))
    (append figures (list :kinds kinds :failures failures))))

(defun print-process-fuzz-figures (figures &optional (stream *standard-output*))
  "Print the process fuzz FIGURES."
  (format stream "~&Signals and pipes: ~D runs of bin/ames (~D stopped by SIGINT or SIGTERM), ~
                  ~D that went wrong~%  inputs: ~{~(~A~) ~D~^, ~}~%~{  ~A~%~}"
          (getf figures :runs) (getf figures :signalled) (getf figures :failed)
          (loop for (kind . count) in (getf figures :kinds) append (list kind count))
          (getf figures :failures)))

(test output-fuzz-keeps-every-format-well-formed
  (let ((figures (output-fuzz-figures *output-fuzz-test-forms*)))
    (print-output-fuzz-figures figures)
    (is (= *output-fuzz-test-forms* (getf figures :forms)))
    (is (output-fuzz-clean-p figures) "~{~A~%~}" (getf figures :failures))))

(test process-fuzz-signals-and-pipes
  (let ((figures (process-fuzz-figures *process-fuzz-test-runs*)))
    (print-process-fuzz-figures figures)
    (is (zerop (getf figures :failed)) "~{~A~%~}" (getf figures :failures))))
