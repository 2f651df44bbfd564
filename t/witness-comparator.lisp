;;;; t/witness-comparator.lisp -- the comparator against a first-order witness, from answers
;;;; kept on file (no Siconos, no Maxima): a swing's velocity set beside AMES's at AMES's own
;;;; position at the sample's time (src/witness/compare-swing.lisp).

(in-package #:ames.tests)

(in-suite witness-crosscheck)

(defun commented-answers (path)
  "AMES's and the witness's answers kept as comments in the disagreement file PATH
(written by WRITE-DISAGREEMENT): (:AMES ANSWER :WITNESS ANSWER), and :FINER-WITNESS, the
witness at a quarter of its step, where the file keeps it."
  (with-open-file (in path)
    (let ((parts '()) (current nil))
      (loop for line = (read-line in nil) while line
            do (cond ((search ";; witness's answer at a quarter of its step:" line)
                      (setf current (list :finer-witness)) (push current parts))
                     ((search ";; AMES's answer:" line) (setf current (list :ames)) (push current parts))
                     ((search ";; witness's answer:" line) (setf current (list :witness)) (push current parts))
                     ((and current (eql 0 (search ";;   " line)))
                      (setf (cdr current) (append (cdr current) (list (subseq line 5)))))))
      (let ((*package* (find-package '#:ames-scenario)) (*read-eval* nil))
        (loop for (key . lines) in (reverse parts)
              append (list key (read-from-string (format nil "~{~A~%~}" lines))))))))

(defun hinged-swing-982 ()
  "The answers of the hinged disc of seed 777 #982 (a uniform disc, r = 1/4, hinged at
its rim, released 39 degrees from the vertical under g = 15; the witness Moreau-Jean
with a step of 1e-3 s)."
  (commented-answers (asdf:system-relative-pathname
                      "ames" "witness/disagreements/witness-wrong-hinged-swing-777-982.lisp")))

(defun compare-kept (answers)
  "The comparison of the kept ANSWERS, the witness's horizon its end."
  (let ((witness (getf answers :witness)))
    (ames.witness:compare-results (getf answers :ames) witness '()
                                  :t-end (getf (getf witness :end) :time))))

(defun swing-982-rk4 (time &optional (steps 20000))
  "The disc's centre velocity (VX VY) at TIME by RK4 on its own equation: the centre's
angle s from the pin, s'' = -40 cos s (I = 3/32 about the pin, m g r = 15/4), from rest at
s = -17 pi/60; the centre at (cos s, sin s)/4."
  (let ((s (- (/ (* 17 pi) 60))) (w 0d0) (h (/ time steps)))
    (flet ((acc (s) (* -40 (cos s))))
      (dotimes (k steps)
        (let* ((k1s w) (k1w (acc s))
               (k2s (+ w (* h 1/2 k1w))) (k2w (acc (+ s (* h 1/2 k1s))))
               (k3s (+ w (* h 1/2 k2w))) (k3w (acc (+ s (* h 1/2 k2s))))
               (k4s (+ w (* h k3w))) (k4w (acc (+ s (* h k3s)))))
          (incf s (* h 1/6 (+ k1s (* 2 k2s) (* 2 k3s) k4s)))
          (incf w (* h 1/6 (+ k1w (* 2 k2w) (* 2 k3w) k4w))))))
    (list (* -1/4 (sin s) w) (* 1/4 (cos s) w))))

(defun comparison-row (comparison what)
  (find what (ames.witness:comparison-rows comparison) :key #'second :test #'equal))

(test swing-velocity-compared-at-ames-own-position
  "The hinged disc 5 ms before a turning point: the first-order witness lags its motion,
and AMES's velocity at the witness's position differed by 0.021 (8 %); at AMES's own
position at the sample's time it is the exact one (RK4 on the disc's equation: vx =
0.253163 at t = 0.971864) and agrees."
  (let* ((comparison (compare-kept (hinged-swing-982)))
         (vx (comparison-row comparison "velocity x swing at 0.9719 s"))
         (vy (comparison-row comparison "velocity y swing at 0.9719 s"))
         (exact (swing-982-rk4 0.9718640166741922d0)))
    (is (eq :agree (ames.witness:comparison-verdict comparison)) "~A" (ames.witness:comparison-reason comparison))
    (is (near (first exact) (third vx) 1d-6) "vx ~A, RK4 ~A" (third vx) (first exact))
    (is (near (second exact) (third vy) 1d-6) "vy ~A, RK4 ~A" (third vy) (second exact))
    (is (= 2 (count-if (lambda (row) (eql 0 (search "turning point" (second row))))
                       (ames.witness:comparison-rows comparison))))))

(defun scale-velocities (answer factor)
  "ANSWER with each on-path velocity form of its states multiplied by FACTOR."
  (let ((answer (copy-tree answer)))
    (dolist (state (getf answer :states) answer)
      (dolist (entry (getf state :velocities))
        (let ((value (second entry)))
          (when (and (consp value) (eq (first value) :on-path))
            (setf (second value) (mapcar (lambda (x) `(* ,factor ,x)) (second value)))))))))

(test swing-velocity-errors-still-caught
  "The same comparison still finds real errors: AMES's velocity 10 % too fast everywhere,
and a witness whose velocity 5 ms before the turn differs from AMES's by 0.03 (the size
of the lag that was taken for an error), are AMES wrong, the second at that sample."
  (let ((answers (hinged-swing-982)))
    (let ((faster (list :ames (scale-velocities (getf answers :ames) 11/10)
                        :witness (getf answers :witness))))
      (is (eq :ames-wrong (ames.witness:comparison-verdict (compare-kept faster)))))
    (let* ((witness (copy-tree (getf answers :witness)))
           (sample (car (last (getf witness :samples))))
           (velocity (second (first (getf sample :velocities)))))
      (incf (first velocity) 0.03d0)
      (let ((comparison (compare-kept (list :ames (getf answers :ames) :witness witness))))
        (is (eq :ames-wrong (ames.witness:comparison-verdict comparison)))
        (is (search "velocity x swing at 0.9719" (ames.witness:comparison-reason comparison))
            "~A" (ames.witness:comparison-reason comparison))))))

(defun rod-ledge-23-14 ()
  "The answers of the rod of seed 23 rod-ledge #14 (landing on a ledge's edge, struck
again by it while spinning at 23 rad/s): AMES's, the witness's at its step 1e-3 and at
2.5e-4."
  (commented-answers (asdf:system-relative-pathname
                      "ames" "witness/disagreements/witness-wrong-rod-ledge-23-14.lisp")))

(defun compare-refining-kept (answers)
  "COMPARE-REFINING of the kept ANSWERS, the witness run at a finer step answered by the
kept finer witness when that is the step asked for (else a failure, as a witness that
gave no answer): (VALUES COMPARISON STEPS-ASKED)."
  (let* ((witness (getf answers :witness)) (finer (getf answers :finer-witness)) (asked '()))
    (values (ames.witness:compare-refining
             (getf answers :ames) '(("t_end" . 1d0)) witness '()
             :t-end (getf (getf witness :end) :time)
             :run (lambda (model &key timeout)
                    (declare (ignore timeout))
                    (let ((step (cdr (assoc "step" model :test #'equal))))
                      (push step asked)
                      (if (near step (getf finer :step) 1d-12) finer '(:status :error :message "no")))))
            (reverse asked))))

(test first-order-disagreement-refined-by-the-witness-step
  "The rod struck by a ledge's edge at 23 rad/s: at the witness's step 1e-3 its impact
comes 0.75 ms late and omega after it is 3.4 % off AMES's; at a quarter of the step the
witness agrees with AMES to 20 steps (0.5 %), and the verdict says at which step."
  (let ((answers (rod-ledge-23-14)))
    (is (eq :ames-wrong (ames.witness:comparison-verdict
                         (ames.witness:compare-results (getf answers :ames) (getf answers :witness) '()
                                                       :t-end (getf (getf (getf answers :witness) :end) :time)))))
    (multiple-value-bind (comparison asked) (compare-refining-kept answers)
      (is (eq :agree (ames.witness:comparison-verdict comparison)) "~A" (ames.witness:comparison-reason comparison))
      (is (equal '(2.5d-4) asked))
      (is (search "step 2.5e-4" (ames.witness:comparison-reason comparison))))))

(test first-order-refinement-still-catches-errors
  "The same rod with AMES's omega after the second impact off by 0.17 (the coarse
witness's error, the other way): the refined witness still disagrees, to its tighter
tolerance."
  (let* ((answers (rod-ledge-23-14))
         (ames (copy-tree (getf answers :ames)))
         (state (third (ames.witness:ames-path (getf ames :states))))
         (entry (first (getf state :final-angular-velocities))))
    (setf (second entry) `(- ,(second entry) 17/100))
    (multiple-value-bind (comparison asked) (compare-refining-kept (list* :ames ames answers))
      (is (eq :ames-wrong (ames.witness:comparison-verdict comparison)))
      (is (= 2 (length asked)))
      (is (search "final angular velocity" (ames.witness:comparison-reason comparison))))))

(defun block-step-2026-433 ()
  "The answers of the block of seed 2026 block-step #433 (plastic landing on its corner on a
ledge, the corner striking again 10.6 ms later at 0.5 mm/s), the witness's with the
collision speed the rotation driver now states (max(0.05, 20 g h) = 0.23 m/s)."
  (let ((answers (commented-answers (asdf:system-relative-pathname
                                     "ames" "witness/disagreements/witness-unseen-impact-block-step-2026-433.lisp"))))
    (setf (getf answers :witness) (list* :collision-speed 0.23d0 (getf answers :witness)))
    answers))

(test impact-slower-than-the-witness-sees-is-unsupported
  "AMES's second impact of the block's corner, at 2 E / J = 4.97e-4 m/s (its own impulse
and energy lost, restitution 0), is under the witness's collision speed: not witnessed
(unsupported, said so), where it was taken for AMES wrong; the same impact losing 2000
times the energy (1 m/s) is one the witness would see, and its absence is AMES wrong."
  (let* ((answers (block-step-2026-433))
         (witness (getf answers :witness))
         (end (getf (getf witness :end) :time)))
    (flet ((verdict (ames restitution)
             (let ((ames.witness::*largest-restitution* restitution))
               (ames.witness:compare-results ames witness '() :t-end end))))
      (is (eq :ames-wrong (ames.witness:comparison-verdict (verdict (getf answers :ames) nil))))
      (let ((comparison (verdict (getf answers :ames) 0)))
        (is (eq :unsupported (ames.witness:comparison-verdict comparison)))
        (is (search "4.97" (ames.witness:comparison-reason comparison)) "~A" (ames.witness:comparison-reason comparison)))
      (let* ((ames (copy-tree (getf answers :ames)))
             (event (getf (second (ames.witness:ames-path (getf ames :states))) :end-event))
             (data (member-if #'keywordp (rest event))))
        (setf (getf data :energy-lost) `(* 2000 ,(getf data :energy-lost)))
        (is (eq :ames-wrong (ames.witness:comparison-verdict (verdict ames 0))))))))

(defun terrain-2029-225 ()
  "The answers of the particle of seed 2029 terrain #225: it slides down piece1's slope to
its foot, where the floor begins (AMES: a leaving, then a state of zero duration ending
with the floor's collision; the witness: the collision alone)."
  (commented-answers (asdf:system-relative-pathname
                      "ames" "witness/disagreements/witness-handover-terrain-2029-225.lisp")))

(test a-face-handing-over-to-another-at-once-agrees
  "AMES's leaving of the slope's foot and its zero-duration state ending with the floor's
collision agree with the witness's one collision at that instant (#225, and #504 at its
fourth state); the leaving is not
accepted when AMES's next state does not end with the witness's event then (a collision
with the other piece instead), nor when that state is missing."
  (is (eq :agree (ames.witness:comparison-verdict
                  (compare-kept (commented-answers
                                 (asdf:system-relative-pathname
                                  "ames" "witness/disagreements/witness-handover-terrain-2029-504.lisp"))))))
  (let ((answers (terrain-2029-225)))
    (is (eq :agree (ames.witness:comparison-verdict (compare-kept answers))))
    (let* ((ames (copy-tree (getf answers :ames)))
           (zero (third (getf ames :states))))
      (setf (third (getf zero :end-event)) 'ames-scenario::piece0)
      (is (eq :ames-wrong (ames.witness:comparison-verdict
                           (compare-kept (list* :ames ames answers))))))
    (let ((ames (copy-tree (getf answers :ames))))
      (setf (getf ames :states) (remove (third (getf ames :states)) (getf ames :states)))
      (is (eq :ames-wrong (ames.witness:comparison-verdict
                           (compare-kept (list* :ames ames answers))))))))
