;;;; bench/bench-bridge.lisp -- the Maxima bridge's speed: round trips, small calls, the wedge solve, against a bare `maxima -b` script.
;;;;
;;;; Loaded by bench/run.lisp after AMES is loaded. Prints numbers; asserts nothing.
;;;; The same work is done twice: through a fresh bridge (process start included), and as
;;;; one bare `maxima --very-quiet -b` script (process start included); the ratio of the
;;;; two is the bridge's overhead (target: at most 1.3).

(defpackage #:ames.bench.bridge
  (:use #:cl)
  (:import-from #:ames.maxima #:make-bridge #:close-bridge #:simplify #:decide
                #:solve-equations #:clear-bridge-cache #:bridge-statistics))

(in-package #:ames.bench.bridge)

(defparameter *latency-calls* 1000)
(defparameter *small-calls* 1000)
(defparameter *wedge-solves* 50)

(defparameter *wedge-equations*
  '((= (* mw awx) (- (* n (sin a))))
    (= (* mp apx) (* n (sin a)))
    (= (* mp apy) (- (* n (cos a)) (* mp g)))
    (= apx (+ awx (* arel (cos a))))
    (= apy (- (* arel (sin a))))))

(defparameter *wedge-script*
  "solve([mw*awx = -n*sin(a), mp*apx = n*sin(a), mp*apy = n*cos(a) - mp*g,
          apx = awx + arel*cos(a), apy = -arel*sin(a)], [n, apx, apy, awx, arel])")

(defun seconds-since (start)
  (/ (- (get-internal-real-time) start) (float internal-time-units-per-second 1d0)))

(defun timing (thunk)
  "The wall seconds calling THUNK takes."
  (let ((start (get-internal-real-time))) (funcall thunk) (seconds-since start)))

(defun run-bare-script (text)
  "Wall seconds of `maxima --very-quiet -b` on a script holding TEXT."
  (uiop:with-temporary-file (:pathname path :stream stream :type "mac" :direction :output)
    (write-string text stream)
    (finish-output stream)
    (close stream)
    (timing (lambda () (sb-ext:run-program "maxima" (list "--very-quiet" "-b" (namestring path))
                                :search t :wait t :input nil :output nil :error nil)))))

(defun statements (count format-control)
  "COUNT Maxima statements, each FORMAT-CONTROL applied to its index (from 1), each
ending in ; so that its result is shown, as the bridge returns every result."
  (with-output-to-string (out)
    (format out "display2d: false$~%")
    (loop for i from 1 to count do (format out format-control i) (terpri out))))

(defun latency-script () (statements *latency-calls* "is(~D > 2);"))
(defun small-calls-script () (statements *small-calls* "ratsimp(x + ~D);"))
(defun wedge-script () (statements *wedge-solves* (concatenate 'string *wedge-script* ";~*")))

(defun silent-loop-script ()
  (format nil "for i thru ~D do ratsimp(x + i)$~%" *small-calls*))

(defun bridge-latency (bridge)
  (dotimes (i *latency-calls*)
    (decide bridge `(> ,(+ 3 i) 2))))

(defun bridge-small-calls (bridge)
  (dotimes (i *small-calls*)
    (simplify bridge `(+ x ,(1+ i)))))

(defun bridge-wedge-solves (bridge)
  (dotimes (i *wedge-solves*)
    (clear-bridge-cache bridge)
    (solve-equations bridge *wedge-equations* '(n apx apy awx arel))))

(defun report (label bridge-seconds bare-seconds)
  (format t "~&~A~%    bridge ~7,3F s   bare maxima -b ~7,3F s   ratio ~5,2F~%"
          label bridge-seconds bare-seconds (/ bridge-seconds bare-seconds)))

(defun main ()
  (let ((startup-bare (run-bare-script ""))
        (bridge (make-bridge)))
    (unwind-protect
         (let* ((startup-bridge (timing (lambda () (decide bridge '(> 2 1)))))
                (latency (timing (lambda () (bridge-latency bridge))))
                (small (timing (lambda () (bridge-small-calls bridge))))
                (wedge (timing (lambda () (bridge-wedge-solves bridge))))
                (cached (let ((n 10000))
                          (/ (timing (lambda ()
                                       (dotimes (i n)
                                         (solve-equations bridge *wedge-equations*
                                                          '(n apx apy awx arel)))))
                             n)))
                (bare-latency (- (run-bare-script (latency-script)) startup-bare))
                (bare-small (- (run-bare-script (small-calls-script)) startup-bare))
                (bare-wedge (- (run-bare-script (wedge-script)) startup-bare))
                (bare-silent (- (run-bare-script (silent-loop-script)) startup-bare))
                (bare-all (run-bare-script (concatenate 'string (latency-script) (small-calls-script)
                                                        (wedge-script)))))
           (format t "~&Process start: bridge ~,1F ms (first call included), bare maxima -b ~,1F ms~%"
                   (* 1000 startup-bridge) (* 1000 startup-bare))
           (format t "Cached answer (the wedge solve again): ~,4F ms per call~%" (* 1000 cached))
           (format t "Bare script: one statement per call, each result shown (display2d:false);~%~
                      start-up (an empty script) subtracted except in the last line.~%")
           (report (format nil "Round trip: ~D calls is(k > 2) (decide), ~,3F ms per call:"
                           *latency-calls* (/ (* 1000 latency) *latency-calls*))
                   latency bare-latency)
           (report (format nil "~D small calls ratsimp(x + i) (simplify):" *small-calls*)
                   small bare-small)
           (format t "    (the same as one silent loop in Maxima: ~,3F s)~%" bare-silent)
           (report (format nil "~D wedge solves (cache cleared each time), ~,2F ms per solve:"
                           *wedge-solves* (/ (* 1000 wedge) *wedge-solves*))
                   wedge bare-wedge)
           (report "All of it, process start-up included (the headline ratio):"
                   (+ startup-bridge latency small wedge) bare-all)
           (format t "Bridge counters: ~S~%" (bridge-statistics bridge)))
      (close-bridge bridge))))

(main)
