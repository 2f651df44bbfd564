;;;; t/closing-at-pulley.lisp -- a rope's piece closing up at its pulley (src/kb/closed-rope-pieces.lisp):
;;;; the body strikes the pulley (an impact: the pulley's stop, Newton's law on the piece's
;;;; rate, the rope jerked), then is held there (a hold force |F| <= T) or bounces off.
;;;;
;;;; The incline pulley: a particle m1 on a 3-4-5 incline (sin a = 4/5) pulls a weight m2
;;;; hanging d = 1 below a pulley on the slope's line. With m1 sin a > m2 both move from
;;;; rest with a = g (m1 sin a - m2) / (m1 + m2): the weight reaches the pulley after
;;;; t = sqrt(2 d (m1 + m2) / ((m1 sin a - m2) g)) at v = a t. A plastic stop (e = 0) leaves
;;;; both at rest: the particle's momentum along the rope is taken by the jerk, J = m1 v,
;;;; the weight's and the particle's by the stop, P = (m1 + m2) v; the energy lost is
;;;; (m1 + m2) v^2 / 2. Then they stay at rest for ever: the pulley holds the weight with
;;;; m2 g (up), the tension is m1 g sin a. With restitution e the weight bounces off at e v
;;;; (and the particle, jerked, goes back up the slope at e v): each flight lasts e times
;;;; the one before (2 e^n v / a), so the impacts accumulate at t0 (1 + e) / (1 - e), and
;;;; then the bodies rest held as before.

(in-package #:ames.tests)

(def-suite closing-at-pulley :in all-tests
  :description "A rope's piece closing up at its pulley: the stop as an impact, the body held there, bouncing off, pulled off (refused).")

(in-suite closing-at-pulley)

(defun incline-pulley-text (name &key (parameters "(parameters (g :positive) (m2 :positive) (k (> k 5/4)))")
                                      (m1 "(* k m2)") (m2 "m2") (g "g") (velocities '("(0 0)" "(0 0)"))
                                      (extra "") (states 3))
  "The incline pulley of the file header as a scenario's text: the particle's mass M1,
the weight's M2, gravity G (expressions), the particle's and the weight's initial
VELOCITIES, EXTRA clauses."
  (format nil "(scenario ~A \"A particle on an incline pulls a weight up into its pulley.\"
     ~A (gravity ~A) (body incline :fixed t :shape (polygon (0 0) (9/4 0) (9/4 3)))
     (body particle :mass ~A :position (27/16 9/4) :velocity ~A :shape point)
     (pulley top :on incline :at (45/16 15/4))
     (body weight :mass ~A :position (45/16 11/4) :velocity ~A :shape point)
     (rope line :length 23/8 :through ((particle (0 0)) top (weight (0 0)))) ~A (simulate :states ~D))"
          name parameters g m1 (first velocities) m2 (second velocities) extra states))

(defun forces-entry (state kind &rest names)
  "The value of STATE's reported force entry (KIND NAME... VALUE) naming NAMES."
  (let ((entry (find-if (lambda (entry)
                          (and (eq (first entry) kind)
                               (every #'same-name-p* (subseq (rest entry) 0 (length names)) names)))
                        (ames::state-forces-of state))))
    (and entry (car (last entry)))))

(defun impact-impulse (state kind)
  "The value of the impulse entry of KIND in the impact that ended STATE."
  (car (last (find kind (getf (ames.simulator:state-impact state) :impulses) :key #'first))))

(test weight-stops-at-its-pulley-and-is-held-there
  "m1 = k m2 with k > 5/4 (m1 sin a > m2): the stop time, the jerk and the stop's impulses
by momentum along the rope, the energy lost, then rest for ever with the hold m2 g and
the tension m1 g sin a (|F| <= T since k >= 5/4)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-of-text (incline-pulley-text "held")))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history)))
      (is (eq :complete (ames::history-outcome history)))
      (is (= 2 (length states)))
      (destructuring-bind (&optional closing held &rest more) states
        (declare (ignore more))
        (when held
          (flet ((x (expression) (in-scenario-terms scenario expression)))
            (let* ((m1 '(* k m2)) (sin-a 4/5)
                   (a `(/ (* g (- (* ,m1 ,sin-a) m2)) (+ ,m1 m2)))
                   (time `(sqrt (/ (* 2 (+ ,m1 m2)) (* (- (* ,m1 ,sin-a) m2) g))))
                   (v `(* ,a ,time)))
              (is (equal '(:strikes-pulley "INCLINE" "WEIGHT") (event-names (ames::state-end-event closing))))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same bridge "time to the pulley" (ames::state-duration closing) (x time))
                 (is-same-vector bridge "weight just before" (per-body (ames::state-final-velocities closing) "WEIGHT")
                                 (x `(0 ,v)))
                 (dolist (body '("WEIGHT" "PARTICLE"))
                   (is-same-vector bridge (format nil "~A just after" body)
                                   (per-body (getf (ames.simulator:state-impact closing) :velocities-after) body)
                                   '(0 0)))
                 (is-same bridge "the jerk" (impact-impulse closing :rope-impulse) (x `(* ,m1 ,v)))
                 (is-same bridge "the stop" (impact-impulse closing :pulley-stop) (x `(* (+ ,m1 m2) ,v)))
                 (is-same bridge "energy lost" (getf (cdddr (ames::state-end-event closing)) :energy-lost)
                          (x `(* 1/2 (+ ,m1 m2) (expt ,v 2))))
                 (is (eq :forever (ames::state-duration held)))
                 (dolist (body '("WEIGHT" "PARTICLE"))
                   (is-same-vector bridge (format nil "~A at rest" body)
                                   (per-body (ames::state-accelerations held) body) '(0 0)))
                 (is-same bridge "tension" (forces-entry held :tension "LINE") (x `(* ,m1 g ,sin-a)))
                 (is-same-vector bridge "the hold on the weight" (forces-entry held :pulley-hold "LINE" "WEIGHT")
                                 (x '(0 (* m2 g)))))))))))))

(test weight-bounces-off-its-pulley-to-rest
  "With restitution e = 1/2 (g = 39/4, m1 = 5/2, m2 = 7/4): the weight leaves the pulley
at e v down, the particle, jerked, at e v up the slope; the impacts repeat scaled by e and
accumulate at t0 (1 + e) / (1 - e) = 3 t0; then both rest, held."
  (with-fixture simulator-bridge ()
    (let* ((e 1/2) (g 39/4) (m1 5/2) (m2 7/4) (sin-a 4/5)
           (scenario (scenario-of-text
                      (incline-pulley-text "bouncing" :parameters "" :m1 "5/2" :m2 "7/4" :g "39/4"
                                                      :extra "(restitution weight incline 1/2)" :states 6)))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames::history-states history))
           (a (/ (* g (- (* m1 sin-a) m2)) (+ m1 m2)))
           (t0 `(sqrt ,(/ 2 a)))
           (v `(* ,a ,t0)))
      (is (eq :complete (ames::history-outcome history)))
      (is (= 3 (length states)))
      (when (= 3 (length states))
        (destructuring-bind (first bouncing held) states
          (let ((after (getf (ames.simulator:state-impact first) :velocities-after)))
            (is-same-vector bridge "weight after" (per-body after "WEIGHT") `(0 (- (* ,e ,v))))
            (is-same-vector bridge "particle after" (per-body after "PARTICLE")
                            `((* 3/5 ,e ,v) (* 4/5 ,e ,v))))
          (is-same bridge "the bounce's flight" (ames::state-duration bouncing) `(* 2 ,e ,v (/ 1 ,a)))
          (is-same bridge "the accumulation" (getf (ames.simulator:state-accumulation bouncing) :time)
                   `(* ,t0 (/ (+ 1 ,e) (- 1 ,e))))
          (is (eq :forever (ames::state-duration held)))
          (is-same-vector bridge "the hold" (forces-entry held :pulley-hold "LINE" "WEIGHT") `(0 ,(* m2 g))))))))

(defparameter *particle-into-pulley*
  "(scenario particle-into-pulley \"A heavier weight drags the particle up the incline into the pulley at its top.\"
     (gravity 10) (body incline :fixed t :shape (polygon (0 0) (4 0) (4 3)))
     (body support :fixed t :position (5 3) :shape point)
     (body particle :mass 1 :position (8/5 6/5) :velocity (0 0) :shape point)
     (pulley top :on incline :at (4 3))
     (pulley wheel :on support :at (0 0))
     (body weight :mass 2 :position (5 1) :velocity (0 0) :shape point)
     (rope line :length 6 :through ((particle (0 0)) top wheel (weight (0 0))))
     (simulate :states 3))"
  "The hanging side heavier (m2 = 2 > m1 sin a = 3/5): the particle, 3 below the pulley at
the incline's top along the slope, is pulled up into it.")

(test particle-dragged-into-the-pulley-at-the-top
  "a = g (m2 - m1 sin a) / (m1 + m2) = 14/3, the particle reaches the pulley after
sqrt(2 * 3 / a) = 3/sqrt(7) at v = 2 sqrt(7); the jerk takes the weight's momentum,
J = m2 v, the stop both, P = (m1 + m2) v; then the pulley holds the particle with m1 g
(up) and the tension is m2 g."
  (with-fixture simulator-bridge ()
    (let* ((history (simulate-stopping-when-ambiguous (scenario-of-text *particle-into-pulley*) bridge))
           (states (ames::history-states history))
           (v '(* 2 (sqrt 7))))
      (is (eq :complete (ames::history-outcome history)))
      (is (= 2 (length states)))
      (when (= 2 (length states))
        (destructuring-bind (closing held) states
          (is (equal '(:strikes-pulley "PARTICLE" "INCLINE") (event-names (ames::state-end-event closing))))
          (is-same bridge "time to the pulley" (ames::state-duration closing) '(/ 3 (sqrt 7)))
          (is-same bridge "the jerk" (impact-impulse closing :rope-impulse) `(* 2 ,v))
          (is-same bridge "the stop" (impact-impulse closing :pulley-stop) `(* 3 ,v))
          (is-same-vector bridge "the hold on the particle" (forces-entry held :pulley-hold "LINE" "PARTICLE") '(0 10))
          (is-same bridge "tension" (forces-entry held :tension "LINE") 20))))))

(test weight-pulled-off-its-pulley-is-refused-named
  "A weight launched up into its pulley (v0 = 3) by a particle too light to hold it
(m1 sin a = 4/5 < m2 = 7/4): after the plastic stop the hold m2 g would exceed the tension
m1 g sin a, and the piece would open from rest along no given direction: refused, naming
the piece, not answered."
  (with-fixture simulator-bridge ()
    (let ((condition (handler-case
                         (progn (ames::simulate (scenario-of-text
                                                 (incline-pulley-text "pulled-off" :parameters "" :m1 "1" :m2 "7/4"
                                                                                   :g "39/4" :velocities '("(-9/5 -12/5)" "(0 3)")))
                                                :bridge bridge)
                                nil)
                       (ames:ames-error (c) c))))
      (is (typep condition 'ames.kb:unmodelled-situation))
      (is (mentions-name-p "SEGMENT-1" (ames.base::ames-error-datum condition))))))

(test held-piece-at-a-later-impact-is-refused-named
  "The weight held at its pulley (as in WEIGHT-STOPS-AT-ITS-PULLEY-AND-IS-HELD-THERE, g =
39/4, m1 = 5/2, m2 = 7/4: held from t = 2 sqrt(34/39) ~ 1.87) when a ball dropped 20
above a floor lands (t = sqrt(40 / g) ~ 2.03): the rope at that impact has a piece with
no direction. Refused, naming the piece, not a division by zero nor an answer."
  (with-fixture simulator-bridge ()
    (let ((condition (handler-case
                         (progn (ames::simulate
                                 (scenario-of-text
                                  (incline-pulley-text
                                   "later-impact" :parameters "" :m1 "5/2" :m2 "7/4" :g "39/4" :states 4
                                   :extra "(body floor :fixed t :shape (polygon (8 -60) (12 -60) (12 -50) (8 -50)))
                                           (body ball :mass 1 :position (10 -30) :velocity (0 0) :shape point)"))
                                 :bridge bridge)
                                nil)
                       (ames:ames-error (c) c))))
      (is (typep condition 'ames.kb:unmodelled-situation))
      (is (mentions-name-p "SEGMENT-1" (ames.base::ames-error-datum condition))))))

(test a-held-body-on-a-rough-incline-is-not-sliding-at-rest
  "With friction (mu_s = 1/5, mu_k = 1/10, m1 = 5/2, m2 = 1, g = 10, sin a = 4/5) the
particle slides down under kinetic friction -mu_k N = -3/2 (N = m1 g cos a = 15) until
the weight strikes its pulley at t = sqrt(14/17). Held there at rest, static friction F
and the tension T share m1 g sin a = 20 in a way the model does not determine (T + F =
20 with |F| <= 3): the run may refuse that state, but no state reports sliding friction
on the particle at rest (it did, as kinetic -3/2 with T = 37/2)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-of-text
                      (incline-pulley-text "rough-held" :parameters "" :g "10" :m1 "5/2" :m2 "1"
                                           :extra "(friction particle incline :static 1/5 :kinetic 1/10)")))
           (history (handler-case (simulate-stopping-when-ambiguous scenario bridge)
                      (ames::ames-error () nil)))
           (states (if history (ames::history-states history) '())))
      (when history
        (let ((slide (first states)))
          (is (not (null slide)))
          (when slide
            (is-same bridge "the strike's time" (ames::state-duration slide) '(sqrt 14/17))
            (check-friction bridge slide "PARTICLE" "INCLINE" :sliding -3/2)))
        (dolist (state (rest states))
          (let ((entry (friction-entry state "PARTICLE" "INCLINE"))
                (velocity (per-body (ames::state-final-velocities state) "PARTICLE")))
            (is (not (and entry (eq :sliding (getf (cddddr entry) :mode))
                          (equal velocity '(0 0))))
                "sliding friction on the particle at rest: ~S" entry)))))))
