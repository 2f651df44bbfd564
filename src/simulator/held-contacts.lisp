;;;; src/simulator/held-contacts.lisp -- at an impact that ends a numerically integrated state,
;;;; the contacts held through that state must still be shown to touch.
;;;;
;;;; A state integrated numerically ends with positions and angles put back exactly on the
;;;; contacts it held and reached (end-values.lisp: numeric-roots.lisp, corner-snapping.lisp,
;;;; flat-corner-snapping.lisp, flush-corner-snapping.lisp). The impact that ends it is
;;;; solved over every contact touching then (impacts.lisp), and the contacts it leaves
;;;; active are kept or dropped by the choice at the next state's start, which reads their
;;;; gaps and their rates. A contact held through the state that none of those snappings
;;;; put back (its gap a round-off off zero, or undecided) would be left out of the impact
;;;; and kept or dropped after it by the round-off, not by the mechanics: a guess. Such an
;;;; impact is refused, naming the contacts, unless the state's end itself ends them (a
;;;; lift-off at the same instant).

(in-package #:ames.simulator)

(defun check-held-contacts-at-impact (run state fired)
  "Signal UNSUPPORTED-SITUATION when STATE, integrated numerically, ends in an impact (among
FIRED) while an instance active through it (a held contact) no longer answers touching
at the end (see the file header), and no FIRED candidate ends that instance."
  (when (state-numeric-trajectory state)
    (let* ((ended (loop for candidate in fired
                        for condition = (candidate-condition candidate)
                        when condition collect (ames.engine:termination-condition-instance condition)))
           (unsettled (remove-if (lambda (key) (member key ended :test #'equal))
                                 (ames.engine:unsettled-active-instances (run-model run)
                                                                         :decider (state-decider run)))))
      (when unsettled
        (error 'unsupported-situation
               :datum unsettled
               :detail "A corner is reached at a speed at the end of a state integrated numerically while a contact held through it is not put back exactly on its face; the impact from the numbers' positions would be guessed.")))))
