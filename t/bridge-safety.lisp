;;;; t/bridge-safety.lisp -- tests that the bridge never hangs, survives its process, and lets nothing run.
;;;;
;;;; Questions become conditions; a runaway call times out and leaves the process usable;
;;;; a killed process is replaced (with its assumptions replayed); and no name or
;;;; expression can smuggle a Maxima command, a :lisp escape or a string to Maxima. The
;;;; injection tests use a canary file that any executed command would create.

(in-package #:ames.tests)

(in-suite bridge)

(defun maxima-calls (bridge)
  (getf (ames.maxima:bridge-statistics bridge) :maxima-calls))

(defun kill-process (pid)
  "Send SIGKILL to PID."
  (sb-ext:run-program "/bin/kill" (list "-9" (princ-to-string pid)) :search nil :wait t))

;;; Questions, timeouts, dead processes

(test a-question-becomes-a-condition
  (call-with-bridge
   (lambda (b)
     (let ((condition (handler-case
                          (ames.maxima:solve-autonomous-ode b '(- (* k s)) 's :initial-position 's0
                                                                              :initial-velocity 'v0)
                        (ames.maxima:maxima-question (c) c))))
       (is (typep condition 'ames.maxima:maxima-question))
       (is (typep condition 'ames-error))
       (is (search "positive, negative or zero" (ames.maxima:maxima-question-text condition)))
       (is (equal '(k) (ames.maxima:maxima-question-expressions condition))))
     ;; the process did not hang and answers the next call
     (is (eq :true (ames.algebra:decide b '(> 2 1))))
     ;; the restart retries under the facts the caller chose
     (let ((solution (handler-bind ((ames.maxima:maxima-question
                                      (lambda (c) (declare (ignore c))
                                        (invoke-restart 'ames.maxima:assume-and-retry '((> k 0))))))
                       (ames.maxima:solve-autonomous-ode b '(- (* k s)) 's :initial-position 's0
                                                                           :initial-velocity 'v0))))
       (is (eq :closed-form (ames.maxima:ode-solution-kind solution))))
     (is (null (ames.maxima:current-assumptions b))))))

(test a-runaway-call-times-out-and-the-next-call-works
  (call-with-bridge
   (lambda (b)
     ;; a first request starts the process (2 > 1 would be settled without Maxima)
     (is (equal '(* 2 y) (ames.maxima:simplify b '(+ y y))))
     (let ((pid (ames.maxima:bridge-process-id b))
           (start (get-internal-real-time)))
       (signals ames.maxima:maxima-timeout
         (ames.maxima:simplify b '(expt (+ a b c d e 1) 60)))
       (is (< (/ (- (get-internal-real-time) start) internal-time-units-per-second) 3))
       (is (equal '(* 2 x) (ames.maxima:simplify b '(+ x x))))
       ;; the interrupt took: the same process answered
       (is (eql pid (ames.maxima:bridge-process-id b)))
       (is (= 1 (getf (ames.maxima:bridge-statistics b) :timeouts)))))
   :timeout 0.5))

(test a-killed-process-is-replaced-and-its-assumptions-replayed
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> x 0) (> a 0) (< a (/ pi 2))))
       (is (eq :true (ames.algebra:decide b '(> x 0))))
       (let ((pid (ames.maxima:bridge-process-id b)))
         (kill-process pid)
         (sleep 0.05)
         (is (eq :true (ames.algebra:decide b '(> (* x (cos a)) 0))))
         (is (not (eql pid (ames.maxima:bridge-process-id b)))))
       ;; killed again, without waiting for the kill to be noticed
       (kill-process (ames.maxima:bridge-process-id b))
       (is (eq :true (ames.algebra:decide b '(> (* x (sin a)) 0)))))
     (is (eq :unknown (ames.algebra:decide b '(> x 0))))
     (is (<= 3 (getf (ames.maxima:bridge-statistics b) :restarts))))))

(test a-closed-bridge-starts-again
  (call-with-bridge
   (lambda (b)
     (is (not (ames.maxima:bridge-alive-p b)))
     (is (eq :true (ames.algebra:decide b '(> 2 1))))
     (is (ames.maxima:bridge-alive-p b))
     (ames.maxima:close-bridge b)
     (is (not (ames.maxima:bridge-alive-p b)))
     (is (eq :false (ames.algebra:decide b '(> 1 2)))))))

(test a-missing-maxima-is-a-condition
  (call-with-bridge
   (lambda (b)
     (signals ames.maxima:maxima-process-died (ames.algebra:decide b '(> 2 1))))
   :program "no-such-maxima-program"))

(test a-bridge-started-ahead-answers-in-that-process
  ;; PRESTART-BRIDGE starts Maxima without waiting; the first request greets it (no
  ;; second process) and is answered; prestarting a live bridge changes nothing
  (call-with-bridge
   (lambda (b)
     (ames.maxima:prestart-bridge b)
     (is (ames.maxima:bridge-alive-p b))
     (let ((pid (ames.maxima:bridge-process-id b)))
       (ames.maxima:with-assumptions (b '((> x 1)))
         (is (eq :true (ames.algebra:decide b '(> (* x x) x)))))
       (ames.maxima:prestart-bridge b)
       (is (eql pid (ames.maxima:bridge-process-id b)))
       (is (= 1 (getf (ames.maxima:bridge-statistics b) :restarts)))
       (is (ames.maxima:equivalent-p b (ames.maxima:simplify b '(- (expt (+ y 1) 2) 1))
                                     '(+ (expt y 2) (* 2 y)))))))
  ;; a process started ahead that dies before its greeting is replaced by the first request
  (call-with-bridge
   (lambda (b)
     (ames.maxima:prestart-bridge b)
     (kill-process (ames.maxima:bridge-process-id b))
     (is (eq :false (ames.algebra:decide b '(> 1 2)))))))

(test a-missing-maxima-started-ahead-is-a-condition-at-the-first-request
  (call-with-bridge
   (lambda (b)
     (finishes (ames.maxima:prestart-bridge b))
     (is (not (ames.maxima:bridge-alive-p b)))
     (signals ames.maxima:maxima-process-died (ames.algebra:decide b '(> 2 1))))
   :program "no-such-maxima-program"))

(test stack-overflows-in-maxima-leave-the-bridge-usable
  ;; GCL's bind stack overflows at a depth of a few hundred; the second overflow in one
  ;; process may end it. Either way the call fails with a condition and the next works.
  (call-with-bridge
   (lambda (b)
     (let ((deep 'x))
       (dotimes (i 300) (setf deep (list 'sin deep)))
       (dotimes (i 3)
         (signals ames.maxima:maxima-condition (ames.maxima:simplify b deep :strategy :trigsimp))
         (is (eq :true (ames.algebra:decide b `(> ,(+ 2 i) 1)))))))))

(test a-maxima-error-carries-maxima-s-message
  (call-with-bridge
   (lambda (b)
     (let ((condition (handler-case (ames.maxima:simplify b '(/ 1 0))
                        (ames.maxima:maxima-error (c) c))))
       (is (typep condition 'ames-error))
       (is (search "expt: undefined: 0 to a negative exponent"
                   (ames.maxima:maxima-error-message condition))))
     (is (eq :true (ames.algebra:decide b '(> 2 1)))))))

;;; Injection

(defparameter *canary* "/tmp/ames-bridge-canary"
  "A file that any command smuggled through the bridge would create.")

(defun canary-commands ()
  "Strings that would create the canary if Maxima (or its Lisp) ran them."
  (list (format nil "system(\"touch ~A\")" *canary*)
        (format nil ":lisp (with-open-file (s \"~A\" :direction :output))" *canary*)
        (format nil "?system(\"touch ~A\")" *canary*)
        (format nil "load(\"~A\")" *canary*)
        (format nil "1; system(\"touch ~A\")$" *canary*)
        (format nil "x$ :lisp (si::system \"touch ~A\")" *canary*)
        (format nil "#.(si::system \"touch ~A\")" *canary*)))

(test injected-names-are-mangled-harmlessly
  (when (probe-file *canary*) (delete-file *canary*))
  (call-with-bridge
   (lambda (b)
     (dolist (command (canary-commands))
       (let* ((name (make-symbol command))
              (solution (ames.maxima:solve-equations b `((= (* 2 ,name) 6)) (list name))))
         (is (equal (list (list (cons name 3))) solution))
         (is (eq name (ames.maxima:simplify b `(+ ,name 0))))
         ;; quantity terms carry names too
         (let ((term (list name (make-symbol command) :x)))
           (is (equal term (ames.maxima:simplify b `(* 1 ,term)))))))))
  (is (not (probe-file *canary*))))

(test injected-expressions-fail-before-reaching-maxima
  (when (probe-file *canary*) (delete-file *canary*))
  (call-with-bridge
   (lambda (b)
     (ames.algebra:decide b '(> 2 1))
     (let ((calls (maxima-calls b)))
       (dolist (command (canary-commands))
         (dolist (bad (list command                     ; a string
                            `(+ 1 ,command)
                            `(system ,command)          ; an operator that is not one
                            `(load ,command)
                            `(foo (bar ,command))
                            `(= x ,command)
                            `(sin ,command)))
           (signals ames.maxima:untranslatable-expression (ames.maxima:simplify b bad))
           (signals ames.maxima:untranslatable-expression (ames.algebra:decide b `(> ,bad 0)))
           (signals ames.maxima:untranslatable-expression
             (ames.maxima:solve-equations b (list `(= x ,bad)) '(x)))))
       (dolist (bad '((lambda (x) x) #(1 2) #\a :lisp (quote x) #c(1 2)))
         (signals ames.maxima:untranslatable-expression (ames.maxima:simplify b bad)))
       (signals ames.maxima:untranslatable-expression
         (ames.maxima:with-assumptions (b (list (first (canary-commands)))) nil))
       ;; nothing was sent
       (is (= calls (maxima-calls b))))))
  (is (not (probe-file *canary*))))

(test the-server-refuses-what-the-bridge-would-never-send
  (when (probe-file *canary*) (delete-file *canary*))
  (call-with-bridge
   (lambda (b)
     ;; A second wall: requests forged below the translation are refused by the server.
     (flet ((forged (form)
              (handler-case (progn (ames.maxima::maxima-request b form :cache nil) :accepted)
                (ames.maxima:maxima-error (c) (ames.maxima:maxima-error-message c)))))
       (is (search "not allowed"
                   (forged (ames.maxima::mform (ames.maxima::wire "$SYSTEM") 1))))
       (is (search "not allowed"
                   (forged (ames.maxima::mform (ames.maxima::wire "$LOAD") (ames.maxima::wire "$X")))))
       (is (search "not allowed" (forged (ames.maxima::wire "$X"))))
       (is (search "alphabet"
                   (forged (ames.maxima::mform ames.maxima::+mplus+
                                               (format nil "touch ~A" *canary*) 1))))
       (is (search "alphabet" (forged (list (format nil "#.(si::system \"touch ~A\")" *canary*)))))
       (is (search "not allowed" (forged (ames.maxima::mform (ames.maxima::wire "$AMESVA") 1))))
       (is (search "alphabet" (forged (ames.maxima::mform ames.maxima::+mplus+ 1/2 1)))))
     (is (eq :true (ames.algebra:decide b '(> 2 1))))))
  (is (not (probe-file *canary*))))

(test names-that-are-maxima-names-are-just-names
  (call-with-bridge
   (lambda (b)
     (let ((maxima-pi (make-symbol "%pi"))
           (maxima-e (make-symbol "%e"))
           (maxima-t (make-symbol "t"))
           (maxima-system (make-symbol "system"))
           (maxima-gamma (make-symbol "gamma")))
       ;; %pi is a variable here, not the constant
       (is (eq :unknown (ames.algebra:decide b `(> ,maxima-pi 3))))
       (is (eq :true (ames.algebra:decide b '(> pi 3))))
       (is (equal `(((,maxima-pi . 2))) (ames.maxima:solve-equations b `((= ,maxima-pi 2)) (list maxima-pi))))
       (is (equal `(((,maxima-t . 2)))
                  (ames.maxima:solve-equations b `((= (* 2 ,maxima-t) 4)) (list maxima-t))))
       (is (not (ames.maxima:equivalent-p b `(log ,maxima-e) 1)))
       (is (ames.maxima:equivalent-p b '(log (exp 1)) 1))
       (is (eq :unknown (ames.algebra:decide b `(> (+ ,maxima-system ,maxima-gamma) 0))))
       (let ((sum (ames.maxima:simplify b `(+ ,maxima-system ,maxima-gamma))))
         (is (eq '+ (first sum)))
         (is (null (set-exclusive-or (rest sum) (list maxima-system maxima-gamma)))))))))
