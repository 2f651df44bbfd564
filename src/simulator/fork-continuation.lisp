;;;; src/simulator/fork-continuation.lisp -- branches share their past: a branch continues
;;;; from the fork's state instead of being simulated anew from t = 0.
;;;;
;;;; At a fork the run holds the positions, velocities, time and impacts of the state it
;;;; splits. A branch under its fact takes a copy of that run, rebuilds the model from
;;;; scratch there under the fact (the engine's beliefs are those a rebuild gives, which
;;;; CHECK-INCREMENTAL holds the incremental model to), and analyses the split state
;;;; again, now decided. Nothing of one branch leaks into another: each has its own run
;;;; and model, and its fact is assumed in a scope of its own. A boundary branch (a
;;;; parameter substituted throughout the scenario) has another scenario and is still
;;;; simulated from the start, as is a branch that the values rule out when the run has
;;;; assumed facts from those values before the fork.

(in-package #:ames.simulator)

(defun branch-run (run values)
  "A fresh RUN at RUN's current point (positions, velocities, rotations, time, impacts and facts
assumed from values), with the parameter VALUES (NIL for a branch the values rule out),
its model not yet built."
  (let ((copy (make-instance 'run :scenario (run-scenario run) :bridge (run-bridge run)
                                  :shapes (run-shapes run) :contacts (run-contacts run)
                                  :locus-kinds (run-locus-kinds run)
                                  :alternatives (run-alternatives run)
                                  :positions (run-positions run)
                                  :velocities (run-velocities run)
                                  :rotations (run-rotations run)
                                  :values values)))
    (setf (run-time copy) (run-time run)
          (run-impacts copy) (run-impacts run)
          (run-assumed copy) (run-assumed run))
    copy))

(defun rebuild-run-model (run)
  "Build RUN's model from scratch at its current point (as MAKE-RUN does at the start)."
  (let ((situation (ames.engine:make-situation (situation-entities run) :data run)))
    (handler-bind ((ames.engine:undecided-relation #'undecided-to-ambiguity))
      (setf (run-model run)
            (ames.engine:build-model (ames.engine:make-engine (ames.kb:mechanics-knowledge-base))
                                     situation :decider (state-decider run))))
    run))

(defun numeric-clock (bridge states values)
  "The number at which the state after STATES (the history's so far) starts under VALUES,
summed as ADD-NUMERIC-VALUES sums it (so that a continued branch prints the numbers a run
from the start prints), or NIL."
  (let ((clock *history-clock*))
    (dolist (state states clock)
      (let ((duration (numeric-duration bridge state values)))
        (setf clock (and clock (realp duration) (+ clock duration)))))))

;;; A branch that the knowledge base stops (a state it has no model for: UNMODELLED-SITUATION,
;;; UNSUPPORTED-SITUATION) keeps the states it finished before: what a physicist reads is how
;;; far the motion is known (the lighter mass of an Atwood machine rising to its pulley),
;;; then why it stops there.

(defun keep-unfinished-branch (history bridge clock)
  "Store HISTORY, the states a refused branch finished, in *UNFINISHED-BRANCH* with their
numbers from CLOCK (ANALYSE-HISTORY); nothing when it has no state or that analysis fails."
  (when (and *unfinished-branch* (history-states history))
    (setf (history-outcome history) :failed)
    (when (ignore-errors (analyse-history history bridge clock) t)
      (setf (car *unfinished-branch*) history))))

(defun continue-branch (run index facts values check-incremental clock)
  "The SIMULATION-HISTORY of a branch that continues RUN from its fork at state INDEX
with FACTS (the branch's own, besides those already in force) assumed and the parameter
VALUES (or NIL); its states are those from INDEX on, its numbers starting at CLOCK (see
NUMERIC-CLOCK). Signals as SIMULATE-CHECKED does; a refusal first leaves the states
finished in *UNFINISHED-BRANCH* (KEEP-UNFINISHED-BRANCH)."
  (let* ((scenario (run-scenario run))
         (bridge (run-bridge run))
         (history (make-instance 'simulation-history :scenario scenario
                                                     :parameter-values values))
         (limit (or (scenario-states scenario) *default-state-limit*))
         (branch nil))
    (ames.maxima:with-assumptions (bridge facts)
      (restart-case
          (handler-bind ((ames.engine:undecided-relation
                           ;; over the state's starting values, as the root's run says it
                           ;; (SIMULATE-WORLD-ONCE): NIL while the model is rebuilt
                           (lambda (condition) (undecided-to-ambiguity condition branch)))
                         ((or ames.kb:unmodelled-situation unsupported-situation)
                           (lambda (condition)
                             (declare (ignore condition))
                             (keep-unfinished-branch history bridge clock))))
            (setf branch (rebuild-run-model (branch-run run values)))
            (let ((*history-clock* clock))
              (run-states branch history index limit check-incremental)))
        (stop-simulation (&optional condition)
          :report "Stop the branch here and return its states so far."
          (setf (history-outcome history)
                (if (typep condition 'ambiguous-transition) :ambiguous :stopped))
          (when (and (typep condition 'ambiguous-transition)
                     (ambiguous-transition-state condition))
            (setf (history-states history)
                  (append (history-states history)
                          (list (ambiguous-transition-state condition)))))
          (setf (getf (history-notes history) :stopped-by) condition)))
      (analyse-history history bridge clock))))
