;;;; t/reliability-bridge.lisp -- the bridge within a budget: bounded replies, timeouts from the limits, a reset between runs.
;;;;
;;;; The floods come from a fake `maxima`, a shell script written for the test, that
;;;; prints without end (outside any frame, or inside the frame of its greeting).

(in-package #:ames.tests)

(in-suite reliability)

(defun write-fake-maxima (script)
  "Write the shell SCRIPT to a fresh executable temporary file; return its name."
  (let ((path (uiop:tmpize-pathname (merge-pathnames "ames-fake-maxima" (uiop:temporary-directory)))))
    (with-open-file (out path :direction :output :if-exists :supersede)
      (format out "#!/bin/sh~%~A~%" script))
    (uiop:run-program (list "chmod" "+x" (namestring path)))
    (namestring path)))

(defun call-with-fake-maxima (script function)
  "Call FUNCTION with a bridge (timeout 1 s) whose `maxima` is the shell SCRIPT."
  (let ((program (write-fake-maxima script)))
    (unwind-protect (call-with-bridge function :program program :timeout 1)
      (delete-file program))))

(test a-flood-outside-the-frames-is-dropped-and-ends-in-a-condition
  (call-with-fake-maxima
   "exec yes 'Maxima prints this again and again, outside any frame'"
   (lambda (b)
     (let ((condition (within-seconds (8)
                        (handler-case (ames.algebra:decide b '(> 2 1))
                          (ames-error (c) c)))))
       (is (typep condition 'ames.maxima:maxima-condition) "~S" condition)
       (is (<= (length (ames.maxima::bridge-buffer b)) ames.maxima:*reply-limit*))))))

(test a-flood-inside-a-frame-is-an-overflow
  (let ((ames.maxima:*reply-limit* 200000))
    (call-with-fake-maxima
     "read -r line; read -r line
nonce=$(echo \"$line\" | sed 's/.*HELLO \\([0-9]*\\).*/\\1/')
printf '@AMES%s@BEGIN\\n' \"$nonce\"
exec yes 'x'"
     (lambda (b)
       (let ((condition (within-seconds (8)
                          (handler-case (ames.algebra:decide b '(> 2 1))
                            (ames-error (c) c)))))
         (is (typep condition 'ames.maxima:maxima-output-overflow) "~S" condition)
         (is (search "200,000" (princ-to-string condition)))
         (is (not (ames.maxima:bridge-alive-p b))))))))

(test a-long-reply-of-maxima-itself-is-an-overflow-and-the-next-request-works
  (call-with-bridge
   (lambda (b)
     (is (eq :true (ames.algebra:decide b '(> 2 1))))
     (let ((ames.maxima:*reply-limit* 20000))
       (signals ames.maxima:maxima-output-overflow
         (ames.maxima:simplify b '(expt (+ x y 1) 100)))
       (is (equal '(* 2 x) (ames.maxima:simplify b '(+ x x))))))))

(test a-request-gets-no-more-than-the-time-left
  (call-with-bridge
   (lambda (b)
     (is (eq :true (ames.algebra:decide b '(> 2 1))))
     (let ((condition (within-seconds (6)
                        (handler-case
                            (with-budget (:limits (make-limits :time-limit 1) :subject 'slow)
                              (ames.maxima:simplify b '(expt (+ a b c d e 1) 60)))
                          (ames-error (c) c)))))
       (is (typep condition 'ames.maxima:maxima-budget-exceeded) "~S" condition)
       (is (typep condition 'budget-exceeded))
       (is (eq 'slow (budget-exceeded-subject condition)))
       (is (search "time limit" (princ-to-string condition))))
     ;; out of time before asking: no request is sent
     (let ((calls (maxima-calls b)))
       (signals budget-exceeded
         (with-budget (:limits (make-limits :time-limit 1/10))
           (sleep 0.2)
           (ames.algebra:decide b '(> 3 1))))
       (is (= calls (maxima-calls b))))
     (is (eq :true (ames.algebra:decide b '(> 4 1)))))
   :timeout 20))

(test the-maxima-timeout-comes-from-the-limits
  (call-with-bridge
   (lambda (b)
     (let* ((*limits* (make-limits :maxima-timeout 1/2))
            (condition (within-seconds (5)
                         (handler-case (ames.maxima:simplify b '(expt (+ a b c d e 1) 60))
                           (ames-error (c) c)))))
       (is (typep condition 'ames.maxima:maxima-timeout) "~S" condition)
       (is (= 1/2 (ames.maxima:maxima-timeout-seconds condition))))
     (is (eq :true (ames.algebra:decide b '(> 2 1)))))
   :timeout 20))

(test a-reset-bridge-answers-as-a-new-one
  (flet ((answer (b) (ames.maxima:simplify b '(+ (* q p) (* p r) (expt r 2)))))
    (let ((fresh (call-with-bridge #'answer)))
      (call-with-bridge
       (lambda (b)
         ;; other names first, so that P, Q and R get other Maxima names
         (ames.maxima:simplify b '(+ zz yy xx r q))
         (ames.maxima:reset-bridge b)
         (is (zerop (hash-table-count (ames.maxima::bridge-cache b))))
         (is (equal fresh (answer b)))
         ;; inside an assumption scope only a restart may reset, ending the process
         (ames.maxima:with-assumptions (b '((> p 0)))
           (ames.algebra:decide b '(> p 0))
           (is (ames.maxima:bridge-in-scope-p b))
           (signals ames.maxima:invalid-bridge-argument (ames.maxima:reset-bridge b))
           (ames.maxima:reset-bridge b :restart t)
           (is (not (ames.maxima:bridge-in-scope-p b)))
           (is (not (ames.maxima:bridge-alive-p b))))
         (is (null (ames.maxima:current-assumptions b)))
         (is (eq :unknown (ames.algebra:decide b '(> p 0)))))))))
