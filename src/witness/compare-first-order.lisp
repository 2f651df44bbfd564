;;;; src/witness/compare-first-order.lisp -- events of a first-order witness that are one.
;;;;
;;;; Moreau-Jean time stepping (friction, rotating bodies) locates an event within a step:
;;;; two events at one instant, such as a disc hitting the floor in the corner of an incline
;;;; and leaving the slope by that impact, may come out one or two steps apart and in
;;;; either order. AMES reports one event for the instant (the others simultaneous with
;;;; it), so the witness's events within two steps of one another are taken as one: their
;;;; pairs together, the state before the impact among them (else the first's).
;;;;
;;;; Its values are compared to *FIRST-ORDER-TOLERANCE* (set for friction's step, 1e-4 s),
;;;; or, for a longer step h (rotating bodies: 1e-3 s), to 20 h: a body at an impact has
;;;; gone on for up to a step at its speed (a disc hitting the floor at 13 m/s, 0.013 m).

(in-package #:ames.witness)

(defun witness-step (witness)
  "The time step of a first-order WITNESS answer (:STEP when it printed one; Moreau-Jean
with friction steps 1e-4 s), or NIL for the event-driven scheme."
  (and (eq (getf witness :scheme) :moreau-jean)
       (or (getf witness :step) 1d-4)))

(defun first-order-tolerance (witness)
  "The relative tolerance (absolute below 1) of a first-order WITNESS's values: the larger
of *FIRST-ORDER-TOLERANCE* and 20 times its step."
  (max *first-order-tolerance* (* 20 (or (witness-step witness) 0))))

(defun merge-simultaneous-events (walk event)
  "EVENT (just taken from WALK's events) with the pairs of the witness's next events within
two steps of it, those taken too, when the witness is first order; else EVENT. The state
of the merged event is its impact's (the state just before it: a contact the impact opens
is recorded with the state after it), else the first's."
  (let ((step (witness-step (walk-witness walk))))
    (if (null step)
        event
        (let ((merged (list event)))
          (loop while (and (walk-events walk)
                           (<= (- (getf (first (walk-events walk)) :time) (getf event :time))
                               (* 2.5d0 step)))
                do (push (pop (walk-events walk)) merged))
          (setf merged (reverse merged))
          (let ((base (or (find-if (lambda (e) (assoc :collision (getf e :pairs))) merged) event)))
            (append (list :pairs (remove-duplicates (loop for e in merged append (getf e :pairs))
                                                    :test #'equal :from-end t))
                    base))))))
