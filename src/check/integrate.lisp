;;;; src/check/integrate.lisp -- the self-check's numeric integrator: classical Runge-Kutta of
;;;; order 4 with step doubling, in double floats.
;;;;
;;;; Independent of the simulator's Dormand-Prince integrator (numeric.lisp), which it may
;;;; have to check. Each step of size H is taken once whole and once as two halves; their
;;;; difference estimates the error, the halves' result corrected by Richardson's
;;;; extrapolation is kept, and H adapts so that the error per step stays under a relative
;;;; tolerance far below the 1e-8 the check asks of the closed forms.

(in-package #:ames.check)

(defparameter *step-tolerance* 1d-13
  "The relative (and absolute, per unit of the state's scale) error one step may make.")

(defparameter *step-limit* 200000
  "The most steps one self-check integration may take; beyond, the state is not checked.")

(defparameter *rate-round-off* (* 64 double-float-epsilon)
  "The round-off of a rate's double value, relative to its ROUND-OFF scale (see
*RATE-SCALES*): a few dozen units in the last place of the largest terms it adds.")

(defvar *rate-scales* nil
  "NIL, or a function of a state vector and a time giving the vector of the round-off
scales of the rates there (the sizes of the terms each adds, see ROUND-OFF-FORM): the
rates are then known no better than *RATE-ROUND-OFF* times these, and a step's error
estimate is not asked to go below the error their round-off makes over the step.")

(defvar *error-sum* nil
  "NIL, or the sum of the error estimates beyond *STEP-TOLERANCE* of the steps
INTEGRATE-RK4 has taken since it was bound to 0 (those the rates' round-off allowed, see
ROUND-OFF-FLOOR): what the round-off may have cost the integration, relative to the
state's sizes. 0 when every step kept to the tolerance.")

(defun round-off-floor (y time h)
  "The largest error estimate (as STEP-ERROR measures it, over 15) that the rates'
round-off alone can make over a step H from Y at TIME: H times their round-off, relative
to each component's size; 0 without *RATE-SCALES*. A rate computed as the small
difference of large terms (a rope's tension near its pulley: terms of 1e9 for a result
of 1e3) has a noise that a step's two estimates differ by in proportion to H, not to
H^5: demanding less than it shrinks the steps without end."
  (if *rate-scales*
      (let ((scales (funcall *rate-scales* y time)))
        (/ (* (abs h) *rate-round-off*
              (loop for i below (length y)
                    maximize (/ (svref scales i) (max 1d0 (abs (svref y i))))))
           15))
      0d0))

(define-condition integration-failed (ames-error) ()
  (:documentation "The self-check's integration could not go on: the rates have no value
(the motion leaves the region where the model is defined) or it takes too many steps."))

(defun rk4-step (rates y time h)
  "One classical Runge-Kutta step of size H from the state vector Y at TIME. RATES maps
a state vector and a time to the derivative vector."
  (let* ((n (length y))
         (k1 (funcall rates y time))
         (k2 (funcall rates (axpy y (* h 1/2) k1) (+ time (* h 1/2))))
         (k3 (funcall rates (axpy y (* h 1/2) k2) (+ time (* h 1/2))))
         (k4 (funcall rates (axpy y h k3) (+ time h)))
         (next (make-array n)))
    (dotimes (i n next)
      (setf (svref next i)
            (+ (svref y i) (* (/ h 6) (+ (svref k1 i) (* 2 (svref k2 i)) (* 2 (svref k3 i)) (svref k4 i))))))))

(defun axpy (y a k)
  "The vector Y + A K."
  (let ((result (copy-seq y)))
    (dotimes (i (length y) result)
      (incf (svref result i) (* a (svref k i))))))

(defun step-error (whole halves)
  "The largest error, relative to each component's size (at least 1), between a whole
step and two half steps."
  (loop for i below (length whole)
        maximize (/ (abs (- (svref whole i) (svref halves i)))
                    (max 1d0 (abs (svref halves i))))))

(defun integrate-rk4 (rates y0 from to)
  "The state vector at time TO, integrating RATES (a function of a state vector and a
time returning the derivative vector, signalling ARITHMETIC-ERROR where undefined) from
Y0 at time FROM. Signals INTEGRATION-FAILED."
  (let ((y (map 'simple-vector (lambda (x) (coerce x 'double-float)) y0))
        (time (coerce from 'double-float))
        (to (coerce to 'double-float))
        (steps 0))
    (when (<= to time) (return-from integrate-rk4 y))
    (let ((h (- to time)))
      (handler-case
          (loop while (< time to)
                do (when (> (incf steps) *step-limit*)
                     (error 'integration-failed :datum steps :detail "The self-check's integration took too many steps."))
                   (setf h (min h (- to time)))
                   (let* ((whole (rk4-step rates y time h))
                          (half (rk4-step rates y time (/ h 2)))
                          (halves (rk4-step rates half (+ time (/ h 2)) (/ h 2)))
                          (err (/ (step-error whole halves) 15))
                          ;; no finer than the rates' own round-off over the step
                          (tolerance (max *step-tolerance*
                                          (handler-case (round-off-floor y time h)
                                            (arithmetic-error () 0d0)))))
                     (if (and (> err tolerance) (> h (* 1d-14 (max 1d0 (abs to)))))
                         (setf h (* h (max 0.1d0 (* 0.9d0 (expt (/ tolerance err) 1/5)))))
                         (progn
                           ;; Richardson: the halves plus a fifteenth of their difference
                           (dotimes (i (length y))
                             (setf (svref halves i)
                                   (+ (svref halves i) (/ (- (svref halves i) (svref whole i)) 15))))
                           ;; a step the rates' round-off allowed beyond the tolerance
                           (when (and *error-sum* (> err *step-tolerance*)) (incf *error-sum* err))
                           (setf y halves time (if (>= (+ time h) to) to (+ time h)))
                           (setf h (* h (min 4d0 (* 0.9d0 (expt (/ tolerance (max err 1d-300)) 1/5)))))))))
        (arithmetic-error ()
          (error 'integration-failed :datum time
                                     :detail "The equations of motion have no value here: the self-check's integration stopped."))))
    y))

(defun integrate-grid (rates y0 end points)
  "The state vectors at POINTS + 1 equally spaced times from 0 to END, integrating RATES
from Y0: a list of (TIME . STATE)."
  (let ((y y0) (previous 0d0) (samples (list (cons 0d0 (coerce y0 'simple-vector)))))
    (loop for k from 1 to points
          for time = (* end (/ k points))
          do (setf y (integrate-rk4 rates y previous time) previous time)
             (push (cons (coerce time 'double-float) y) samples))
    (nreverse samples)))
