;;;; src/simulator/branching.lisp -- branching on ambiguity (thesis 3.2.4, "Simulation Scope
;;;; Extensions"): where the assumptions do not decide which event ends a state, or which
;;;; contacts and modes hold, the run splits into branches, one per outcome, each under the
;;;; fact that selects it; the result is a tree (an envisionment).
;;;;
;;;; The fork is a state of zero duration whose end event is (:BRANCH) and which holds the
;;;; branches. For a missing fact X > 0 (in factored core form) the branches assume X > 0,
;;;; X < 0, and the boundary X = 0, where the system behaves differently again: for the
;;;; boundary, a parameter the equation determines is replaced by its value throughout the
;;;; scenario (an equation among the assumptions simplifies nothing in Maxima; a
;;;; substituted parameter does), its own assumptions becoming facts on that value. Each
;;;; branch is simulated anew from the start under its fact (the states before the fork
;;;; come out the same, and are not repeated), so that nothing of one branch leaks into
;;;; another. Parameter values (--set) select one branch, marked :SELECTED; every branch is
;;;; still listed, but only the selected one is simulated (the others have the outcome
;;;; :NOT-SIMULATED) unless (simulate :all-branches t) or --all-branches asks for all.
;;;; A fork is not a period of motion: it takes the index of the state it splits, which
;;;; the branches' first states keep, and queries count no fork (`(end 0)` is the end of
;;;; the first period of motion). The tree is bounded: *BRANCH-LIMIT* branches in all,
;;;; *BRANCH-DEPTH-LIMIT* forking states on a path, and *FORKS-PER-STATE-LIMIT* forks nested
;;;; within the first of them (one at each later one); a branch beyond the bound stops at
;;;; its ambiguity, and the history says so.

(in-package #:ames.simulator)

(defvar *unfinished-branch* nil
  "NIL, or a cell bound by GROW-BRANCH: CONTINUE-BRANCH sets its car to the branch's
SIMULATION-HISTORY (its finished states, their numbers added) when a refusal stops the
branch, before the condition unwinds.")

(defparameter *branch-limit* 24
  "The most branches one run's tree may hold (the whole tree's, each simulated: a fork
is refused when its branches could take the tree past it).")

(defparameter *branch-depth-limit* 2
  "The most states on one path from the root of a run's tree at which the run forks.
Each branch is simulated anew from the start (or from its fork), so a deeper tree costs
a run per branch; a state that forks after a forked state mostly forks on a fact the
earlier fork should have decided, and a motion that forks at every state (a bounce after
a bounce, each on a new fact) would never end. A later forking state forks once; the
first one may nest forks, up to *FORKS-PER-STATE-LIMIT*.")

(defparameter *forks-per-state-limit* 4
  "The most forks nested on one path within the analysis of the first state at which it
forks. That state's analysis is the problem's own case analysis, as a textbook does it
before any motion: which contacts hold and in which friction mode (the choice search's
consistency facts: a normal force's sign, each side of a static friction limit), then
which event ends the state first. Where the assumptions leave several undecided, each is
a genuine split of the motion (a block pushed hard tips or slides flat; tipping, its
front edge sticks, or slides back or forward; the tipping ends where its torques balance
or where its centre passes over its edge: four nested facts), and a fact once assumed is
never forked on again on that path (ASSUMED-ON-THIS-PATH-P), so the nesting ends with the
state's questions; this bound only caps it. A state reached after a fork and a period of
motion forks once (*BRANCH-DEPTH-LIMIT*): its nested questions are mostly facts an
earlier fork left open, and the tree would multiply at each.")

(defun branch-room-p (&optional index)
  "True when the current tree may still fork at the state INDEX (at a state not forked
yet on the current path when INDEX is NIL): the branches of the whole tree so far are
under *BRANCH-LIMIT*, and either INDEX is the state of the path's last fork, the first
at which the path forks, and the forks nested there are under *FORKS-PER-STATE-LIMIT*,
or INDEX is another state and the path's forking states are under *BRANCH-DEPTH-LIMIT*."
  (let ((count (max (getf *branching* :count 0) (first (getf *branching* :tree '(0)))))
        (depth (getf *branching* :depth 0)))
    (and (< (+ count 3) *branch-limit*)
         (if (and index (eql index (getf *branching* :state)))
             (and (= depth 1) (< (getf *branching* :nested 0) *forks-per-state-limit*))
             (< depth *branch-depth-limit*)))))

(defun nested-branching (index alternatives)
  "The plist *BRANCHING* holds for the branches of a fork at the state INDEX with
ALTERNATIVES: the path's count grows by their number, and so does the whole tree's
(:TREE, one cell shared by every branch, so that a branch's forks leave less room to
the branches grown after it); the depth counts the forking states of the path (a fork
at the state of the path's last fork nests within it, :NESTED)."
  (let ((same-state (and *branching* (eql index (getf *branching* :state))))
        (tree (or (getf *branching* :tree) (list 0))))
    (incf (first tree) (length alternatives))
    (list :count (+ (getf *branching* :count 0) (length alternatives))
          :tree tree
          :depth (if same-state (getf *branching* :depth 0) (1+ (getf *branching* :depth 0)))
          :state index
          :nested (if same-state (1+ (getf *branching* :nested 0)) 1)
          :extra-facts (getf *branching* :extra-facts))))

(defun negated-fact (fact)
  "The strict opposite of the inequality FACT (X > Y gives X < Y): the boundary is a
branch of its own."
  (list (ecase (first fact) ((> >=) '<) ((< <=) '>)) (relation-lhs fact) (relation-rhs fact)))

(defun fork-alternatives (run fact)
  "The branches of the missing FACT: plists (:ASSUME RELATION :FACTS FACTS :SCENARIO S)
with FACTS the assumptions the branch adds and S its scenario (the boundary's has a
parameter substituted). They do not overlap: X > 0, X < 0 and X = 0 when there is a
boundary branch, else FACT and its strict opposite (and, for a strict FACT, its boundary
marked :UNSOLVED with why, with no scenario: see UNSOLVED-BOUNDARY-BRANCH). Alternatives the assumptions
already exclude, or proven impossible under the facts in force (IMPOSSIBLE-FACT-P), are
left out."
  (let* ((scenario (run-scenario run))
         (boundary
           (multiple-value-bind (parameter value)
               (and (<= (ames.maxima:expression-size fact) *largest-boundary-fact*)
                    (boundary-substitution run fact))
             (when parameter
               (let ((facts (parameter-facts scenario parameter value)))
                 (unless (or (some (lambda (f) (eq (decide run f) :false)) facts)
                             (impossible-fact-p run `(= ,(relation-lhs fact) ,(relation-rhs fact))))
                   (let ((form (substituted-form (scenario-form scenario) parameter value)))
                     (handler-case
                         (list :assume `(= ,(relation-lhs fact) ,(relation-rhs fact))
                               :facts facts
                               :scenario (parse-scenario form :source (scenario-source scenario))
                               :substitution (list parameter value))
                       (scenario-error () nil))))))))
         (alternatives '()))
    ;; with a boundary branch of its own, the sides are strict (X >= 0 becomes X > 0)
    (dolist (side (list (if boundary (negated-fact (negated-fact fact)) fact) (negated-fact fact)))
      (unless (or (eq (decide run side) :false) (impossible-fact-p run side))
        (push (list :assume side :facts (list side) :scenario scenario) alternatives)))
    (cond (boundary (push boundary alternatives))
          ;; X > 0 and X < 0 leave X = 0 out: where no parameter is solved for from it,
          ;; the boundary is listed unsimulated, with why, rather than left unsaid
          ((and (member (first fact) '(> <))
                (not (impossible-fact-p run `(= ,(relation-lhs fact) ,(relation-rhs fact)))))
           (push (list :assume `(= ,(relation-lhs fact) ,(relation-rhs fact)) :facts '()
                       :unsolved (if (<= (ames.maxima:expression-size fact) *largest-boundary-fact*)
                                     "no parameter of the scenario could be solved for from this boundary, so it is not simulated"
                                     "this boundary's fact is too large for a parameter to be solved for from it, so it is not simulated"))
                 alternatives)))
    (nreverse alternatives)))

(defun branchable-fact-p (fact)
  "True when FACT is an inequality over the parameters (not a description)."
  (and (consp fact) (member (first fact) '(< > <= >=))
       (notany #'keywordp (alexandria:flatten fact))))

(defun values-satisfy-p (bridge relation values)
  "True when the parameter VALUES (an alist) satisfy RELATION numerically (within 1e-12;
an equation only when its sides agree so closely); NIL when they do not or when it
cannot be evaluated."
  (let ((difference (numeric-or-nil bridge `(- ,(relation-lhs relation) ,(relation-rhs relation))
                                    values)))
    (and difference
         (ecase (first relation)
           (> (> difference 1d-12))
           (>= (>= difference -1d-12))
           (< (< difference -1d-12))
           (<= (<= difference 1d-12))
           (= (<= (abs difference) 1d-12))))))

(defun selected-alternative (run alternatives values)
  "The alternative of ALTERNATIVES whose fact the parameter VALUES satisfy, or NIL."
  (when values
    (find-if (lambda (alternative)
               (values-satisfy-p (run-bridge run) (getf alternative :assume) values))
             alternatives)))

(defun assumed-on-this-path-p (fact)
  "True when FACT, its opposite or its boundary is already assumed by a fork on the path
from the root to the branch being simulated: the assumption did not decide it, and
forking on it again would only repeat the same branches one level deeper."
  (let ((assumed (getf *branching* :extra-facts))
        (lhs (relation-lhs fact)) (rhs (relation-rhs fact)))
    (some (lambda (other)
            (and (consp other) (member (first other) '(< > <= >= =))
                 (or (and (equal (relation-lhs other) lhs) (equal (relation-rhs other) rhs))
                     (and (equal (relation-lhs other) rhs) (equal (relation-rhs other) lhs)))))
          assumed)))

(defun fork (run history index condition check-incremental)
  "Split the run at state INDEX on the ambiguity CONDITION: append to HISTORY a fork
state (zero duration, end event (:BRANCH)) holding each branch's states and outcome.
Returns true, or NIL when CONDITION cannot be branched on (its missing fact is no
inequality over the parameters, the tree is full, or a fork on this path already assumed
that fact: see ASSUMED-ON-THIS-PATH-P)."
  (let ((fact (core-fact run (ambiguous-transition-missing-fact condition))))
    (when *branching*
      ;; why the fork is refused, for the branch's failure (GROW-BRANCH)
      (setf (getf *branching* :refusal)
            (cond ((not (branchable-fact-p fact)) :not-branchable)
                  ((assumed-on-this-path-p fact) :assumed)
                  ((not (branch-room-p index)) :bound))))
    (when (and (branchable-fact-p fact) (not (assumed-on-this-path-p fact))
               (branch-room-p index))
      (let* ((alternatives (fork-alternatives run fact))
             (values (history-parameter-values history))
             (selected (selected-alternative run alternatives values))
             (partial (ambiguous-transition-state condition))
             (fork (make-instance 'qualitative-state
                                  :index index :start (run-time run) :duration 0
                                  :initial-velocities (run-velocities run)
                                  :contacts (and partial (state-contacts partial))
                                  :accelerations (and partial (state-accelerations partial))
                                  :forces (and partial (state-forces partial))
                                  :positions (mapcar (lambda (entry) (list (first entry) (second entry)))
                                                     (run-positions run))
                                  :velocities (run-velocities run)
                                  :end-event '(:branch)
                                  :final-positions (run-positions run)
                                  :final-velocities (run-velocities run)
                                  :missing-fact fact :fork t)))
        (note-rotation-held run fork)
        ;; one consistent outcome (the others proven impossible) is still a fork: its
        ;; branch assumes the fact that the facts in force imply
        (when alternatives
          (setf (state-branches fork)
                (let ((*branching* (nested-branching index alternatives)))
                  (mapcar (lambda (alternative)
                            (cond
                              ((getf alternative :unsolved)
                               (unsolved-boundary-branch alternative (eq alternative selected)))
                              ((or (eq alternative selected)
                                   (simulate-every-branch-p run selected))
                               (grow-branch run alternative index check-incremental
                                            (eq alternative selected)
                                            (and values (numeric-clock (run-bridge run)
                                                                       (history-states history)
                                                                       values))))
                              (t (unsimulated-branch alternative))))
                          alternatives)))
          (setf (history-states history) (append (history-states history) (list fork))
                (history-outcome history) :branched)
          t)))))

(defun simulate-every-branch-p (run selected)
  "True when every branch of a fork is simulated: no values select one (SELECTED is NIL),
the scenario's (simulate :all-branches t) or *ALL-BRANCHES* (--all-branches) asks for
all, or a query selects a parameter (its answer is read off every branch). Otherwise
only the selected branch is (the language page, \"Ambiguity and branching\")."
  (or (null selected) *all-branches* (scenario-all-branches (run-scenario run))
      (some (lambda (query) (eq (first (second query)) :parameter))
            (scenario-queries (run-scenario run)))))

(defun unsimulated-branch (alternative)
  "The branch ALTERNATIVE listed with its fact only, as the values rule it out:
(:ASSUME FACT :STATES () :OUTCOME :NOT-SIMULATED [:SUBSTITUTION (P V)])."
  (append (list :assume (getf alternative :assume) :states '() :outcome :not-simulated)
          (and (getf alternative :substitution)
               (list :substitution (getf alternative :substitution)))))

(defun continuable-branch-p (run alternative selected)
  "True when the branch ALTERNATIVE continues from the fork (see fork-continuation.lisp):
its scenario is the run's (no parameter substituted), and either it is the SELECTED one
or the run has no values (which may have settled facts before the fork that another
branch must not inherit)."
  (and (null (getf alternative :substitution))
       (or selected (null (run-values run)))))

(defun grow-branch (run alternative index check-incremental selected &optional clock)
  "Simulate the branch ALTERNATIVE under its facts, from the fork on when it may continue
there (CONTINUABLE-BRANCH-P), else from the start; CLOCK is the number at which the fork
starts under the values (see NUMERIC-CLOCK); its states from the fork on, as (:ASSUME FACT :STATES ... :OUTCOME ...
[:SELECTED T] [:SUBSTITUTION (P V)])."
  (let* ((facts (append (getf *branching* :extra-facts) (getf alternative :facts)))
         (failure nil)
         (outcome :failed)
         (unfinished (list nil))
         (history (let ((*branching* (list* :extra-facts facts *branching*))
                        (*unfinished-branch* unfinished))
                    (handler-case
                        ;; the values satisfy the selected branch's fact only: in the
                        ;; others they would settle facts against the branch's own
                        (if (continuable-branch-p run alternative selected)
                            (continue-branch run index (getf alternative :facts)
                                             (and selected (run-values run)) check-incremental
                                             clock)
                            (simulate-branch (getf alternative :scenario) (run-bridge run)
                                             (and selected (run-values run)) check-incremental
                                             facts))
                      ;; the run's budget is the whole tree's: it is not one branch's failure
                      (budget-exceeded (condition) (error condition))
                      ;; an ambiguity the tree may not fork on (its bound, or a fact
                      ;; already assumed on this path): the branch ends ambiguous
                      (ambiguous-transition (condition)
                        (setf outcome :ambiguous
                              failure (format nil "~A; the missing fact: ~A"
                                              (case (getf *branching* :refusal)
                                                (:bound "the tree's bound is reached")
                                                (:not-branchable
                                                 (concatenate 'string "the question is no inequality over"
                                                              " the parameters that a fork could assume"))
                                                (t "a fact this path already assumed does not decide it"))
                                              (let ((*print-pretty* nil) (*print-case* :downcase))
                                                (princ-to-string
                                                 (ambiguous-transition-missing-fact condition)))))
                        nil)
                      (ames-error (condition)
                        ;; one branch that cannot be simulated (or whose scenario, with a
                        ;; parameter substituted at a boundary, cannot be checked) does not
                        ;; lose the others
                        (setf failure (failure-text condition))
                        ;; the states it finished before a refusal (KEEP-UNFINISHED-BRANCH)
                        (first unfinished)))))
         (states (and history
                      (remove-if (lambda (state) (< (state-index state) index))
                                 (history-states history)))))
    (append (list :assume (getf alternative :assume)
                  :states states
                  :outcome (if history (history-outcome history) outcome))
            (and failure (list :failure failure))
            (and selected (list :selected t))
            (and (getf alternative :substitution)
                 (list :substitution (getf alternative :substitution))))))

(defun failure-text (condition)
  "Why a branch failed, from the AMES-ERROR CONDITION: its detail (or its type) and the
form at fault (its datum, printed on one line; one over 300 characters only by its
length), so that the fact a geometry could not decide is named."
  (let* ((detail (or (ames-error-detail condition) (string-downcase (type-of condition))))
         (datum (ames-error-datum condition))
         (printed (and datum
                       (let ((*print-pretty* nil) (*print-case* :downcase))
                         (princ-to-string datum)))))
    (cond ((or (null printed) (search printed detail)) detail)
          ;; a prefix form cut short could not be read back as a formula by the reports
          ((> (length printed) 300)
           (format nil "~A (at a formula of ~D characters, too long to print)" detail (length printed)))
          (t (format nil "~A (at ~A)" detail printed)))))

(defun history-leaf-outcomes (history)
  "The outcomes of HISTORY's paths: its own outcome, or, when it ends in a fork, every
branch's leaf outcomes (:FAILED for a branch that could not be simulated)."
  (labels ((leaves (outcome states)
             (if (eq outcome :branched)
                 (loop for branch in (state-branches (car (last states)))
                       append (leaves (getf branch :outcome) (getf branch :states)))
                 (list outcome))))
    (leaves (history-outcome history) (history-states history))))

(defun simulate-branch (scenario bridge values check-incremental facts)
  "SCENARIO simulated from the start with FACTS assumed besides its own assumptions:
its SIMULATION-HISTORY. VALUES are the run's parameter values (an alist by symbol)."
  (let ((*history-clock* 0))            ; its history starts at t = 0
    (simulate-checked scenario bridge
                      ;; the values of the parameters SCENARIO still has, keyed by its symbols
                      (loop for (name . value) in values
                            for parameter = (find-scenario-parameter name scenario)
                            when parameter
                              collect (cons (scenario-parameter-name parameter) value))
                      check-incremental :extra-facts facts)))
