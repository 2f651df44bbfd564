;;;; t/speed-questions.lisp -- issue 24: DECIDE's questions asked in fewer round trips give
;;;; the answers of the one-at-a-time way.
;;;;
;;;; The sign() requests of a form asked together, is() with the signs, the failing request
;;;; of a batch left out alone, and the parts of a difference around one square root found
;;;; in one request: the same signs and verdicts as each request asked alone, in fewer
;;;; round trips.

(in-package #:ames.tests)

(in-suite bridge-shortcuts)

(defparameter *batched-facts* '((> a 0) (> b 0) (> l1 l2) (> l2 0) (> g 0))
  "Facts in force for the relations below.")

(defparameter *batched-relations*
  '(((> (- (sqrt (+ (expt a 2) (expt b 2))) a) 0) . :true)          ; hypotenuse > leg
    ((< (- (sqrt (+ (expt a 2) (expt b 2))) (+ a b)) 0) . :true)     ; triangle inequality
    ((< (* g (- l1 l2)) 0) . :false)
    ((> (- (* 2 (sqrt a)) 1) 0) . :unknown)                          ; a > 1/4 is not known
    ((>= (/ (- l1 l2) (sqrt (+ (expt (- l1 l2) 2) (expt a 2)))) 0) . :true)
    ((> (- (* a b) (expt a 2)) 0) . :unknown))
  "Relations with the verdict every sound method gives under *BATCHED-FACTS*.")

(defun verdicts-and-round-trips (prefetch)
  "DECIDE's verdicts on *BATCHED-RELATIONS* in a fresh bridge with the batching on or off
(PREFETCH), and the round trips they took."
  (let ((ames.maxima:*prefetch-signs* prefetch))
    (call-with-bridge
     (lambda (b)
       (ames.maxima:with-assumptions (b *batched-facts*)
         (let* ((before (round-trips b))
                (verdicts (mapcar (lambda (entry) (ames.algebra:decide b (car entry)))
                                  *batched-relations*)))
           (values verdicts (- (round-trips b) before))))))))

(test batched-questions-give-the-verdicts-in-fewer-round-trips
  (multiple-value-bind (alone alone-trips) (verdicts-and-round-trips nil)
    (multiple-value-bind (batched batched-trips) (verdicts-and-round-trips t)
      (loop for (relation . expected) in *batched-relations*
            for a in alone for v in batched
            do (is (eq expected v) "~S: ~S batched, ~S expected" relation v expected)
               (is (eq a v) "~S: ~S alone, ~S batched" relation a v))
      (is (< batched-trips alone-trips) "~D round trips batched, ~D alone"
          batched-trips alone-trips))))

(test a-failing-request-leaves-its-batch-answered
  (call-with-bridge
   (lambda (b)
     ;; log(0) is a Maxima error: the others of the batch are cached, it is asked alone
     (ames.maxima:prefetch-simplifications b '((+ w1 w2) (log 0) (* 2 (+ w1 w2))))
     (let ((before (round-trips b)))
       (is (equal '(+ w1 w2) (ames.maxima:simplify b '(+ w1 w2) :strategy :full)))
       (is (equal '(* 2 (+ w1 w2))
                  (ames.maxima:simplify b '(* 2 (+ w1 w2)) :strategy :full)))
       (is (= before (round-trips b)) "the good answers of the batch were not cached"))
     (signals ames.maxima:maxima-condition
       (ames.maxima:simplify b '(log 0) :strategy :full)))))

(test square-root-parts-of-a-difference
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> x 0)))
       ;; 2 sqrt(x) - 1 = a + b sqrt(x): a = -1 < 0, b = 2 > 0, b^2 x - a^2 = 4 x - 1 of
       ;; any sign, x > 0, denominator 1 > 0
       (is (equal '((:negative) (:positive) (:negative :positive :zero) (:positive) (:positive))
                  (mapcar (lambda (signs) (sort (copy-list signs) #'string<
                                                :key #'symbol-name))
                          (ames.maxima:square-root-part-signs b '(* 2 (sqrt x)) 1))))
       ;; (sqrt(x) + 3) / (x + 1): a = 3, b = 1, 9 - x ... over a positive denominator
       (let ((parts (ames.maxima:square-root-part-signs b '(/ (+ (sqrt x) 3) (+ x 1)) 0)))
         (is (equal '(:positive) (first parts)))
         (is (equal '(:positive) (second parts)))
         (is (equal '(:positive) (fifth parts))))
       ;; no square root: nothing to clear
       (is (null (ames.maxima:square-root-part-signs b '(+ x 1) 0)))))))
