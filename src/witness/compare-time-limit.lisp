;;;; src/witness/compare-time-limit.lisp -- the comparator's states cut by the scenario's own
;;;; end ((simulate :until T): AMES's end event (:TIME-LIMIT T)), and the witness's probe
;;;; events passed over.
;;;;
;;;; A state AMES ends at the time limit has no event for the witness to find: the witness
;;;; runs to that time exactly (WITNESS-HORIZON in src/interface/check.lisp), must have no
;;;; event before it (turning points and Zeno residue apart), and its end is compared with
;;;; AMES's final positions, velocities, angles and angular velocities.
;;;;
;;;; The witness's (:reaches BODY "angle") events are the crossings of the angles the
;;;; queries ask about (rotation.lisp's probes), not events of the motion: AMES's states do
;;;; not end there, so they are taken out of the event sequence before it is walked.

(in-package #:ames.witness)

(defun time-limit-event-p (event)
  "True when EVENT (AMES's end event) is the scenario's time limit."
  (and (consp event) (eq (first event) :time-limit)))

(defun motion-events (events)
  "The witness's EVENTS without the probes' crossings (pairs of kind :REACHES); an event
left with no pair is dropped."
  (loop for event in events
        for pairs = (remove :reaches (getf event :pairs) :key #'first)
        when pairs
          collect (if (= (length pairs) (length (getf event :pairs)))
                      event
                      (list* :pairs pairs event))))

(defun compare-time-limit-state (walk state numeric end)
  "STATE ends at the scenario's time limit END: no witness event before it (turning
points and settling apart), and the witness's end (at END) has AMES's final values."
  (let ((early (find-if (lambda (e) (and (< (getf e :time) (- end (* 3 (or (witness-step (walk-witness walk)) 0)) 1d-9))
                                         (not (settling-p e)) (not (turns-only-p e))))
                        (walk-events walk)))
        (witness-end (witness-end (walk-witness walk))))
    (when early
      (finish walk :ames-wrong "AMES has no event before its time limit ~A; the witness has ~S at ~A"
              end (getf early :pairs) (getf early :time)))
    (when (getf (walk-witness walk) :truncated)
      (finish walk :unsupported "the witness stopped at ~A: ~A"
              (getf witness-end :time) (getf (walk-witness walk) :truncated)))
    (compare-number walk "end time (time limit)" end (getf witness-end :time))
    (compare-vectors walk "final position" (getf numeric :final-positions) (getf witness-end :positions))
    (compare-vectors walk "final velocity" (getf numeric :final-velocities) (getf witness-end :velocities))
    (compare-final-angles walk state numeric witness-end) ; compare-angles.lisp
    (finish walk :agree)))
