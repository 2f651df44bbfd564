;;;; t/zero-folding.lisp -- the zeros of a raw series term folded in Lisp (src/simulator/zero-folding.lisp).

(in-package #:ames.tests)

(def-suite zero-folding :in all-tests
  :description "WITHOUT-ZEROS drops what Maxima's simplifier would drop at once, and keeps
the value.")

(in-suite zero-folding)

(test zeros-folded-keep-the-value
  "The chain rule's raw terms at a body at rest (omega = 0, v = 0): WITHOUT-ZEROS gives a
smaller expression of the same value (Maxima: the difference ratsimps to 0), and leaves
a float zero and an expression without zeros as they are."
  (call-with-bridge
   (lambda (b)
     (let* ((raw '(+ 0 (* (- (* 1/2 k (sin a)) (* 0 w (cos a))) 0 (expt omega 2))
                   (- (* g (sin a)) 0) (/ 0 (+ w k)) (expt 0 3) (expt (+ w k) 0)
                   (* (+ 0 (* 3 omega 0)) (cos (+ a 0))) (- 0 (* m g))))
            (folded (ames.simulator::without-zeros raw)))
       (is (< (ames.maxima:expression-size folded) (ames.maxima:expression-size raw)))
       (is (eql 0 (ames.maxima:simplify b `(- ,raw ,folded) :strategy :ratsimp)))
       (is (equal '(+ (* g (sin a)) 1 (- (* m g))) folded))
       (is (equal '(* 0.0 x) (ames.simulator::without-zeros '(* 0.0 x))))
       (is (equal '(+ x (sin y)) (ames.simulator::without-zeros '(+ x (sin y)))))))))
