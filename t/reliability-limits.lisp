;;;; t/reliability-limits.lisp -- the budget of a run, the bounds of Lisp-side work, reports cut short with their context.
;;;;
;;;; The hostile inputs of issue 15: an exact (expt 10 (expt 10 9)), a product of 26
;;;; constant sums, loops that would run for hours. Each must end in a BUDGET-EXCEEDED (an
;;;; AMES-ERROR naming the quantity) within a second or so, never in a hang.

(in-package #:ames.tests)

(def-suite reliability :in all-tests
  :description "Issue 15: budgets and bounds, reader recovery, error locations,
determinism, crash safety and the whole-path fuzz.")

(in-suite reliability)

(defun seconds-since (start)
  "Wall seconds since the internal real time START."
  (/ (- (get-internal-real-time) start) internal-time-units-per-second))

(defmacro within-seconds ((seconds) &body body)
  "Run BODY; check that it took less than SECONDS of wall time. Returns BODY's values."
  (let ((start (gensym "START")) (values (gensym "VALUES")))
    `(let* ((,start (get-internal-real-time))
            (,values (multiple-value-list (progn ,@body))))
       (is (< (seconds-since ,start) ,seconds) "took ~,2F s, more than ~A"
           (seconds-since ,start) ,seconds)
       (values-list ,values))))

(defun budget-condition (thunk)
  "The BUDGET-EXCEEDED that calling THUNK signals, or NIL."
  (handler-case (progn (funcall thunk) nil)
    (budget-exceeded (condition) condition)))

(test limits-are-checked-when-made
  (dolist (bad '((:time-limit 0) (:time-limit -1) (:time-limit "10") (:maxima-timeout 0)
                 (:integer-bits 1.5) (:integer-bits nil) (:expression-size 0)))
    (signals invalid-limit (apply #'make-limits bad)))
  (is (null (limits-time-limit (make-limits :time-limit nil))))
  (is (= 64 (limits-integer-bits (make-limits :integer-bits 3))))
  (let ((limits (change-limits (make-limits) :time-limit 7)))
    (is (= 7 (limits-time-limit limits)))
    (is (= (limits-integer-bits (make-limits)) (limits-integer-bits limits))))
  (signals invalid-limit (call-with-budget (lambda () nil) :limits 42)))

(test the-deadline-stops-a-loop-that-checks-the-budget
  (let ((condition (within-seconds (3)
                     (budget-condition
                      (lambda ()
                        (with-budget (:limits (make-limits :time-limit 1/2) :subject 'spin)
                          (loop (check-budget))))))))
    (is (typep condition 'ames-error))
    (is (eq :time (budget-exceeded-quantity condition)))
    (is (eq 'spin (budget-exceeded-subject condition)))
    (is (not (budget-exceeded-asynchronous-p condition)))
    (is (search "time limit" (princ-to-string condition)))))

(test a-budget-inside-another-ends-no-later
  (let ((condition (within-seconds (3)
                     (budget-condition
                      (lambda ()
                        (with-budget (:limits (make-limits :time-limit 1/2))
                          (with-budget (:limits (make-limits :time-limit 1000))
                            (loop (check-budget)))))))))
    (is (typep condition 'budget-exceeded))
    ;; the limit named is the one whose deadline came
    (is (= 1/2 (budget-exceeded-limit condition))))
  ;; no budget, no deadline: the checks do nothing
  (is (null (budget-time-left)))
  (is (null (dotimes (i 100000) (check-budget)))))

(test the-backstop-stops-work-no-check-covers
  (let* ((ames.base::*backstop-grace* 1/2)
         (condition (within-seconds (4)
                      (budget-condition
                       (lambda ()
                         (with-budget (:limits (make-limits :time-limit 1/2))
                           (loop (sleep 0.01))))))))
    (is (typep condition 'budget-exceeded))
    (is (budget-exceeded-asynchronous-p condition)))
  ;; a run that ends in time leaves no timer behind (it would fire during the sleep)
  (let ((ames.base::*backstop-grace* 1/10))
    (is (eql 3 (with-budget (:limits (make-limits :time-limit 1/2)) 3)))
    (sleep 0.8)))

(test exact-numbers-and-expressions-are-bounded-in-the-geometry
  (let ((condition (within-seconds (2)
                     (budget-condition
                      (lambda ()
                        (ames.geometry::normalize-expression '(/ h (expt 10 (expt 10 9)))))))))
    (is (eq :integer-bits (budget-exceeded-quantity condition)))
    (is (equal '(expt 10 1000000000) (ames-error-datum condition)))
    (is (search "bits" (princ-to-string condition))))
  (let ((condition (within-seconds (2)
                     (budget-condition
                      (lambda ()
                        (ames.geometry::normalize-expression
                         (cons '* (loop for k from 1 to 26 collect `(+ ,k (sqrt ,(1+ k)))))))))))
    (is (eq :expression-size (budget-exceeded-quantity condition))))
  ;; powers of a constant sum, nested powers, and a sum of very many terms
  (dolist (form (list '(* 2 (expt (+ 1 (sqrt 2) (sqrt 3) (sqrt 5) (sqrt 7) (sqrt 11) (sqrt 13)
                             (sqrt 17) (sqrt 19) (sqrt 23) (sqrt 29) (sqrt 31)) 6))
                      '(expt (expt (expt 7 1000) 1000) 1000)
                      (cons '+ (loop for k below 30000 collect (intern (format nil "V~D" k))))))
    (is (typep (within-seconds (3) (budget-condition
                                    (lambda () (ames.geometry::normalize-expression form))))
               'budget-exceeded)
        "~S was built" (if (> (length form) 10) (subseq form 0 10) form)))
  ;; within the limits, exact arithmetic is exact
  (is (eql (expt 3 100) (ames.geometry::normalize-expression '(expt 3 100))))
  (is (equal 0 (ames.geometry::normalize-expression '(- (* (+ 1 (sqrt 2)) (- (sqrt 2) 1)) 1)))))

(test the-integer-limit-is-configurable
  (let ((*limits* (make-limits :integer-bits 200)))
    (is (typep (budget-condition (lambda () (ames.geometry::normalize-expression '(expt 10 100))))
               'budget-exceeded)))
  (is (eql (expt 10 100) (ames.geometry::normalize-expression '(expt 10 100)))))

(test expression-value-stays-exact-within-the-limits-and-approximates-beyond
  (is (eql (expt 10 50) (expression-value '(* (expt 10 25) (expt 10 25)))))
  (let ((*limits* (make-limits :integer-bits 100)))
    (multiple-value-bind (value exact) (expression-value '(* (expt 10 25) (expt 10 25)))
      (is (floatp value))
      (is (not exact))
      (is (< (abs (- value 1d50)) 1d36))))
  ;; hostile sizes give an approximation or no value at once
  (within-seconds (2)
    (is (null (expression-value '(expt 10 (expt 10 9)))))
    (is (null (expression-value (cons '* (make-list 400 :initial-element (expt 10 3000))))))))

(test expression-value-honours-the-deadline
  (let ((deep 1))
    (dotimes (i 900) (setf deep (list '+ deep 1)))
    (let ((condition (within-seconds (4)
                       (budget-condition
                        (lambda ()
                          (with-budget (:limits (make-limits :time-limit 1/2))
                            (loop (expression-value deep))))))))
      (is (typep condition 'budget-exceeded)))))

(test reports-are-cut-short-and-their-context-comes-first
  (let* ((long (make-string 1200000 :initial-element #\x))
         (condition (make-condition 'ames-error :detail long :datum 'd)))
    (is (< (length (princ-to-string condition)) 4000))
    (is (search "more characters" (princ-to-string condition)))
    (is (search "--verbose" (princ-to-string condition)))
    (is (> (length (ames-error-full-report condition)) 1200000))
    (let ((*full-reports* t))
      (is (> (length (princ-to-string condition)) 1200000))))
  (let ((many-lines (format nil "~{~A~^~%~}" (loop for i below 1500 collect i))))
    (is (< (count #\Newline (princ-to-string (make-condition 'ames-error :detail many-lines)))
           40)))
  (let ((condition (make-condition 'ames.maxima:maxima-timeout :seconds 20 :datum '(+ a b))))
    (setf (ames-error-context condition)
          (make-error-context :file "x.lisp" :line 7 :scenario 'drop :location "body BALL"))
    (let ((report (princ-to-string condition)))
      (is (eql 0 (search "Scenario DROP, body BALL (x.lisp, line 7): Maxima did not answer"
                         report)))))
  ;; printed with escapes, a condition is still #<...>
  (is (eql 0 (search "#<" (prin1-to-string (make-condition 'ames-error :detail "x"))))))
