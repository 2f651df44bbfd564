;;;; src/simulator/end-values.lisp -- every body's position and velocity when a state ends:
;;;; closed forms at the end time, numerically integrated values made exact, corners put
;;;; back on their faces (moved from states.lisp, unchanged).

(in-package #:ames.simulator)

(defun final-values (run groups fired what)
  "Every body's position (WHAT :POS) or velocity (:VEL) when the state ends at FIRED. A
numerically integrated body's end position is put exactly on the contacts FIRED reaches
(SNAP-ONTO-CONTACTS: the event's bisection leaves it a round-off, 1e-18, through the
face, and the next state would not find the contact), a body held on a circle exactly on
it, moving along it (SNAP-ONTO-HELD-CIRCLES), and a rotating body's corners on the
faces they touch, and its velocity along them (SNAP-CORNERS-ONTO-FACES and
SNAP-CORNER-VELOCITIES). With the run's parameter values, the end values are numbers
(VALUED-END-VALUES)."
  (let ((values (unsnapped-final-values run groups fired what)))
    (if (notany (lambda (group) (eq (group-kind group) :numeric)) groups)
        values
        ;; numbers at the run's values, not the integration's rationals times symbols
        (valued-end-values run (snapped-final-values run groups fired what values))))) ; numeric-ends.lisp

(defun snapped-final-values (run groups fired what values)
  "FINAL-VALUES' VALUES (unsnapped) of a state with a numeric group, put on the contacts
they reach (see FINAL-VALUES)."
  (cond ((eq what :pos)
         (let ((values (snap-onto-held-circles ; circle-snapping.lisp
                        run (snap-onto-contacts run values fired)))) ; numeric-roots.lisp
           (if (run-rotations run)
               (snap-corners-onto-faces run values ; corner-snapping.lisp
                                        (rotation-final-values run groups fired 'ames.kb:angle) fired)
               values)))
        ((null (run-rotations run))
         (snap-velocities-onto-held-circles run values (snapped-positions run groups fired) fired))
        (t (snap-corner-velocities run values (snapped-positions run groups fired)
                                   (rotation-final-values run groups fired 'ames.kb:angle)
                                   (rotation-final-values run groups fired 'ames.kb:angvel) fired))))

(defun snapped-positions (run groups fired)
  "The positions SNAPPED-FINAL-VALUES puts on their contacts, before the run's values are
put in: the exact points the velocities are put along (a circle's radius, a face's
place, as the geometry writes them)."
  (snapped-final-values run groups fired :pos (unsnapped-final-values run groups fired :pos)))

(defun unsnapped-final-values (run groups fired what)
  "FINAL-VALUES before the positions are put on the contacts reached."
  (mapcar (lambda (body)
            (list body
                  (cond
                    ((body-fixed-p run body) (body-motion run groups body what))
                    ((and (eq (group-kind (body-group groups body)) :numeric)
                          (null (group-end-state (body-group groups body)))
                          (ends-at-start-p fired))
                     ;; a numeric group never integrated: the state ends where it starts
                     (if (eq what :pos) (body-position run body) (body-velocity run body)))
                    ((eq (group-kind (body-group groups body)) :numeric)
                     (numeric-final-value run (body-group groups body) body what))
                    (t
                      (let* ((group (body-group groups body))
                             (at (group-at-end run groups group fired)))
                        (mapcar (lambda (x)
                                  (end-value run (substitute-expressions
                                                  (list (cons (group-variable group) at)) x)))
                                (body-motion run groups body what)))))))
          (body-names run)))

(defun end-value (run expression)
  "EXPRESSION, a closed form at a state's end, simplified for the next state: a sine or
cosine of an angle with an arc tangent in it (a spring's motion at a root found by the
half angle, sin(2 atan u)) expanded first, so that it becomes algebraic in u (2 u / (1 +
u^2)) and a velocity that vanishes there simplifies to 0. Where that expansion leaves
the algebra (a complex number: the angle holds a root Maxima writes with %i, as a
landing point found from a quartic), the expression is kept as it is."
  (tidy-real run (if (trig-of-atan-p expression)
                     (handler-case (tidy run expression :trigexpand)
                       (ames.maxima:untranslatable-result () expression))
                     expression)))

(defun trig-of-atan-p (expression)
  "True when EXPRESSION has a sine or cosine whose argument contains an arc tangent."
  (labels ((has-atan (x) (and (consp x) (or (eq (first x) 'atan) (some #'has-atan (rest x)))))
           (walk (x) (and (consp x)
                          (or (and (member (first x) '(sin cos)) (has-atan (second x)))
                              (some #'walk (rest x))))))
    (walk expression)))

(defun ends-at-start-p (fired)
  "True when the FIRED candidates end the state at its start (an impact there)."
  (and fired (every (lambda (candidate) (eql (candidate-time candidate) 0)) fired)))

(defun numeric-final-value (run group body what)
  "BODY's position (WHAT :POS) or velocity (:VEL) at the end of a numeric GROUP's state.
A body moving along a curved contact is put on it exactly: its obstacle's end value plus
the contact's point (or velocity) at the end arc length and speed, so that the next
state finds it on the contact's locus. A state that ends at once (an impact at its
start, before any integration: no end state) ends where it started."
  (unless (group-end-state group)
    (return-from numeric-final-value
      (if (eq what :pos) (body-position run body) (body-velocity run body))))
  (let* ((end (group-end-state group))
         (contact (find-if (lambda (k) (eq body (first (contact-bodies run k))))
                           (loop for term in (group-terms group)
                                 when (eq (first term) 'ames.kb:path-position) collect (second term))))
         (head (if (eq what :pos) 'ames.kb:pos 'ames.kb:vel)))
    (flet ((own (b axis) (rational-of (cdr (assoc (list head b axis) end :test #'equal))))
           (path (term) (rational-of (cdr (assoc (list term contact) end :test #'equal)))))
      (if (null contact)
          (list (own body :x) (own body :y))
          (let* ((obstacle (second (contact-bodies run contact)))
                 (base (if (body-fixed-p run obstacle)
                           (if (eq what :pos) (body-position run obstacle) '(0 0))
                           (list (own obstacle :x) (own obstacle :y))))
                 (geometry (contact-geometry run contact))
                 (s (path 'ames.kb:path-position)))
            (mapcar (lambda (x) (tidy run x))
                    (ames.geometry:v+ base (if (eq what :pos)
                                   (ames.geometry:contact-point geometry s)
                                   (ames.geometry:vscale (path 'ames.kb:path-speed)
                                              (ames.geometry:contact-unit-tangent geometry s))))))))))

(defun rational-of (x)
  "The double X as the exact rational it is (a numeric state's end value carried into
the next state's exact arithmetic), rounded to 15 significant digits."
  (rationalize (coerce (float x 1d0) 'double-float)))
