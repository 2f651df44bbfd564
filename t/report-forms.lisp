;;;; t/report-forms.lisp -- the report's own algebra and data: arranging keeps values, numbers, JSON, phrase tables.
;;;;
;;;; Arranged forms are compared with the originals by numeric evaluation at several points
;;;; (EXPRESSION-VALUE), never by their printed text.

(in-package #:ames.tests)

(def-suite report :in all-tests
  :description "The reports (src/report/): the presentation step, text, LaTeX, JSON, SVG, HTML.")

(in-suite report)

(defun plain-arrangement ()
  "An arrangement by symbol name that knows no difference's sign and takes every name to
be >= 0, as the positive test points make it."
  (ames.report::make-arrangement
   :symbol-key (lambda (name) (list 3 (princ-to-string name)))
   :negative-p (constantly nil)
   :nonnegative-p #'symbolp
   :variable 'tau))

(defun random-positive-points (expression count seed)
  "COUNT alists giving each variable of EXPRESSION a random value in (0.1, 2.1)."
  (let ((state (sb-ext:seed-random-state seed))
        (names (expression-variables expression)))
    (loop repeat count
          collect (mapcar (lambda (n) (cons n (+ 0.1d0 (random 2d0 state)))) names))))

(defun same-values-at-points-p (a b &key (points 6) (seed 7))
  "True when A and B evaluate alike (relative 1e-9) wherever both are defined, at
POINTS random positive points, and are both defined at two of them at least."
  (let ((compared 0))
    (dolist (point (random-positive-points (list '+ a b) points seed) (>= compared 2))
      (let ((x (expression-value a point)) (y (expression-value b point)))
        (when (and (realp x) (realp y))
          (incf compared)
          (unless (< (abs (- x y)) (* 1d-9 (max 1 (abs x) (abs y))))
            (return nil)))))))

(defparameter *forms-to-arrange*
  '((/ (+ (* (cos a) (sin a) (tan a) tau tau mw g) (* (expt (sin a) 2) mp h) (* mw h))
       (* (tan a) (+ (* (expt (sin a) 2) mp) mw) 2))
    (* (+ (* mp mw) (* mw mw)) g)
    (- (/ (* (sqrt 2) (sqrt g) (sqrt h)) (* (sin a) (sqrt (+ mp mw)))))
    (/ (* (expt 2 3/2) (expt (cos c) 3/2) (sqrt g) (sqrt r)) (expt 3 3/2))
    (- (* (- (* mb g l1) (* f l3) (* mb g l2)) l3))
    (/ (* (cos a) h) (* 2 (sin a)))
    (* -2 g r (- (sin (/ s r)) (cos c)))
    (- (- (* 2 l1 l2) (expt l1 2) (expt l2 2)))
    (/ (+ (* w (sqrt g)) (* v0 (sqrt 2) (sqrt h))) (sqrt g))
    (+ (* 1/2 (expt tau 2) g) (* -3 tau v0) h))
  "Forms like those the bridge returns: products, quotients, radicals, differences.")

(test arranging-keeps-the-value
  "Every arranged form takes the value of the form it came from."
  (dolist (form *forms-to-arrange*)
    (let ((arranged (ames.report:arrange form (plain-arrangement))))
      (is (ames.base:valid-expression-p arranged :kind :arithmetic) "~S arranged to ~S" form arranged)
      (is (same-values-at-points-p form arranged) "~S arranged to ~S, of another value" form arranged))))

(test arranging-merges-roots-and-tangents
  "sqrt(2) sqrt(g) sqrt(h) is one root; cos/sin is 1/tan; a polynomial in tau starts with its constant."
  (let ((arranged (ames.report:arrange '(* (sqrt 2) (sqrt g) (sqrt h)) (plain-arrangement))))
    (is (and (consp arranged) (eq (first arranged) 'sqrt))))
  (let ((arranged (ames.report:arrange '(/ (* (cos a) h) (* 2 (sin a))) (plain-arrangement))))
    (is (equal '(a) (remove-duplicates (loop for x in (alexandria:flatten arranged)
                                             when (member x '(a)) collect x))))
    (is (not (member 'cos (alexandria:flatten arranged))))
    (is (member 'tan (alexandria:flatten arranged))))
  (let ((arranged (ames.report:arrange '(+ (* g (expt tau 2)) (* v0 tau) h) (plain-arrangement))))
    (is (eq 'h (second arranged)))))

(test the-text-printer-balances-and-never-names-a-package
  (dolist (form *forms-to-arrange*)
    (let ((text (ames.report:text-form (ames.report:arrange form (plain-arrangement)))))
      (is (= (count #\( text) (count #\) text)) "~A" text)
      (is (not (search "::" text)) "~A" text))))

(test numbers-for-people
  (is (string= "3" (ames.report:number-text 3)))
  (is (string= "0.9071" (ames.report:number-text 0.9071101110464866d0)))
  (is (string= "-29.43" (ames.report:number-text -29.43d0)))
  (is (string= "0" (ames.report:number-text 0d0)))
  (is (string= "1.5e-7" (ames.report:number-text 1.5d-7))))

(defparameter *json-sample*
  '(:scenario ames-scenario::drop
    :states ((:index 0 :start 0 :duration (/ (* (sqrt 2) (sqrt ames-scenario::h)) (sqrt ames-scenario::g))
              :contacts nil
              :forces ((:gravity ames-scenario::ball (0 (- (* ames-scenario::m ames-scenario::g))))
                       (:friction ames-scenario::a ames-scenario::b 1/2 :mode :static))
              :end-event (:collision ames-scenario::ball ames-scenario::floor :impulse 3/4)
              :numeric (:start 0 :duration 0.4515236409857309d0)
              :undecided "a reason, in words"
              :selected t
              :time (:time-limit 5)))
    :outcome :collision)
  "An s-expression report with every kind of datum JSON must carry.")

(test json-round-trips-the-sexp
  (let* ((json (with-output-to-string (out) (yason:encode (ames.report:sexp-to-json *json-sample*) out)))
         (back (ames.report:json-to-sexp json)))
    (is (equal *json-sample* back))
    (is (search "\"scenario\":\"drop\"" json))
    (is (search "[\"/\",[\"*\",[\"sqrt\",2]" json)))
  (signals ames.report:report-error (ames.report:json-to-sexp "{\"scenario\": "))
  (signals ames.report:report-error (ames.report:json-to-sexp "[\"no-such-symbol-anywhere\"]")))

(test force-and-event-phrases-take-any-kind
  "Unknown kinds of forces and events are printed generically, never refused."
  (multiple-value-bind (label symbol value options)
      (ames.report::force-entry '(:magnetic ames-scenario::a ames-scenario::b (1 2) :mode :on))
    (is (search "magnetic" label))
    (is (null symbol))
    (is (equal '(1 2) value))
    (is (equal '(:mode :on) options)))
  (multiple-value-bind (label symbol value) (ames.report::force-entry '(:tension ames-scenario::rope ames-scenario::tt))
    (is (search "tension in rope" label))
    (is (string= "T" symbol))
    (is (eq 'ames-scenario::tt value)))
  (multiple-value-bind (label symbol value) (ames.report::force-entry '(:normal ames-scenario::p ames-scenario::w 5))
    (is (string= "normal force of w on p" label))
    (is (string= "N" symbol))
    (is (eql 5 value))))

;;; Square roots of bases that may be negative

(defparameter *signed-points*
  (let ((state (sb-ext:seed-random-state 11)))
    (loop repeat 8
          collect (flet ((magnitude () (+ 0.1d0 (random 2d0 state))))
                    (list (cons 'p1 (magnitude)) (cons 'p2 (magnitude))
                          (cons 'n1 (- (magnitude))) (cons 'n2 (- (magnitude)))
                          (cons 'u1 (- (random 4d0 state) 2d0)) (cons 'u2 (- (random 4d0 state) 2d0))))))
  "Points where p1, p2 > 0, n1, n2 < 0 and u1, u2 take either sign.")

(defun signed-arrangement ()
  "An arrangement that knows a sign where an expression has it at every signed point (a
numeric stand-in, for the test, of the bridge's proof)."
  (flet ((everywhere (test)
           (lambda (expression)
             (every (lambda (point)
                      (let ((v (complex-value expression point)))
                        (and (realp v) (funcall test v))))
                    *signed-points*))))
    (ames.report::make-arrangement
     :symbol-key (lambda (name) (list 3 (princ-to-string name)))
     :negative-p (everywhere #'minusp)
     :nonnegative-p (everywhere (lambda (v) (>= v 0)))
     :variable 'tau)))

(test arranging-keeps-the-value-of-roots-of-negatives
  "sqrt(x) sqrt(y) is not sqrt(x y) when x and y are negative, and sqrt(x)/sqrt(y) is
not sqrt(x/y) when y is: the arranged forms keep the complex value of the original at
points where the radicands take either sign; a real quantity written with roots of
negatives (the corner's falling blocks) is written with real roots."
  (dolist (form '((* p1 (sqrt n1) (sqrt n2))
                  (/ (* p1 (sqrt (- n1 p2)) (sqrt n2)) (+ p2 p1))
                  (* (sqrt u1) (sqrt u2))
                  (/ (sqrt p1) (sqrt u1))
                  (/ (sqrt u1) (sqrt u2))
                  (/ 1 (* (sqrt u1) (sqrt p1)))
                  (* (expt u1 3/2) (sqrt p1))
                  (* (sqrt n1) (sqrt p1) (sqrt u1))
                  (* (sqrt n1) (sqrt n2) (sqrt u1) (sqrt u2))
                  (/ (sqrt n1) (sqrt n2))))
    (let ((arranged (ames.report:arrange form (signed-arrangement))))
      (is (ames.base:valid-expression-p arranged :kind :arithmetic) "~S arranged to ~S" form arranged)
      (is (every (lambda (point)
                   (< (abs (- (complex-value form point) (complex-value arranged point)))
                      (* 1d-9 (max 1 (abs (complex-value form point))))))
                 *signed-points*)
          "~S arranged to ~S, of another value" form arranged)))
  (let ((arranged (ames.report:arrange '(* p1 (sqrt n1) (sqrt n2)) (signed-arrangement))))
    (is (every (lambda (point) (realp (complex-value arranged point))) *signed-points*)
        "~S still has imaginary factors" arranged)
    (is (eq '- (first arranged)) "~S: sqrt(n1) sqrt(n2) = -sqrt(n1 n2)" arranged)))
