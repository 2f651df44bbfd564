;;;; src/simulator/turning-point-snapping.lisp -- at the end of a numerically integrated
;;;; state, a body held on a circle given the speed along it at which the event that ended
;;;; the state holds exactly.
;;;;
;;;; Circle snapping (circle-snapping.lisp) puts a body held on a circle exactly on it and
;;;; removes its velocity's radial part; the part along the circle is the integration's,
;;;; as a short rational. When the state ended on an event whose function is written over
;;;; positions and velocities alone (a swing's angular rate, (B - A) x (B' - A'), whose
;;;; sign change is a turning point), that function is exactly zero at the event: with
;;;; the positions exact and the velocity s u along the circle's unit tangent u, it is
;;;; linear in s, and its root s* is the speed the event means. s* replaces the integrated
;;;; speed when it is a rational number within the snapping tolerance of it: at a
;;;; turning point s* = 0, and the next state starts at rest exactly (its start judged by
;;;; the local series after it: a rope piece at rest turns at once, choice.lisp's
;;;; FORCED-EXIT), not with the integration's 1e-11. Any other event (its function over a
;;;; model quantity, or not linear in s) leaves the speed as it is.

(in-package #:ames.simulator)

(defun position-velocity-function-p (expression)
  "True when EXPRESSION's quantity terms are all positions and velocities."
  (every (lambda (term) (member (first term) '(ames.kb:pos ames.kb:vel)))
         (remove-if-not #'quantity-term-p (expression-variables expression))))

(defun speed-root (run body tangent positions velocities function)
  "The speed s along TANGENT of BODY at which FUNCTION (over positions and velocities)
vanishes with the other bodies at POSITIONS and VELOCITIES, when it is linear in s with
a decided non-zero slope: an expression free of the motion, or NIL."
  (let* ((s (ames.maxima:keyed-auxiliary-variable (run-bridge run) (list :turning-speed body)
                                                  "CIRCLE-SPEED"))
         (bindings (loop for (name at) in positions
                         append (list (cons `(ames.kb:pos ,name :x) (first at))
                                      (cons `(ames.kb:pos ,name :y) (second at)))))
         (speeds (loop for (name v) in velocities
                       for own = (if (eq name body) (list `(* ,s ,(first tangent)) `(* ,s ,(second tangent))) v)
                       append (list (cons `(ames.kb:vel ,name :x) (first own))
                                    (cons `(ames.kb:vel ,name :y) (second own)))))
         (at-end (substitute-expressions (append bindings speeds) function)))
    (when (null (motion-terms at-end))
      (let ((coefficients (ames.maxima:call-or-nil
                           (lambda () (ames.maxima:polynomial-coefficients-in (run-bridge run) at-end s)))))
        (when (and (= 2 (length coefficients))
                   (member (one-sign (sign-of run (second coefficients))) '(:positive :negative)))
          (tidy run `(- (/ ,(first coefficients) ,(second coefficients)))))))))

(defun event-speed-on-circle (run body tangent positions velocities fired along)
  "The speed along the circle (unit TANGENT) of BODY at which one of the FIRED candidates'
relations holds exactly at the state's end (see the file header), when it is a rational
within the snapping tolerance of the integrated speed ALONG; else NIL."
  (dolist (candidate fired)
    (let* ((condition (candidate-condition candidate))
           (relation (and condition (ames.engine:termination-condition-relation condition))))
      (when (and relation (member (first relation) '(< > <= >=))
                 (position-velocity-function-p relation))
        (let ((root (handler-case (speed-root run body tangent positions velocities
                                              `(- ,(relation-lhs relation) ,(relation-rhs relation)))
                      (ames-error () nil))))
          (when (and (rationalp root)
                     (<= (abs (- root along)) (* *circle-snap-tolerance* (max 1 (abs along)))))
            (return root)))))))
