;;;; t/queries-answers.lisp -- queries that read the knowledge base's terms (issue 20, class 6),
;;;; answers at events that need no time (issue 26, thesis 4.2.2), and queries that fail
;;;; without ending the run. Every answer is checked by Maxima equivalence against the
;;;; textbook's formula, written here independently of AMES.

(in-package #:ames.tests)

(def-suite queries :in all-tests
  :description "Queries (thesis 3.2.4): answers read from the knowledge base's reported
terms, at events, per branch, and the questions of issue 26.")

(in-suite queries)

(defun scenario-from-text (text)
  "The validated scenario of the scenario form TEXT."
  (ames:parse-scenario (first (ames:read-scenario-forms text))))

(defun answers-named (history name)
  "The answers of HISTORY to the query NAME (one per branch)."
  (remove-if-not (lambda (entry) (string= (symbol-name (first entry)) name))
                 (ames:history-answers history)))

(defun answer-value (history name)
  "The value of the only answer of HISTORY to the query NAME."
  (let ((answers (answers-named history name)))
    (is (= 1 (length answers)) "~A: ~D answers ~S" name (length answers) answers)
    (second (first answers))))

(test bumper-energy-is-the-kb-total
  "A block pressing a bumper spring: the energy at the greatest compression (a time
inside the contact state, d/v0 + pi/2 sqrt(m/k)) is all elastic, m v0^2/2, with no kinetic
energy left; the kinetic energy alone (what queries used to return) would be 0 there. At
the contact's start and end the energy is m v0^2/2 too, and the block is at l0 - v0 sqrt(m/k)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (with-queries "block-hits-bumper"
                        "(query e-mid (value (energy) :at (+ (/ d v0) (* (/ pi 2) (sqrt (/ m k))))))"
                        "(query t-mid (value (kinetic-energy block) :at (+ (/ d v0) (* (/ pi 2) (sqrt (/ m k))))))"
                        "(query x-mid (value (x block) :at (+ (/ d v0) (* (/ pi 2) (sqrt (/ m k))))))"
                        "(query e-start (value (energy) :at (start 1)))"
                        "(query e-end (value (energy) :at (end 1)))"
                        "(query p-end (value (momentum block) :at (end 1)))")))
           (history (ames:simulate scenario :bridge bridge)))
      (flet ((x (e) (in-scenario-terms scenario e)))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (dolist (name '("E-MID" "E-START" "E-END"))
             (is-same bridge name (answer-value history name) (x '(* 1/2 m (expt v0 2)))))
           (is-same bridge "kinetic energy at the greatest compression" (answer-value history "T-MID") 0)
           (is-same bridge "greatest compression" (answer-value history "X-MID")
                    (x '(- l0 (* v0 (sqrt (/ m k))))))
           (is-same-vector bridge "momentum leaving the bumper" (answer-value history "P-END")
                           (x '((* m v0) 0)))))))))

(test asteroids-speed-when-they-touch
  "Two spheres released at rest a distance d apart: when they touch (r = a + b) momentum
zero and energy -G m1 m2 / d give the second's speed m1 sqrt(2 G (1/(a+b) - 1/d) / (m1 + m2)),
with no time needed; the energy there is still -G m1 m2 / d and the first's momentum
is the opposite of the second's."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (with-queries "spheres-under-gravitation"
                        "(query v (value (speed second) :at (:collision first second)))"
                        "(query e (value (energy) :at (end 0)))"
                        "(query p1 (value (momentum first) :at (end 0)))"
                        "(query p2 (value (momentum second) :at (end 0)))")))
           (history (ames:simulate scenario :bridge bridge)))
      (flet ((x (e) (in-scenario-terms scenario e)))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (let ((v2 (x '(* m1 (sqrt (/ (* 2 big-g (- (/ 1 (+ a b)) (/ 1 d))) (+ m1 m2)))))))
             (is-same bridge "speed at the touch" (answer-value history "V") v2)
             (is-same bridge "energy at the touch" (answer-value history "E") (x '(- (/ (* big-g m1 m2) d))))
             (is-same-vector bridge "momentum of the first" (answer-value history "P1")
                             (list (x `(* m2 ,v2)) 0))
             (is-same-vector bridge "momentum of the second" (answer-value history "P2")
                             (list (x `(- (* m2 ,v2))) 0)))))))))

(defparameter *rough-incline-text*
  "(scenario particle-on-rough-incline
     \"A particle at rest on a rough incline: it stays or slides.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
                 (h :positive (:value 1)) (a (> a 0) (< a (/ pi 2)) (:value 1/2))
                 (mu :positive (:value 1/2)))
     (gravity g)
     (body incline :fixed t :shape (polygon (0 0) ((/ h (tan a)) 0) (0 h)))
     (body particle :mass m :position ((/ h (* 2 (tan a))) (/ h 2)) :velocity (0 0) :shape point)
     (friction particle incline :static mu)
     (simulate :states 2)
     ~{~A~^ ~})"
  "A particle on a rough incline, forking at t = 0 on mu cos a - sin a; the queries are
spliced in at the end.")

(test a-failing-query-never-ends-the-run
  "A run that forks at its start: the energy of the fork (a state with no motion of its
own) is not answered, with a reason, on each branch; a parameter selection that a branch
cannot decide (one ends ambiguous) is not answered rather than 'always'; the run still
ends as it would without queries."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-from-text
                      (format nil *rough-incline-text*
                              '("(query e (value (energy) :at (start 0)))"
                                "(query stays (parameter mu :such-that (= (speed particle) 0)))"))))
           (history (ames:simulate scenario :bridge bridge)))
      (is (eq :branched (ames::history-outcome history)))
      (let ((energies (answers-named history "E")))
        (is (= 2 (length energies)))
        ;; the branch that ends ambiguous at once has no motion to answer from; where a
        ;; period of motion is counted as state 0, its energy is m g h / 2
        (is (some (lambda (entry) (eq :unanswered (second entry))) energies))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (dolist (entry energies)
             (is (consp (getf (cddr entry) :assume)) "~S" entry)
             (if (eq :unanswered (second entry))
                 (is (stringp (getf (cddr entry) :reason)))
                 (is-same bridge "energy at rest" (second entry)
                          (in-scenario-terms scenario '(* 1/2 m g h))))))))
      (let ((stays (first (answers-named history "STAYS"))))
        (is (eq :unanswered (second stays)) "~S" stays)))))

(defun energy-queries (states)
  "Query clauses asking the energy at the start and end of each of STATES (0 ...)."
  (loop for i below states
        append (list (format nil "(query start-~D (value (energy) :at (start ~D)))" i i)
                     (format nil "(query end-~D (value (energy) :at (end ~D)))" i i))))

(defun report-total-energy (state at)
  "The report's total T + V of STATE (the sum of its :ENERGY note's terms, as the report
adds them) at AT, :START or :END, or NIL where it has none there in closed form."
  (let* ((notes (ames.simulator::state-notes state))
         (terms (mapcar #'third (getf notes :energy)))
         (total (and terms (cons '+ terms)))
         (arc (find "ARC-LENGTH" (alexandria:flatten total) :key (lambda (x) (and (symbolp x) (symbol-name x)))
                                                            :test #'equal)))
    (cond ((null total) nil)
          (arc (let ((s (if (eq at :start)
                            (or (getf (getf notes :path-coordinates) :arc-length-from)
                                (let ((lines (getf notes :line-coordinates)))
                                  (and (= 1 (length lines)) (getf (first lines) :from))))
                            (getf notes :end-arc-length))))
                 (and s (subst s arc total))))
          ((eq at :start) (subst 0 'tau total))
          (t (let ((d (ames.simulator::state-duration state)))
               (and (not (keywordp d)) (not (and (consp d) (keywordp (first d))))
                    (subst d 'tau total)))))))

(test energy-query-is-the-report-total-on-every-scenario
  "On every scenario under scenarios/ (each path of a branching one), the query
(value (energy) :at (start N)) and (end N) equals the total energy T + V the report
prints for state N there, wherever the report has one in closed form (Maxima-checked)."
  (with-fixture simulator-bridge ()
    (let ((compared 0))
      (dolist (file (scenario-files))
        (dolist (form (ames:read-scenario-forms (uiop:read-file-string file)))
          (let* ((plain (ames:parse-scenario form))
                 (states (or (ames:scenario-states plain) 3))
                 (scenario (ames:parse-scenario
                            (append form (first (ames:read-scenario-forms
                                                 (format nil "(~{~A~^ ~})" (energy-queries states)))))))
                 (history (handler-case (ames:simulate scenario :bridge bridge)
                            (ames-error () nil))))
            (when history
              (loop for (facts nil . path-states) in (ames.simulator::history-paths history)
                    for k from 0
                    do (ames.maxima:with-assumptions
                           (bridge (append (ames:scenario-assumption-relations scenario) facts))
                         (dolist (state path-states)
                           (dolist (at '(:start :end))
                             (let* ((name (format nil "~:@(~A~)-~D" at (ames.simulator::state-index state)))
                                    (entry (nth k (answers-named history name)))
                                    (expected (report-total-energy state at)))
                               (when (and expected entry)
                                 (incf compared)
                                 (is (not (eq :unanswered (second entry)))
                                     "~A ~A: not answered (~A) where the report has ~S"
                                     (pathname-name file) name (getf (cddr entry) :reason) expected)
                                 (unless (eq :unanswered (second entry))
                                   (is-same bridge (format nil "~A ~A" (pathname-name file) name)
                                            (second entry) expected))))))))))))
      (is (> compared 40) "only ~D energies compared" compared))))
