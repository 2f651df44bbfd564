;;;; t/bridge.lisp -- tests of the Maxima bridge: translation, solving, deciding, assumptions, caching.
;;;;
;;;; Every test starts its own bridge (a fresh Maxima process, about 30 ms) and closes it,
;;;; so tests share no state. Results are compared by meaning (Maxima simplifies the
;;;; difference to 0), never by printed strings.

(in-package #:ames.tests)

(def-suite bridge :in all-tests :description "The Maxima bridge (src/maxima-bridge/).")

(in-suite bridge)

(defun call-with-bridge (function &rest options)
  "Call FUNCTION with a fresh bridge made with OPTIONS; close the bridge afterwards."
  (let ((bridge (apply #'ames.maxima:make-bridge options)))
    (unwind-protect (funcall function bridge)
      (ames.maxima:close-bridge bridge))))

(defparameter *wedge-equations*
  '((= (* mw awx) (- (* n (sin a))))
    (= (* mp apx) (* n (sin a)))
    (= (* mp apy) (- (* n (cos a)) (* mp g)))
    (= apx (+ awx (* arel (cos a))))
    (= apy (- (* arel (sin a)))))
  "Thesis section 2.6.1: Newton's second law for the wedge (horizontal) and the particle
(both axes), and the particle's acceleration as the wedge's plus its acceleration AREL
relative to the wedge, down the slope (direction (cos a, -sin a)).")

(defparameter *wedge-unknowns* '(n apx apy awx arel))

(defparameter *wedge-facts* '((> mp 0) (> mw 0) (> g 0) (> a 0) (< a (/ pi 2))))

(defparameter *wedge-normal-force* '(/ (* mp mw g (cos a)) (+ mw (* mp (expt (sin a) 2))))
  "The thesis's result for N.")

(defun flatten (tree)
  "The atoms of TREE."
  (if (atom tree) (list tree) (mapcan #'flatten tree)))

(defun solution-value (solution unknown)
  (cdr (assoc unknown solution :test #'equal)))

;;; The wedge

(test wedge-normal-force-is-the-thesis-result
  (call-with-bridge
   (lambda (b)
     (let ((solutions (ames.maxima:solve-equations b *wedge-equations* *wedge-unknowns*)))
       (is (= 1 (length solutions)))
       (let ((solution (first solutions)))
         (is (equal *wedge-unknowns* (mapcar #'car solution)))
         (is (ames.maxima:equivalent-p b (solution-value solution 'n) *wedge-normal-force*))
         ;; a wrong formula is not accepted
         (is (not (ames.maxima:equivalent-p b (solution-value solution 'n)
                                            '(/ (* mp mw g (cos a)) (+ mw mp)))))
         ;; the solution satisfies every equation
         (dolist (equation *wedge-equations*)
           (let ((substituted (substitute-expressions solution equation)))
             (is (ames.maxima:equivalent-p b (relation-lhs substituted)
                                           (relation-rhs substituted))))))))))

(test wedge-normal-force-is-positive-under-the-declared-assumptions
  (call-with-bridge
   (lambda (b)
     (let ((n (solution-value (first (ames.maxima:solve-equations b *wedge-equations*
                                                                  *wedge-unknowns*))
                              'n)))
       (is (eq :unknown (ames.algebra:decide b `(> ,n 0))))
       (ames.maxima:with-assumptions (b *wedge-facts*)
         (is (eq :true (ames.algebra:decide b `(> ,n 0))))
         (is (eq :false (ames.algebra:decide b `(<= ,n 0)))))
       ;; the facts are gone with their scope
       (is (eq :unknown (ames.algebra:decide b `(> ,n 0))))
       (is (null (ames.maxima:current-assumptions b)))))))

;;; Assumptions

(test trigonometric-sign-facts-are-derived-from-bounds
  (call-with-bridge
   (lambda (b)
     (is (eq :unknown (ames.algebra:decide b '(> (cos a) 0))))
     (ames.maxima:with-assumptions (b '((> a 0) (< a (/ pi 2))))
       (is (eq :true (ames.algebra:decide b '(> (sin a) 0))))
       (is (eq :true (ames.algebra:decide b '(> (cos a) 0))))
       (is (eq :true (ames.algebra:decide b '(> (tan a) 0)))))
     (ames.maxima:with-assumptions (b '((< (/ pi 2) b) (<= b pi)))
       (is (eq :true (ames.algebra:decide b '(< (cos b) 0))))
       (is (eq :true (ames.algebra:decide b '(>= (sin b) 0))))
       (is (eq :unknown (ames.algebra:decide b '(> (sin b) 0)))))
     (ames.maxima:with-assumptions (b '((> c (- pi)) (< c 0)))
       (is (eq :true (ames.algebra:decide b '(< (sin c) 0))))
       (is (eq :unknown (ames.algebra:decide b '(> (cos c) 0))))))))

(test assumption-scopes-nest
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> a 0)))
       (is (eq :unknown (ames.algebra:decide b '(> (sin a) 0))))
       (ames.maxima:with-assumptions (b '((< a (/ pi 2)) (> k 0)))
         (is (equal '((> a 0) (< a (/ pi 2)) (> k 0)) (ames.maxima:current-assumptions b)))
         (is (eq :true (ames.algebra:decide b '(> (sin a) 0))))
         (is (eq :true (ames.algebra:decide b '(> (* k a) 0)))))
       (is (eq :unknown (ames.algebra:decide b '(> (sin a) 0))))
       (is (eq :unknown (ames.algebra:decide b '(> k 0))))
       (is (eq :true (ames.algebra:decide b '(> a 0)))))
     (is (eq :unknown (ames.algebra:decide b '(> a 0)))))))

(test a-scope-ends-on-a-non-local-exit
  (call-with-bridge
   (lambda (b)
     (block leave
       (ames.maxima:with-assumptions (b '((> q 0)))
         (return-from leave)))
     (is (eq :unknown (ames.algebra:decide b '(> q 0))))
     (is (null (ames.maxima:current-assumptions b))))))

(test inconsistent-assumptions-name-the-fact
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> x 1)))
       (let ((condition (handler-case
                            (ames.maxima:with-assumptions (b '((> y 0) (< x 0)))
                              :body-ran)
                          (ames.maxima:inconsistent-assumptions (c) c))))
         (is (typep condition 'ames-error))
         (is (equal '(< x 0) (ames.maxima:inconsistent-assumptions-fact condition)))
         (is (search "(< X 0)" (princ-to-string condition))))
       ;; the failed scope left nothing behind
       (is (eq :unknown (ames.algebra:decide b '(> y 0))))
       ;; the restart runs the body without the offending fact
       (is (eq :true
               (handler-bind ((ames.maxima:inconsistent-assumptions
                                (lambda (c) (declare (ignore c))
                                  (invoke-restart 'ames.maxima:retract-assumption))))
                 (ames.maxima:with-assumptions (b '((> y 0) (< x 0)))
                   (ames.algebra:decide b '(> (* x y) 0)))))))
     (is (null (ames.maxima:current-assumptions b))))))

;;; Simplify, equivalence, decide

(test simplify-strategies
  (call-with-bridge
   (lambda (b)
     (let ((quotient (ames.maxima:simplify b '(/ (- (expt x 2) 1) (- x 1)))))
       (is (ames.maxima:equivalent-p b quotient '(+ x 1)))
       (is (< (length (flatten quotient)) 6)))
     (is (eql 1 (ames.maxima:simplify b '(+ (expt (sin u) 2) (expt (cos u) 2))
                                       :strategy :trigsimp)))
     (ames.maxima:with-assumptions (b '((> x 0)))
       (is (eq 'x (ames.maxima:simplify b '(sqrt (expt x 2)) :strategy :radcan))))
     (is (eql 1 (ames.maxima:simplify b '(/ (+ (expt (sin u) 2) (expt (cos u) 2)) 1)
                                       :strategy :full)))
     (signals ames.maxima:invalid-bridge-argument
       (ames.maxima:simplify b 'x :strategy :magic)))))

(test equivalence-is-checked-by-maxima
  (call-with-bridge
   (lambda (b)
     (is (ames.maxima:equivalent-p b '(* 2 (sin u) (cos u)) '(sin (* 2 u))))
     (is (ames.maxima:equivalent-p b '(exp (* 2 (log z))) '(expt z 2)))
     (is (not (ames.maxima:equivalent-p b '(sin u) '(cos u))))
     (is (not (ames.maxima:equivalent-p b 'x 'y))))))

(test decide-is-three-valued
  (call-with-bridge
   (lambda (b)
     (is (eq :true (ames.algebra:decide b '(> 2 1))))
     (is (eq :false (ames.algebra:decide b '(< 2 1))))
     (is (eq :true (ames.algebra:decide b '(< 1 (sqrt 2)))))
     (is (eq :unknown (ames.algebra:decide b '(> x 0))))
     (is (eq :true (ames.algebra:decide b '(>= (expt x 2) 0))))
     (is (eq :true (ames.algebra:decide b '(= (* 2 (sin u) (cos u)) (sin (* 2 u))))))
     (is (eq :false (ames.algebra:decide b '(= 1 2))))
     (is (eq :true (ames.algebra:decide b '(/= 1 2))))
     (is (eq :false (ames.algebra:decide b '(and (> 2 1) (< 2 1)))))
     (is (eq :true (ames.algebra:decide b '(or (> x 0) (> 2 1)))))
     (is (eq :unknown (ames.algebra:decide b '(and (> x 0) (> 2 1)))))
     (is (eq :true (ames.algebra:decide b '(not (< 2 1))))))))

(test solve-reports-none-all-and-several
  (call-with-bridge
   (lambda (b)
     (is (null (ames.maxima:solve-equations b '((= x 1) (= x 2)) '(x))))
     (let ((roots (ames.maxima:solve-equations b '((= (expt x 2) 4)) '(x))))
       (is (= 2 (length roots)))
       (is (equal '(-2 2) (sort (mapcar (lambda (s) (solution-value s 'x)) roots) #'<))))
     ;; complex solutions are left out
     (is (null (ames.maxima:solve-equations b '((= (expt x 2) -1)) '(x))))
     (signals ames.maxima:solve-failed
       (ames.maxima:solve-equations b '((= (+ x y) 1)) '(x y)))
     (signals ames.maxima:solve-failed
       (ames.maxima:solve-equations b '((= (- x x) 0)) '(x)))
     (signals ames.maxima:invalid-bridge-argument
       (ames.maxima:solve-equations b '((= x 1)) '((+ x 1))))
     (signals ames.maxima:invalid-bridge-argument
       (ames.maxima:solve-equations b '((< x 1)) '(x)))
     ;; an expression stands for expression = 0
     (is (equal '(((x . 3))) (ames.maxima:solve-equations b '((- x 3)) '(x))))
     ;; quantity terms are unknowns like any other
     (let ((solution (first (ames.maxima:solve-equations
                             b '((= (* m (acc particle :x)) f)) '((acc particle :x))))))
       (is (ames.maxima:equivalent-p b (solution-value solution '(acc particle :x)) '(/ f m)))))))

(test translation-round-trips-by-meaning
  (call-with-bridge
   (lambda (b)
     (dolist (expression '(x 3 -5/7 pi 2.5d0 (exp 1)
                           (- a b c) (- a) (/ a b c) (/ a)
                           (+ (* 3 (expt x 2)) (/ y 2) -1)
                           (sqrt (+ 1 (expt u 2))) (exp (- t0)) (log (+ 1 z))
                           (atan y x) (atan y) (asin (/ 1 3)) (acos w) (tan w)
                           (* (acc particle :x) (mass particle))
                           (/ (- (sin a)) (+ 1 (cos a)))))
       (let ((back (ames.maxima:simplify b expression)))
         (is (valid-expression-p back) "~S came back as ~S, outside the algebra" expression back)
         (is (ames.maxima:equivalent-p b back expression)
             "~S came back as ~S" expression back))))))

(test identical-requests-are-cached
  (call-with-bridge
   (lambda (b)
     (ames.maxima:reset-bridge-statistics b)
     (ames.algebra:decide b '(> (expt x 2) -1))
     (let ((before (getf (ames.maxima:bridge-statistics b) :maxima-calls)))
       (ames.algebra:decide b '(> (expt x 2) -1))
       (let ((statistics (ames.maxima:bridge-statistics b)))
         (is (= before (getf statistics :maxima-calls)))
         (is (<= 1 (getf statistics :cache-hits)))))
     ;; the same request under other assumptions is asked again
     (ames.maxima:with-assumptions (b '((> x 0)))
       (is (eq :true (ames.algebra:decide b '(> x 0)))))
     (is (eq :unknown (ames.algebra:decide b '(> x 0)))))))

(test the-questions-of-the-deciding-algebra-answer-in-its-terms
  ;; questions.lisp: is(), sign() and a square root cleared, asked in prefix, answered
  ;; as truth values and sign lists
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> m 0) (> g 0) (>= (- x y) 0)))
       (is (eq :true (ames.maxima:maxima-is b '(> (* m g) 0))))
       (is (eq :false (ames.maxima:maxima-is b '(< (* m g) 0))))
       ;; the opposite of m g < 0 is m g >= 0, which is() proves
       (is (eq :true (ames.maxima:maxima-is-opposite b '(< (* m g) 0))))
       (is (eq :unknown (ames.maxima:maxima-is-opposite b '(< (- m g) 0))))
       (is (equal '(:negative) (ames.maxima:maxima-signs b '(- (* m g)))))
       (is (equal '(:positive) (ames.maxima:maxima-difference-signs b '(+ m 1) 'm)))
       ;; is() uses the fact about x - y, which sign() may not
       (is (not (member :negative (ames.maxima:maxima-fact-signs b '(- x y)))))
       ;; 1 + g sqrt(m) - 0: a = 1, b = g, b^2 A - a^2 = g^2 m - 1, A = m, c = 1
       (destructuring-bind (a-signs b-signs gap-signs radicand-signs denominator-signs)
           (ames.maxima:square-root-part-signs b '(+ 1 (* g (sqrt m))) 0)
         (is (equal '(:positive) a-signs))
         (is (equal '(:positive) b-signs))
         (is (subsetp '(:positive :negative) gap-signs))
         (is (equal '(:positive) radicand-signs))
         (is (equal '(:positive) denominator-signs)))
       (is (null (ames.maxima:square-root-part-signs b '(+ m g) 0)))
       (is (eql 1 (ames.maxima:ratsimp-with-sines
                   b '(+ (expt (cos a) 2) (expt (sin a) 2)) '(a))))))))
