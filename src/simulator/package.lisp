;;;; src/simulator/package.lisp -- the qualitative-state simulator's package.

(defpackage #:ames.simulator
  (:use #:cl #:ames.base #:ames.scenario)
  (:documentation "The qualitative-state simulator (thesis sections 2.5.8 and 3.2.3): for
each state it chooses the contacts and modes the components offer, builds the model with
the engine, classifies and integrates it, proves which termination condition comes first
and applies the transition. It knows no force, event or mode by name: those are the
knowledge base's (package AMES.KB).")
  (:export
   #:simulate #:*bridge* #:current-bridge #:stop-simulation #:*all-branches* #:*state-hook*
   #:simulation-error #:ambiguous-transition #:ambiguous-transition-candidates
   #:ambiguous-transition-missing-fact #:ambiguous-transition-state
   #:unsolvable-model #:unsupported-situation
   #:statically-indeterminate #:indeterminate-bodies #:indeterminate-free #:indeterminate-shares
   #:indeterminate-lower #:indeterminate-upper
   #:simulation-history #:history-scenario #:history-states #:history-outcome #:history-leaf-outcomes
   #:history-notes #:history-rederived #:history-parameter-values #:history-answers
   #:unanswerable
   #:qualitative-state #:state-index #:state-start #:state-duration #:state-contacts
   #:state-accelerations #:state-forces #:state-positions #:state-velocities
   #:state-end-event #:state-final-positions #:state-final-velocities #:state-notes
   #:state-analysis #:state-initial-velocities #:state-branches #:body-entry #:numeric-or-nil
   ;; a state's notes, one slot each (history.lisp)
   #:state-numbers #:state-accumulation #:state-impact #:state-end-arc-length
   #:state-numeric-trajectory #:state-simultaneous-events #:state-periodic
   #:*numeric-tolerance* ; the numeric integrator's error per step, for the self-check's floors
   #:state-undecided-detail #:state-path-coordinates #:state-line-coordinates
   #:state-missing-fact #:state-fork-p #:state-reported-sections #:state-contact-points
   ;; rotating bodies (rotation.lisp)
   #:state-angles #:state-angular-velocities #:state-angular-accelerations
   #:state-final-angles #:state-final-angular-velocities))
