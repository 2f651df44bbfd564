;;;; t/fork-pruning.lisp -- a fork lists only the consistent outcomes (issue 24).
;;;;
;;;; The thesis's corner without values forks at t = 0 on f l3 - mb g (l1 - l2) (B rises or
;;;; falls), and each branch forks again at the start of state 1. Under "B falls" (f l3 <
;;;; mb g (l1 - l2)) the second fork's fact is P = (l1 - l2)^2 (mb g (3 l1 + l2) - f l3) +
;;;; 2 ma g l3^2 (l1 + l2), which is then positive: its outcome P <= 0 is impossible, and
;;;; under "B rises" so is Q < 0 for Q = 3 ma f l3^2 + 2 mb f (l1 - l2)^2 - ma mb g l3 (l1 -
;;;; l2). Both are proven by the two facts linear in f combined (src/algebra/
;;;; contradictions.lisp); the possible outcomes are not pruned, and the proofs agree with
;;;; the numbers: the pruned relation fails at every admissible point drawn.

(in-package #:ames.tests)

(def-suite fork-pruning :in all-tests
  :description "Issue 24: a fork's branch whose fact contradicts the facts in force is
left out (two facts linear in one variable combined), checked against the numbers.")

(in-suite fork-pruning)

(defparameter *corner-facts* '((> ma 0) (> mb 0) (> g 0) (> f 0) (> l2 0) (> l1 l2) (> l3 0))
  "The corner's assumptions (scenarios/two-blocks-in-corner.lisp).")

(defparameter *b-falls* '(< (- (* f l3) (* mb g (- l1 l2))) 0)
  "The corner's first fork: B falls.")

(defparameter *b-rises* '(> (- (* f l3) (* mb g (- l1 l2))) 0)
  "The corner's first fork: B rises.")

(defparameter *p* '(+ (* (expt (- l1 l2) 2) (- (* mb g (+ (* 3 l1) l2)) (* f l3)))
                      (* 2 ma g (expt l3 2) (+ l1 l2)))
  "The fact of the second fork under B falls, P.")

(defparameter *q* '(- (+ (* 3 ma f (expt l3 2)) (* 2 mb f (expt (- l1 l2) 2)))
                      (* ma mb g l3 (- l1 l2)))
  "The fact of the second fork under B rises, Q.")

(defun contradicts-p (bridge facts relation)
  "CONTRADICTS-FACTS-P of RELATION under FACTS."
  (ames.maxima:with-assumptions (bridge facts)
    (ames.algebra:contradicts-facts-p bridge relation)))

(defun sampled-truths (relation facts &key (draws 4000))
  "(HOLDS FAILS): at how many random points satisfying FACTS (positive parameters drawn
over three decades) RELATION holds and fails, by floating-point evaluation."
  (let ((state (sb-ext:seed-random-state 24)) (holds 0) (fails 0)
        (names '(ma mb g f l1 l2 l3)))
    (flet ((value (expression point)
             (expression-value (sublis point expression))))
      (loop repeat draws
            do (let ((point (mapcar (lambda (name) (cons name (expt 10d0 (- (random 3d0 state) 1.5d0))))
                                    names)))
                 (when (every (lambda (fact) (> (value `(- ,(second fact) ,(third fact)) point) 0))
                              (mapcar (lambda (fact)
                                        (if (eq (first fact) '<) (list '> (third fact) (second fact)) fact))
                                      facts))
                   (let ((difference (value `(- ,(second relation) ,(third relation)) point)))
                     (if (ecase (first relation)
                           (> (> difference 0)) (>= (>= difference 0))
                           (< (< difference 0)) (<= (<= difference 0)) (= (zerop difference)))
                         (incf holds)
                         (incf fails)))))))
    (list holds fails)))

(test corner-impossible-outcomes-are-proven-impossible
  "Under B falls, P <= 0 and P = 0 contradict the facts, P > 0 does not; under B rises,
Q < 0 and Q = 0 contradict them, Q > 0 does not. Each pruned relation fails at every
admissible point drawn, each kept one holds at some."
  (call-with-bridge
   (lambda (b)
     (let ((falls (cons *b-falls* *corner-facts*)) (rises (cons *b-rises* *corner-facts*)))
       (is (contradicts-p b falls `(<= ,*p* 0)))
       (is (contradicts-p b falls `(= ,*p* 0)))
       (is (not (contradicts-p b falls `(> ,*p* 0))))
       (is (contradicts-p b rises `(< ,*q* 0)))
       (is (not (contradicts-p b rises `(> ,*q* 0))))
       ;; the numbers agree: no admissible point has P <= 0 under B falls (or Q < 0 under
       ;; B rises), and many have the kept outcome
       (destructuring-bind (holds fails) (sampled-truths `(<= ,*p* 0) falls)
         (is (zerop holds))
         (is (plusp fails)))
       (destructuring-bind (holds fails) (sampled-truths `(< ,*q* 0) rises)
         (is (zerop holds))
         (is (plusp fails)))))))

(test only-a-provable-contradiction-prunes
  "a > 0, p > 2 a: p < a is impossible (p - 2 a > 0 and a - p > 0 sum to -a > 0), p <= 2 a
too, but p < 3 a is possible (p = 5/2 a) and is kept; without the bound on p, nothing
is pruned. A relation in a variable no fact bounds is never pruned."
  (call-with-bridge
   (lambda (b)
     (let ((facts '((> a 0) (> p (* 2 a)))))
       (is (contradicts-p b facts '(< p a)))
       (is (contradicts-p b facts '(<= p (* 2 a))))
       (is (contradicts-p b facts '(= p a)))
       (is (not (contradicts-p b facts '(< p (* 3 a)))))
       (is (not (contradicts-p b '((> a 0)) '(< p a))))
       (is (not (contradicts-p b facts '(< q a))))))))

(test corner-fork-under-b-falls-keeps-one-branch
  "The corner's run at its start, under B falls: the fork on P lists one alternative, P >
0 (the impossible P <= 0 is left out)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "two-blocks-in-corner"))
           (p (in-scenario-terms scenario *p*)))
      (call-with-scenario-facts
       bridge scenario
       (lambda ()
         (let ((run (ames.simulator::make-run (nth-value 1 (ames.scenario::check-scenario scenario bridge)) bridge)))
           (ames.maxima:with-assumptions (bridge (list (in-scenario-terms scenario *b-falls*)))
             (let ((alternatives (ames.simulator::fork-alternatives run `(<= ,p 0))))
               (is (= 1 (length alternatives)))
               (let ((kept (getf (first alternatives) :assume)))
                 (is (eq '> (first kept)))
                 (is (equal p (second kept))))))))))))

(test witnesses-know-exact-zeros
  "At a point, sin(atan2(0, x)/2) is exactly 0 for x > 0 and 1 for x < 0 (the imaginary
part of sqrt(x) over sqrt|x|): > 0 fails at x = 2 and holds at x = -2, >= 0 holds at
both; a product with the number 0 is exactly 0; an equation is never sure; and a ball
that only rounds to zero settles nothing."
  (let ((imaginary '(sin (/ (atan 0 x) 2))))
    (is (eq :false (ames.algebra::condition-truth `(> ,imaginary 0) '((x . 2d0)))))
    (is (eq :true (ames.algebra::condition-truth `(> ,imaginary 0) '((x . -2d0)))))
    (is (eq :true (ames.algebra::condition-truth `(>= ,imaginary 0) '((x . 2d0)))))
    (is (eq :true (ames.algebra::condition-truth `(<= (* 0 y) 0) '((y . 5d0)))))
    (is (eq :false (ames.algebra::condition-truth `(< (* 0 y) 0) '((y . 5d0)))))
    (is (null (ames.algebra::condition-truth `(= (* 0 y) 0) '((y . 5d0)))))
    ;; 0.1 + 0.2 - 0.3 is not exactly zero in floating point: no verdict
    (is (null (ames.algebra::condition-truth '(> (- (+ a b) c) 0) '((a . 0.1d0) (b . 0.2d0) (c . 0.3d0)))))))

(test undecidable-imaginary-part-is-seen-both-ways
  "The imaginary part of a root sqrt(x), x of either sign, is positive at some admissible
points and zero at others: > 0 is undecidable, and DECIDE answers :UNKNOWN; under x > 0
it is zero everywhere, and > 0 is never answered :TRUE."
  (call-with-bridge
   (lambda (b)
     (let ((relation '(> (* (sqrt 3) (sin (/ (atan 0 x) 2))) 0)))
       (ames.maxima:with-assumptions (b '((> y 0)))
         (is (eq :unknown (ames.algebra:decide b relation))))
       (ames.maxima:with-assumptions (b '((> x 0)))
         (is (not (eq :true (ames.algebra:decide b relation)))))))))
