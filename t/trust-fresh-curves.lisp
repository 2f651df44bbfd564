;;;; t/trust-fresh-curves.lisp -- issue 20, classes 2 and 7 on a curve, written fresh for
;;;; these tests: a particle kicked along the bottom of a circular bowl, symbolic.
;;;;
;;;; Its run used to fork four times on facts that always hold (atan2(y, x) - pi > 0, which
;;;; the polar angle's range excludes; v0^4 - 4 g r v0^2 <= 0, which v0 < sqrt(2 g r) gives
;;;; squared; the energy integral at the mirror turning point, exactly 0, which is() could
;;;; not read because logarc() knows no atan2) and to end ambiguous. Closed forms are checked
;;;; by Maxima equivalence, the elliptic period by its values.

(in-package #:ames.tests)

(in-suite trust-fresh)

(defparameter *kicked-in-a-bowl*
  "(scenario kicked-in-a-bowl
     \"A particle kicked along the bottom of a circular bowl swings for ever.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 10)) (r :positive (:value 1))
                 (v0 :positive (< v0 (sqrt (* 2 g r))) (:value 2)))
     (gravity g)
     (body bowl :fixed t :shape (arc :center (0 r) :radius r :from pi :to (* 2 pi) :solid :outside))
     (body p :mass m :position (0 0) :velocity (v0 0) :shape point)
     (simulate :states 2))"
  "Kicked at v0 < sqrt(2 g r) it turns at height v0^2/(2 g), where cos theta0 = 1 - v0^2/(2 g r),
and then swings between the two turning points with the pendulum's period 4 sqrt(r/g)
K(sin^2(theta0/2)) = 4 sqrt(r/g) K(v0^2/(4 g r)).")

(test a-particle-kicked-in-a-bowl-turns-and-swings-with-the-pendulum-period
  "Without values: no fork; the first state ends where the particle turns, at (v0 sqrt(4 g
r - v0^2)/(2 g), v0^2/(2 g)), at rest; the second swings for ever with period 4 sqrt(r/g)
K(v0^2/(4 g r)) between two turning points at that height."
  (with-fixture simulator-bridge ()
    (let* ((scenario (first (ames:read-scenarios-from-string *kicked-in-a-bowl*)))
           (history (ames:simulate scenario :bridge bridge))
           (states (ames:history-states history)))
      (is (eq :complete (ames:history-outcome history)) "outcome ~S" (ames:history-outcome history))
      (is (notany #'ames::state-branches states) "a fork on a fact that always holds")
      (destructuring-bind (&optional rise swing) states
        (when swing
          (flet ((x (form) (in-scenario-terms scenario form)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same-vector bridge "where it turns" (per-body (ames::state-final-positions rise) "P")
                               (x '((/ (* v0 (sqrt (- (* 4 g r) (expt v0 2)))) (* 2 g)) (/ (expt v0 2) (* 2 g)))))
               (is-same-vector bridge "at rest there" (per-body (ames::state-final-velocities rise) "P") '(0 0))))
            (is (eq :forever (ames::state-duration swing)))
            (let ((periodic (ames.simulator:state-periodic swing)))
              (is (not (null periodic)))
              (loop for (g r v0) in '((10 1 2) (981/100 2 3) (1 1/2 1/2))
                    for bindings = (in-scenario-terms scenario `((m . 1) (g . ,g) (r . ,r) (v0 . ,v0)))
                    for expected = (* 4 (sqrt (float (/ r g) 1d0))
                                      (expression-value `(elliptic-k ,(/ (* v0 v0) (* 4 g r)))))
                    for got = (and periodic (expression-value (getf periodic :period) bindings))
                    do (is (and got (< (abs (- got expected)) (* 1d-9 expected)))
                           "period ~A, expected ~A" got expected)
                       ;; both turning points at the height v0^2/(2 g): y = r - r sin(s/r)
                       (dolist (s (getf periodic :between))
                         (let ((height (- r (* r (sin (/ (expression-value s bindings) r))))))
                           (is (< (abs (- height (/ (* v0 v0) (* 2 g)))) 1d-9)
                               "turning height ~A at ~S" height s)))))))))))
