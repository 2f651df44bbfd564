;;;; t/friction.lisp -- Coulomb friction (issue 11): the friction clause, the component's modes and
;;;; events, and the textbook scenarios of scenarios/ with their results checked by Maxima.
;;;;
;;;; Each scenario's expected results are those its file's header states, written here over
;;;; the scenario's own parameters and compared by Maxima-checked equivalence under its
;;;; assumptions. Where a scenario leaves the deciding fact open (tan a against mu, the
;;;; pull against its threshold), a test adds the assumption to the parameter's spec, or
;;;; gives parameter values, or checks that the run names the fact as an ambiguity.

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
      (ames:check-scenario scenario bridge)
      (ames.maxima:with-assumptions (bridge (ames:scenario-assumption-relations scenario))
        (let* ((run (ames.simulator::make-run scenario bridge))
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
                  "the chosen modes rebuild to the same model"))))))))

(test friction-mode-is-decided-when-sliding
  "A rough contact whose relative tangential velocity is not zero has one mode: no choice."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "block-sliding-on-rough-floor")))
      (ames:check-scenario scenario bridge)
      (ames.maxima:with-assumptions (bridge (ames:scenario-assumption-relations scenario))
        (let* ((run (ames.simulator::make-run scenario bridge))
               (model (ames.simulator::run-model run))
               (friction (find 'ames.kb::coulomb-friction (ames.engine:model-active-instances model)
                               :key (lambda (i) (first (ames.engine:instance-key i))))))
          (is (null (remove :activation (ames.engine:model-choice-points
                                         model :decider (ames.simulator::state-decider run))
                            :key #'ames.engine:choice-point-kind)))
          (is (not (null friction)))
          (when friction
            (is (member (ames.engine:instance-mode friction)
                        '(:sliding-forward :sliding-backward)))))))))

;;; A block on a fixed incline

(test rough-incline-block-sticks
  "With tan a < mu the block sticks: static friction m g sin a up the slope (the
contact's tangent points uphill), N = m g cos a, no motion, forever. Sliding down with
kinetic friction muk <= mu is not decided (muk against tan a is open) but a pair that
can stick does not start sliding."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "block-sticking-on-rough-incline")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (eq :complete (ames::history-outcome history)))
          (is (= 1 (length states)))
          (let ((state (first states)))
            (when state
              (is (eq :forever (ames::state-duration state)))
              (is (eq :none (ames::state-end-event state)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same-vector bridge "no motion" (per-body (ames::state-accelerations state) "BLOCK")
                                 '(0 0))
                 (is-same bridge "N" (normal-force-between state "BLOCK" "INCLINE")
                          (x '(* m g (cos a))))
                 (check-friction bridge state "BLOCK" "INCLINE" :static
                                 (x '(* m g (sin a)))))))))))))

(test rough-incline-block-slides-to-the-foot
  "With tan a > mu the block slides down with acceleration g (sin a - mu cos a) under
kinetic friction mu m g cos a, leaves the slope's foot at
t1 = sqrt((h / sin a + b) / (g (sin a - mu cos a))), then falls freely."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "block-sliding-down-rough-incline")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (eq :complete (ames::history-outcome history)))
          (is (= 2 (length states)))
          (destructuring-bind (&optional slide fall) states
            (when (and slide fall)
              (is (equal '(:leaves "BLOCK" "INCLINE" :endpoint)
                         (event-names (ames::state-end-event slide))))
              (is (null (friction-entry fall "BLOCK" "INCLINE")))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (let ((along (x '(* g (- (sin a) (* mu (cos a)))))))
                   (is-same-vector bridge "acceleration down the slope"
                                   (per-body (ames::state-accelerations slide) "BLOCK")
                                   `((* ,along ,(x '(cos a))) (- (* ,along ,(x '(sin a))))))
                   (is-same bridge "N" (normal-force-between slide "BLOCK" "INCLINE")
                            (x '(* m g (cos a))))
                   (check-friction bridge slide "BLOCK" "INCLINE" :sliding
                                   (x '(* mu m g (cos a))))
                   (is-same bridge "time to the foot" (ames::state-duration slide)
                            `(sqrt (/ ,(x '(+ (/ h (sin a)) b)) ,along)))
                   (is-same-vector bridge "free fall" (per-body (ames::state-accelerations fall) "BLOCK")
                                   (x '(0 (- g))))))))))))))

;;; A block launched up a rough incline

(defun check-launch (bridge scenario state)
  "Check the first state of the block launched up the incline: sliding up under kinetic
friction, stopping at t1 = v0 / (g (sin a + mu cos a)) after d = v0^2 / (2 g (sin a + mu
cos a))."
  (flet ((x (form) (in-scenario-terms scenario form)))
    (is (equal '(:stops-sliding "BLOCK" "INCLINE") (event-names (ames::state-end-event state))))
    (call-with-scenario-facts
     bridge scenario
     (lambda ()
       (let ((along (x '(* g (+ (sin a) (* mu (cos a))))))
             (d (x '(/ (expt v0 2) (* 2 g (+ (sin a) (* mu (cos a))))))))
         (is-same-vector bridge "deceleration" (per-body (ames::state-accelerations state) "BLOCK")
                         `((* ,along ,(x '(cos a))) (- (* ,along ,(x '(sin a))))))
         (check-friction bridge state "BLOCK" "INCLINE" :sliding (x '(- (* mu m g (cos a)))))
         (is-same bridge "time to stop" (ames::state-duration state) `(/ ,(x 'v0) ,along))
         (is-same-vector bridge "where it stops" (per-body (ames::state-final-positions state) "BLOCK")
                         `((- (* ,d ,(x '(cos a)))) (* ,d ,(x '(sin a)))))
         (is-same-vector bridge "at rest" (per-body (ames::state-final-velocities state) "BLOCK")
                         '(0 0)))))))

(test launched-block-stops-then-sticks-or-slides-back
  "Launched up the incline, the block stops; with tan a < mu it then sticks forever
(static friction m g sin a uphill), with tan a > mu it slides back down with
acceleration g (sin a - mu cos a) forever."
  (with-fixture simulator-bridge ()
    (dolist (relation '(> <))
      (let ((scenario (scenario-assuming "block-launched-up-rough-incline" "MU"
                                         (list relation 'mu '(tan a)))))
        (multiple-value-bind (history states) (run-of scenario bridge)
          (flet ((x (form) (in-scenario-terms scenario form)))
            (is (eq :complete (ames::history-outcome history)) "mu ~A tan a: ~S" relation
                (ames::history-outcome history))
            (is (= 2 (length states)))
            (destructuring-bind (&optional launch after) states
              (when (and launch after)
                (check-launch bridge scenario launch)
                (is (eq :forever (ames::state-duration after)))
                (call-with-scenario-facts
                 bridge scenario
                 (lambda ()
                   (if (eq relation '>)
                       (progn
                         (check-friction bridge after "BLOCK" "INCLINE" :static (x '(* m g (sin a))))
                         (is-same-vector bridge "sticks" (per-body (ames::state-accelerations after) "BLOCK")
                                         '(0 0)))
                       (let ((along (x '(* g (- (sin a) (* mu (cos a)))))))
                         (check-friction bridge after "BLOCK" "INCLINE" :sliding
                                         (x '(* mu m g (cos a))))
                         (is-same-vector bridge "slides back"
                                         (per-body (ames::state-accelerations after) "BLOCK")
                                         `((* ,along ,(x '(cos a)))
                                           (- (* ,along ,(x '(sin a))))))))))))))))))

(test launched-block-names-the-open-fact-or-uses-values
  "Without an assumption on mu against tan a the run stops after the block stops,
naming the fact; parameter values decide it: mu = 1/5 < tan 1/2 slides back, mu = 1
sticks."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "block-launched-up-rough-incline")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :ambiguous (ames::history-outcome history)))
        (is (= 1 (length states)))
        (let ((fact (ames:ambiguous-transition-missing-fact
                     (getf (ames::history-notes history) :stopped-by))))
          (is (and (mentions-name-p "MU" fact) (mentions-name-p "A" fact))
              "the missing fact ~S is not about mu and a" fact)))
      (dolist (case '((1/5 :sliding) (1 :static)))
        (destructuring-bind (mu mode) case
          (multiple-value-bind (history states)
              (run-of scenario bridge
                      :parameter-values `(("M" . 1) ("G" . 981/100) ("A" . 1/2) ("B" . 1)
                                          ("V0" . 2) ("MU" . ,mu)))
            (is (eq :complete (ames::history-outcome history)) "mu = ~A: ~S" mu
                (ames::history-outcome history))
            (is (= 2 (length states)))
            (when (second states)
              (is (eq mode (getf (cddddr (friction-entry (second states) "BLOCK" "INCLINE")) :mode))
                  "mu = ~A" mu))))))))

;;; A block sliding on a rough floor

(test rough-floor-block-slides-to-a-stop
  "Launched at v0 along a rough floor the block decelerates at mu g, stops after
v0^2 / (2 mu g) at t1 = v0 / (mu g), and stays: static friction 0, forever."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "block-sliding-on-rough-floor")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (eq :complete (ames::history-outcome history)))
          (is (= 2 (length states)))
          (check-rederived history)
          (destructuring-bind (&optional slide rest) states
            (when (and slide rest)
              (is (equal '(:stops-sliding "BLOCK" "FLOOR") (event-names (ames::state-end-event slide))))
              (is (eq :forever (ames::state-duration rest)))
              (is (eq :none (ames::state-end-event rest)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same-vector bridge "deceleration" (per-body (ames::state-accelerations slide) "BLOCK")
                                 (x '((- (* mu g)) 0)))
                 ;; the floor's contact tangent points toward -x: friction along it is +mu m g
                 (check-friction bridge slide "BLOCK" "FLOOR" :sliding (x '(* mu m g)))
                 (is-same bridge "N" (normal-force-between slide "BLOCK" "FLOOR") (x '(* m g)))
                 (is-same bridge "time to stop" (ames::state-duration slide) (x '(/ v0 (* mu g))))
                 (is-same-vector bridge "where it stops" (per-body (ames::state-final-positions slide) "BLOCK")
                                 (x '((/ (expt v0 2) (* 2 mu g)) 0)))
                 (check-friction bridge rest "BLOCK" "FLOOR" :static 0)
                 (is-same-vector bridge "stays" (per-body (ames::state-accelerations rest) "BLOCK")
                                 '(0 0)))))))))))

;;; A block on a pulled cart

(defparameter *cart-threshold* '(* mu g (+ m mc))
  "The pull above which the block slides on the cart.")

(test cart-block-sticks-below-the-threshold
  "Below f* = mu g (m + mc) the block rides with the cart: both accelerate at
f / (m + mc), the static friction on the cart is -m f / (m + mc) along the top's tangent
(+x), forever."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-assuming "block-on-cart-pulled" "F" (list '< 'f *cart-threshold*))))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (eq :complete (ames::history-outcome history)))
          (is (= 1 (length states)))
          (let ((state (first states)))
            (when state
              (is (eq :forever (ames::state-duration state)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (dolist (body '("BLOCK" "CART"))
                   (is-same-vector bridge body (per-body (ames::state-accelerations state) body)
                                   (x '((/ f (+ m mc)) 0))))
                 (check-friction bridge state "CART" "BLOCK" :static (x '(- (/ (* m f) (+ m mc)))))
                 (is-same bridge "N block-cart" (normal-force-between state "CART" "BLOCK")
                          (x '(* m g))))))))))))

(test cart-block-slides-above-the-threshold
  "Above f* = mu g (m + mc) the block slides back on the cart: block (mu g, 0), cart
((f - mu m g) / mc, 0), kinetic friction -mu m g on the cart; the block leaves the
cart's top at t1 = sqrt((l + b) mc / (f - mu g (m + mc)))."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-assuming "block-on-cart-pulled" "F" (list '> 'f *cart-threshold*))))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (declare (ignore history))
        (flet ((x (form) (in-scenario-terms scenario form)))
          (let ((state (first states)))
            (is (not (null state)))
            (when state
              (is (equal '(:leaves "CART" "BLOCK" :endpoint) (event-names (ames::state-end-event state))))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same-vector bridge "block" (per-body (ames::state-accelerations state) "BLOCK")
                                 (x '((* mu g) 0)))
                 (is-same-vector bridge "cart" (per-body (ames::state-accelerations state) "CART")
                                 (x '((/ (- f (* mu m g)) mc) 0)))
                 (check-friction bridge state "CART" "BLOCK" :sliding (x '(- (* mu m g))))
                 (is-same bridge "time to the end of the top" (ames::state-duration state)
                          (x `(sqrt (/ (* (+ l b) mc) (- f ,*cart-threshold*))))))))))))))

(test cart-threshold-is-the-open-fact
  "Without an assumption on f the run names the missing fact, which changes sign at
f = mu g (m + mc); the default values (f = 20 > 3.924) decide it: the block slides."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "block-on-cart-pulled")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :ambiguous (ames::history-outcome history)))
        (is (null states))
        (let ((fact (ames:ambiguous-transition-missing-fact
                     (getf (ames::history-notes history) :stopped-by))))
          (is (and (consp fact) (member (first fact) '(< > <= >=))) "fact ~S" fact)
          (when (and (consp fact) (member (first fact) '(< > <= >=)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (is-same bridge "the fact's function at f = mu g (m + mc)"
                        (substitute-expressions
                         (list (cons (in-scenario-terms scenario 'f)
                                     (in-scenario-terms scenario *cart-threshold*)))
                         `(- ,(relation-lhs fact) ,(relation-rhs fact)))
                        0))))))
      (multiple-value-bind (history states)
          (run-of scenario bridge :parameter-values (ames:scenario-parameter-values scenario))
        (is (member (ames::history-outcome history) '(:collision :state-limit :complete)))
        (when (first states)
          (is (eq :sliding (getf (cddddr (friction-entry (first states) "CART" "BLOCK")) :mode))))))))

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
      (is (search "friction of floor on block (mode static): 0" text) "~A" text))))
