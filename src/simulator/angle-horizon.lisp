;;;; src/simulator/angle-horizon.lisp -- under values, the conditions along a rotation path
;;;; that cannot come first, set aside by numbers before any proof.
;;;;
;;;; Along a :ROTATION-PATH motion (rotation-path.lisp) each termination condition is a
;;;; function of the angle, and its proven first root (COORDINATE-ROOT-AHEAD's half-angle
;;;; method, the guards of a corner's meeting at its root: guarded-meetings.lisp) costs
;;;; hundreds of Maxima requests; a tipping block has a dozen such conditions (each corner
;;;; against each face of what it stands on, the pivot's normal force and friction
;;;; limits), most of them met, if ever, long after the state has ended. In a run with
;;;; values, where the values settle the order of two event angles anyway (NEARER-P,
;;;; NUMERIC-ANGLE-ORDER), every condition's function of the angle is sampled with the
;;;; run's numbers first, as NUMERIC-ANGLE-ROOT does (a 512th of a turn a step, up to
;;;; where the body turns back or one full turn):
;;;;   - a condition's EARLIEST possible angle is its function's first crossing below zero
;;;;     (for a guarded meeting, its gap's first closing, guards or not; for an OR, its
;;;;     earliest part), or, with no crossing, the reach itself (where the body turns back);
;;;;   - a condition SURELY fires at that crossing when it is a plain inequality, or a
;;;;     guarded meeting whose guards hold there by the numbers;
;;;;   - the HORIZON is the nearest sure firing; a condition whose earliest angle lies
;;;;     beyond it (by more than round-off) cannot end the state: it is set aside as
;;;;     (:NEVER) (fires, if ever, after the state's end), as the horizon phase sets aside
;;;;     meetings proven out of reach (horizon-phase.lisp).
;;;; The condition at the horizon, and any whose earliest angle is not beyond it, get the
;;;; full work (a closed form where the algebra finds one, else the numeric root). Only
;;;; while the values decide first (AMES.ALGEBRA:VALUES-FIRST-P) and the facts in force
;;;; hold at them (a branch the values do not select gets the full work); without them,
;;;; the proofs of angle-horizon-proofs.lisp set aside what they can.

(in-package #:ames.simulator)

(defmacro unless-failing (form)
  "FORM's values, or NIL where it signals an error other than the run's budget running out
(a side with no value, a request Maxima refuses): the screen then sets nothing aside."
  `(handler-case ,form ((and error (not budget-exceeded)) () nil)))

(defun angle-horizon-active-p (run)
  "True when the run's values may set conditions along a rotation path aside (see the
file header)."
  (and (run-numbers-known-p run)
       (ames.algebra:values-first-p)
       (ames.algebra:facts-hold-at-values-p (run-bridge run))))

(defun numeric-relation-margin (run group relation u)
  "How clearly the inequality RELATION (or an OR of them; over the angle) holds by the
run's numbers at the distance U turned ahead of GROUP's start: :HOLDS, :FAILS, or NIL
within round-off or where a side has no value."
  (if (eq (first relation) 'or)
      (let ((margins (mapcar (lambda (part) (numeric-relation-margin run group part u)) (rest relation))))
        (cond ((member :holds margins) :holds)
              ((every (lambda (m) (eq m :fails)) margins) :fails)))
      (let* ((f (angle-function run group (violation-function relation)))
             (value (and f (funcall f u)))
             (round-off (and value (* 1d-9 (max 1d0 (abs value))))))
        ;; the relation holds where its violation function is below zero
        (cond ((null value) nil)
              ((< value (- round-off)) :holds)
              ((> value round-off) :fails)))))

(defun guarded-numeric-angle (run group f guards over-angle reach)
  "The first distance turned U (up to REACH) where the gap F (a function of the distance
turned) closes with none of GUARDS clearly failing there, and whether every guard
clearly holds: (values U SURE); (values REACH NIL) when no such closing is found. A
closing where a guard clearly fails (past the face's end) is passed, the search going on
once the gap is positive again (up to eight closings)."
  (let ((step (/ (* 2 pi) *angle-search-steps*))
        (negated (lambda (u) (let ((v (funcall f u))) (and v (- v)))))
        (from nil))
    (loop repeat 8
          do (let ((u (first-numeric-crossing (if from (masked-after f from) f) (constantly nil) step reach)))
               (cond ((null u) (return (values reach nil)))
                     ((consp u) (return (values (second u) nil)))
                     (t (let ((margins (mapcar (lambda (guard)
                                                 (numeric-relation-margin
                                                  run group (guard-at guard over-angle) u))
                                               guards)))
                          (unless (member :fails margins)
                            (return (values u (every (lambda (m) (eq m :holds)) margins))))
                          (let ((back (first-numeric-crossing (masked-after negated u) (constantly nil)
                                                              step reach)))
                            (if (realp back)
                                (setf from back)
                                (return (values reach nil))))))))
          finally (return (values 0d0 nil)))))

(defun numeric-first-angle (run group relation over-angle reach)
  "Where RELATION (a termination condition's, over the state terms) may first fire along
GROUP's angle by the run's numbers: (values U SURE), U the distance turned (a double, at
most REACH), SURE true when it surely fires there (see the file header); NIL when the
numbers do not tell."
  (flet ((crossing (expression)
           (let ((f (angle-function run group (funcall over-angle expression))))
             (and f (first-numeric-crossing f (constantly nil)
                                            (/ (* 2 pi) *angle-search-steps*) reach)))))
    (multiple-value-bind (gap guards) (guarded-relation-parts relation)
      (cond (gap
             (let ((f (angle-function run group (funcall over-angle gap))))
               (and f (guarded-numeric-angle run group f guards over-angle reach))))
            ((eq (first relation) 'or)
             (let ((earliest nil))
               (dolist (part (rest relation) (and earliest (values earliest nil)))
                 (let ((u (numeric-first-angle run group part over-angle reach)))
                   (unless u (return nil))
                   (setf earliest (if earliest (min earliest u) u))))))
            ((member (first relation) '(< <= > >=))
             (let ((u (crossing (violation-function relation))))
               (cond ((null u) (values reach nil))
                     ((realp u) (values u t))
                     (t (values (second u) nil)))))
            ((eq (first relation) '=)
             (let ((u (crossing (violation-function relation))))
               (cond ((null u) (values reach nil))
                     ((realp u) (values u nil))
                     (t (values (second u) nil)))))))))

(defun angle-horizon-screen (run solved groups reach conditions)
  "A function CONDITION -> (:NEVER) for those of CONDITIONS that cannot end the state by
the run's numbers (see the file header), else NIL; when the run has no values to decide
first, PROVEN-ANGLE-SCREEN's (angle-horizon-proofs.lisp; REACH the broad phase's); NIL
throughout when no group is a rotation path."
  (let ((earliest (make-hash-table :test #'eq))
        (horizons '()))
    (unless (some (lambda (g) (eq (group-kind g) :rotation-path)) groups)
      (return-from angle-horizon-screen (constantly nil)))
    (unless (angle-horizon-active-p run)
      (return-from angle-horizon-screen (proven-angle-screen run solved groups reach conditions)))
    (dolist (condition conditions)
      (let* ((relation (ames.engine:termination-condition-relation condition))
             (involved (unless-failing (condition-groups run solved groups relation)))
             (group (first involved)))
        (when (and group (null (rest involved)) (eq (group-kind group) :rotation-path))
          (let ((reach (numeric-turning-reach run group))
                (over-angle (lambda (x) (motion-value (list group) (over-state-terms run solved x)))))
            (when reach
              (multiple-value-bind (u sure)
                  (unless-failing (numeric-first-angle run group relation over-angle reach))
                (when u
                  (setf (gethash condition earliest) (cons group u))
                  (when (and sure (> u 0))
                    (let ((entry (assoc group horizons)))
                      (if entry
                          (setf (cdr entry) (min (cdr entry) u))
                          (push (cons group u) horizons)))))))))))
    (lambda (condition)
      (let* ((entry (gethash condition earliest))
             (horizon (and entry (cdr (assoc (car entry) horizons)))))
        (when (and horizon (> (cdr entry) (+ horizon (* 1d-6 (max 1d0 horizon)))))
          (list :never))))))
