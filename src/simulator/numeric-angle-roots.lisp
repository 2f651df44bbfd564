;;;; src/simulator/numeric-angle-roots.lisp -- where a condition fires along a rotation path
;;;; whose root has no closed form, searched with numbers (under parameter values).
;;;;
;;;; Along a :ROTATION-PATH motion (rotation-path.lisp) a condition is a function of the
;;;; angle theta; a block tipping about its edge has a normal force and a friction limit
;;;; that are quadratic in sin theta and cos theta, whose zeros the algebra's proven root
;;;; search (COORDINATE-ROOT-AHEAD) leaves :UNKNOWN. When every parameter has a number, the
;;;; function is sampled ahead of the start in the direction of motion, a 512th of a turn a
;;;; step, up to one full turn (the conditions are periodic in theta) or up to where the
;;;; energy integral E(theta) = omega^2 turns negative (the body turns back before: not
;;;; reached), and a crossing below zero is bisected to double precision, as
;;;; numeric-roots.lisp does in time. A condition not found crossing stays undecided:
;;;; never is not proven by numbers.

(in-package #:ames.simulator)

(defparameter *angle-search-steps* 512
  "The samples per full turn of the numeric search along a rotation path.")

(defun angle-function (run group expression)
  "EXPRESSION (of the angle +ARC-LENGTH+) as a function of the distance turned u >= 0
ahead of GROUP's start under the run's parameter values: a double, or NIL where it has
no value. NIL when the start has no value."
  (let* ((bindings (numeric-bindings run))
         (start (expression-value (group-s0 group) bindings))
         (direction (group-direction group)))
    (when (realp start)
      (lambda (u)
        (let ((value (expression-value expression
                                       (acons +arc-length+ (+ start (* direction u)) bindings))))
          (and (realp value) (coerce value 'double-float)))))))

(defun numeric-turning-reach (run group)
  "How far GROUP's body turns ahead before its energy integral turns negative, within a
full turn: a double (the full turn when it does not), or NIL when not known."
  (let ((energy (angle-function run group (group-speed-squared group)))
        (turn (* 2 pi)))
    (when energy
      (or (first-numeric-crossing energy (constantly nil) (/ turn *angle-search-steps*) turn)
          turn))))

(defun numeric-angle-root (run group function)
  "Under the run's parameter values, the first angle ahead of GROUP's start where
FUNCTION (of the angle) crosses below zero before the body turns back (see the file
header), as an exact rational; NIL when none is found or the run has no numbers."
  (when (run-numbers-known-p run)
    (let ((f (angle-function run group function))
          (reach (numeric-turning-reach run group)))
      (when (and f reach)
        (let ((u (first-numeric-crossing f (constantly nil)
                                         (/ (* 2 pi) *angle-search-steps*) reach)))
          (when (and u (plusp u) (< u reach))
            (rational-of (+ (expression-value (group-s0 group) (numeric-bindings run))
                            (* (group-direction group) u)))))))))

(defun numeric-reached-p (run group s)
  "True when, under the run's parameter values, GROUP's body reaches the angle S (a
number) before its energy integral turns negative."
  (when (run-numbers-known-p run)
    (let ((reach (numeric-turning-reach run group))
          (start (expression-value (group-s0 group) (numeric-bindings run)))
          (target (expression-value s (numeric-bindings run))))
      (and reach (realp start) (realp target)
           (< (* (group-direction group) (- target start)) reach)))))

(defun numeric-angle-order (run group a b)
  "Whether the angle A comes before B along GROUP's rotation path, by the run's numbers,
when one of them was found with numbers (a rational; NUMERIC-ANGLE-ROOT): :TRUE or
:FALSE; NIL otherwise (for any other group, or numbers too close to tell), the proof is
then the algebra's."
  (when (and (eq (group-kind group) :rotation-path) (run-numbers-known-p run)
             (or (rationalp a) (rationalp b)))
    (let ((bindings (numeric-bindings run)))
      (let ((na (expression-value a bindings)) (nb (expression-value b bindings)))
        (when (and (realp na) (realp nb)
                   (> (abs (- na nb)) (* 1d-9 (max 1d0 (abs na)))))
          (if (< (* (group-direction group) (- na nb)) 0) :true :false))))))
