;;;; bench/bench-scale.lisp -- the scale families (issue 16): time, time per state and growth.
;;;;
;;;; For each family of bench/scale-families.lisp (chain, stack at rest, stack under a pull,
;;;; independent drops, blocks falling off a pulled plank) at N = 1, 2, 4, 8, 16, 32 (and
;;;; the stack at 64): the wall time of AMES:SIMULATE on a fresh Maxima bridge (its start
;;;; included), the states, the time per state, and the growth exponent fitted by least
;;;; squares to log time against log N (from N = 4 on), with the exponent from 8 to 32.
;;;; A family stops growing once a run takes longer than *GIVE-UP-SECONDS*.
;;;; Then the targets: the chain of 32 under 10 s growing at most as N^1.5 from 8 to 32,
;;;; the stack of 64 under 10 s; the chain of 8 against SymPy doing the same derivation by
;;;; hand (when python3 has sympy: Debian's python3-sympy); and bin/ames run --jobs 2
;;;; against --jobs 1 on six scenario files (target: at least 1.7 times faster).
;;;; Prints numbers; asserts nothing.

(load (merge-pathnames "scale-families.lisp" *load-truename*))

(defpackage #:ames.bench.scale
  (:use #:cl #:ames.bench.scale-families)
  (:documentation "The scale benchmark."))

(in-package #:ames.bench.scale)

(defparameter *sizes* '(1 2 4 8 16 32)
  "The numbers of blocks each family is run with.")

(defparameter *give-up-seconds* 60
  "A family is not run at larger sizes once one run takes longer than this.")

(defparameter *checkout* (merge-pathnames "../" (make-pathname :name nil :type nil
                                                                :defaults *load-truename*))
  "The checkout's root.")

(defun seconds-since (start)
  "Seconds of real time since the internal time START."
  (/ (- (get-internal-real-time) start) (float internal-time-units-per-second 1d0)))

(defun run-family (family n)
  "Simulate FAMILY with N blocks on a fresh bridge: (values SECONDS STATES OUTCOME)."
  (let ((bridge (ames.maxima:make-bridge))
        (start (get-internal-real-time)))
    (unwind-protect
         (let ((outcome (handler-case
                            (handler-bind ((ames:ambiguous-transition #'ames:stop-simulation))
                              (ames:simulate (family-scenario family n) :bridge bridge))
                          (ames:ames-error (condition) condition))))
           (values (seconds-since start)
                   (if (typep outcome 'ames:simulation-history)
                       (length (ames:history-states outcome))
                       0)
                   (if (typep outcome 'ames:simulation-history)
                       (string-downcase (ames:history-outcome outcome))
                       (string-downcase (type-of outcome)))))
      (ames.maxima:close-bridge bridge))))

(defun fitted-exponent (points)
  "The slope of the least-squares line through (log N, log SECONDS) of POINTS ((N .
SECONDS) ...), or NIL with fewer than two."
  (when (>= (length points) 2)
    (let* ((xs (mapcar (lambda (p) (log (float (car p) 1d0))) points))
           (ys (mapcar (lambda (p) (log (max 1d-3 (cdr p)))) points))
           (k (length points))
           (mx (/ (reduce #'+ xs) k)) (my (/ (reduce #'+ ys) k))
           (sxx (reduce #'+ (mapcar (lambda (x) (expt (- x mx) 2)) xs)))
           (sxy (reduce #'+ (mapcar (lambda (x y) (* (- x mx) (- y my))) xs ys))))
      (and (plusp sxx) (/ sxy sxx)))))

(defun exponent-between (times from to)
  "log(t(TO)/t(FROM)) / log(TO/FROM) from TIMES ((N . SECONDS) ...), or NIL."
  (let ((a (cdr (assoc from times))) (b (cdr (assoc to times))))
    (and a b (/ (log (/ b (max a 1d-3))) (log (/ to from))))))

(defun bench-family (family sizes)
  "Run FAMILY at SIZES, print a line per size and the growth; return ((N . SECONDS) ...)."
  (format t "~&~(~A~):~%" family)
  (let ((times '()))
    (dolist (n sizes)
      (multiple-value-bind (seconds states outcome) (run-family family n)
        (format t "  N = ~2D: ~7,3F s, ~3D state~:P, ~6,3F s per state  (~A)~%"
                n seconds states (if (plusp states) (/ seconds states) 0) outcome)
        (finish-output)
        (push (cons n seconds) times)
        (when (> seconds *give-up-seconds*)
          (format t "  (larger N not run: over ~D s)~%" *give-up-seconds*)
          (return))))
    (setf times (reverse times))
    (let ((fit (fitted-exponent (remove-if (lambda (p) (< (car p) 4)) times)))
          (from-8 (exponent-between times 8 32)))
      (format t "  growth: fitted exponent ~:[n/a~;~:*~,2F~] (N >= 4), ~:[n/a~;~:*~,2F~] from 8 to 32~%"
              fit from-8))
    times))

(defun best-process-seconds (program arguments &key (runs 3))
  "The least wall time of RUNS runs of PROGRAM with ARGUMENTS (output discarded), and
the last exit code."
  (let ((best nil) (code nil))
    (dotimes (i runs)
      (let ((start (get-internal-real-time)))
        (setf code (nth-value 2 (uiop:run-program (cons program arguments)
                                                  :output nil :error-output nil
                                                  :ignore-error-status t)))
        (let ((seconds (seconds-since start)))
          (setf best (if best (min best seconds) seconds)))))
    (values best code)))

(defun ames-program ()
  "bin/ames of this checkout (its image built first, by a throw-away run)."
  (let ((program (namestring (merge-pathnames "bin/ames" *checkout*))))
    (uiop:run-program (list program "help") :output nil :ignore-error-status t)
    program))

(defun sympy-available-p ()
  "True when python3 can import sympy."
  (zerop (nth-value 2 (uiop:run-program '("sh" "-c" "python3 -c 'import sympy'")
                                        :output nil :error-output nil :ignore-error-status t))))

(defun bench-sympy (directory)
  "The chain of 8 by bin/ames against SymPy deriving the same by hand."
  (if (not (sympy-available-p))
      (format t "~&sympy: python3 cannot import sympy (apt-get install python3-sympy); skipped~%")
      (let* ((file (namestring (write-family-file :chain 8 directory)))
             (script (namestring (merge-pathnames "sympy-chain.py" (merge-pathnames "bench/" *checkout*))))
             (ames (best-process-seconds (ames-program) (list "run" file "--format" "sexp")))
             (sympy (best-process-seconds "python3" (list script "8"))))
        (format t "~&chain of 8, whole processes (best of 3): bin/ames ~,3F s, SymPy by hand ~,3F s; ratio ~,2F (target <= 1)~%"
                ames sympy (/ ames sympy)))))

(defun bench-jobs (directory)
  "bin/ames run --jobs 1 and --jobs 2 on six scenario files."
  (let* ((files (loop for (family n) in '((:chain 16) (:stack 16) (:pull 8)
                                          (:drops 8) (:plank 4) (:chain 8))
                      collect (namestring (write-family-file family n directory))))
         (program (ames-program)))
    (multiple-value-bind (one code-one) (best-process-seconds program (list* "run" "--jobs" "1" files))
      (multiple-value-bind (two code-two) (best-process-seconds program (list* "run" "--jobs" "2" files))
        (format t "~&--jobs on six files (~{~A~^ ~}):~%  --jobs 1 ~,3F s (exit ~D), --jobs 2 ~,3F s (exit ~D): ~,2Fx faster (target >= 1.7 on 2 cores; this machine has ~:[?~;~:*~D~])~%"
                (mapcar #'pathname-name files) one code-one two code-two (/ one two)
                (parse-integer (uiop:run-program '("nproc") :output :string) :junk-allowed t))))))

(let ((directory (merge-pathnames (format nil "ames-scale-~36R/" (random (expt 36 8) (make-random-state t)))
                                  (uiop:temporary-directory)))
      (results '()))
  (dolist (family +families+)
    (push (cons family (bench-family family *sizes*)) results))
  (let ((stack-64 (multiple-value-list (run-family :stack 64))))
    (format t "~&stack of 64: ~,3F s, ~D state~:P (~A)~%" (first stack-64) (second stack-64) (third stack-64))
    (let ((chain (cdr (assoc :chain results))))
      (format t "~&targets: chain of 32 ~:[not run~;~:*~,3F s~] (target < 10 s); growth from 8 to 32 N^~:[n/a~;~:*~,2F~] (target <= 1.5); stack of 64 ~,3F s (target < 10 s)~%"
              (cdr (assoc 32 chain)) (exponent-between chain 8 32) (first stack-64))))
  (bench-sympy directory)
  (bench-jobs directory)
  (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore))
