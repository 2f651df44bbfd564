;;;; t/rocking-symbolic.lisp -- the symbolic rocking block's rise (issue 23):
;;;; scenarios/awaiting-rotation/block-rocking-symbolic.lisp, its first state.
;;;;
;;;; With the declared "rough enough" (mu above the largest friction over the least normal
;;;; force at any angle, see the file's header) the run starts with the textbook's one
;;;; state, no fork: the block turns about its right edge, its normal force (m g / 4)((3 c
;;;; - b)^2 + 1 - b^2) > 0 and its friction within mu N proven at every angle
;;;; (src/algebra/sinusoid-quadratics.lisp), so the state ends where it turns back, at s* =
;;;; 2 atan(T) (t/atan-orders.lisp: the energy balance (1/2) I_edge w0^2 = m g ((k/2)(cos
;;;; s* - 1) - (w/2) sin s*)), at rest there. The run takes minutes on a loaded machine:
;;;; LONG-CHECKS (`make fuzz`).

(in-package #:ames.tests)

(defun rocking-symbolic-scenario (states)
  "The symbolic rocking block's scenario, simulated for STATES states."
  (let ((text (uiop:read-file-string
               (merge-pathnames "scenarios/awaiting-rotation/block-rocking-symbolic.lisp"
                                (asdf:system-source-directory "ames")))))
    (first (ames:read-scenarios-from-string
            (cl-ppcre:regex-replace "\\(simulate :states 3\\)" text
                                    (format nil "(simulate :states ~D)" states))))))

(test (symbolic-rocking-block-rises-and-turns-back :suite long-checks)
  "One state on the right edge, no fork: the textbook's normal force and friction along
the angle, its end the turning point s* = 2 atan(T), at rest."
  (with-fixture simulator-bridge ()
    (let* ((scenario (rocking-symbolic-scenario 1))
           (s 'ames.simulator::arc-length))
      (flet ((x (form)
               (sublis (cons (cons 's s)
                             (mapcar (lambda (p) (cons p (in-scenario-terms scenario p))) '(m g w k w0 mu)))
                       form)))
        (multiple-value-bind (history states) (run-of scenario bridge)
          (is (eq :state-limit (ames::history-outcome history)))
          (is (= 1 (length states)))
          (when (= 1 (length states))
            (let* ((rise (first states))
                   (forces (ames::state-forces rise)))
              (flet ((force (kind) (car (last (find kind forces :key #'first)))))
                (call-with-scenario-facts
                 bridge scenario
                 (lambda ()
                   (is (same-name-p* 'turns (first (ames::state-end-event rise))))
                   (is-same bridge "normal force along the rise"
                            (force :normal) (x (textbook-rocking-normal-force)))
                   (let ((friction (find :friction forces :key #'first)))
                     (is (eq :static (getf (cddddr friction) :mode)))
                     (is-same bridge "friction along the rise" (fourth friction) (x *rocking-friction*)))
                   (let ((angle (second (assoc 'block (ames::state-final-angles rise) :test #'same-name-p*))))
                     (is-same bridge "the turning angle" angle (x `(* 2 (atan ,*rocking-turning-tangent*)))))
                   (is-same bridge "at rest at the turning point"
                            (second (assoc 'block (ames::state-final-angular-velocities rise)
                                           :test #'same-name-p*))
                            0)))))))))))
