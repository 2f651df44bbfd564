;;;; t/quick-signs.lisp -- the shortcuts of issue 24: relations settled by the rules of signs
;;;; before Maxima is asked, and the broad phase's signs after like terms cancel.
;;;;
;;;; Each shortcut must give the answer the long way gives (Maxima's, with the shortcut
;;;; off), answer nothing it cannot prove, and cost no round trip where it answers.

(in-package #:ames.tests)

(in-suite bridge-shortcuts)

(defparameter *quick-relations*
  '(((> (+ w1 w2) 0) :true)
    ((< (+ (- w1) (- w2)) 0) :true)
    ((= (+ w1 w2) 0) :false)
    ((> (+ (- w1) -1) 0) :false)
    ((>= (expt w1 2) 0) :true)
    ((<= (- (expt w1 2)) 0) :true)
    ((> (* w1 w2) 0) :true)
    ((> (- (* w1 w2)) 0) :false)
    ((< (/ w1 k) 0) :true)
    ((> (* 2 (sqrt (+ w1 h))) 0) :true)
    ((>= h 0) :true)
    ((> h 0) :unknown)                  ; h may be 0
    ((< (+ w1 (- w2)) 0) :unknown)      ; either sign
    ((> (/ w1 h) 0) :unknown)           ; h may be 0: undefined there
    ((> (sqrt (- w1 w2)) 0) :unknown))  ; not real everywhere
  "Relations under w1, w2, w3 > 0, h >= 0, k < 0, each with what the rules of signs say.")

(test quick-verdicts-agree-with-the-long-way
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> w1 0) (> w2 0) (> w3 0) (>= h 0) (< k 0)))
       (loop for (relation expected) in *quick-relations*
             do (let ((before (round-trips b))
                      (quick (ames.algebra::quick-verdict b relation)))
                  (is (eq expected quick) "~S: ~S, expected ~S" relation quick expected)
                  (is (= before (round-trips b)) "~S asked Maxima" relation)
                  (unless (eq quick :unknown)
                    (ames.maxima:clear-bridge-cache b)
                    (let ((long (let ((ames.algebra::*quick-verdicts* nil))
                                  (ames.algebra:decide b relation))))
                      (is (eq quick long) "~S: quick ~S, long way ~S" relation quick long)))))
       ;; DECIDE takes the shortcut: no round trip for what the signs settle
       (ames.maxima:clear-bridge-cache b)
       (let ((before (round-trips b)))
         (is (eq :true (ames.algebra:decide b '(> (+ w1 (* w2 w3) (expt w3 2)) 0))))
         (is (= before (round-trips b))))))))

(defun polynomial-value (monomials point)
  "The value at POINT (an alist symbol -> rational) of MONOMIALS (from EXPANDED-MONOMIALS)."
  (loop for (monomial . coefficient) in monomials
        sum (* coefficient
               (reduce #'* (mapcar (lambda (factor)
                                     (expt (cdr (assoc (car factor) point)) (cdr factor)))
                                   monomial)))))

(test expanded-signs-cancel-like-terms
  (let ((signs '((w1 :positive) (w2 :positive) (w3 :positive) (k :negative)))
        (unknown '(:positive :negative :zero)))
    (flet ((sign (expression) (ames.simulator::expanded-sign signs expression))
           (same (a b) (null (set-exclusive-or a b))))
      ;; (w1 + w2 + w3) - w1 - (w2 + w3/2) = w3/2 > 0: the rules of signs alone see nothing
      (let ((gap '(- (+ w1 w2 w3) w1 (+ w2 (/ w3 2)))))
        (is (same unknown (ames.simulator::sign-algebra signs gap)))
        (is (same '(:positive) (sign gap))))
      (is (same '(:negative) (sign '(- (+ w1 w2) (+ w1 w2 w3)))))
      (is (same '(:zero) (sign '(- (* 2 (+ w1 w2)) (* 2 w1) (* 2 w2)))))
      ;; (w1 + k)^2 - w1^2 - k^2 = 2 w1 k < 0
      (is (same '(:negative) (sign '(- (expt (+ w1 k) 2) (expt w1 2) (expt k 2)))))
      ;; not proven: either sign, or beyond a polynomial
      (is (same unknown (sign '(- w1 w2))))
      (is (same unknown (sign '(- (sqrt w1) w2))))
      (is (same unknown (sign '(/ w1 w2)))))
    ;; the expansion is the expression: both evaluated exactly at several points
    (let ((expression '(- (* (+ a (/ b 3)) (- a (* 2 c)) (+ 1 c)) (expt (- a b) 3) (/ c 7))))
      (dolist (point '(((a . 1) (b . 2) (c . 3)) ((a . -1/2) (b . 5) (c . 0))
                       ((a . 7/3) (b . -4) (c . -11/5)) ((a . 0) (b . 0) (c . 1))))
        (is (= (ames.base:expression-value expression point)
               (polynomial-value (ames.simulator::expanded-monomials expression) point)))))))

(test a-scope-seen-before-is-set-up-only-when-a-request-needs-it
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> x 0)))
       ;; first time: set up at once (a contradiction is still signalled where it is entered)
       (signals ames.maxima:inconsistent-assumptions
         (ames.maxima:with-assumptions (b '((< x -1)))
           (ames.algebra:decide b '(> (* x y) 0))))
       (ames.maxima:with-assumptions (b '((> y 1)))
         (is (eq :true (ames.algebra:decide b '(> (+ (* x y) (* x y y)) (* x y))))))
       ;; again: the answer is in the cache, and entering and leaving cost no round trip
       (let ((before (round-trips b)))
         (ames.maxima:with-assumptions (b '((> y 1)))
           (is (eq :true (ames.algebra:decide b '(> (+ (* x y) (* x y y)) (* x y))))))
         (is (= before (round-trips b))))
       ;; again, with a question that reaches Maxima: the scope is set up first, and its
       ;; facts are in force for the answer
       (let ((before (round-trips b)))
         (ames.maxima:with-assumptions (b '((> y 1)))
           (is (ames.maxima:equivalent-p b '(abs (- y 1)) '(- y 1))))
         (is (< before (round-trips b))))
       ;; left: y > 1 is no longer in force, x > 0 still is
       (is (eq :unknown (ames.algebra:decide b '(> (- y 1) 0))))
       (is (eq :true (ames.algebra:decide b '(> (* 2 x) 0))))
       (is (not (ames.maxima:equivalent-p b '(abs (- y 1)) '(- y 1))))))))
