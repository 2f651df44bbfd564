;;;; src/algebra/periods.lisp -- the period of a swing between two turning points.
;;;;
;;;; A body whose energy integral is E(s) = A + D cos(k s - phi) with A < D (elliptic.lisp's
;;;; libration: a pendulum, a particle in a bowl) swings between the two roots of E around
;;;; the well. With mu = (A + D)/(2 D) and lambda = k sqrt(2 D)/2 its position is
;;;; (phi + 2 asin(sqrt(mu) sn(lambda t + u0 | mu)))/k, and sn has the period 4 K(mu): the
;;;; period of the swing is 4 K(mu)/lambda. For a particle in a bowl of radius r released at
;;;; theta0 (E = 2 g r (cos(s/r - pi/2) - cos theta0)) that is 4 sqrt(r/g) K(sin^2(theta0/2)),
;;;; the textbook pendulum's period.

(in-package #:ames.algebra)

(defun libration-period (bridge speed-squared position)
  "The period of the swing of a body whose speed squared along its path is SPEED-SQUARED
in POSITION, when that is a libration A + D cos(k s - phi), A < D proven (see the file
header): 4 K(mu) / lambda, simplified. NIL when SPEED-SQUARED has another shape or the
regime is not proven."
  (let ((wave (call-or-nil (lambda () (analyse-sinusoid bridge speed-squared position)))))
    (when (and wave (eq (sinusoid-regime wave) :libration)
               (eq (decide bridge `(< ,(sinusoid-a wave) ,(sinusoid-d wave))) :true))
      (let* ((a (sinusoid-a wave)) (d (sinusoid-d wave)) (k (sinusoid-k wave))
             (mu (simplified bridge `(/ (+ ,a ,d) (* 2 ,d))))
             (rate (simplified bridge `(/ (* ,k (sqrt (* 2 ,d))) 2))))
        (simplified bridge `(/ (* 4 (elliptic-k ,mu)) ,rate))))))
