;;;; t/friction.lisp -- Coulomb friction (issue 11): the friction clause, the component's modes,
;;;; entry choices and events, the report; and the helpers of t/friction-scenarios.lisp, which
;;;; checks the textbook scenarios.

(in-package #:ames.tests)

(def-suite friction :in all-tests
  :description "Coulomb friction: the friction clause, the coulomb-friction component
(src/kb/friction.lisp) and scenarios with static and sliding contacts.")

(in-suite friction)

;;; Helpers

(defun scenario-form-named (name)
  "The form of the first scenario of the file scenarios/NAME.lisp."
  (first (ames:read-scenario-forms
          (uiop:read-file-string (find name (scenario-files) :key #'pathname-name
                                                             :test #'string=)))))

(defun scenario-assuming (name parameter relation)
  "The scenario of scenarios/NAME.lisp with RELATION (over names of its parameters)
added to the assumptions of its PARAMETER (a name), whose default value is dropped (it
may violate RELATION)."
  (ames:parse-scenario
   (mapcar (lambda (clause)
             (if (and (consp clause) (same-name-p* (first clause) "PARAMETERS"))
                 (cons (first clause)
                       (mapcar (lambda (spec)
                                 (if (and (consp spec) (same-name-p* (first spec) parameter))
                                     (append (remove-if (lambda (item)
                                                          (and (consp item)
                                                               (eq (first item) :value)))
                                                        spec)
                                             (list relation))
                                     spec))
                               (rest clause)))
                 clause))
           (scenario-form-named name))))

(defun friction-entry (state body-1 body-2)
  "The (:friction BODY-1 BODY-2 VALUE :mode MODE) entry of STATE's forces (names), or NIL."
  (find-if (lambda (force)
             (and (eq (first force) :friction)
                  (same-name-p* (second force) body-1)
                  (same-name-p* (third force) body-2)))
           (ames::state-forces-of state)))

(defun check-friction (bridge state body-1 body-2 mode value)
  "Check that STATE reports friction of BODY-2 on BODY-1 in MODE (:static or :sliding)
whose signed component along the contact's tangent is VALUE (Maxima-checked)."
  (let ((entry (friction-entry state body-1 body-2)))
    (is (not (null entry)) "no friction ~A-~A in ~S" body-1 body-2 (ames::state-forces-of state))
    (when entry
      (is (eq mode (getf (cddddr entry) :mode)) "mode ~S, expected ~S" entry mode)
      (is-same bridge (format nil "friction ~A-~A" body-1 body-2) (fourth entry) value))))

(defun run-of (scenario bridge &rest keys)
  "SCENARIO's history and its states, as two values (an ambiguity stops the run)."
  (let ((history (apply #'simulate-stopping-when-ambiguous scenario bridge keys)))
    (values history (ames::history-states history))))

;;; The clause

(defparameter *rough-floor-form*
  '(scenario rough-floor "A block on a rough floor."
    (parameters (m :positive) (g :positive) (mu :positive))
    (gravity g)
    (body floor :fixed t :shape (half-plane (1 0) (0 0)))
    (body block :mass m :position (0 0) :velocity (0 0)
     :shape (polygon (-1 0) (1 0) (1 1) (-1 1)))
    (force push :on block :value (1 0)))
  "A valid scenario to which the tests add friction clauses.")

(test friction-clause-is-validated
  (flet ((with (&rest clauses) (append *rough-floor-form* clauses)))
    (let* ((scenario (ames:parse-scenario (with '(friction floor block :static mu))))
           (friction (first (ames:scenario-frictions scenario))))
      (is (= 1 (length (ames:scenario-frictions scenario))))
      (is (equal '("FLOOR" "BLOCK") (names-of (ames:scenario-friction-bodies friction))))
      (is (same-name-p* 'mu (ames:scenario-friction-static friction)))
      (is (equal (ames:scenario-friction-static friction) (ames:scenario-friction-kinetic friction))
          "MU-K defaults to MU-S")
      (is (eq friction (ames:find-scenario-friction 'block 'floor scenario))))
    (is (equal '(/ 1 3) (ames:scenario-friction-kinetic
                         (first (ames:scenario-frictions
                                 (ames:parse-scenario
                                  (with '(friction block floor :static 1/2 :kinetic (/ 1 3)))))))))
    (signals-naming (ames:undeclared-symbol-error :location "FRICTION" :datum wall)
      (with '(friction block wall :static mu)))
    (signals-naming (ames:undeclared-symbol-error :datum push)
      (with '(friction block push :static mu)))
    (signals-naming (ames:scenario-syntax-error :location "friction BLOCK BLOCK" :detail "itself")
      (with '(friction block block :static mu)))
    (signals-naming (ames:missing-property-error :location "friction BLOCK FLOOR" :detail ":static")
      (with '(friction block floor :kinetic mu)))
    (signals-naming (ames:missing-property-error :location "FRICTION")
      (with '(friction block)))
    (signals-naming (ames:scenario-syntax-error :datum :slippery)
      (with '(friction block floor :static mu :slippery t)))
    (signals-naming (ames:scenario-expression-error :datum -1 :detail "negative")
      (with '(friction block floor :static -1)))
    (signals-naming (ames:scenario-expression-error :datum 1 :detail "exceeds")
      (with '(friction block floor :static 1/2 :kinetic 1)))
    (signals-naming (ames:undeclared-symbol-error :datum nu)
      (with '(friction block floor :static nu)))
    (signals-naming (ames:duplicate-clause-error :location "friction FLOOR BLOCK")
      (with '(friction block floor :static mu) '(friction floor block :static 1)))))

;;; The component: modes, entry conditions settled by consistency, events

(test friction-component-modes-and-events
  "A rough contact at rest leaves its mode open (every entry condition is at its
boundary): the three modes are the options, in the component's order of preference.
Static ends when the friction would exceed MU-S N either way, (:starts-sliding A B), into
the sliding mode the other forces drive; each sliding mode ends when the relative
tangential velocity reaches zero, (:stops-sliding A B), into static."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "block-sticking-on-rough-incline")))
      (let ((world (nth-value 1 (ames:check-scenario scenario bridge))))
        (ames.maxima:with-assumptions (bridge (ames:scenario-assumption-relations scenario))
          (let* ((run (ames.simulator::make-run world bridge))
                 (model (ames.simulator::run-model run))
                 (points (ames.engine:model-choice-points
                          model :decider (ames.simulator::state-decider run)))
                 (point (find :mode points :key #'ames.engine:choice-point-kind)))
            (is (not (null point)) "no mode choice at rest: ~S" points)
            (when point
              (is (equal '(:static :sliding-forward :sliding-backward)
                         (ames.engine:choice-point-options point)))
              (is (eq 'ames.kb::coulomb-friction (first (ames.engine:choice-point-instance point))))
              (flet ((transitions (mode)
                       (ames.simulator::apply-assignment
                        run points (list (cons (ames.engine:choice-point-instance point) mode)))
                       (loop for condition in (ames.engine:model-termination-conditions model)
                             when (and (eq :mode-transition (ames.engine:termination-condition-kind condition))
                                       (equal (ames.engine:choice-point-instance point)
                                              (ames.engine:termination-condition-instance condition)))
                               collect (list (sixth (ames.engine:termination-condition-change condition))
                                             (event-names (ames.engine:termination-condition-event condition)))))
                     (reported-mode ()
                       (loop for belief in (ames.engine:model-beliefs model)
                             when (and (eq (first belief) 'ames.kb:reported)
                                       (eq (first (third belief)) :friction))
                               return (getf (cddddr (third belief)) :mode))))
                (is (set-equal-p '((:sliding-backward (:starts-sliding "BLOCK" "INCLINE"))
                                   (:sliding-forward (:starts-sliding "BLOCK" "INCLINE")))
                                 (transitions :static)))
                (is (eq :static (reported-mode)))
                (is (equal '((:static (:stops-sliding "BLOCK" "INCLINE")))
                           (transitions :sliding-forward)))
                (is (eq :sliding (reported-mode)))
                (is (equal '((:static (:stops-sliding "BLOCK" "INCLINE")))
                           (transitions :sliding-backward)))
                (is (null (ames.engine:check-incremental model :signal nil))
                    "the chosen modes rebuild to the same model")))))))))

(test friction-mode-is-decided-when-sliding
  "A rough contact whose relative tangential velocity is not zero has one mode: no choice."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "block-sliding-on-rough-floor")))
      (let ((world (nth-value 1 (ames:check-scenario scenario bridge))))
        (ames.maxima:with-assumptions (bridge (ames:scenario-assumption-relations scenario))
          (let* ((run (ames.simulator::make-run world bridge))
                 (model (ames.simulator::run-model run))
                 (friction (find 'ames.kb::coulomb-friction (ames.engine:model-active-instances model)
                                 :key (lambda (i) (first (ames.engine:instance-key i))))))
            (is (null (remove :activation (ames.engine:model-choice-points
                                           model :decider (ames.simulator::state-decider run))
                              :key #'ames.engine:choice-point-kind)))
            (is (not (null friction)))
            (when friction
              (is (member (ames.engine:instance-mode friction)
                          '(:sliding-forward :sliding-backward))))))))))

;;; The engine: a stale mode is a choice point

(test a-stale-mode-is-a-choice-point
  "When a jump of the state variables (an impact's) leaves an instance's mode with false
entry conditions while another mode's hold, the mode is listed as a choice point whose
options are the possible modes (the lamps of t/engine-choices.lisp: the dimmer is
bright, but the knob now allows only dim)."
  (let* ((kb (make-lamp-kb))
         (decider (lambda (relation)
                    (cond ((eq (first relation) '=) :true)
                          ((eq (first relation) '>) :false)
                          (t :true))))
         (model (ames.engine:build-model (ames.engine:make-engine kb)
                                         (ames.engine:make-situation '((switch s1) (lamp l1 :switch s1)))
                                         :decider decider
                                         :decisions '((:mode (dimmer l1) bright))))
         (points (ames.engine:model-choice-points model)))
    (is (eq 'bright (ames.engine:instance-mode (ames.engine:find-instance model '(dimmer l1)))))
    (is (= 1 (length points)))
    (let ((point (first points)))
      (when point
        (is (eq :mode (ames.engine:choice-point-kind point)))
        (is (equal '(dim) (ames.engine:choice-point-options point)))
        (is (eq 'bright (ames.engine:choice-point-current point)))
        (ames.engine:apply-transition model (list (ames.engine:choice-change model point 'dim)))
        (is (null (ames.engine:model-choice-points model)) "dim is not stale")))))

;;; The report

(test friction-is-reported-without-special-cases
  "The friction entry reaches the s-expression as the knowledge base reports it, and the
text report prints it through its generic phrase."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "block-sliding-on-rough-floor"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (sexp (ames:history-sexp history))
           (text (with-output-to-string (out) (ames:print-history-text history out))))
      (let ((forces (getf (first (getf sexp :states)) :forces)))
        (is (find :friction forces :key #'first) "no friction in ~S" forces))
      (is (search "friction of floor on block (mode sliding)" text) "~A" text)
      (is (search "friction of floor on block (mode static): F = 0" text) "~A" text))))
