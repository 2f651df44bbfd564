;;;; src/simulator/implied-facts.lisp -- only the consistent outcomes of an ambiguity: a
;;;; fork's branches whose facts contradict the assumptions (and the facts of the forks
;;;; above) are not simulated.
;;;;
;;;; A state is ambiguous when DECIDE cannot settle a missing fact X > 0. Its outcomes are
;;;; X > 0, X < 0 and the boundary X = 0; one whose fact is proven to hold at no admissible
;;;; point (ames.algebra:CONTRADICTS-FACTS-P: two facts linear in one variable combined) is
;;;; impossible, and the language page's fork has "one branch per consistent outcome". The
;;;; impossible ones are left out of a fork (FORK-ALTERNATIVES); when all but one side are
;;;; impossible, the fact that side states is implied by the facts in force: the run
;;;; assumes it and analyses the state again (there is nothing to branch on), noting it in
;;;; the history (:IMPLIED, beside the facts :ASSUMED from values).

(in-package #:ames.simulator)

(defun impossible-fact-p (run fact)
  "True when FACT (a relation over the parameters) is proven to hold at no point that
satisfies the facts in force."
  (ames.algebra:contradicts-facts-p (run-bridge run) fact))

(defun implied-fact (run fact)
  "The fact the facts in force imply about the inequality FACT's difference X = LHS - RHS
when some of its outcomes X > 0, X < 0 and X = 0 are proven impossible and the others
are one relation's: (> LHS RHS), (>= LHS RHS), (< LHS RHS) or (<= LHS RHS). NIL when
FACT is no inequality over the parameters, when every outcome may hold (or only the
equation, which a boundary branch's substitution handles), or when no outcome is
possible (contradictory facts, for the caller's error to report)."
  (when (branchable-fact-p fact)
    (let* ((lhs (relation-lhs fact)) (rhs (relation-rhs fact))
           (above (not (impossible-fact-p run (list '> lhs rhs))))
           (below (not (impossible-fact-p run (list '< lhs rhs)))))
      (unless (and above below)
        (let ((equal (not (impossible-fact-p run (list '= lhs rhs)))))
          (cond ((and above equal) (list '>= lhs rhs))
                (above (list '> lhs rhs))
                ((and below equal) (list '<= lhs rhs))
                (below (list '< lhs rhs))))))))

(defun assume-implied-fact (run history index condition)
  "When the missing fact of the AMBIGUOUS-TRANSITION CONDITION at state INDEX is decided
by the facts in force once its impossible outcomes are seen (IMPLIED-FACT), and this
history has not assumed it yet, the fact, pushed onto HISTORY's :IMPLIED notes as
(:STATE INDEX :FACT FACT); else NIL. The caller analyses the state again with it
assumed."
  (let* ((missing (core-fact run (ambiguous-transition-missing-fact condition)))
         (implied (implied-fact run missing)))
    (when (and implied
               (not (member implied (getf (history-notes history) :implied)
                            :key (lambda (entry) (getf entry :fact)) :test #'equal)))
      (push (list :state index :fact implied) (getf (history-notes history) :implied))
      implied)))
