;;;; src/witness/compare-grazes.lisp -- AMES's contacts reached with no approach speed,
;;;; checked against the witness's trajectory.
;;;;
;;;; A contact reached at zero approach speed (an Atwood machine's light mass coming back
;;;; to the floor exactly at rest) is a double root of its gap: the witness's root finding,
;;;; a change of sign, sees no event there. Where AMES ends a state with such a (:CONTACT
;;;; A B) and the witness's next event is not it, the witness is asked for its motion at
;;;; AMES's time (witness/siconos_grazes.py: the model's samples include the ends of such
;;;; states) and AMES's event is checked against it instead of given up:
;;;;  - the witness has no event before AMES's time (else the normal walk finds AMES wrong);
;;;;  - the witness's least gap of the pair within 10 ms of AMES's time is zero to
;;;;    *GRAZE-GAP-TOLERANCE* (its resolution: Lsodar's positions, about 1e-12 here, and
;;;;    the comparator's 1e-7 relative), and its gap's rate there zero to the speed
;;;;    tolerance (*VALUE-TOLERANCE*);
;;;;  - the witness's positions and velocities at AMES's time are AMES's final ones (to
;;;;    *VALUE-TOLERANCE*, the states before having agreed).
;;;; Each checked quantity is a row; one that differs is a disagreement (AMES wrong). When
;;;; all agree the walk goes on from AMES's time (the next state, or the verdict). Only the
;;;; event-driven witness reports its motion (a first-order witness's gap is known to its
;;;; step only): otherwise, or with no report for that time, the state stays unsupported.

(in-package #:ames.witness)

(defvar *graze-gap-tolerance* 1d-7
  "The largest least gap (m, absolute; the models' lengths are of order 1) of a pair that
the event-driven witness takes as zero: its resolution at a graze.")

(defun graze-event-p (event)
  "True when AMES's EVENT is a contact reached with no approach speed."
  (and (consp event) (eq (event-kind event) :contact)))

(defun graze-times (ames values)
  "The end times of AMES's states (its answer AMES) that end with a contact reached with
no approach speed: the witness reports its motion there."
  (loop for state in (ames-path (getf ames :states))
        for numbers = (state-numbers state values)
        when (and (graze-event-p (getf state :end-event))
                  (realp (getf numbers :start)) (realp (getf numbers :duration)))
          collect (+ (getf numbers :start) (getf numbers :duration))))

(defun witness-graze (walk end)
  "The witness's report of its motion at END (a plist :TIME :POSITIONS :VELOCITIES
:PAIRS), or NIL."
  (find-if (lambda (g) (close-p (getf g :time) end *value-tolerance*))
           (getf (walk-witness walk) :grazes)))

(defun graze-pair (graze event)
  "The witness's (A B LEAST-GAP AT RATE) for the pair of AMES's EVENT in GRAZE, or NIL."
  (let ((names (event-pair-names event)))
    (find-if (lambda (entry)
               (and (every (lambda (n) (or (name= n (first entry)) (name= n (second entry)))) names)
                    (every (lambda (w) (some (lambda (n) (name= n w)) names))
                           (list (first entry) (second entry)))))
             (getf graze :pairs))))

(defun check-graze (walk numeric event end)
  "When AMES's EVENT (ending a state at END with the final values NUMERIC) is a contact
reached with no approach speed that the witness's next event is not, check it against the
witness's motion (see the file's header): true when it is witnessed (every row agreed:
the walk is at END), NIL when the witness cannot say (the caller's rules apply). A
disagreement ends the comparison."
  (let* ((events (member-if-not #'settling-p (walk-events walk)))
         (next (first events))
         (graze (and (graze-event-p event) (realp end)
                     (null (witness-step (walk-witness walk)))
                     (not (and next (event-matches-p event next)))
                     (witness-graze walk end)))
         (pair (and graze (graze-pair graze event))))
    (when (and pair
               ;; an earlier witness event: the walk finds AMES wrong there
               (or (null next) (> (getf next :time) (+ end (* *value-tolerance* (max 1 end)))))
               ;; a witness cut short before AMES's time has not seen it
               (or next (>= (getf (witness-end (walk-witness walk)) :time) end)))
      (destructuring-bind (a b gap at rate) pair
        (declare (ignore a b))
        (compare-number walk "end time (the witness's least gap)" end at
                        (max *value-tolerance* (sqrt *graze-gap-tolerance*)))
        (compare-number walk (format nil "least gap ~(~{~A~^ ~}~)" (event-pair-names event)) 0 gap
                        *graze-gap-tolerance*)
        (compare-number walk "gap's rate there" 0 rate))
      (push (list (walk-index walk) "end event" (format nil "~(~{~A~^ ~}~)" (event-head event))
                  "graze (no event)" nil t)
            (walk-rows walk))
      (compare-vectors walk "final position" (getf numeric :final-positions) (getf graze :positions))
      (compare-vectors walk "final velocity" (getf numeric :final-velocities) (getf graze :velocities))
      (setf (walk-events walk) events
            (walk-time walk) end)
      t)))
