;;;; src/simulator/frozen-rotation.lisp -- a rotating body held at rest in its angle: its
;;;; translation integrated in closed form.
;;;;
;;;; A block sliding flat on two of its corners has a model over (x, y, theta, omega): the
;;;; contacts' constraints give its angular acceleration as a function of theta and omega
;;;; (and its acceleration with omega^2 / cos theta terms), so the rates mention the state
;;;; and the group would be integrated numerically. But where each rotating body starts
;;;; with omega = 0 and its angular acceleration vanishes at theta = theta0, omega = 0
;;;; whatever the other state terms are, theta = theta0, omega = 0 is part of the solution
;;;; (the rates of theta and omega vanish along it; the solution from the initial values
;;;; is unique), and the other rates, with theta0 and 0 put in, are those of the motion.
;;;; When they mention no state term then, the group is :CONSTANT: its accelerations
;;;; are their values at the start, and its angular accelerations 0.

(in-package #:ames.simulator)

(defun frozen-rotation-bindings (run solved group)
  "The bindings (angle B) -> theta0, (angvel B) -> 0 of GROUP's rotating bodies when each
starts with no angular velocity and its angular acceleration in SOLVED vanishes
identically under them (see the file header); else NIL."
  (let ((bodies (group-rotating-bodies run group)))
    (when bodies
      (let ((bindings (loop for body in bodies
                            for omega0 = (body-angular-velocity run body)
                            unless (and omega0 (sign-is run omega0 :zero))
                              do (return-from frozen-rotation-bindings nil)
                            collect (cons `(ames.kb:angle ,body) (body-angle run body))
                            collect (cons `(ames.kb:angvel ,body) 0))))
        (and (every (lambda (body)
                      (let ((rate (angular-rate solved body)))
                        (and rate
                             (eql 0 (tidy run (substitute-expressions bindings rate) :full)))))
                    bodies)
             bindings)))))

(defun frozen-rotation-constant-p (run solved group rates)
  "True when GROUP's RATES (its accelerations and angular accelerations) mention no state
term once its rotating bodies are held at rest in their angles (FROZEN-ROTATION-BINDINGS):
the group then moves with constant accelerations."
  (let ((bindings (frozen-rotation-bindings run solved group)))
    (and bindings
         (notany (lambda (rate) (mentions-state-p solved (substitute-expressions bindings rate)))
                 rates))))

(defun frozen-rotation-p (run solved group)
  "True when GROUP, classified :CONSTANT, is so only with its rotating bodies held at rest
in their angles (its rates in SOLVED mention the state): a group at rest in equilibrium
then keeps the equilibrium's integrator (equilibrium.lisp), as it had before."
  (some (lambda (rate) (and rate (mentions-state-p solved rate)))
        (append (loop for body in (group-bodies group)
                      append (loop for axis in '(:x :y)
                                   collect (cdr (assoc `(ames.kb:vel ,body ,axis)
                                                       (solved-model-rates solved) :test #'equal))))
                (rotation-rates run solved group))))
