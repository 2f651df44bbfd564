;;;; bench/bench-issue-24.lisp -- the table of issue 24, row by row, beside its baseline.
;;;;
;;;; Every row is the wall time of whole bin/ames processes (the best of RUNS where a row
;;;; is quick), printed beside a bare Maxima start (maxima --very-quiet --batch-string
;;;; "quit();"), the baseline every run pays once:
;;;;   the wedge, cold (the ratio to a bare Maxima start: goal at most 3);
;;;;   the thesis's corner with --numeric (the values select a branch: goal under 3 s), with
;;;;   other values (B falls, the boundary), and without values (the whole envisionment:
;;;;   goal under 10 s); the block launched up a rough incline with --numeric (goal 3 s);
;;;;   a chain of N blocks pushed into a wall, every mass and width symbolic, N = 8, 16,
;;;;   24, 32, 64 (goal: 32 under 10 s, growth at most N^1.5, 64 under a minute) with the
;;;;   growth exponents; the same chain with numbers, N = 32, 64, 128 (goal: 128 under 10 s).
;;;; A row stops growing once a run takes longer than *GIVE-UP-SECONDS*; every run has
;;;; --time-limit *TIME-LIMIT*. Prints numbers; asserts nothing. `make test`'s own time is
;;;; printed by `make test` (its closing figures).

(defpackage #:ames.bench.issue-24
  (:use #:cl)
  (:documentation "The rows of issue 24's table."))

(in-package #:ames.bench.issue-24)

(defparameter *checkout* (merge-pathnames "../" (make-pathname :name nil :type nil
                                                                :defaults *load-truename*))
  "The checkout's root.")

(defparameter *give-up-seconds* 120
  "A chain is not run at larger N once one run takes longer than this.")

(defparameter *time-limit* 600
  "The --time-limit of every run, in seconds.")

(defun seconds-since (start)
  "Seconds of real time since the internal time START."
  (/ (- (get-internal-real-time) start) (float internal-time-units-per-second 1d0)))

(defun timed-run (arguments &key (runs 1))
  "The least wall time of RUNS runs of the command ARGUMENTS (output discarded), and the
last exit code."
  (let ((best nil) (code nil))
    (dotimes (i runs)
      (let ((start (get-internal-real-time)))
        (setf code (nth-value 2 (uiop:run-program arguments :output nil :error-output nil
                                                            :ignore-error-status t)))
        (setf best (min (or best most-positive-double-float) (seconds-since start)))))
    (values best code)))

(defun ames (&rest arguments)
  "The command line of this checkout's bin/ames with ARGUMENTS and the time limit."
  (list* (namestring (merge-pathnames "bin/ames" *checkout*))
         (append arguments (list "--time-limit" (princ-to-string *time-limit*)))))

(defun scenario-path (name)
  "The path of scenarios/NAME.lisp as a string."
  (namestring (merge-pathnames (format nil "scenarios/~A.lisp" name) *checkout*)))

(defun row (label seconds code &optional baseline goal)
  "Print one row: LABEL, SECONDS, the exit CODE, the ratio to BASELINE and the GOAL text."
  (format t "~&  ~52A ~8,2F s  (exit ~D)~@[  ~,1F x Maxima's start~]~@[  goal: ~A~]~%"
          label seconds code (and baseline (/ seconds baseline)) goal)
  (finish-output))

;;; The chain family of the issue: every block its own symbolic mass and width

(defun chain-form (n &key numbers)
  "A chain of N blocks touching in a row on a floor, the first pushed by f into a wall
against the last; block k has mass mk and width wk (symbolic, or with NUMBERS the
numbers k and 1 + k/10), height 1."
  (flet ((sym (control k) (intern (string-upcase (format nil control k)) '#:ames.bench.issue-24)))
    (let* ((widths (loop for k from 1 to n
                         collect (if numbers (+ 1 (/ k 10)) (sym "w~D" k))))
           (masses (loop for k from 1 to n collect (if numbers k (sym "m~D" k))))
           (lefts (loop for k below n collect (if (zerop k) 0 `(+ ,@(subseq widths 0 k))))))
      `(scenario ,(sym "chain-~D" n)
         "A chain of blocks of symbolic masses and widths pushed into a wall."
         (parameters ,@(unless numbers
                         (loop for k from 1 to n
                               append (list `(,(sym "m~D" k) :positive) `(,(sym "w~D" k) :positive))))
                     (g :positive ,@(and numbers '((:value 981/100))))
                     (f :positive ,@(and numbers '((:value 10)))))
         (gravity g)
         (body floor :fixed t :shape (half-plane (1 0) (0 0)))
         (body wall :fixed t :shape (half-plane ((+ ,@widths) 1) ((+ ,@widths) 0)))
         ,@(loop for k from 1 to n
                 for width in widths for mass in masses for left in lefts
                 collect `(body ,(sym "b~D" k) :mass ,mass :position (,left 0) :velocity (0 0)
                                :shape (polygon (0 0) (,width 0) (,width 1) (0 1))))
         (force push :on ,(sym "b~D" 1) :value (f 0))
         (simulate :states 2)))))

(defun write-chain (n directory &key numbers)
  "Write CHAIN-FORM of N to a file in DIRECTORY; return its namestring."
  (let ((path (merge-pathnames (format nil "chain-~D~:[~;-numbers~].lisp" n numbers) directory)))
    (with-open-file (out path :direction :output :if-exists :supersede)
      (with-standard-io-syntax
        (let ((*print-case* :downcase) (*package* (find-package '#:ames.bench.issue-24)))
          (print (chain-form n :numbers numbers) out))))
    (namestring path)))

(defun growth (times from to)
  "log(t(TO)/t(FROM)) / log(TO/FROM) from TIMES ((N . SECONDS) ...), or NIL."
  (let ((a (cdr (assoc from times))) (b (cdr (assoc to times))))
    (and a b (/ (log (/ b (max a 1d-3))) (log (/ to from))))))

(defun bench-chain (sizes directory baseline &key numbers)
  "Time the chain at SIZES; print a row each and the growth exponents."
  (let ((times '()))
    (dolist (n sizes)
      (multiple-value-bind (seconds code)
          (timed-run (ames "run" (write-chain n directory :numbers numbers) "--format" "sexp"
                           ))
        (row (format nil "chain of ~D, ~:[every mass and width symbolic~;with numbers~]" n numbers)
             seconds code baseline)
        (push (cons n seconds) times)
        (when (> seconds *give-up-seconds*)
          (format t "  (larger N not run: over ~D s)~%" *give-up-seconds*)
          (return))))
    (setf times (reverse times))
    (loop for (a b) on (mapcar #'car times) while b
          do (format t "  growth from ~D to ~D: N^~,2F~%" a b (growth times a b)))
    times))

(defvar cl-user::*issue-24-chains-only* nil
  "True when bench/chain-rows.lisp loads this file for its functions: the table is not run.")

(unless cl-user::*issue-24-chains-only*
(let* ((baseline (timed-run '("maxima" "--very-quiet" "--batch-string" "quit();") :runs 3))
       (directory (uiop:ensure-directory-pathname
                   (merge-pathnames (format nil "ames-bench-24-~36R" (random (expt 36 6) (make-random-state t)))
                                    (uiop:temporary-directory)))))
  (ensure-directories-exist directory)
  (format t "~&Issue 24's table (wall times of whole bin/ames runs):~%")
  (row "a bare Maxima start (the baseline)" baseline 0)
  (timed-run (ames "help"))              ; the image built first
  (multiple-value-bind (s c) (timed-run (ames "run" (scenario-path "particle-on-wedge")) :runs 3)
    (row "the wedge, cold" s c baseline "at most 3 x Maxima's start"))
  (multiple-value-bind (s c) (timed-run (ames "run" (scenario-path "two-blocks-in-corner") "--numeric"))
    (row "the corner, --numeric" s c baseline "under 3 s"))
  (multiple-value-bind (s c) (timed-run (ames "run" (scenario-path "two-blocks-in-corner") "--numeric"
                                              "--set" "f=5"))
    (row "the corner, --numeric --set f=5 (B falls)" s c baseline "under 3 s"))
  (multiple-value-bind (s c) (timed-run (ames "run" (scenario-path "two-blocks-in-corner") "--numeric"
                                              "--set" "l1=3" "f=12"))
    (row "the corner, --numeric --set l1=3 f=12" s c baseline "under 3 s"))
  (multiple-value-bind (s c) (timed-run (ames "run" (scenario-path "block-launched-up-rough-incline")
                                              "--numeric"))
    (row "the block launched up a rough incline, --numeric" s c baseline "under 3 s"))
  (multiple-value-bind (s c) (timed-run (ames "run" (scenario-path "two-blocks-in-corner")))
    (row "the corner without values (every branch)" s c baseline "under 10 s"))
  (bench-chain '(8 16 24 32 64) directory baseline)
  (format t "  goal: N = 32 under 10 s, growth at most N^1.5, N = 64 under a minute~%")
  (bench-chain '(32 64 128) directory baseline :numbers t)
  (format t "  goal: N = 128 under 10 s~%")
  (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore)))
