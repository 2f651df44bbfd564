;;;; src/check/package.lisp -- the self-check's package.

(defpackage #:ames.check
  (:use #:cl #:ames.base #:ames.simulator)
  (:documentation "The self-check: under parameter values, AMES checks the claims of a
simulation history before they are printed, with code that shares nothing with the
closed-form path: each state's closed-form positions and velocities against a numeric
(Runge-Kutta) integration of the state's equations of motion, its end against a numeric
search over every termination condition the knowledge base defines for it, its model's
equations against the solved quantities along that integration, and every number printed
beside a formula against that formula's value.")
  (:export
   #:self-check-history #:*self-check* #:self-check-failed-p #:self-check-result
   #:check-state #:check-failure #:check-failure-claim #:check-failure-discrepancy
   #:compile-numeric #:integrate-rk4))
