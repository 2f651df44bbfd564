;;;; src/witness/generate-drag.lisp -- random scenarios with drag (the language's "Drag"):
;;;; linear drag -b v (closed forms: exponentials, the damped oscillator) and quadratic drag
;;;; -c |v| v (closed forms along a line, numbers under values in two dimensions). The
;;;; witness (siconos_forces.py) integrates the same forces with Lsodar.
;;;;
;;;; The coefficients keep the motion of order one: a terminal speed m g / b (or
;;;; sqrt(m g / c)) between about 1 and 20 m/s, so that the drag matters over the run
;;;; without stopping the body at once.

(in-package #:ames.witness)

(defun drag-law-text (name body)
  "A drag clause NAME on BODY, linear or quadratic, with its coefficient's parameter
\(b or c) and value: returns the clause and the parameter's name and value."
  (if (zerop (random 2 *random*))
      (values (format nil "(drag ~A :on ~A :linear b)" name body) 'b (random-ratio 1/10 2 20))
      (values (format nil "(drag ~A :on ~A :quadratic c)" name body) 'c (random-ratio 1/50 1/2 100))))

(defun family-drag-fall (name)
  "A ball dropped, or thrown up, over the floor through a medium with linear or quadratic
drag; it lands (restitution 0, 1/2 or 1) and, when it bounces, rises and falls again."
  (multiple-value-bind (drag coefficient value) (drag-law-text "air" "ball")
    (let ((e (restitution-choice)))
      (scenario-text name "A ball falls through a medium with drag onto the floor."
                     (parameters-text 'g (random-ratio 5 15) 'm (random-ratio 1/2 3)
                                      'h (random-ratio 1/2 5) 'v (random-ratio 1/4 6)
                                      coefficient value)
                     (list (format nil "(restitution ~A)" e) (floor-text)
                           (format nil "(body ball :mass m :position (0 h) :velocity (0 ~A) :shape point)"
                                   (pick 0 "v" "(- v)"))
                           drag)
                     (if (zerop e) 3 4)))))

(defun family-drag-projectile (name)
  "A ball launched from the floor at an angle through a medium with linear or quadratic
drag (in two dimensions: closed forms for linear drag, numbers for quadratic), sometimes
under a constant horizontal push, landing on the floor (restitution 0 or 1/2)."
  (multiple-value-bind (drag coefficient value) (drag-law-text "air" "ball")
    (let ((e (pick 0 1/2)) (push (zerop (random 3 *random*))))
      (scenario-text name "A ball launched through a medium with drag lands on the floor."
                     (parameters-text 'g (random-ratio 5 15) 'm (random-ratio 1/2 3)
                                      'vx (random-ratio 1/4 6) 'vy (random-ratio 1/2 8)
                                      'f (random-ratio 1/4 3) coefficient value)
                     (list (format nil "(restitution ~A)" e) (floor-text)
                           (format nil "(body ball :mass m :position (0 0) :velocity ((* ~D vx) vy) :shape point)"
                                   (side))
                           (if push "(force push :on ball :value (f 0))" "")
                           drag)
                     (if (zerop e) 2 3)))))

(defun family-drag-slide (name)
  "A block sliding on a frictionless floor through a medium with linear or quadratic drag,
sometimes toward a wall (restitution 0, 1/2 or 1): with linear drag the block coasts at
most m v / b, and the wall is put well short of or well beyond that distance."
  (multiple-value-bind (drag coefficient value) (drag-law-text "oil" "block")
    (let* ((m (random-ratio 1/2 3)) (v (random-ratio 1/2 4))
           (reach (if (eq coefficient 'b) (/ (* m v) value) 10))
           (wall (and (zerop (random 2 *random*))
                      (+ 1 (* (min reach 10) (pick 1/2 3/2))))))
      (scenario-text name "A block slides through a medium with drag on a frictionless floor."
                     (parameters-text 'g (random-ratio 5 15) 'm m 'v v coefficient value)
                     (list (format nil "(restitution ~A)" (restitution-choice)) (floor-text)
                           (if wall
                               (format nil "(body wall :fixed t :shape (polygon (~A 0) (~A 0) (~A 2) (~A 2)))"
                                       wall (+ wall 1) (+ wall 1) wall)
                               "")
                           "(body block :mass m :position (0 0) :velocity (v 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))"
                           drag)
                     3))))

(defun family-drag-spring (name)
  "The damped oscillator: a block on a frictionless floor tied by a spring to a fixed
post, pulled out and released (or pushed) in a medium with linear drag, under-, critically
or over-damped as the values fall."
  (scenario-text name "A block on a spring in a viscous medium."
                 (parameters-text 'g (random-ratio 5 15) 'm (random-ratio 1/2 3) 'k (random-ratio 1 20)
                                  'b (random-ratio 1/10 4 20) 'l0 (random-ratio 1/2 2)
                                  'a (random-ratio 1/10 1/2 20) 'v (random-ratio 1/4 2))
                 (list (floor-text)
                       "(body post :fixed t :position (-1 0) :shape point)"
                       (format nil "(body block :mass m :position ((+ l0 a) 0) :velocity (~A 0) :shape point)"
                               (pick 0 "v" "(- v)"))
                       "(spring s :from (post (1 0)) :to (block (0 0)) :stiffness k :rest-length l0)"
                       "(drag oil :on block :linear b)")
                 2))

(defparameter *drag-families*
  '((:drag-fall . family-drag-fall) (:drag-projectile . family-drag-projectile)
    (:drag-slide . family-drag-slide) (:drag-spring . family-drag-spring))
  "The families with drag, added to *FAMILIES*.")

(dolist (entry *drag-families*)
  (unless (assoc (car entry) *families*)
    (setf *families* (append *families* (list entry)))))
