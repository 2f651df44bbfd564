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

;;; A strike of the first-order witness where AMES's path clears the pair by less than the
;;; witness's resolution
;;;
;;; Moreau-Jean time stepping knows a body's state to O(h V) (h its step, V the speed of the
;;; body's points): a face that clears a fixed corner by 11 micrometres on AMES's exact
;;; flight (seed 2027 rod-ledge #773) is struck by the witness at every step it can take.
;;; Where the refined comparison still disagrees, and the witness strikes a pair during a
;;; state that AMES does not end with that pair's event, AMES's least gap of that pair over
;;; the state is computed (the witness's own gap functions along AMES's closed forms,
;;; sampled: witness/siconos_probe_gaps.py, an upper bound of the least gap). When it is
;;; positive and below the resolution 20 h V (the comparator's first-order tolerance, 20
;;; steps), the verdict is :UNSUPPORTED with both figures; otherwise the disagreement stays.

(defparameter +strike-samples+ 800 "The samples of AMES's motion over a state.")

(defun state-motion (state model values)
  "AMES's motion over STATE as the gap probe's samples: ((T ((X Y THETA VX VY OMEGA) per
free body of MODEL)) ...), or NIL when a closed form has no value (a state integrated
numerically)."
  (let* ((numbers (state-numbers state values))
         (start (getf numbers :start)) (duration (getf numbers :duration))
         (names (loop for body in (rest (cdr (assoc "bodies" model :test #'equal)))
                      collect (cdr (assoc "name" body :test #'equal)))))
    (unless (and (realp start) (realp duration) (plusp duration))
      (return-from state-motion nil))
    (flet ((entry (key name) (second (find name (getf state key) :key #'first :test (lambda (n s) (name= s n))))))
      (loop for k from 0 to +strike-samples+
            for elapsed = (* duration (/ k +strike-samples+))
            for bindings = (acons 'tau elapsed values)
            collect (list (+ start elapsed)
                          (loop for name in names
                                collect (mapcar (lambda (x)
                                                  (let ((value (and x (expression-value (canonical-expression x) bindings))))
                                                    (cond ((realp value) (coerce value 'double-float))
                                                          ((null x) 0d0)
                                                          (t (return-from state-motion nil)))))
                                                (append (or (entry :positions name) '(nil nil))
                                                        (list (entry :angles name))
                                                        (or (entry :velocities name) '(nil nil))
                                                        (list (entry :angular-velocities name))))))))))

(defun witness-strike (state witness values)
  "The witness's first collision pair (:COLLISION A B) within AMES's STATE (after its start
by more than 2.5 steps, before its end by more than that) that is not AMES's end event, and
its time; NIL when none."
  (let* ((numbers (state-numbers state values))
         (start (getf numbers :start)) (end (and (realp (getf numbers :duration)) (+ start (getf numbers :duration))))
         (margin (* 2.5d0 (or (witness-step witness) 0))))
    (when (and (realp start) end)
      (loop for event in (witness-events witness)
            for time = (getf event :time)
            when (and (> time (+ start margin)) (< time (- end margin)))
              do (let ((pair (find :collision (getf event :pairs) :key #'first)))
                   (when (and pair (not (event-matches-p (getf state :end-event) (list :pairs (list pair)))))
                     (return (values pair time))))))))

(defun gap-probe-entry (pair motion)
  "The model's entry asking the witness for the gap of PAIR ((:COLLISION A B)) along
MOTION (STATE-MOTION's samples)."
  (flet ((sample (entry)
           (destructuring-bind (time bodies) entry
             (list :array time (cons :array (mapcar (lambda (b) (cons :array b)) bodies))))))
    (list (cons "gap_probe"
                (list (cons "pair" (list :array (second pair) (third pair)))
                      (cons "motion" (cons :array (mapcar #'sample motion))))))))

(defun strike-below-resolution (comparison answer model witness values run)
  "COMPARISON made :UNSUPPORTED when it is a disagreement of a first-order WITNESS whose
strike of a pair within the failing state AMES's path clears by a positive gap below the
witness's resolution (see above); else COMPARISON. RUN runs the witness on a model."
  (let* ((step (witness-step witness))
         (index (first (car (last (comparison-rows comparison)))))
         (state (find index (ames-path (getf answer :states)) :key (lambda (s) (getf s :index)))))
    (unless (and (eq (comparison-verdict comparison) :ames-wrong) step state)
      (return-from strike-below-resolution comparison))
    (multiple-value-bind (pair time) (witness-strike state witness values)
      (let ((motion (and pair (state-motion state model values))))
        (unless motion
          (return-from strike-below-resolution comparison))
        (let ((probe (funcall run (append model (gap-probe-entry pair motion)) :timeout 120)))
          (let* ((gap (getf probe :least-gap)) (speed (getf probe :speed))
                 (resolution (and (realp speed) (* 20 step (max 1 speed)))))
            (if (and (eq (witness-status probe) :ok) (realp gap) resolution (< 0 gap resolution))
                (make-comparison
                 :unsupported
                 (format nil "state ~D: the witness strikes ~A ~A at ~,6F s; AMES's least gap of that pair over the state is ~,3,,,,,'eE m (at ~,6F s, positive), below the witness's resolution ~,3,,,,,'eE m (20 steps of ~A s at ~,3F m/s): a graze the witness cannot resolve (the comparison: ~A)"
                         index (second pair) (third pair) time gap (getf probe :at) resolution
                         (coerce step 'single-float) speed (comparison-reason comparison))
                 (comparison-rows comparison))
                comparison)))))))
