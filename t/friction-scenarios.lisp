;;;; t/friction-scenarios.lisp -- Coulomb friction on the textbook scenarios of scenarios/: a block
;;;; sticking on or sliding down a rough incline, launched up one, sliding to a stop on a rough
;;;; floor, riding on a pulled cart.
;;;;
;;;; Every expected result is the one the scenario file's header states, over the scenario's
;;;; own parameters, compared by Maxima-checked equivalence under its assumptions. Where a
;;;; scenario leaves the deciding fact open, a test adds the assumption to the parameter's
;;;; spec (SCENARIO-ASSUMING), gives parameter values, or checks that the run names the fact.
;;;; The helpers are in t/friction.lisp.

(in-package #:ames.tests)

(in-suite friction)

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

(test rough-incline-block-that-could-slide-sticks
  "With muk < tan a < mu both sticking and sliding down under kinetic friction are
consistent at rest; the component lists static first: the block sticks."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-assuming "block-sticking-on-rough-incline" "MUK" '(< muk (tan a)))))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (is (eq :complete (ames::history-outcome history)))
        (let ((state (first states)))
          (when state
            (is (eq :forever (ames::state-duration state)))
            (is (eq :static (getf (cddddr (friction-entry state "BLOCK" "INCLINE")) :mode)))
            (let ((consistent (loop for trial in (tried-assignments state)
                                    when (eq :consistent (getf trial :verdict))
                                      collect (getf trial :assignment))))
              (is (= 2 (length consistent)) "static and sliding down: ~S" consistent)
              (is (some (lambda (assignment) (rassoc :sliding-backward assignment)) consistent)
                  "sliding down is consistent: ~S" consistent))))))))

(test undecided-sticking-is-not-passed-over
  "With muk < tan a but mu against tan a open, sliding down is consistent and sticking
undecided: sticking would be preferred, so the run names the open fact rather than
let the block slide."
  (with-fixture simulator-bridge ()
    (let* ((form (subst '(mu :positive) '(mu :positive (> mu (tan a)))
                        (scenario-form-named "block-sticking-on-rough-incline")
                        :test (lambda (old new) (same-by-name-p new old))))
           (scenario (ames:parse-scenario
                      (subst '(muk :positive (<= muk mu) (< muk (tan a))) '(muk :positive (<= muk mu))
                             form :test (lambda (old new) (same-by-name-p new old))))))
      (is (= 3 (length (ames:scenario-parameter-assumptions
                        (ames:find-scenario-parameter 'muk scenario)))))
      (multiple-value-bind (history states) (run-of (unbranched scenario) bridge)
        (is (eq :ambiguous (ames::history-outcome history)))
        (is (null states))
        (let ((fact (ames:ambiguous-transition-missing-fact
                     (getf (ames::history-notes history) :stopped-by))))
          (is (mentions-name-p "MU" fact) "the missing fact ~S is not about mu" fact)
          (is (not (mentions-name-p "MUK" fact)) "the missing fact ~S is about muk" fact))))))

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
      (multiple-value-bind (history states) (run-of (unbranched scenario) bridge)
        (is (eq :ambiguous (ames::history-outcome history)))
        (is (= 1 (length states)))
        (let ((fact (ames:ambiguous-transition-missing-fact
                     (getf (ames::history-notes history) :stopped-by))))
          (is (and (mentions-name-p "MU" fact) (mentions-name-p "A" fact))
              "the missing fact ~S is not about mu and a" fact)))
      (dolist (case '((1/5 :sliding) (1 :static)))
        (destructuring-bind (mu mode) case
          (multiple-value-bind (history states)
              (run-of (unbranched scenario) bridge
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
      (multiple-value-bind (history states) (run-of (unbranched scenario) bridge)
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
          (run-of (unbranched scenario) bridge :parameter-values (ames:scenario-parameter-values scenario))
        (is (member (ames::history-outcome history) '(:collision :state-limit :complete)))
        (when (first states)
          (is (eq :sliding (getf (cddddr (friction-entry (first states) "CART" "BLOCK")) :mode))))))))


;;; A block bouncing off a wall on a rough floor (an impact reverses the sliding)

(test rough-floor-block-bounces-and-slides-back
  "The impact with the wall reverses the block's velocity along the floor: the floor's
friction changes its sliding direction at once (a stale mode is changed by the choice
search), and the block slides back to a stop at x = -5."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "block-bouncing-on-rough-floor")))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (flet ((x (form) (in-scenario-terms scenario form)))
          (is (eq :complete (ames::history-outcome history)))
          (is (= 3 (length states)))
          (destructuring-bind (&optional toward back rest) states
            (when (and toward back rest)
              (is (eq :collision (first (ames::state-end-event toward))))
              (is (equal '(:stops-sliding "BLOCK" "FLOOR") (event-names (ames::state-end-event back))))
              (is (eq :forever (ames::state-duration rest)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same bridge "time to the wall" (ames::state-duration toward) '(- 5 (* 2 (sqrt 6))))
                 (is-same-vector bridge "before the impact" (per-body (ames::state-final-velocities toward) "BLOCK")
                                 '((* 4 (sqrt 6)) 0))
                 (check-friction bridge toward "BLOCK" "FLOOR" :sliding (x '(* 2 m)))
                 (check-friction bridge back "BLOCK" "FLOOR" :sliding (x '(- (* 2 m))))
                 (is-same-vector bridge "sliding back" (per-body (ames::state-accelerations back) "BLOCK")
                                 '(2 0))
                 (is-same bridge "time to stop" (ames::state-duration back) '(sqrt 6))
                 (is-same-vector bridge "where it stops" (per-body (ames::state-final-positions back) "BLOCK")
                                 '(-5 0))
                 (check-friction bridge rest "BLOCK" "FLOOR" :static 0))))))))))
