;;;; t/speed-batches.lisp -- issue 24's batches and tables give the answers of the long way.
;;;;
;;;; The prefetched simplifications (many in a round trip) are the answers of the single
;;;; requests; a sum of many polynomials in one table is the fold of POLYNOMIAL-SUM, term
;;;; for term and in order; the engine's index on a ground form finds what a scan finds.

(in-package #:ames.tests)

(in-suite bridge-shortcuts)

(defparameter *prefetched-expressions*
  '((+ w4 w3) (+ (- w1) (- w2) 1) (+ w1 (* 2 w2) (/ w3 2)) (- (+ w1 w2) w1)
    (+ (* 3/2 w1) (- w2 1)) (sqrt (+ (expt w1 2) (expt w2 2))) (atan w2 w1)
    (/ (+ w1 w2) (sqrt (+ (expt w1 2) (expt w2 2)))) (sin (+ (asin (/ w1 (+ w1 w2))) 0)))
  "Expressions as the geometry tidies them, with sums, quotients, roots and angles.")

(test prefetched-simplifications-are-the-single-answers
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> w1 0) (> w2 0) (> w3 0) (> w4 0)))
       (let ((single (mapcar (lambda (e) (ames.maxima:simplify b e :strategy :full))
                             *prefetched-expressions*)))
         (ames.maxima:clear-bridge-cache b)
         (let ((before (round-trips b)))
           (ames.maxima:prefetch-simplifications b *prefetched-expressions*)
           ;; a handful of requests fits in one batch; atoms and numbers are not asked
           (is (= (1+ before) (round-trips b)))
           (let ((after (round-trips b))
                 (cached (mapcar (lambda (e) (ames.maxima:simplify b e :strategy :full))
                                 *prefetched-expressions*)))
             (is (= after (round-trips b)) "the simplifications were not all cached")
             (loop for e in *prefetched-expressions* for s in single for c in cached
                   do (is (equal s c) "~S: ~S alone, ~S prefetched" e s c)))))))))

(test a-failing-batch-is-dropped-and-asked-alone
  (call-with-bridge
   (lambda (b)
     ;; log(0) is a Maxima error: the batch fails, SIMPLIFY then signals it alone
     (ames.maxima:prefetch-simplifications b '((+ w1 w2) (log 0)))
     (is (equal '(+ w1 w2) (ames.maxima:simplify b '(+ w1 w2) :strategy :full)))
     (signals ames.maxima:maxima-condition
       (ames.maxima:simplify b '(log 0) :strategy :full)))))

(test a-sum-of-polynomials-is-the-fold-term-for-term
  (let ((random-state (sb-ext:seed-random-state 24)))
    (flet ((random-polynomial ()
             (loop repeat (random 6 random-state)
                   collect (cons (let ((power (random 4 random-state)))
                                   (and (plusp power)
                                        (list (cons (nth (random 3 random-state) '(a b c)) power))))
                                 (- (random 5 random-state) 2)))))
      (dotimes (i 2000)
        (let ((polynomials (loop repeat (random 6 random-state) collect (random-polynomial))))
          (is (equal (reduce #'ames.simulator::polynomial-sum polynomials :initial-value '())
                     (ames.simulator::polynomial-sums polynomials))
              "~S" polynomials))))))
