;;;; t/witness-ropes.lisp -- the witness's ropes whose pieces turn or close at a pulley
;;;; (witness/siconos_ropes.py), its motion near a contact reached with no approach speed
;;;; and its gaps along a given motion (siconos_grazes.py, siconos_probe_gaps.py,
;;;; src/witness/compare-grazes.lisp), checked on closed forms. Skipped, with a message,
;;;; when /usr/bin/python3 cannot import Siconos (WITH-SICONOS, t/witness.lisp).

(in-package #:ames.tests)

(def-suite witness-ropes :in all-tests
  :description "The witness's exact ropes, grazes and gap probes (issue 21).")

(in-suite witness-ropes)

(defun agm (a b)
  "The arithmetic-geometric mean of A and B."
  (loop repeat 60 do (psetf a (/ (+ a b) 2) b (sqrt (* a b)))) a)

(defun pendulum-period (length g amplitude)
  "The exact period of a simple pendulum of LENGTH under G swinging to AMPLITUDE (rad):
4 sqrt(L/g) K(sin(A/2)), K(k) = pi / (2 AGM(1, sqrt(1 - k^2)))."
  (let ((k (sin (/ amplitude 2))))
    (* 4 (sqrt (/ length g)) (/ pi (* 2 (agm 1d0 (sqrt (- 1 (* k k)))))))))

(defun witness-pair-event (answer kind)
  "The first event of ANSWER with a pair of KIND."
  (find-if (lambda (e) (assoc kind (getf e :pairs))) (ames.witness:witness-events answer)))

(defun entry-of (name entries) (second (assoc name entries :test #'string=)))

(test witness-rope-pendulum
  "A bob on a taut rope (L = 1) from a fixed point, released at rest 60 degrees from the
vertical (g = 49/5): the rope's piece turns, so the witness takes the exact rope; it turns
back at the mirror point after half the exact period, 2 sqrt(L/g) K(1/2) (elliptic), with
speed sqrt(2 g L (1 - cos 60)) at the bottom: its speed at the end by energy."
  (with-siconos
    (let* ((g 9.8d0) (a (/ pi 3))
           (answer (witness-run (format nil "(scenario p \"\" (gravity 49/5)
                                   (body anchor :fixed t :position (0 0) :shape point)
                                   (body bob :mass 1 :position (~F ~F) :velocity (0 0) :shape point)
                                   (rope r :length 1 :through ((anchor (0 0)) (bob (0 0))))
                                   (simulate :states 2))" (sin a) (- (cos a)))
                                1.3d0))
           (turn (witness-pair-event answer :turns))
           (half (/ (pendulum-period 1 g a) 2)))
      (is (eq :ok (ames.witness:witness-status answer)))
      (is (null (getf answer :truncated)))
      (is (equal '(:turns "bob" "bob") (first (getf turn :pairs))))
      (is (near half (getf turn :time) 1d-7))
      (is (near (- (sin a)) (first (entry-of "bob" (getf turn :positions))) 1d-7))
      (is (near (- (cos a)) (second (entry-of "bob" (getf turn :positions))) 1d-7))
      (let* ((end (ames.witness:witness-end answer))
             (p (entry-of "bob" (getf end :positions))) (v (entry-of "bob" (getf end :velocities))))
        ;; on the circle, and the energy of the release: v^2 = 2 g (y - y0)... downward
        (is (near 1 (sqrt (+ (expt (first p) 2) (expt (second p) 2))) 1d-7))
        (is (near (* 2 g (- (second p) (- (cos a))) -1)
                  (+ (expt (first v) 2) (expt (second v) 2)) 1d-6))))))

(test witness-rope-piece-closes
  "The refused incline pulley (witness/disagreements/refused-incline-pulley-piece-closes.lisp):
m1 = 5/2 on a 3-4-5 incline (sin a = 4/5) pulls m2 = 7/4, 1 below the pulley, up into it
after t = sqrt(2 (m1 + m2) / ((m1 sin a - m2) g)), at speed a t, a = (m1 sin a - m2) g /
(m1 + m2); the pulley stops it plastically (restitution 0) and the rope the particle: both
at rest after (:strikes-pulley weight incline), and at rest to the end, the weight held
at the pulley along its vertical piece."
  (with-siconos
    (let* ((g 39/4) (acc (/ (* (- (* 5/2 4/5) 7/4) g) (+ 5/2 7/4)))
           (time (sqrt (/ 2d0 acc)))
           (answer (witness-run (uiop:read-file-string
                                 (asdf:system-relative-pathname
                                  "ames" "witness/disagreements/refused-incline-pulley-piece-closes.lisp"))
                                2.5d0))
           (event (witness-pair-event answer :strikes-pulley)))
      (is (equal '(:strikes-pulley "weight" "incline") (first (getf event :pairs))))
      (is (near time (getf event :time) 1d-9))
      (is (near (* acc time) (second (entry-of "weight" (getf event :velocities))) 1d-9))
      (is (near 45/16 (first (entry-of "weight" (getf event :positions))) 1d-12))
      (is (near 15/4 (second (entry-of "weight" (getf event :positions))) 1d-9))
      (dolist (body '("weight" "particle"))
        (is (< (reduce #'max (mapcar #'abs (entry-of body (getf event :after)))) 1d-9)))
      ;; then held there, the particle held by the rope: both at rest to the end
      (let ((end (ames.witness:witness-end answer)))
        (is (null (getf answer :truncated)))
        (is (near 2.5d0 (getf end :time) 1d-2))
        (is (near 15/4 (second (entry-of "weight" (getf end :positions))) 1d-9))
        (dolist (body '("weight" "particle"))
          (is (< (reduce #'max (mapcar #'abs (entry-of body (getf end :velocities)))) 1d-9)))))))

(defparameter *atwood-graze*
  "(scenario atwood-29 \"\" (gravity 43/4)
 (restitution 1) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body support :fixed t :position (0 13/2) :shape point)
 (body heavy :mass 11/4 :position (-1/2 3) :velocity (0 0) :shape point)
 (body light :mass 3/4 :position (1/2 0) :velocity (0 0) :shape point)
 (pulley left-wheel :on support :at (-1/2 0)) (pulley right-wheel :on support :at (1/2 0))
 (rope rope :length 11 :through ((heavy (0 0)) left-wheel right-wheel (light (0 0))))
 (simulate :states 3))"
  "Seed 2027 atwood #29: heavy lands elastically (e = 1) after sqrt(42/43), flies up with
the rope slack, lands again as the rope tightens at 15/7 sqrt(42/43), and the light mass
comes back to the floor at rest at 22/7 sqrt(42/43): a contact reached with no approach
speed.")

(test witness-graze-motion
  "The witness's motion near 22/7 sqrt(42/43) (the atwood graze): light's least gap to the
floor there is 0 and its rate 0 (to 1e-9), heavy back at 3 at rest: AMES's event is
checked against it."
  (with-siconos
    (let* ((end (* 22/7 (sqrt (/ 42d0 43))))
           (scenario (witness-scenario *atwood-graze*))
           (values (ames.scenario:run-parameter-values scenario :numeric t))
           (answer (ames.witness:run-witness
                    (ames.witness:scenario-model scenario values (+ end 0.02d0) :samples (list end))))
           (graze (first (getf answer :grazes)))
           (pair (find "light" (getf graze :pairs) :key #'first :test #'string=)))
      (is (near end (getf graze :time) 1d-12))
      (is (equal "floor" (second pair)))
      (is (< (abs (third pair)) 1d-9))
      (is (near end (fourth pair) 1d-4))
      (is (< (abs (fifth pair)) 1d-8))
      (is (near 3 (second (entry-of "heavy" (getf graze :positions))) 1d-9))
      (is (< (abs (second (entry-of "heavy" (getf graze :velocities)))) 1d-9))
      ;; no event of the witness there (a double root): what the comparator makes up for
      (is (notany (lambda (e) (near end (getf e :time) 1d-6)) (ames.witness:witness-events answer))))))

(test witness-graze-verdicts
  "The atwood graze through AMES and the witness: agreed, its least gap a row under
*GRAZE-GAP-TOLERANCE*; AMES's answer with the graze's time moved by 1e-4 s (its state's
duration) disagrees: the rule never turns a disagreement into an agreement."
  (with-siconos
    (let* ((scenario (witness-scenario *atwood-graze*))
           (result (ames::witness-check scenario :numeric t))
           (comparison (getf result :comparison))
           (row (find-if (lambda (r) (search "least gap light floor" (second r))) (ames.witness:comparison-rows comparison))))
      (is (eq :agree (getf result :verdict)))
      (is (< (abs (fourth row)) ames.witness::*graze-gap-tolerance*))
      (let* ((answer (copy-tree (getf result :answer)))
             (states (ames.witness:ames-path (getf answer :states)))
             (last-state (car (last states)))
             (values (ames.scenario:run-parameter-values scenario :numeric t)))
        ;; no parameters: AMES's closed forms are what the comparator evaluates
        (is (null (getf last-state :numeric)))
        (setf (getf last-state :duration) (list '+ (getf last-state :duration) 1/10000))
        ;; the witness asked for its motion at the moved time, as witness-check does
        (let* ((horizon (ames::witness-horizon answer values))
               (witness (ames.witness:run-witness
                         (ames.witness:scenario-model scenario values horizon
                                                      :samples (ames.witness:witness-sample-times answer values))))
               (moved (ames.witness:compare-results answer witness values :t-end horizon)))
          (is (eq :ames-wrong (ames.witness:comparison-verdict moved)))
          (is (search "final velocity" (ames.witness:comparison-reason moved))))))))

(test witness-gap-probe
  "The gap of a rod (half-length 1/2, turned 30 degrees) over a floor along a given motion,
its centre falling from 2 to 1 at 1 m/s: least at the end, 1 - sin(30)/2 = 3/4, at its
lower end; the speed of its points 1 (no turning)."
  (with-siconos
    (let* ((scenario (witness-scenario "(scenario r \"\" (gravity 10)
                                          (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                                          (body rod :mass 1 :inertia :uniform :shape (segment (-1/2 0) (1/2 0))
                                                :position (0 2) :angle (/ pi 6) :velocity (0 0))
                                          (simulate :states 1))"))
           (values (ames.scenario:run-parameter-values scenario :numeric t))
           (model (ames.witness:scenario-model scenario values 1d0))
           (motion (loop for k from 0 to 10
                         collect (list (/ k 10d0) (list (list 0d0 (- 2 (/ k 10d0)) (/ pi 6) 0d0 -1d0 0d0)))))
           (probe (ames.witness:run-witness
                   (append model (ames.witness::gap-probe-entry '(:collision "rod" "floor") motion)))))
      (is (eq :ok (ames.witness:witness-status probe)))
      (is (near 3/4 (getf probe :least-gap) 1d-12))
      (is (near 1 (getf probe :at) 1d-12))
      (is (near 1 (getf probe :speed) 1d-12)))))

(test witness-strike-below-resolution
  "Seed 2027 rod-ledge #773 from its kept answers: the first-order witness (step 6.25e-5 s)
strikes the ledge at 0.494 s where AMES's exact flight clears the ledge's edge by
1.137e-5 m (Maxima, 40 digits): AMES's least gap along its own closed forms, sampled, is
that to 1 %, positive and below the witness's resolution (20 steps at the speed of the
rod's points): unsupported, both figures said. With a step ten thousand times finer the
resolution is under the gap and the disagreement stays."
  (with-siconos
    (let* ((path (asdf:system-relative-pathname "ames" "witness/disagreements/witness-wrong-rod-ledge-2027-773.lisp"))
           (answers (commented-answers path))
           (scenario (first (ames.scenario:read-scenario-file path)))
           (values (ames.scenario:run-parameter-values scenario :numeric t))
           (witness (getf answers :witness))
           (t-end (getf (ames.witness:witness-end witness) :time))
           (model (ames.witness:scenario-model scenario values t-end))
           (comparison (ames.witness:compare-results (getf answers :ames) witness values :t-end t-end)))
      (is (eq :ames-wrong (ames.witness:comparison-verdict comparison)))
      (let* ((state (second (ames.witness:ames-path (getf (getf answers :ames) :states))))
             (probe (ames.witness:run-witness
                     (append model (ames.witness::gap-probe-entry
                                    '(:collision "rod" "ledge")
                                    (ames.witness::state-motion state model values)))))
             (graze (ames.witness::strike-below-resolution comparison (getf answers :ames) model witness
                                                           values #'ames.witness:run-witness)))
        (is (< 1.137d-5 (getf probe :least-gap) (* 1.01 1.137d-5)))
        (is (near 0.49597d0 (getf probe :at) 1d-3))
        (is (eq :unsupported (ames.witness:comparison-verdict graze)))
        (is (search "below the witness's resolution" (ames.witness:comparison-reason graze)))
        (let* ((finer (list* :step 6.25d-9 witness))
               (kept (ames.witness::strike-below-resolution comparison (getf answers :ames) model finer
                                                            values #'ames.witness:run-witness)))
          (is (eq :ames-wrong (ames.witness:comparison-verdict kept))))))))
