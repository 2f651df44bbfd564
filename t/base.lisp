;;;; t/base.lisp -- tests of the prefix algebra's grammar and walkers.

(in-package #:ames.tests)

(in-suite base)

(test algebra-accepts-the-wedge-equation
  (is (equal '(= (* mp (acc particle :x)) (- (* n (sin a))))
             (check-expression '(= (* mp (acc particle :x)) (- (* n (sin a))))))))

(test algebra-rejects-what-is-not-in-the-grammar
  (dolist (bad '("system(\"ls\")" (+ 1 "x") (foo (bar)) (sin) (expt 2) #c(1 2)
                 (+ 1 . 2) (< 1 2 3) :key (quote x)))
    (signals malformed-expression (check-expression bad)))
  (signals malformed-expression (check-expression '(+ a b) :kind :condition))
  (signals malformed-expression (check-expression '(< a b) :kind :arithmetic))
  (signals malformed-expression (check-expression '(acc p :x) :allow-terms nil)))

(test malformed-expression-is-an-ames-error-naming-the-datum
  (let ((condition (handler-case (check-expression '(+ a (frob "x")))
                     (ames-error (c) c))))
    (is (typep condition 'malformed-expression))
    (is (equal '(frob "x") (ames-error-datum condition)))
    (is (search "FROB" (princ-to-string condition)))))

(test expression-walkers
  (is (equal '(a (acc p :x) b) (expression-variables '(+ a (* (acc p :x) b pi) a))))
  (is (free-of-p 'c '(+ a (sin b))))
  (is (not (free-of-p '(acc p :x) '(* 2 (acc p :x)))))
  (is (equal '(+ 2 (sin (* 3 y)))
             (substitute-expressions '((x . 2) (z . (* 3 y))) '(+ x (sin z))))))
