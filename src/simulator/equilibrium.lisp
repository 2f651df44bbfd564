;;;; src/simulator/equilibrium.lisp -- a group that starts at rest in equilibrium stays there.
;;;;
;;;; A state's motion is the solution of its ODEs y' = F(y) from the start values y0. When
;;;; F(y0) = 0 exactly (every velocity, angular velocity and speed along a path is zero and
;;;; so is every acceleration), the constant y(t) = y0 is a solution, and the only one when
;;;; F is smooth (Lipschitz) near y0: the bodies stay at rest. Two spheres pressed together
;;;; by their gravitation after a plastic collision, a particle at rest on the top of a
;;;; dome, a ladder held by friction: the algebra decides this exactly; integrated
;;;; numerically instead, the start values in floating point sit off the equilibrium by
;;;; round-off (sin(pi) is 1.2e-16 in double floats), and a turning point or a lift-off
;;;; is found in the noise. Such a group is :CONSTANT: every state term keeps its start value.
;;;;
;;;; F must not depend on the time itself (a driven force may vanish at the start only),
;;;; and a root of odd order (sqrt(u), u^(1/3)) whose argument vanishes at the start may
;;;; let the motion leave the equilibrium (F is not Lipschitz there): such a group is left
;;;; to its integrator.

(in-package #:ames.simulator)

(defun non-lipschitz-bases (expression)
  "The bases of the fractional powers in EXPRESSION (sqrt(u), u^(p/q) with q > 1, or a
power not a number): where such a base vanishes, the expression may fail to be Lipschitz."
  (let ((bases '()))
    (labels ((walk (x)
               (when (consp x)
                 (case (first x)
                   (sqrt (push (second x) bases))
                   (expt (unless (integerp (third x)) (push (second x) bases))))
                 (mapc #'walk (rest x)))))
      (walk expression))
    bases))

(defun at-rest-in-equilibrium-p (run solved group)
  "True when every rate of GROUP's state terms in SOLVED (velocities, accelerations,
speeds and accelerations along paths, angular ones) is exactly zero at the start of the
state, no rate depends on the time, and no fractional power in them has a base that
vanishes at the start (see the file header)."
  (let ((initial (solved-model-initial solved))
        (terms (group-state-terms run solved group)))
    (and terms
         (every (lambda (term)
                  (let ((rate (cdr (assoc term (solved-model-rates solved) :test #'equal))))
                    (and rate
                         (free-of-p 'tau rate)
                         (eql 0 (tidy run (substitute-expressions initial rate) :full))
                         (every (lambda (base)
                                  (let ((b (tidy run (substitute-expressions initial base) :full)))
                                    (or (and (numberp b) (/= b 0))
                                        (holds run `(> ,b 0))
                                        (holds run `(< ,b 0)))))
                                (non-lipschitz-bases rate)))))
                terms))))

(defun integrate-equilibrium (run solved group)
  "When GROUP starts at rest in equilibrium (AT-REST-IN-EQUILIBRIUM-P), make it
:CONSTANT with every state term (positions, angles, arc lengths along curved contacts,
and their rates, all zero) kept at its start value, and return GROUP; else NIL."
  (when (at-rest-in-equilibrium-p run solved group)
    (setf (group-kind group) :constant
          (group-terms group) (group-state-terms run solved group)
          (group-motion group)
          (mapcar (lambda (term)
                    (cons term (cdr (assoc term (solved-model-initial solved) :test #'equal))))
                  (group-terms group)))
    group))
