;;;; t/one-freedom.lisp -- one degree of freedom with a configuration-dependent inertia
;;;; (src/algebra/one-freedom.lisp): the rod on a hinge, the ladder, a bead on a parabola.
;;;;
;;;; Textbook results checked by Maxima equivalence (or by value where elliptic integrals
;;;; are compared), numbers against an independent quadrature written here.

(in-package #:ames.tests)

(def-suite one-freedom :in bridge
  :description "The energy integral of one degree of freedom with inertia M(q): q' of q,
constraint forces along the motion, turning points, travel times and periods.")

(in-suite one-freedom)

(defparameter *hinged-rod-parts* '((m (/ (* m (expt l 2)) 12) (* (/ l 2) (cos q)) (* (/ l 2) (sin q)) q))
  "A uniform rod of length l hinged at its end at the origin, at angle q.")

(defparameter *ladder-parts* '((m (/ (* m (expt l 2)) 12) (- (* (/ l 2) (cos q))) (* (/ l 2) (sin q)) q))
  "A uniform ladder of length l, its foot on the floor y = 0 and its top on the wall
x = 0, at angle q (pi - q with the floor).")

(defun o-system (b parts potential start &optional (rate 0))
  (ames.algebra:make-one-freedom b :coordinate 'q :inertia (ames.algebra:generalized-inertia b parts 'q)
                                   :potential potential :start start :rate rate))

(test hinged-rod-reaches-the-bottom-at-root-3g-over-l
  (g-call-with-bridge
   '((> m 0) (> g 0) (> l 0))
   (lambda (b)
     (is (ames.maxima:equivalent-p b (ames.algebra:generalized-inertia b *hinged-rod-parts* 'q)
                                   '(/ (* m (expt l 2)) 3)))
     (let ((rod (o-system b *hinged-rod-parts* '(* m g (/ l 2) (sin q)) 0)))
       ;; released horizontal it falls clockwise, from alpha = -3 g / (2 l)
       (is (eql -1 (ames.algebra:one-freedom-direction rod)))
       (is (ames.maxima:equivalent-p b (substitute-expressions '((q . 0)) (ames.algebra:one-freedom-acceleration rod))
                                     '(- (/ (* 3 g) (* 2 l)))))
       ;; omega^2 = 3 g / l at the bottom
       (is (ames.maxima:equivalent-p b (substitute-expressions '((q . (- (/ pi 2))))
                                                               (ames.algebra:one-freedom-speed-squared rod))
                                     '(/ (* 3 g) l)))
       ;; the hinge's vertical pull m y'' + m g: m g / 4 at release, (5/2) m g at the bottom
       (let ((hinge (ames.algebra:along-motion b rod '(+ (* m (/ l 2) (- (* (cos q) al) (* (sin q) (expt w 2)))) (* m g))
                                               :rate 'w :acceleration 'al)))
         (is (ames.maxima:equivalent-p b (substitute-expressions '((q . 0)) hinge) '(/ (* m g) 4)))
         (is (ames.maxima:equivalent-p b (substitute-expressions '((q . (- (/ pi 2)))) hinge) '(* 5/2 m g))))
       ;; it turns at the horizontal on the other side
       (multiple-value-bind (root status) (ames.algebra:turning-point b rod)
         (is (eq :found status))
         (is (ames.maxima:equivalent-p b root '(- pi))))
       ;; the quarter swing's time in closed form agrees with the quadrature
       (multiple-value-bind (time kind) (ames.algebra:coordinate-travel-time b rod '(- (/ pi 2)))
         (is (eq :closed-form kind))
         (is (close-to-p (ames.maxima:numeric-value b time '((g . 981/100) (l . 1) (m . 1)))
                         (ames.algebra:numeric-travel-time b (ames.algebra:one-freedom-speed-squared rod) 'q
                                                           0 '(- (/ pi 2)) '((g . 981/100) (l . 1) (m . 1)))
                         1d-8)))
       ;; the period of the physical pendulum swung from the horizontal: 4 sqrt(2 l/(3 g)) K(1/2)
       (multiple-value-bind (period kind between) (ames.algebra:swing-period b rod)
         (is (eq :closed-form kind))
         (is (ames.maxima:equivalent-p b (first between) 0))
         (is (ames.maxima:equivalent-p b (second between) '(- pi)))
         (dolist (point '(((g . 981/100) (l . 1)) ((g . 2) (l . 7/2))))
           (is (close-to-p (ames.maxima:numeric-value b period point)
                           (ames.maxima:numeric-value b '(* 4 (sqrt (/ (* 2 l) (* 3 g))) (elliptic-k 1/2)) point)
                           1d-10))))))))

(test ladder-leaves-the-wall-at-two-thirds-of-its-height
  (g-call-with-bridge
   '((> m 0) (> g 0) (> l 0) (> a 0) (< a (/ pi 2)))
   (lambda (b)
     (is (ames.maxima:equivalent-p b (ames.algebra:generalized-inertia b *ladder-parts* 'q)
                                   '(/ (* m (expt l 2)) 3)))
     (let ((ladder (o-system b *ladder-parts* '(* m g (/ l 2) (sin q)) '(- pi a))))
       ;; phi = pi - q its angle to the floor: phi'^2 = 3 g (sin a - sin phi) / l
       (is (eql 1 (ames.algebra:one-freedom-direction ladder)))
       (is (ames.maxima:equivalent-p b (ames.algebra:one-freedom-speed-squared ladder)
                                     '(/ (* 3 g (- (sin a) (sin q))) l)))
       ;; the wall's push is m x'': zero when the top is at 2/3 of its starting height
       (let ((wall (ames.algebra:along-motion b ladder '(* m (/ l 2) (+ (* (sin q) al) (* (cos q) (expt w 2))))
                                              :rate 'w :acceleration 'al)))
         (is (ames.maxima:equivalent-p b wall '(* 3/2 m g (cos q) (- (sin a) (* 3/2 (sin q))))))
         ;; its factors cos q and sin a - (3/2) sin q vanish ahead at 3 pi/2 and at
         ;; pi - asin((2/3) sin a), the earlier (sine-roots.lisp gives the asin form)
         (multiple-value-bind (root status) (ames.algebra:earliest-coordinate-root b ladder wall)
           (is (eq :found status))
           (is (ames.maxima:equivalent-p b root '(- pi (asin (* 2/3 (sin a))))))
           (is (ames.maxima:equivalent-p b `(* l (sin ,root)) '(* 2/3 l (sin a))))
           ;; the cos factor alone: its first zero ahead is 3 pi/2
           (is (ames.maxima:equivalent-p
                b (ames.algebra:coordinate-root-ahead b '(cos q) 'q '(- pi a) 1) '(* 3/2 pi)))
           ;; the top reaches the floor (its height l sin q vanishes) at q = pi, later
           (is (ames.maxima:equivalent-p b (ames.algebra:coordinate-root-ahead b '(* l (sin q)) 'q '(- pi a) 1) 'pi))
           ;; the time it takes, in closed form, agrees with the quadrature
           (multiple-value-bind (time kind) (ames.algebra:coordinate-travel-time b ladder root)
             (is (eq :closed-form kind))
             (let ((point '((g . 981/100) (l . 1) (a . 1))))
               (is (close-to-p (ames.maxima:numeric-value b time point)
                               (ames.algebra:numeric-travel-time
                                b (ames.algebra:one-freedom-speed-squared ladder) 'q
                                (ames.maxima:numeric-value b '(- pi a) point)
                                (ames.maxima:numeric-value b root point) point)
                               1d-8))))))))))

(defun o-bead-period (g)
  "An independent quadrature of the bead's period on y = x^2 from x = 1 at rest:
4 times the integral over [0, pi/2] of sqrt((1 + 4 sin^2 p) / (2 g)) dp (x = sin p), by
Simpson's rule on 2000 intervals."
  (let* ((n 2000) (h (/ pi 2 n)))
    (flet ((f (p) (sqrt (/ (+ 1 (* 4 (expt (sin p) 2))) (* 2 g)))))
      (* 4 (/ h 3) (loop for i from 0 to n
                         sum (* (cond ((or (= i 0) (= i n)) 1) ((oddp i) 4) (t 2))
                                (f (* i h))))))))

(test bead-on-a-parabola-swings-with-a-varying-inertia
  (g-call-with-bridge
   '((> m 0) (> g 0))
   (lambda (b)
     ;; a particle on y = x^2 (x = q): M = m (1 + 4 q^2), V = m g q^2, released at q = 1
     (let ((bead (o-system b '((m 0 q (expt q 2) 0)) '(* m g (expt q 2)) 1)))
       (is (ames.maxima:equivalent-p b (ames.algebra:one-freedom-inertia bead) '(* m (+ 1 (* 4 (expt q 2))))))
       (is (ames.maxima:equivalent-p b (ames.algebra:one-freedom-speed-squared bead)
                                     '(/ (* 2 g (- 1 (expt q 2))) (+ 1 (* 4 (expt q 2))))))
       (is (eql -1 (ames.algebra:one-freedom-direction bead)))
       (multiple-value-bind (root status) (ames.algebra:turning-point b bead)
         (is (eq :found status))
         (is (eql -1 root)))
       ;; no elliptic form of this one here: under values a number, marked so
       (multiple-value-bind (period kind between) (ames.algebra:swing-period b bead :values '((g . 981/100) (m . 1)))
         (is (member kind '(:closed-form :numeric)))
         (is (equal '(1 -1) between))
         (is (close-to-p (if (eq kind :numeric)
                             period
                             (ames.maxima:numeric-value b period '((g . 981/100) (m . 1))))
                         (o-bead-period 9.81d0) 1d-7)))))))
