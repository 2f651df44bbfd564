;;;; t/approximate-starts.lisp -- the work a run under values skips (issue 23, the tipping
;;;; block): candidates along a rotation path proven beyond another are never worked out
;;;; (src/simulator/pending-candidates.lisp), and at a state's start that numbers put there
;;;; the values decide a sign the algebra does not prove cheaply
;;;; (src/simulator/approximate-starts.lisp), recorded as assumed from them.

(in-package #:ames.tests)

(def-suite approximate-starts :in all-tests
  :description "Pending candidates along an angle, and signs at a start found with numbers.")

(in-suite approximate-starts)

(defun turning-group (direction)
  "A :ROTATION-PATH group from the angle 0 in DIRECTION."
  (let ((group (ames.simulator::make-group '(block))))
    (setf (ames.simulator::group-kind group) :rotation-path
          (ames.simulator::group-variable group) 'ames.simulator::arc-length
          (ames.simulator::group-s0 group) 0
          (ames.simulator::group-direction group) direction)
    group))

(defun two-parameter-run (bridge values)
  "A RUN over a scenario with the positive parameters a and b, given VALUES."
  (make-instance 'ames.simulator::run
                 :bridge bridge :values values
                 :scenario (ames:parse-scenario
                            '(scenario s "x" (parameters (a :positive) (b :positive)) (gravity 1)
                              (body c :mass 1 :shape (circle 1) :position (0 0) :velocity (0 0))))))

(test candidates-beyond-another-on-the-path-are-not-worked-out
  "Of two pending candidates on one path, the one at the angle proven farther in the
direction of motion is dropped without working it out, the nearer one worked out; two
whose order is not proven are both worked out."
  (with-fixture simulator-bridge ()
    (let ((run (two-parameter-run bridge '()))
          (worked '()))
      (flet ((pending (group s)
               (ames.simulator::make-pending-candidate
                nil s group (lambda ()
                              (push s worked)
                              (ames.simulator::make-candidate nil :event s :at-arc s :group group)))))
        (dolist (direction '(1 -1))
          (setf worked '())
          (let* ((group (turning-group direction))
                 (settled (ames.simulator::settle-pending-candidates
                           run (list (pending group (* direction 2)) (pending group (* direction 1/2))))))
            (is (equal (list (* direction 1/2)) worked) "worked out: ~S" worked)
            (is (equal (list (* direction 1/2)) (mapcar #'ames.simulator::candidate-time settled)))))
        (setf worked '())
        (ames.maxima:with-assumptions (bridge '((> a 0) (> b 0)))
          (let* ((group (turning-group 1))
                 (settled (ames.simulator::settle-pending-candidates
                           run (list (pending group 'a) (pending group 'b)))))
            (is (= 2 (length settled)))
            (is (null (set-exclusive-or '(a b) worked)))
            (is (notany #'ames.simulator::pending-candidate-p settled))))))))

(test values-decide-signs-at-a-start-found-with-numbers
  "Under values deciding first, a - b (a = 2, b = 1) is positive at a state's start that
an end found with numbers gave (the fact recorded as assumed from the values), b - a
negative, a - 2 b zero (within the tolerance); at a start in closed form the sign of
a - b stays undecided (a fork's fact), and so it does without values."
  (with-fixture simulator-bridge ()
    (let ((run (two-parameter-run bridge '((a . 2) (b . 1)))))
      (ames.maxima:with-assumptions (bridge '((> a 0) (> b 0)))
        (ames.algebra:with-parameter-values ('((a . 2) (b . 1)))
          (ames.algebra:call-with-values-first
           (lambda ()
             (is (equal ames.algebra:+all-signs+ (ames.simulator::sign-of run '(- a b))))
             (setf (ames.simulator::run-time run) '(:no-closed-form :after-state 0))
             (is (equal '(:positive) (ames.simulator::sign-of run '(- a b))))
             (is (equal '(:negative) (ames.simulator::sign-of run '(- b a))))
             (is (member '(> (- a b) 0) (ames.algebra:facts-from-values) :test #'equal)
                 "recorded: ~S" (ames.algebra:facts-from-values))
             ;; (a - 2 b) vanishes at the values (as a friction limit at the event that
             ;; ended the previous state): zero there, recorded as assumed from them;
             ;; (a - 2 b + a/10^6) is small but clearly not zero: positive
             (is (equal '(:zero) (ames.simulator::sign-of run '(- a (* 2 b)))))
             (is (member '(= (- a (* 2 b)) 0) (mapcar (lambda (entry) (getf entry :fact)) (ames.simulator::run-assumed run))
                         :test #'equal))
             (is (equal '(:positive) (ames.simulator::sign-of run '(+ (- a (* 2 b)) (/ a 1000000))))))))
        (let ((without (two-parameter-run bridge '())))
          (setf (ames.simulator::run-time without) '(:no-closed-form :after-state 0))
          (is (equal ames.algebra:+all-signs+ (ames.simulator::sign-of without '(- a b)))))))))
