;;;; src/simulator/angle-horizon-proofs.lisp -- without values, the corner meetings along a
;;;; rotation path proven to come after one that surely ends the state, set aside before
;;;; their guards are proven.
;;;;
;;;; A corner meeting a face along a rotating body's angle (a guarded meeting:
;;;; guarded-meetings.lisp) fires where its gap first closes with the corner within the
;;;; face; proving the guards at that closing (an angle in arc tangents) is the costliest
;;;; part of a tipping block's end: for a corner meeting the slope far beyond the point
;;;; where the block falls flat, minutes of DECIDE, to no end. Here, in a run without
;;;; values:
;;;;   - the scenario's own (:value N) defaults, an admissible point, ORDER the guarded
;;;;     meetings (NUMERIC-FIRST-ANGLE, angle-horizon.lisp): which one probably fires first;
;;;;     they prove nothing;
;;;;   - that one is worked out in full (CONDITION-RESULT); when it is a candidate (its gap
;;;;     closes with its guards proven there, reached before any turning point), its angle
;;;;     is the HORIZON: the state surely ends there or before;
;;;;   - every other guarded meeting whose gap's first closing (no guards asked) is PROVEN
;;;;     beyond the horizon (the closing found with DECIDE's cheap strategies only,
;;;;     AMES.ALGEBRA:*DECIDE-CHEAPLY*, *SCREEN-PROOF-SECONDS*: where they fail, the
;;;;     meeting gets the full work as before; its order against the horizon, NEARER-P, by DECIDE) cannot end the
;;;;     state: it is set aside as (:NEVER), as angle-horizon.lisp does under values and
;;;;     horizon-phase.lisp does for meetings out of reach. Its firing is at or after
;;;;     that first closing.
;;;; Nothing is set aside on the defaults' word alone; without defaults for every parameter,
;;;; or where the horizon's candidate is not proven, nothing is set aside.

(in-package #:ames.simulator)

(defparameter *screen-proof-seconds* 0
  "The wall time for which the search for a guarded meeting's first closing gets DECIDE's
full work (FIRST-CLOSING-BEYOND-P); its cheap strategies only after that. 0: cheap only
(the tipping block: 2 s, two meetings set aside, one of them 648 s of guards; with 30 s,
three, but the screen took 294 s at a load near 10).")

(defun defaults-run (run)
  "A stand-in RUN carrying only the scenario's (:value N) defaults as its values (for
ANGLE-FUNCTION's numbers), or NIL when some parameter has none."
  (let ((values (unless-failing (ames.scenario:run-parameter-values (run-scenario run) :numeric t))))
    (when (and values
               (= (length values) (length (ames.scenario:scenario-parameters (run-scenario run)))))
      (make-instance 'run :scenario (run-scenario run) :values values))))

(defun guarded-angle-entries (run defaults solved groups conditions)
  "For each guarded meeting of CONDITIONS over one :ROTATION-PATH group: (CONDITION GROUP
U SURE), U and SURE NUMERIC-FIRST-ANGLE's at the defaults of DEFAULTS (a stand-in run)."
  (let ((entries '()))
    (dolist (condition conditions (nreverse entries))
      (let* ((relation (ames.engine:termination-condition-relation condition))
             (involved (and (guarded-relation-parts relation)
                            (unless-failing (condition-groups run solved groups relation))))
             (group (first involved)))
        (when (and group (null (rest involved)) (eq (group-kind group) :rotation-path))
          (let ((reach (unless-failing (numeric-turning-reach defaults group)))
                (over-angle (lambda (x) (motion-value (list group) (over-state-terms run solved x)))))
            (when reach
              (multiple-value-bind (u sure)
                  (unless-failing (numeric-first-angle defaults group relation over-angle reach))
                (when u (push (list condition group u sure) entries))))))))))

(defun first-closing-beyond-p (run solved group condition horizon)
  "True when CONDITION's gap (a guarded meeting's) first closes along GROUP's angle at an
angle proven beyond HORIZON, or never closes ahead."
  (let* ((gap (guarded-relation-parts (ames.engine:termination-condition-relation condition)))
         (f (motion-value (list group) (over-state-terms run solved gap))))
    (multiple-value-bind (status s)
        ;; the closing by DECIDE's full work for *SCREEN-PROOF-SECONDS*, its cheap
        ;; strategies only after that: an :UNKNOWN just sets nothing aside
        (let ((ames.algebra:*decide-cheaply*
                (+ (get-internal-real-time)
                   (round (* *screen-proof-seconds* internal-time-units-per-second)))))
          (handler-case (angle-root-ahead run group f)
            (ames.maxima:maxima-error () :unknown)))
      (case status
        (:never t)
        ;; the order of two angles in closed form, by DECIDE's full work (arc tangents
        ;; against multiples of pi: atan-orders.lisp)
        (:at (eq :true (nearer-p run group horizon s)))))))

(defun proven-angle-screen (run solved groups reach conditions)
  "A function CONDITION -> its result (see CONDITION-RESULT) or NIL, for a run without
values (see the file header): the horizon's condition gets its result, worked out here
once; a guarded meeting proven to close beyond the horizon gets (:NEVER); others NIL."
  (let ((defaults (and (some (lambda (g) (eq (group-kind g) :rotation-path)) groups)
                       (defaults-run run))))
    (unless defaults
      (return-from proven-angle-screen (constantly nil)))
    (let* ((entries (guarded-angle-entries run defaults solved groups conditions))
           (first-sure (first (sort (remove-if-not #'fourth (copy-list entries)) #'< :key #'third)))
           (result (and first-sure (condition-result run solved groups reach (first first-sure))))
           (candidate (and result (candidate-p (first result)) (first result)))
           (horizon (and candidate (candidate-at-arc candidate))))
      (lambda (condition)
        (cond ((null first-sure) nil)
              ((eq condition (first first-sure)) result)
              (horizon
               (let ((entry (find condition entries :key #'first)))
                 (when (and entry (eq (second entry) (second first-sure))
                            (> (third entry) (third first-sure))
                            (first-closing-beyond-p run solved (second entry) condition horizon))
                   (list :never)))))))))
