;;;; bench/bench-issue-24-corner-wedge.lisp -- two rows of issue 24 beside a baseline
;;;; checkout: the wedge run cold, and the thesis's corner under --numeric (and, in
;;;; process, without values).
;;;;
;;;; Wall times of whole bin/ames processes (the least of RUNS), of this checkout and, when
;;;; the environment variable AMES_BASELINE names another checkout (e.g. a worktree of the
;;;; previous commit or of main), of that one, side by side, each also as a multiple of a
;;;; bare Maxima start. On a shared, loaded machine wall times swing by several times;
;;;; the figures that do not depend on the load are printed too, for this checkout: the
;;;; round trips to Maxima and the CPU seconds Maxima spent, simulation and text report
;;;; (measured in this process, the report on a fresh bridge state as bin/ames makes it).
;;;; Prints numbers; asserts nothing. Run alone:
;;;;   AMES_BASELINE=/path/to/main sbcl --non-interactive --eval '(require :asdf)' \
;;;;     --eval '(asdf:load-asd (truename "ames.asd"))' --eval '(asdf:load-system "ames")' \
;;;;     --load bench/bench-issue-24-corner-wedge.lisp
;;;;
;;;; Figures of 2026-11-26 (branch speedcorner against main e490684, same hour, a machine
;;;; at load average 20-29 on 2 cores, so the wall times are 10-20 times the work):
;;;;                                   main                 speedcorner
;;;;   corner --numeric, run           4656 trips  9.2 s    2912 trips  8.3 s  (Maxima CPU)
;;;;   corner --numeric, text report   2048 trips  4.3 s    1031 trips  3.5 s
;;;;   wedge, run                       376 trips  0.60 s    351 trips  0.57 s
;;;;   wedge, text report                73 trips  0.15 s     64 trips  0.13 s
;;;; SBCL's own CPU: the corner 1.8 s, the wedge 0.2 s. A bare Maxima start: 0.07 s CPU,
;;;; 0.3 s wall when the machine is quiet.
;;;;
;;;; Figures of 2026-11-26 (branch numeric against main 95ce0d1, load average 10-23; see
;;;; bench/results-issue-24-corner-wedge.txt for the phases and where the time goes):
;;;;                                   main                 numeric
;;;;   wedge, SBCL's own CPU cold      0.215 s, 93 MiB      0.142 s, 64 MiB  (warm-up image)
;;;;   wedge, Maxima's start           after the scenario   with it (started first)
;;;;   wedge, run / report             318 / 64 trips       the same, Maxima 0.60 / 0.16 s CPU
;;;;   corner --numeric, run           2882 trips  7.7 s    2834 trips  7.8 s  (Maxima CPU)
;;;;   corner --numeric, text report   1031 trips  3.0 s    1031 trips  3.3 s
;;;;
;;;; Figures of 2026-11-26 (branch forks against main 68e2679, load average ~25; see
;;;; bench/results-issue-24-forks.txt):
;;;;                                   main                 forks
;;;;   corner --numeric, run           2972 trips  8.1 s    2349 trips  6.2 s  (Maxima CPU)
;;;;   corner --numeric, text report   1031 trips  3.2 s     530 trips  1.3 s
;;;;   corner --numeric, bin/ames wall 94.5 s               51.4 s (the same minutes)
;;;;
;;;; Figures of 2026-11-26 (branch s6-corner against main a1f5c78, in process, load average
;;;; 8-12; see bench/results-issue-24-corner.txt; CPU seconds, Maxima's from /proc):
;;;;                                   main                          s6-corner
;;;;   corner without values, run      4874 trips 14.0 + 2.9 s SBCL  4513 trips 13.1 + 2.7 s SBCL
;;;;   corner --numeric, run           2322 trips  6.1 + 1.6 s SBCL  2252 trips  6.0 + 1.6 s SBCL
;;;;   corner --numeric, text report    530 trips  1.1 + 0.3 s SBCL   527 trips  1.1 + 0.2 s SBCL

(defpackage #:ames.bench.corner-wedge
  (:use #:cl)
  (:documentation "Issue 24's corner and wedge rows beside a baseline checkout."))

(in-package #:ames.bench.corner-wedge)

(defparameter *checkout* (merge-pathnames "../" (make-pathname :name nil :type nil
                                                                :defaults *load-truename*))
  "This checkout's root.")

(defparameter *runs* 3 "Runs of each quick command; the least time counts.")

(defun seconds-since (start)
  "Seconds of real time since the internal time START."
  (/ (- (get-internal-real-time) start) (float internal-time-units-per-second 1d0)))

(defun least-time (arguments runs)
  "The least wall time of RUNS runs of the command ARGUMENTS (output discarded)."
  (loop repeat runs
        minimize (let ((start (get-internal-real-time)))
                   (uiop:run-program arguments :output nil :error-output nil :ignore-error-status t)
                   (seconds-since start))))

(defun command (root &rest arguments)
  "ROOT's bin/ames with ARGUMENTS, a scenario named by its file name in ROOT/scenarios."
  (cons (namestring (merge-pathnames "bin/ames" root))
        (mapcar (lambda (a) (if (uiop:string-suffix-p a ".lisp")
                                (namestring (merge-pathnames (format nil "scenarios/~A" a) root))
                                a))
                arguments)))

(defun maxima-cpu-seconds (bridge)
  "The CPU seconds (user and system) BRIDGE's Maxima process has used, from /proc."
  (let ((pid (ames.maxima::bridge-process-id bridge)))
    (if (null pid)
        0
        (with-open-file (in (format nil "/proc/~D/stat" pid))
          (let* ((line (read-line in))
                 (fields (uiop:split-string (subseq line (+ 2 (position #\) line :from-end t)))
                                            :separator " ")))
            ;; utime and stime are the 14th and 15th fields of the line
            (/ (+ (parse-integer (nth 11 fields)) (parse-integer (nth 12 fields)))
               100d0))))))

(defun in-process-figures (file numeric)
  "Round trips and Maxima CPU seconds of FILE's run and of its text report, in this
process with a fresh Maxima: (values TRIPS CPU REPORT-TRIPS REPORT-CPU)."
  (let ((bridge (ames.maxima::make-bridge)))
    (unwind-protect
         (flet ((trips () (getf (ames.maxima:bridge-statistics bridge) :maxima-calls)))
           (let* ((histories (ames::run-file (merge-pathnames (format nil "scenarios/~A" file) *checkout*)
                                             :numeric numeric :bridge bridge))
                  (trips (trips)) (cpu (maxima-cpu-seconds bridge)))
             (ames.report:report-history (ames.report:make-report-output
                                          :text (make-broadcast-stream) :bridge bridge)
                                         (first histories))
             (values trips cpu (- (trips) trips) (- (maxima-cpu-seconds bridge) cpu))))
      (ames.maxima:close-bridge bridge))))

(defun row (label arguments baseline-root bare runs goal)
  "Print LABEL's wall time for this checkout and BASELINE-ROOT (when given), with
ARGUMENTS for bin/ames, as multiples of BARE too."
  (let ((here (least-time (apply #'command *checkout* arguments) runs))
        (there (and baseline-root (least-time (apply #'command baseline-root arguments) runs))))
    (format t "~&  ~34A ~7,2F s (~5,1F x Maxima)~@[  baseline ~7,2F s~]~@[ (~5,1F x Maxima)~]~@[  now/baseline ~4,2F~]  goal: ~A~%"
            label here (/ here bare) there (and there (/ there bare)) (and there (/ here there)) goal)
    (finish-output)))

(defun sbcl-cpu-seconds (arguments)
  "The CPU seconds (user and system) of the bin/ames process of ARGUMENTS alone, by
/usr/bin/time: Maxima, which outlives it by a moment (it leaves on end of input), is not
its reaped child and is not counted. NIL when /usr/bin/time is missing."
  (when (probe-file "/usr/bin/time")
    (let* ((text (nth-value 1 (uiop:run-program (list* "/usr/bin/time" "-f" "AMES-CPU %U %S" arguments)
                                                :output nil :error-output :string
                                                :ignore-error-status t)))
           (at (search "AMES-CPU " text :from-end t)))
      (when at
        (with-input-from-string (in (subseq text (+ at 9)))
          (+ (read in) (read in)))))))

(defun first-answer-seconds ()
  "The wall seconds from starting a bridge's Maxima (the server loaded) to its first
answer, in this process (the least of *RUNS*)."
  (loop repeat *runs*
        minimize (let ((bridge (ames.maxima:make-bridge))
                       (start (get-internal-real-time)))
                   (unwind-protect (ames.maxima:simplify bridge 1)
                     (ames.maxima:close-bridge bridge))
                   (seconds-since start))))

(defun wedge-phases (root bare)
  "Print the phases of a cold wedge run of the checkout ROOT: the command line's start
(bin/ames help: the script's staleness check and the image's start), SBCL's own CPU in
a cold run, and, for this checkout (measured in this process), the bridge's Maxima start
to its first answer beside BARE, a bare Maxima start. Maxima's CPU for the work is among
the in-process figures."
  (let ((help (least-time (command root "help") *runs*))
        (first-answer (and (equal root *checkout*) (first-answer-seconds)))
        (sbcl-cpu (loop repeat *runs*
                        minimize (or (sbcl-cpu-seconds (command root "run" "particle-on-wedge.lisp"))
                                     0))))
    (format t "  the wedge, phase by phase (~A):~%" (namestring root))
    (format t "    bin/ames help (script and image start)   ~6,3F s wall~%" help)
    (when first-answer
      (format t "    Maxima started to its first answer       ~6,3F s wall (a bare start ~5,3F s)~%"
              first-answer bare))
    (format t "    SBCL's own CPU in a cold run             ~6,3F s~%" sbcl-cpu)
    (finish-output)))

(let* ((baseline (let ((root (uiop:getenv "AMES_BASELINE")))
                   (and root (plusp (length root)) (uiop:ensure-directory-pathname root))))
       (bare (least-time '("maxima" "--very-quiet" "--batch-string" "quit();") *runs*)))
  (format t "~&Issue 24, the corner and the wedge (least wall time of whole runs)~@[; baseline ~A~]:~%"
          (and baseline (namestring baseline)))
  (format t "  ~34A ~7,2F s~%" "a bare Maxima start" bare)
  (uiop:run-program (command *checkout* "help") :output nil :ignore-error-status t) ; image built
  (when baseline (uiop:run-program (command baseline "help") :output nil :ignore-error-status t))
  (row "the wedge, cold" '("run" "particle-on-wedge.lisp") baseline bare *runs*
       "at most 3 x Maxima's start")
  (row "the corner, --numeric" '("run" "two-blocks-in-corner.lisp" "--numeric") baseline bare 1
       "under 3 s")
  (wedge-phases *checkout* bare)
  (when baseline (wedge-phases baseline bare))
  (format t "  this checkout, in process (load-independent): round trips and Maxima CPU~%")
  (loop for (label file numeric) in '(("the wedge" "particle-on-wedge.lisp" nil)
                                      ("the corner, --numeric" "two-blocks-in-corner.lisp" t)
                                      ("the corner, without values" "two-blocks-in-corner.lisp" nil))
        do (multiple-value-bind (trips cpu report-trips report-cpu) (in-process-figures file numeric)
             (format t "  ~34A run ~5D trips ~6,2F s CPU; text report ~5D trips ~6,2F s CPU~%"
                     label trips cpu report-trips report-cpu)
             (finish-output))))
