;;;; src/simulator/simulate.lisp -- the qualitative-state loop (thesis sections 2.5.8 and 3.2.3):
;;;; SIMULATE and the transitions between states (the numbers beside the formulas:
;;;; state-numbers.lisp).
;;;;
;;;; For each state: choose the contacts and modes by consistency, solve and integrate its
;;;; model, prove which termination condition fires first, then carry the positions and
;;;; velocities over and apply to the model, incrementally, only the changes the fired
;;;; conditions stand for (checked against a rebuild from scratch).

(in-package #:ames.simulator)

(defvar *bridge* nil
  "The current Maxima bridge of the REPL and the command line, made on first use.")

(defun current-bridge ()
  "The current Maxima bridge, made on first use."
  (or *bridge* (setf *bridge* (ames.maxima:make-bridge))))

(defvar *state-hook* nil
  "NIL, or a function of a SIMULATION-HISTORY and the QUALITATIVE-STATE just appended to
it, called as each state's analysis is done (the command line's progress report).")

(defvar *states-reported-before* -1
  "The last state index of the run in hand that an abandoned attempt already gave to
*STATE-HOOK* (SIMULATE-IN-WORLD): those states are not given to it again.")

(defvar *attempt-history* nil
  "A cons whose CAR SIMULATE-WORLD-ONCE sets to the history it makes (so that an
abandoned attempt's states can be counted).")

(defparameter *default-state-limit* 12
  "How many states a scenario runs when its (simulate ...) clause sets no :states.")

(defun initial-motion-state (scenario)
  "The alists body -> position and body -> velocity at the start of SCENARIO."
  (values (mapcar (lambda (body) (list (scenario-body-name body) (scenario-body-position body)))
                  (scenario-bodies scenario))
          (mapcar (lambda (body) (list (scenario-body-name body)
                                       (or (scenario-body-velocity body) '(0 0))))
                  (scenario-bodies scenario))))

(defun time-after (run start state)
  "The global time at which STATE, started at START, ends: an expression, or
(:NO-CLOSED-FORM :AFTER-STATE N) when a duration so far has no closed form."
  (let ((duration (state-duration state)))
    (if (and (closed-form-time-p start) (closed-form-time-p duration))
        (tidy run `(+ ,start ,duration))
        (list :no-closed-form :after-state (state-index state)))))

(defun impulsive-p (candidate)
  "True when CANDIDATE is reached at a non-zero rate: an impact."
  (let ((rate (candidate-rate candidate)))
    (and rate (not (eql rate 0)) (candidate-condition candidate)
         (ames.engine:termination-condition-impact (candidate-condition candidate))
         (equal (candidate-event candidate)
                (ames.engine:termination-condition-impact (candidate-condition candidate))))))

(defun enter-next-state (run state fired &key (check-incremental t))
  "Carry STATE's final positions and velocities over, resolve the impact when FIRED
holds an impulsive candidate (the velocities then jump: see impacts.lisp; the state's
end event gets the impulse and the energy lost), and apply to the model, incrementally,
the changes the other FIRED candidates stand for, and after an impact the activations
the new velocities decide. Checked against a rebuild from scratch when
CHECK-INCREMENTAL."
  (setf (run-positions run) (state-final-positions state)
        (run-velocities run) (state-final-velocities state)
        (run-time run) (time-after run (run-time run) state))
  (carry-rotations-over run state)
  (let* ((impulsive (remove-if-not #'impulsive-p fired))
         (changes (remove nil (remove-duplicates
                               (mapcar #'candidate-change (set-difference fired impulsive))
                               :test #'equal))))
    (when impulsive
      (check-held-contacts-at-impact run state fired) ; held-contacts.lisp
      (multiple-value-bind (after impact)
          (let ((*impact-at-values* (numeric-end-state-p state))) ; numeric-ends.lisp
            (multiple-value-call #'valued-impact run *impact-at-values* (resolve-impact run impulsive)))
        (setf (run-velocities run) after
              (run-rotations run) (impact-rotations run impact)
              (state-impact state) impact
              (state-end-event state) (impact-event (state-end-event state) impact))
        (let ((events (state-simultaneous-events state)))
          (when events
            (setf (state-simultaneous-events state)
                  (mapcar (lambda (event)
                            (if (find event impulsive :key #'candidate-event :test #'equal)
                                (impact-event event impact)
                                event))
                          events))))))
    (multiple-value-bind (model report)
        (ames.engine:apply-transition (run-model run) changes :decider (state-decider run))
      (declare (ignore model))
      (push (ames.engine:transition-report-rederived-count report) (run-rederived run)))
    (when impulsive
      (apply-stale-changes run)
      (sum-zeno-sequence run state)
      (when (state-accumulation state)
        ;; the run goes on from the series' limit, at rest: what that decides
        (apply-stale-changes run)))
    (when check-incremental
      (ames.engine:check-incremental (run-model run)))))

(defun apply-stale-changes (run)
  "Apply to RUN's model the activations and then the modes the current start decides
anew (after an impact, the new velocities: AMES.ENGINE:STALE-ACTIVATION-CHANGES and
STALE-MODE-CHANGES)."
  (let ((stale (ames.engine:stale-activation-changes (run-model run) :decider (state-decider run))))
    (when stale
      (ames.engine:apply-transition (run-model run) stale :decider (state-decider run))))
  (let ((stale (ames.engine:stale-mode-changes (run-model run) :decider (state-decider run))))
    (when stale
      (ames.engine:apply-transition (run-model run) stale :decider (state-decider run)))))

(defun depends-on-motion-p (x)
  "True when the expression (or list of expressions) X has TAU or a state quantity (a
position, a velocity...) in it."
  (or (eq x 'tau)
      (and (consp x) (or (state-quantity-p x) (some #'depends-on-motion-p x)))))

(defun sum-zeno-sequence (run state)
  "Record the impact that ended STATE; when it repeats the previous one scaled (see
ZENO-ACCUMULATION), jump to the accumulation point: the run goes on from there with the
velocities' limit, zero, and STATE says so (STATE-ACCUMULATION)."
  (let* ((impact (state-impact state))
         (record (list :time (run-time run) :positions (run-positions run)
                       :after (run-velocities run)
                       :contacts (mapcar (lambda (c) (subseq c 0 2)) (getf impact :contacts))
                       ;; a flight that scales with its start speed: constant accelerations
                       ;; (free of tau, and of the velocities and positions: a drag's
                       ;; acceleration written over the velocity is no constant)
                       :uniform (notany (lambda (entry) (depends-on-motion-p (second entry)))
                                        (state-accelerations state))))
         (accumulation (zeno-accumulation run (first (run-impacts run)) record)))
    (push record (run-impacts run))
    (when accumulation
      (setf (state-accumulation state) accumulation
            (run-time run) (getf accumulation :time)
            (run-velocities run) (mapcar (lambda (entry) (list (first entry) (list 0 0)))
                                         (run-velocities run))
            (run-impacts run) '()))))

(defun fact-from-values (run fact values)
  "FACT, or its negation, as the parameter VALUES decide it numerically; when the values
make its two sides equal (exactly, in rational arithmetic), the equation (= LHS RHS) of
that boundary case. NIL when they do not decide it (no values, a value missing). When
the two sides differ under the values the negation is the strict one: (< X Y) false
means (> X Y)."
  (when (and values (consp fact) (member (first fact) '(< > <= >=))
             (notany #'keywordp (alexandria:flatten fact)))
    (let* ((difference-form `(- ,(relation-lhs fact) ,(relation-rhs fact)))
           (exact (expression-value (substitute-expressions values difference-form)))
           (difference (if (rationalp exact)
                           exact
                           (numeric-or-nil (run-bridge run) difference-form values))))
      (cond ((null difference) nil)
            ((and (rationalp difference) (zerop difference))
             (list '= (relation-lhs fact) (relation-rhs fact)))
            ((zerop difference) nil)
            ((ecase (first fact) ((> >=) (plusp difference)) ((< <=) (minusp difference)))
             fact)
            (t (list (ecase (first fact) ((> >=) '<) ((< <=) '>))
                     (relation-lhs fact) (relation-rhs fact)))))))

(defun run-states (run history index limit check-incremental)
  "Analyse the states of RUN from INDEX on, appending them to HISTORY, until nothing
more changes, an impact, or LIMIT states. When the assumptions leave a state ambiguous
but the history's parameter values decide the missing fact, that fact is assumed (and
noted in the history) for the rest of the run."
  (loop for index from index
        do (check-budget index)
           (when (>= index limit)
             (setf (history-outcome history) :state-limit)
             (return))
           (multiple-value-bind (state fired)
               (handler-case (analyse-state run index)
                 (ambiguous-transition (condition)
                   (when (and (scenario-branch (run-scenario run))
                              (fork run history index condition check-incremental))
                     (return-from run-states))
                   ;; no fork (the tree is full, or no branching): an outcome the facts in
                   ;; force imply (the others proven impossible) is assumed
                   (let ((implied (assume-implied-fact run history index condition)))
                     (when implied
                       (return-from run-states
                         (ames.maxima:with-assumptions ((run-bridge run) (list implied))
                           (run-states run history index limit check-incremental)))))
                   (let ((fact (fact-from-values run (core-fact run (ambiguous-transition-missing-fact condition))
                                                 (history-parameter-values history))))
                     (when (and (null fact) (note-rootless-end run history index condition))
                       ;; a state's end at a root without closed form, no numbers
                       (return-from run-states))
                     (when (or (null fact)
                               (member fact (getf (history-notes history) :assumed)
                                       :key (lambda (entry) (getf entry :fact)) :test #'equal)
                               (> (length (getf (history-notes history) :assumed)) 24))
                       (error condition))
                     (push (list :state index :fact fact) (getf (history-notes history) :assumed))
                     (return-from run-states
                       (ames.maxima:with-assumptions ((run-bridge run) (list fact))
                         (run-states run history index limit check-incremental))))))
             (setf (history-states history) (append (history-states history) (list state)))
             (when (and *state-hook* (> index *states-reported-before*))
               (funcall *state-hook* history state))
             (cond ((null fired)
                    (setf (history-outcome history) :complete)
                    (return))
                   ((eq fired :undecided)
                    (setf (history-outcome history) :undecided)
                    (return))
                   ((find :time-limit fired :key (lambda (c) (first (candidate-event c))))
                    (setf (history-outcome history) :time-limit)
                    (return))
                   ((not (closed-form-time-p (state-duration state)))
                    ;; the next state starts at a time without closed form: fine, its
                    ;; start is reported as such
                    (enter-next-state run state fired :check-incremental check-incremental))
                   ((>= (1+ index) limit)
                    ;; the last state allowed: its end (the impact) is carried over, but a
                    ;; next state the knowledge base has no model for is not needed
                    (handler-case (enter-next-state run state fired :check-incremental check-incremental)
                      (ames.kb:unmodelled-situation () nil)))
                   (t (enter-next-state run state fired :check-incremental check-incremental))))))

(defun simulate (scenario &key (bridge (current-bridge)) parameter-values
                            (check-incremental t) (limits *limits*))
  "Simulate SCENARIO (a SCENARIO object, or a scenario form as in a file) and return its
SIMULATION-HISTORY. BRIDGE is the Maxima bridge (by default the current one).
PARAMETER-VALUES, an alist (PARAMETER-NAME . NUMBER) matched by name, adds numeric
values to the report and decides what the assumptions leave open. CHECK-INCREMENTAL
compares every incrementally updated model with a rebuild from scratch.
Signals SCENARIO-ERROR for a defective scenario, AMBIGUOUS-TRANSITION (restart
STOP-SIMULATION, which returns the history so far) when the assumptions do not decide
which contacts hold or which event ends a state, UNSOLVABLE-MODEL and
UNSUPPORTED-SITUATION, and the Maxima bridge's conditions.
The run has a budget made from LIMITS (see AMES.BASE:CALL-WITH-BUDGET): going over its
time or sizes signals BUDGET-EXCEEDED. PARAMETER-VALUES are checked first
(PARAMETER-VALUES-ERROR). Outside an assumption scope the bridge is reset first (fresh
names and cache), so that what a run prints does not depend on what ran before it."
  (let* ((scenario (if (scenario-p scenario) scenario (parse-scenario scenario)))
         (parameter-values (check-parameter-values parameter-values scenario)))
    (unless (ames.maxima:bridge-in-scope-p bridge)
      (ames.maxima:reset-bridge bridge))
    (refuse-awaiting scenario bridge)
    (call-with-budget
     (lambda () (simulate-within-budget scenario bridge parameter-values check-incremental))
     :limits limits :subject (scenario-name scenario))))

(defun refuse-awaiting (scenario bridge)
  "Signal UNSUPPORTED-SITUATION naming the first thing SCENARIO asks that AMES does not
simulate yet (SCENARIO-AWAITING: a rotating body...), after the checks of its
assumptions (so that a mistake in it is reported first). Never runs such a scenario
without it (a rotating body as a translating one)."
  (let ((awaiting (scenario-awaiting scenario)))
    (when awaiting
      (check-scenario-assumptions scenario bridge)
      (error 'unsupported-situation
             :datum (first (first awaiting))
             :detail (format nil "~{~A~^; ~}. The scenario is refused rather than simulated ~
                                  without it." (mapcar #'second awaiting))))))

(defun simulate-within-budget (scenario bridge parameter-values check-incremental)
  "SIMULATE's run of the validated SCENARIO, once its budget is set."
  (progn
    (handler-bind ((arithmetic-error
                     ;; numbers beyond floating point in the geometry's or our own arithmetic
                     (lambda (condition)
                       (error 'simulation-error
                              :datum (scenario-name scenario)
                              :detail (format nil "Arithmetic on the scenario's numbers failed (~A); use exact numbers or smaller magnitudes."
                                              (type-of condition))))))
      (simulate-checked scenario bridge parameter-values check-incremental))))

(defun undecided-to-ambiguity (condition &optional run)
  "An engine's UNDECIDED-RELATION (a touching contact whose normal velocity's sign the
assumptions do not decide) as an AMBIGUOUS-TRANSITION. Given the RUN, the missing fact
is the relation over the state's starting values (see RELATION-AT-START: a fact over
the parameters, not the knowledge base's quantity terms)."
  (let* ((relation (ames.engine:undecided-relation-relation condition))
         (fact (if run
                   (handler-case (tidy-relation run (relation-at-start run relation))
                     (ames-error () relation))
                   relation)))
    (error 'ambiguous-transition
           :datum fact :missing-fact fact
           :detail "start of a state (an activation condition)")))

(defun tidy-relation (run relation)
  "RELATION with both sides' difference simplified: (OP (- LHS RHS) 0)."
  (if (and (consp relation) (member (first relation) '(= /= < > <= >=)))
      (list (first relation) (tidy run `(- ,(second relation) ,(third relation))) 0)
      relation))

(defun make-run (world bridge &optional parameter-values)
  "The RUN of WORLD's validated scenario at its start, in the shapes and contact pairs
its checks built (see CHECK-SCENARIO), its first model built (call under the scenario's
assumptions in BRIDGE). PARAMETER-VALUES as SIMULATE has checked them."
  (let ((scenario (world-scenario world)))
    (multiple-value-bind (positions velocities) (initial-motion-state scenario)
      (let* ((contacts (world-contacts world))
             (run (multiple-value-bind (loci kinds) (probe-loci scenario bridge (length contacts))
                    (setf contacts (append contacts loci))
                    (make-instance 'run :scenario scenario :bridge bridge
                                        :shapes (world-shapes world)
                                        :contacts contacts :locus-kinds kinds
                                        :alternatives (corner-alternatives bridge contacts)
                                        :positions positions :velocities velocities
                                        :rotations (initial-rotations scenario)
                                        :values parameter-values)))
             (situation (ames.engine:make-situation (situation-entities run) :data run)))
        (handler-bind ((ames.engine:undecided-relation #'undecided-to-ambiguity))
          (setf (run-model run)
                (ames.engine:build-model (ames.engine:make-engine (ames.kb:mechanics-knowledge-base))
                                         situation :decider (state-decider run))))
        run))))

(defun simulate-checked (scenario bridge parameter-values check-incremental &key extra-facts)
  "SIMULATE's work on the validated SCENARIO with PARAMETER-VALUES as CHECK-PARAMETER-VALUES
returns them (keyed by the scenario's symbols), with EXTRA-FACTS (relations) assumed
besides the scenario's own assumptions (a branch's). The scenario's checks (shapes, no
overlap at the start) see the extra facts too: a boundary branch's scenario has lost a
parameter's declaration to them. The run is made in the WORLD the checks built."
  (let* ((*pair-screen* (and *defer-pairs* (make-pair-screen)))
         (world (unless extra-facts
                  ;; first on its own, so that contradictory assumptions are named by parameter
                  (nth-value 1 (check-scenario scenario bridge)))))
    (ames.maxima:with-assumptions (bridge (append (scenario-assumption-relations scenario) extra-facts))
      (simulate-in-world (or world (nth-value 1 (check-scenario scenario bridge)))
                         bridge parameter-values check-incremental))))

(defun simulate-in-world (world bridge parameter-values check-incremental)
  "SIMULATE-WORLD-ONCE of WORLD; when a pair the world left out (deferred-pairs.lisp)
cannot be proven apart in a state, again from the start in a world with every pair
built (its contacts then numbered as they always were, so that the canonical order of
the model's equations, which their names enter, is the one a full world gives). The
states an abandoned attempt gave *STATE-HOOK* are not given to it again."
  (let ((reported -1))
    (loop
      (let ((needed nil) (attempt-history (list nil)))
        (let ((history
                (block attempt
                  (handler-bind ((deferred-pairs-needed
                                   (lambda (condition)
                                     (setf needed (deferred-pairs-needed-pairings condition))
                                     (return-from attempt nil))))
                    (let ((*deferred-pairings* (world-deferred-pairings world))
                          (*states-reported-before* reported)
                          (*attempt-history* attempt-history))
                      (simulate-world-once world bridge parameter-values check-incremental))))))
          (cond (needed
                 (when (first attempt-history)
                   (setf reported (max reported
                                       (1- (length (history-states (first attempt-history)))))))
                 (setf world (world-with-pairings world bridge (world-deferred-pairings world))))
                (t (return history))))))))

(defun simulate-world-once (world bridge parameter-values check-incremental)
  "The SIMULATION-HISTORY of WORLD's scenario run in WORLD under the assumptions in force
(see SIMULATE-CHECKED): the states, then the numbers under PARAMETER-VALUES and the
answers to the queries. The restart STOP-SIMULATION returns the history so far."
  (let* ((scenario (world-scenario world))
         (history (make-instance 'simulation-history
                                 :scenario scenario
                                 :parameter-values parameter-values))
         (limit (or (scenario-states scenario) *default-state-limit*))
         (run nil))
    (when *attempt-history* (setf (car *attempt-history*) history))
    (restart-case
        (handler-bind ((ames.engine:undecided-relation
                         (lambda (condition) (undecided-to-ambiguity condition run))))
          (setf run (make-run world bridge parameter-values))
          (run-states run history 0 limit check-incremental))
      (stop-simulation (&optional condition)
        :report "Stop the simulation here and return the states so far."
        (setf (history-outcome history) (if (typep condition 'ambiguous-transition)
                                            :ambiguous
                                            :stopped))
        (when (and (typep condition 'ambiguous-transition)
                   (ambiguous-transition-state condition))
          (setf (history-states history)
                (append (history-states history)
                        (list (ambiguous-transition-state condition)))))
        (setf (getf (history-notes history) :stopped-by) condition)))
    (when run
      (when (run-assumed run)
        (setf (getf (history-notes history) :decided-by-values) (reverse (run-assumed run))))
      (setf (getf (history-notes history) :model-sizes) (run-statistics run))
      (setf (history-rederived history) (reverse (run-rederived run))))
    ;; a run stopped by its time (or a signal) has no time left to ask Maxima more
    (unless (typep (getf (history-notes history) :stopped-by) 'budget-exceeded)
      (analyse-history history bridge))
    history))

(defun analyse-history (history bridge &optional (clock 0))
  "The analysis that follows a simulation, reading only HISTORY (its states and what the
knowledge base reported in them), never the run: the numbers beside the formulas under
the history's parameter values (ADD-NUMERIC-VALUES, its first state starting at CLOCK),
then the answers to the scenario's queries (ANSWER-QUERIES), unless HISTORY is a branch
still growing (the root's analysis answers them for every path). Call under the
scenario's assumptions. Returns HISTORY."
  (add-numeric-values history bridge clock)
  (when (and (scenario-queries (history-scenario history)) (null *branching*))
    (setf (history-answers history) (answer-queries history bridge)))
  history)
