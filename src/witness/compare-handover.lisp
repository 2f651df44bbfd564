;;;; src/witness/compare-handover.lisp -- a face's end handing a body over to another face
;;;; at the same instant.
;;;;
;;;; A particle sliding down a ramp that ends on the floor reaches the ramp's foot and the
;;;; floor at once. AMES ends the slide with (:leaves particle ramp :endpoint) and starts a
;;;; state of zero duration that ends with the floor's collision; the witness, whose
;;;; contact set changes in one step, reports the collision alone (seed 2029, terrain
;;;; #225). The same instant and the same motion, told in two steps. A :LEAVES of AMES's
;;;; that the witness's event at the same time does not name is accepted provisionally:
;;;; the final positions and velocities are still compared with the witness's (the
;;;; instant is one), and the witness's event is put back, so that AMES's next state must
;;;; start then and end at once with it, or the comparison fails there.

(in-package #:ames.witness)

(defun handed-over-p (walk event witness-event end)
  "True when AMES's EVENT, ending a state at END, is a body leaving a face at its end
and WITNESS-EVENT (the witness's event matched against it) is at the same time and names
no leaving: WITNESS-EVENT is then put back in WALK's events, for AMES's next state."
  (when (and (eq (event-kind event) :leaves)
             (close-p end (getf witness-event :time) (walk-time-tolerance walk))
             (notany (lambda (pair) (eq (first pair) :leaves)) (getf witness-event :pairs)))
    (push witness-event (walk-events walk))
    t))
