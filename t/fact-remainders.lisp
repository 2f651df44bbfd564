;;;; t/fact-remainders.lisp -- DECIDE by one fact and a remainder of proven sign (src/algebra/fact-remainders.lisp).
;;;;
;;;; The pushed block of scenarios/pushed-block-tips-or-slides.lisp,
;;;; pushed at y = 9k/20, tips about its front edge (t/tipping-criterion.lisp). Turning
;;;; about that edge from rest, alpha = (m g w/2 - (y + k/2) P) / I_edge, I_edge = m (w^2 +
;;;; k^2)/3; its centre, at (-w/2, k/2) from the edge, accelerates by alpha x r =
;;;; (-alpha k/2, -alpha w/2); the floor's friction F = m a_x - P and normal force N = m g +
;;;; m a_y. The edge sticks while -mu N <= F <= mu N. Where F + mu N < 0 (it slides
;;;; forward), mu N - F = 2 mu N - (F + mu N) > 0 follows: N > 0 there, a sum of positive
;;;; terms at y = 9k/20. DECIDE proves it by that one fact and a remainder of one sign;
;;;; where F + mu N > 0 instead, both signs of mu N - F occur (a tall block pushed hard
;;;; kicks its edge backward), and DECIDE must not prove either.

(in-package #:ames.tests)

(def-suite fact-remainders :in all-tests
  :description "DECIDE by one fact and a remainder of proven sign: the pushed block's front
edge cannot fail both of its friction limits.")

(in-suite fact-remainders)

(defparameter *front-edge-start*
  (let* ((y '(* 9/20 k))
         (alpha `(/ (- (* 1/2 m g w) (* (+ ,y (* 1/2 k)) p)) (* 1/3 m (+ (* w w) (* k k)))))
         (friction `(- (* m (* -1/2 k ,alpha)) p))
         (normal `(+ (* m g) (* m (* -1/2 w ,alpha)))))
    (list :friction friction :normal normal
          :lower `(+ ,friction (* mu ,normal)) :upper `(- (* mu ,normal) ,friction)))
  "The floor's friction F and normal force N on the pushed block's front edge (y = 9k/20)
as it starts to turn about that edge from rest, and the slacks of its two static
friction limits, F + mu N (>= 0: not beyond -mu N) and mu N - F (>= 0).")

(defun front-edge (key)
  "The entry KEY of *FRONT-EDGE-START*."
  (getf *front-edge-start* key))

(defparameter *tipping-facts*
  '((> m 0) (> g 0) (> w 0) (> k 0) (> mu 0) (> p 0)
    (> p (* mu m g)) (< (* 3 mu w k) (+ (* 4 w w) (* k k)))
    (> (+ (* 9 k p) (* 10 m g k mu) (* -10 m g w)) 0))
  "The pushed block's assumptions (the push beats friction, no Painleve paradox) and the
run's tipping branch (the textbook criterion failing at y = 9k/20: 9 k P + 10 m g k mu >
10 m g w).")

(test front-edge-limits-are-the-runs-fork-facts
  "The lower limit's slack times 40 (w^2 + k^2) is the fact the symbolic run branches on
after the criterion (17 k^2 P + 57 w k mu P + 10 m g w^2 mu + 40 m g k^2 mu - 40 w^2 P -
30 m g w k), and the two slacks add up to 2 mu N."
  (call-with-bridge
   (lambda (b)
     (let ((fork '(+ (* 17 k k p) (* 57 w k mu p) (* 10 m g w w mu) (* 40 m g k k mu)
                   (* -40 w w p) (* -30 m g w k))))
       (is (eql 0 (ames.maxima:simplify
                   b `(- ,fork (* 40 (+ (* w w) (* k k)) ,(front-edge :lower))) :strategy :ratsimp))))
     (is (eql 0 (ames.maxima:simplify
                 b `(- (+ ,(front-edge :lower) ,(front-edge :upper)) (* 2 mu ,(front-edge :normal)))
                 :strategy :ratsimp))))))

(test front-edge-cannot-fail-both-friction-limits
  "Where the edge's lower limit fails (it slides forward), its upper one holds: DECIDE
proves mu N - F > 0 from F + mu N < 0 and the positive rest 2 mu N; where the lower limit
holds, it proves nothing, and at w = 1, k = 3, mu = 1/100, m g = 1, P = 1 (the block tips,
the lower limit holds) the upper one fails."
  (call-with-bridge
   (lambda (b)
     (let ((lower (front-edge :lower)) (upper (front-edge :upper)))
       (is (eq :true (decided b (cons `(< ,lower 0) *tipping-facts*) `(> ,upper 0))))
       (is (eq :false (decided b (cons `(< ,lower 0) *tipping-facts*) `(< ,upper 0))))
       (is (eq :unknown (decided b (cons `(> ,lower 0) *tipping-facts*) `(> ,upper 0))))
       (flet ((at (x)
                (ames.maxima:simplify
                 b (sublis '((w . 1) (k . 3) (mu . 1/100) (m . 1) (g . 1) (p . 1)) x))))
         ;; every assumption holds there
         (dolist (fact *tipping-facts*)
           (is (< 0 (at (if (eq (first fact) '>) `(- ,(second fact) ,(third fact)) `(- ,(third fact) ,(second fact)))))
               "~S fails at the point" fact))
         (is (> (at lower) 0))
         (is (< (at upper) 0)))))))

(test one-fact-and-a-positive-rest
  "2 (a - b) + x y > 0 follows from a > b and x, y > 0 (multiplier 2, rest x y), and so
does its quotient by x + y; 2 (a - b) - x y > 0 does not (it fails at a = b + 1/4, x = y
= 1)."
  (call-with-bridge
   (lambda (b)
     (let ((facts '((> x 0) (> y 0) (> (- a b) 0))))
       (is (eq :true (decided b facts '(> (+ (* 2 a) (* -2 b) (* x y)) 0))))
       (is (eq :true (decided b facts '(> (/ (+ (* 2 a) (* -2 b) (* x y)) (+ x y)) 0))))
       (is (not (eq :true (decided b facts '(> (- (+ (* 2 a) (* -2 b)) (* x y)) 0)))))))))
