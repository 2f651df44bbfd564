;;;; src/simulator/oscillation.lisp -- a state that lasts forever as an oscillation with one
;;;; frequency: a mass on a spring, two masses on a spring with no drift.
;;;;
;;;; When nothing ends a state and every free body moves with a :LINEAR group (or stays at
;;;; rest), each position and velocity being A + B cos(w tau) + C sin(w tau) with one w for
;;;; all of them, the motion is periodic with the period 2 pi / |w| (2 pi sqrt(m/k) for a
;;;; mass on a spring, with the reduced mass m1 m2/(m1 + m2) for two free masses): the
;;;; state's notes get :PERIODIC (:PERIOD P :BETWEEN (S1 S2) :COORDINATE Q), S1 and S2 the
;;;; turning points A -+ sqrt(B^2 + C^2) of the first coordinate Q that oscillates (the
;;;; language's "Oscillation and turning points"). A body drifting (a term in tau) or two
;;;; frequencies make it no such state; nothing in it knows which force acts.

(in-package #:ames.simulator)

(defun motion-sinusoids (run group)
  "For each of GROUP's motion entries (TERM . EXPRESSION) that varies in TAU, the list
(TERM A B C W) with EXPRESSION = A + B cos(w tau) + C sin(w tau); NIL when an entry
varies otherwise (the second value then :OTHER)."
  (let ((waves '()))
    (dolist (entry (group-motion group) (values (nreverse waves) nil))
      (unless (free-of-p 'tau (cdr entry))
        (let ((parts (handler-case (ames.algebra:sinusoid-coefficients (run-bridge run) (cdr entry) 'tau)
                       (ames.maxima:maxima-condition () nil))))
          (unless parts (return-from motion-sinusoids (values nil :other)))
          (push (cons (car entry) parts) waves))))))

(defun linear-oscillation (run groups)
  "The plist (:PERIOD P :BETWEEN (S1 S2) :COORDINATE Q) of a state whose GROUPS move as
one oscillation (see the file header), or NIL."
  (let ((waves '()))
    (dolist (group groups)
      (case (group-kind group)
        (:constant (unless (every (lambda (entry) (free-of-p 'tau (cdr entry))) (group-motion group))
                     (return-from linear-oscillation nil)))
        (:linear (multiple-value-bind (group-waves other) (motion-sinusoids run group)
                   (when other (return-from linear-oscillation nil))
                   (setf waves (append waves group-waves))))
        (t (return-from linear-oscillation nil))))
    (when waves
      (let ((w (fifth (first waves))))
        (unless (and (sign-is run w :positive :negative)
                     (every (lambda (wave) (holds run `(= ,(fifth wave) ,w))) (rest waves)))
          (return-from linear-oscillation nil))
        (let ((position (or (find 'ames.kb:pos waves :key (lambda (wave) (first (first wave))))
                            (first waves))))
          (destructuring-bind (term a b c k) position
            (declare (ignore k))
            (let ((amplitude (tidy run `(sqrt (+ (expt ,b 2) (expt ,c 2))))))
              (list :period (tidy run `(/ (* 2 pi) ,(if (sign-is run w :positive) w `(- ,w))))
                    :between (list (tidy run `(- ,a ,amplitude)) (tidy run `(+ ,a ,amplitude)))
                    :coordinate term))))))))
