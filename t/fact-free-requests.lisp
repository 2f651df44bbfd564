;;;; t/fact-free-requests.lisp -- a rational simplification is asked of Maxima once for
;;;; all facts; one that the facts can change is asked under each.

(in-package #:ames.tests)

(def-suite fact-free-requests :in all-tests
  :description "Requests whose answer no fact changes are cached once for all facts
(src/maxima-bridge/fact-free-requests.lisp), and only those.")

(in-suite fact-free-requests)

(test a-rational-simplification-is-shared-by-siblings
  "ratsimp((m + g)^2 - (m - g)^2) is 4 m g under f > m g, and its sibling f < m g gets
the same answer from the cache, without a round trip."
  (call-with-bridge
   (lambda (b)
     (let ((form '(- (expt (+ m g) 2) (expt (- m g) 2))))
       (ames.maxima:with-assumptions (b '((> f (* m g))))
         (is (ames.maxima:equivalent-p b (ames.maxima:simplify b form) '(* 4 m g))))
       (ames.maxima:with-assumptions (b '((< f (* m g))))
         (let ((trips (getf (ames.maxima:bridge-statistics b) :maxima-calls))
               (simplified (ames.maxima:simplify b form)))
           (is (= trips (getf (ames.maxima:bridge-statistics b) :maxima-calls)))
           (is (ames.maxima:equivalent-p b simplified '(* 4 m g)))))))))

(test a-radical-is-simplified-under-each-facts
  "sqrt(x^2) is x under x > 0 and -x under x < 0: a radical's simplification depends on
the facts, and each scope asks its own."
  (call-with-bridge
   (lambda (b)
     (let ((form '(sqrt (expt x 2))))
       (is (not (ames.maxima::fact-free-request-p
                 (ames.maxima::mcall "$RATSIMP" (ames.maxima::to-mx b form)))))
       (is (ames.maxima::fact-free-request-p
            (ames.maxima::mcall "$RATSIMP" (ames.maxima::to-mx b '(/ (+ x 1) (expt x 2))))))
       (ames.maxima:with-assumptions (b '((> x 0)))
         (is (ames.maxima:equivalent-p b (ames.maxima:simplify b form) 'x)))
       (ames.maxima:with-assumptions (b '((< x 0)))
         (is (ames.maxima:equivalent-p b (ames.maxima:simplify b form) '(- x))))))))
