;;;; src/simulator/flat-corner-snapping.lisp -- at the end of a numerically integrated state, a
;;;; rotating body resting by two corners on one face put back flat on it: its angle too.
;;;;
;;;; SNAP-CORNERS-ONTO-FACES (corner-snapping.lisp) moves a body's position only, its angle
;;;; kept. Two corners on one face (a block landed flat on the floor) cannot both be put on
;;;; it so: their gaps G1 and G2 differ by a function of the angle alone, D(theta) =
;;;; G1 - G2, free of the position, which the integration left at about 1e-12, not 0. Here
;;;; the angle is moved first, the least that makes D exactly 0: for a vertex on a face (or
;;;; two corners on parallel faces through one line) D = A cos theta + B sin theta, with A
;;;; and B exact (checked: D less that form simplifies to 0), so D = 0 at theta* =
;;;; atan(-A/B) + n pi (pi/2 + n pi when B = 0), n the integer that puts theta* nearest the
;;;; integrated angle. The tolerance is checked: theta* is used only within
;;;; *CORNER-SNAP-TOLERANCE* (relative to the larger of 1 and |theta|) of the integrated
;;;; angle, and only for two corners whose gaps are both within that tolerance (the
;;;; corners the state's event lifts off are left out, as in corner-snapping.lisp). The
;;;; position is then put on the faces at theta* as before (the second gap follows from
;;;; the first there). The angular velocity follows: the two gaps' rates differ by omega
;;;; D'(theta*), and D'(theta*) is not 0 where D has a simple root, so a body whose two
;;;; corners keep touching has omega = 0 exactly: an omega within the tolerance of 0
;;;; (relative to the larger of 1 and |omega|, as a rate of the gaps) is set to 0.

(in-package #:ames.simulator)

(defun gap-angle-difference (run body first second)
  "FIRST - SECOND, two gaps over BODY's position and angle, as a function of the symbol
SNAP-ANGLE when it is free of the position (its coefficients in x and y simplify to 0);
NIL otherwise."
  (let* ((x `(ames.kb:pos ,body :x)) (y `(ames.kb:pos ,body :y)) (angle `(ames.kb:angle ,body))
         (over (substitute-expressions (list (cons x 'snap-x) (cons y 'snap-y) (cons angle 'snap-angle))
                                       `(- ,first ,second)))
         (dx (tidy run (ames.geometry:differentiate over 'snap-x)))
         (dy (tidy run (ames.geometry:differentiate over 'snap-y))))
    (and (eql dx 0) (eql dy 0)
         (tidy run (substitute-expressions (list (cons 'snap-x 0) (cons 'snap-y 0)) over)))))

(defun sinusoid-parts (run difference)
  "(A B) with DIFFERENCE (over SNAP-ANGLE) exactly A cos + B sin of it, A and B exact
constants; NIL when it is not of that form."
  (flet ((at (angle) (tidy run (substitute-expressions (list (cons 'snap-angle angle)) difference) :full)))
    (let* ((at-0 (at 0)) (at-half (at '(/ pi 2))) (at-pi (at 'pi))
           (c (tidy run `(/ (+ ,at-0 ,at-pi) 2)))
           (a (tidy run `(/ (- ,at-0 ,at-pi) 2)))
           (b (tidy run `(- ,at-half ,c))))
      (and (eql c 0)
           (every (lambda (e) (realp (snap-number run e))) (list a b))
           (eql 0 (tidy run `(- ,difference (+ (* ,a (cos snap-angle)) (* ,b (sin snap-angle)))) :full))
           (list a b)))))

(defun flat-angle (run difference theta)
  "The angle theta* nearest THETA (a rational) where DIFFERENCE (over SNAP-ANGLE, A cos +
B sin) is exactly 0, and its value as a double; NIL when DIFFERENCE has no such form or
is identically 0."
  (let ((parts (sinusoid-parts run difference)))
    (when parts
      (destructuring-bind (a b) parts
        (let ((an (snap-number run a)) (bn (snap-number run b)))
          (unless (and (zerop an) (zerop bn))
            (let* ((base (if (zerop bn) '(/ pi 2) `(atan (/ (- ,a) ,b))))
                   (base-value (snap-number run base))
                   (turns (and base-value (round (- (coerce theta 'double-float) base-value) pi))))
              (when turns
                (let ((angle (tidy run `(+ ,base (* ,turns pi)) :full)))
                  (values angle (snap-number run angle)))))))))))

(defun flat-corner-angle (run body theta position fired)
  "The angle theta* that puts two of BODY's corners near one face (within the tolerance,
at POSITION and THETA) exactly flat on it (see the file header), or NIL when there are
no such two corners, or theta* is further from THETA than the tolerance; a body's face
flush with a fixed face, a corner of each on the other's, likewise (FLUSH-CORNER-ANGLE).
Second value: D'(theta*), the rate of the two gaps' difference per unit angle (a double)."
  (multiple-value-bind (conditions tolerance gaps)
      (corner-snap-conditions run body theta position (leaving-contacts fired))
    (declare (ignore conditions tolerance))
    (loop for (first . others) on gaps
          do (dolist (second others)
               (let ((difference (gap-angle-difference run body first second)))
                 (when difference
                   (multiple-value-bind (angle value) (flat-angle run difference theta)
                     (when (and angle value
                                (<= (abs (- value theta))
                                    (* *corner-snap-tolerance* (max 1d0 (abs (coerce theta 'double-float))))))
                       (let ((slope (snap-number run (substitute-expressions
                                                      (list (cons 'snap-angle angle))
                                                      (ames.geometry:differentiate difference 'snap-angle)))))
                         (when (and slope (/= slope 0d0))
                           (return-from flat-corner-angle (values angle slope))))))))))
    ;; a corner of each body on the other's face: flush-corner-snapping.lisp
    (flush-corner-angle run body theta position gaps)))

(defun snap-flat-rotation (run group body head value fired)
  "VALUE, BODY's angle (HEAD ANGLE) or angular velocity (ANGVEL) at the end of its
numeric GROUP's state (a rational), with the body put back flat on a face it rests on by
two corners (FLAT-CORNER-ANGLE): the angle theta*, the angular velocity 0 when it is
within the tolerance of it; else VALUE."
  (let* ((theta (rational-of (cdr (assoc `(ames.kb:angle ,body) (group-end-state group) :test #'equal))))
         (position (numeric-final-value run group body :pos)))
    (multiple-value-bind (angle slope) (flat-corner-angle run body theta position fired)
      (cond ((null angle) value)
            ((eq head 'ames.kb:angle) angle)
            ((and (eq head 'ames.kb:angvel)
                  (<= (abs (* (coerce value 'double-float) slope))
                      (* *corner-snap-tolerance* (max 1d0 (abs (coerce value 'double-float))))))
             0)
            (t value)))))
