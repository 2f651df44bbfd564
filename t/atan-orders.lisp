;;;; t/atan-orders.lisp -- DECIDE compares an inverse tangent with an angle through tan
;;;; (src/algebra/atan-orders.lisp), and one square root by cases on the sign of the part
;;;; beside it (src/algebra/radical-cases.lisp).
;;;;
;;;; The symbolic rocking block (scenarios/awaiting-rotation/block-rocking-symbolic.lisp)
;;;; turns back at s* = 2 atan(T), T = (sqrt(A) - 3 g w) / B, A = 9 g^2 w^2 - 6 g k D^2
;;;; w0^2 - D^4 w0^4, B = 6 g k + D^2 w0^2, D^2 = w^2 + k^2: the root nearest 0 of B t^2 + 6
;;;; g w t + D^2 w0^2 (the energy balance (1/2) I_edge w0^2 = m g ((k/2)(cos s - 1) - (w/2)
;;;; sin s) in t = tan(s/2)). As the centre does not pass over the edge (the declared bound
;;;; on w0), -atan(w/k) < s* < 0, so s* > -pi/2 and s* > atan(k/w) - pi, which the run asks
;;;; as pi + 4 atan(T) < 0 (false) and the like. T > -1 holds although the sign of B - 3 g w
;;;; (a, beside the root) is not fixed: where a < 0, A - a^2 = 2 B (3 g w - 3 g k - D^2
;;;; w0^2) > 0 follows from a < 0.

(in-package #:ames.tests)

(def-suite atan-orders :in all-tests
  :description "DECIDE: an inverse tangent against an angle of multiples of pi and inverse
tangents, through tan; a square root against the part beside it, by cases.")

(in-suite atan-orders)

(defparameter *rocking-turning-tangent*
  (let ((d2 '(+ (expt w 2) (expt k 2))))
    `(/ (- (sqrt (- (* 9 (expt g 2) (expt w 2)) (* 6 g k ,d2 (expt w0 2))
                    (* (expt ,d2 2) (expt w0 4))))
           (* 3 g w))
        (+ (* 6 g k) (* ,d2 (expt w0 2)))))
  "tan(s*/2) at the symbolic rocking block's first turning point.")

(test rocking-turning-tangent-balances-the-energy
  "T is a root of B t^2 + 6 g w t + D^2 w0^2, so 2 atan(T) balances (1/2) I_edge w0^2
against the centre's rise m g ((k/2)(cos s - 1) - (w/2) sin s) (Maxima)."
  (call-with-bridge
   (lambda (b)
     (let ((tt *rocking-turning-tangent*) (d2 '(+ (expt w 2) (expt k 2))))
       (is (same-expression-p b `(+ (* (+ (* 6 g k) (* ,d2 (expt w0 2))) (expt ,tt 2))
                                    (* 6 g w ,tt) (* ,d2 (expt w0 2)))
                              0))
       ;; the energy balance at s = 2 atan(T), through sin s = 2T/(1+T^2), cos s = (1-T^2)/(1+T^2)
       (is (same-expression-p b `(- (* 1/6 ,d2 (expt w0 2))
                                    (* g (- (* 1/2 k (- (/ (- 1 (expt ,tt 2)) (+ 1 (expt ,tt 2))) 1))
                                            (* 1/2 w (/ (* 2 ,tt) (+ 1 (expt ,tt 2)))))))
                              0))))))

(test rocking-turning-angle-against-fixed-angles
  "Under the declared bound on w0, s* = 2 atan(T) lies in (-pi/2, 0) and above atan(k/w)
- pi; DECIDE proves it and refutes the opposite relations."
  (call-with-bridge
   (lambda (b)
     (let* ((tt *rocking-turning-tangent*) (s `(* 2 (atan ,tt))) (facts *rocking-bound-facts*))
       (is (eq :true (decided b facts `(> ,tt -1))))
       (is (eq :true (decided b facts `(< ,tt 0))))
       (is (eq :false (decided b facts `(< (+ pi (* 4 (atan ,tt))) 0))))
       (is (eq :true (decided b facts `(> ,s (- (atan (/ k w)) pi)))))
       (is (eq :false (decided b facts `(<= ,s (- (atan (/ k w)) pi)))))
       (is (eq :true (decided b facts `(< ,s 0))))
       ;; the centre is not past the edge at s*: its offset from the edge, -(w cos s* + k
       ;; sin s*)/2, is negative (linear in sin and cos of 2 atan(T): times 1 + T^2)
       (is (eq :true (decided b facts `(> (+ (* w (cos ,s)) (* k (sin ,s))) 0))))
       ;; the same through the half angle: (sqrt(w^2 + k^2) + w)/k > 1, so its atan is above
       ;; pi/4 and atan(T) > -pi/4 is above minus it
       (is (eq :false (decided b facts `(< (+ (atan ,tt) (atan (/ (+ (sqrt (+ (expt w 2) (expt k 2))) w) k))) 0))))))))

(test atan-against-constant-and-inverse-angles
  "atan(x) against q pi, -atan(y) + pi/2 and a span of angles: decided through tan where
the facts decide the tangents, and left open where a point breaks the relation."
  (call-with-bridge
   (lambda (b)
     (is (eq :true (decided b '((> x 1)) '(> (atan x) (/ pi 4)))))
     (is (eq :false (decided b '((> x 1)) '(< (- (* 4 (atan x)) pi) 0))))
     (is (eq :true (decided b '((< x -1)) '(< (+ pi (* 4 (atan x))) 0))))
     (is (eq :true (decided b '((> x (sqrt 3))) '(> (* 3 (atan x)) pi))))
     ;; tan(pi/2 - atan y) = 1/y: atan x < pi/2 - atan y when x < 1/y, not when x > 1/y
     (is (eq :true (decided b '((> y 0) (< x (/ 1 y))) '(< (atan x) (- (/ pi 2) (atan y))))))
     (is (eq :false (decided b '((> y 0) (> x (/ 1 y))) '(< (atan x) (- (/ pi 2) (atan y))))))
     ;; a span: (atan y - pi)/2 lies in (-pi/2, -pi/4), below atan x for x > -1
     (is (eq :true (decided b '((> x -1) (> y 0)) '(> (* 2 (atan x)) (- (atan y) pi)))))
     ;; beyond the range of atan: below -pi/2 always
     (is (eq :true (decided b '((> y 0)) '(> (atan x) (- (- (/ pi 2)) (atan y))))))
     ;; not decided where it fails somewhere: x = 1/2 and x = 2 (x > 0)
     (is (eq :unknown (decided b '((> x 0)) '(> (atan x) (/ pi 4))))))))

(test square-root-by-cases-on-the-part-beside-it
  "sqrt(A) against a part whose sign the facts leave open: proven where each case is,
and not where one case fails."
  (call-with-bridge
   (lambda (b)
     ;; sqrt(x^2 + 1) > x - 1 for every x (x - 1 < 0: trivially; else x^2 + 1 - (x - 1)^2
     ;; = 2 x > 0 as x > 1)
     (is (eq :true (decided b '() '(> (sqrt (+ (expt x 2) 1)) (- x 1)))))
     (is (eq :false (decided b '() '(<= (sqrt (+ (expt x 2) 1)) (- x 1)))))
     ;; but not sqrt(x^2 + 1) > x + 1 (fails at x = 1)
     (is (not (eq :true (decided b '() '(> (sqrt (+ (expt x 2) 1)) (+ x 1)))))))))
