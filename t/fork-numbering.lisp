;;;; t/fork-numbering.lisp -- state numbers count periods of motion, and the values pick the path.
;;;;
;;;; A ball thrown horizontally from height h toward a tall wall at distance d (a scenario
;;;; written for these tests) either lands first (v0 sqrt(2 h/g) < d) or hits the wall
;;;; first: the run forks at t = 0. The zero-duration fork takes no number that queries
;;;; count, so (end 0) is the end of the flight, in every branch: the speed there is
;;;; sqrt(v0^2 + 2 g h) when it lands first, sqrt(v0^2 + (g d/v0)^2) when it hits the wall.
;;;; Under values only the selected branch is simulated; the others are listed with their
;;;; facts, and no number is printed beside a branch the values rule out.

(in-package #:ames.tests)

(in-suite simulator)

(defun ball-at-a-wall (&optional (simulate '(simulate :states 1)))
  "The scenario of this file, with SIMULATE as its (simulate ...) clause."
  (ames:parse-scenario
   `(scenario ball-at-a-wall
      "A ball thrown horizontally from height h toward a wall at distance d."
      (parameters (m :positive (:value 1)) (g :positive (:value 10)) (h :positive (:value 5))
                  (d :positive (:value 2)) (v0 :positive (:value 1)))
      (gravity g)
      (body floor :fixed t :shape (half-plane (1 0) (0 0)))
      (body wall :fixed t :shape (half-plane (d 1) (d 0)))
      (body ball :mass m :position (0 h) :velocity (v0 0) :shape point)
      (query speed-at-first-end (value (speed ball) :at (end 0)))
      ,simulate)))

(defun fact-holds-at-p (scenario relation values)
  "True when RELATION holds at the parameter VALUES (an alist by name)."
  (let ((difference (expression-value `(- ,(relation-lhs relation) ,(relation-rhs relation))
                                      (in-scenario-terms scenario values))))
    (ecase (first relation)
      ((> >=) (> difference 0)) ((< <=) (< difference 0)) (= (< (abs difference) 1d-12)))))

(defparameter *lands-first* '((m . 1) (g . 10) (h . 5) (d . 2) (v0 . 1))
  "Values under which the ball lands before it reaches the wall (x at landing 1 < 2).")

(defparameter *hits-wall-first* '((m . 1) (g . 10) (h . 5) (d . 2) (v0 . 3))
  "Values under which the ball hits the wall first (x at landing 3 > 2).")

(test a-fork-takes-no-state-number
  "Without values: the fork at t = 0 and each branch's first state share the index 0, and
(end 0) is the end of the flight in every branch: the speed there is Maxima-checked."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ball-at-a-wall))
           (history (ames:simulate scenario :bridge bridge))
           (fork (first (ames::history-states history))))
      (is (equal '(:branch) (ames::state-end-event fork)))
      (is (eql 0 (ames::state-index fork)))
      (dolist (branch (ames::state-branches fork))
        (let ((first-state (first (getf branch :states))))
          (when first-state
            (is (eql 0 (ames::state-index first-state))))))
      (let ((answers (remove "SPEED-AT-FIRST-END" (ames::history-answers history)
                             :key (lambda (a) (symbol-name (first a))) :test-not #'string=))
            (checked 0))
        (dolist (answer answers)
          (let ((facts (getf (cddr answer) :assume)) (value (second answer)))
            (call-with-scenario-facts
             bridge scenario
             (lambda ()
               (cond ((some (lambda (f) (eq (first f) '=)) facts)) ; the boundary
                     ((every (lambda (f) (fact-holds-at-p scenario f *lands-first*)) facts)
                      (incf checked)
                      (ames.maxima:with-assumptions (bridge facts)
                        (is-same bridge "speed on landing" value
                                 (in-scenario-terms scenario '(sqrt (+ (expt v0 2) (* 2 g h)))))))
                     ((every (lambda (f) (fact-holds-at-p scenario f *hits-wall-first*)) facts)
                      (incf checked)
                      (ames.maxima:with-assumptions (bridge facts)
                        (is-same bridge "speed at the wall" value
                                 (in-scenario-terms
                                  scenario '(sqrt (+ (expt v0 2) (/ (* g g d d) (expt v0 2)))))))))))))
        (is (= 2 checked) "answers ~S" answers)))))

(defun pushed-crate (&optional (simulate '(simulate :states 1)))
  "A crate on a rough floor pushed by f toward a wall at distance d: it slides when
f > mu m g, sticks when f < mu m g; which, the consistency of the friction modes says,
so the run forks at t = 0 even under values. SIMULATE is its (simulate ...) clause."
  (ames:parse-scenario
   `(scenario pushed-crate
      "A crate on a rough floor pushed toward a wall at distance d."
      (parameters (m :positive (:value 1)) (g :positive (:value 10)) (mu :positive (:value 1/2))
                  (f :positive (:value 8)) (d :positive (:value 4)))
      (gravity g)
      (body floor :fixed t :shape (half-plane (1 0) (0 0)))
      (body wall :fixed t :shape (half-plane ((+ d 1) 1) ((+ d 1) 0)))
      (body crate :mass m :position (0 0) :velocity (0 0)
                  :shape (polygon (0 0) (1 0) (1 1) (0 1)))
      (force push :on crate :value (f 0))
      (friction crate floor :static mu :kinetic mu)
      (query speed-at-first-end (value (speed crate) :at (end 0)))
      ,simulate)))

(defparameter *crate-slides* '((m . 1) (g . 10) (mu . 1/2) (f . 8) (d . 4))
  "The crate's default values: f = 8 > mu m g = 5, it slides.")

(test values-pick-the-path
  "Under values only the selected branch (the crate slides) is simulated; the others are
listed by their facts, not simulated, and their answers have no number. (end 0) is the
end of the slide: the speed at the wall is sqrt(2 (f - mu m g) d / m), Maxima-checked,
sqrt(24) under the values. With (simulate :all-branches t) every branch is simulated, and
still only the selected one has numbers."
  (with-fixture simulator-bridge ()
    (dolist (all '(nil t))
      (let* ((scenario (pushed-crate (if all
                                         '(simulate :states 1 :all-branches t)
                                         '(simulate :states 1))))
             (history (ames:run-scenario scenario :bridge bridge :numeric t))
             (fork (first (ames::history-states history)))
             (branches (ames::state-branches fork))
             (selected (remove-if-not (lambda (b) (getf b :selected)) branches)))
        (is (equal '(:branch) (ames::state-end-event fork)))
        (is (= 3 (length branches)))
        (is (= 1 (length selected)))
        (is (fact-holds-at-p scenario (getf (first selected) :assume) *crate-slides*))
        (dolist (branch branches)
          (cond ((getf branch :selected)
                 (is (eq :state-limit (getf branch :outcome)))
                 (is (eql 0 (ames::state-index (first (getf branch :states))))))
                (all (is (eq :complete (getf branch :outcome)))
                     (dolist (state (getf branch :states))
                       (is (null (ames.simulator:state-numbers state)))))
                (t (is (eq :not-simulated (getf branch :outcome)))
                   (is (null (getf branch :states))))))
        (dolist (answer (ames::history-answers history))
          (let ((facts (getf (cddr answer) :assume)))
            (if (every (lambda (f) (fact-holds-at-p scenario f *crate-slides*)) facts)
                (progn
                  (call-with-scenario-facts
                   bridge scenario
                   (lambda ()
                     (ames.maxima:with-assumptions (bridge facts)
                       (is-same bridge "speed at the wall" (second answer)
                                (in-scenario-terms scenario
                                                   '(sqrt (/ (* 2 (- f (* mu m g)) d) m)))))))
                  (is (< (abs (- (or (getf (cddr answer) :numeric) 0) (sqrt 24d0))) 1d-9)
                      "the selected path's answer ~S" answer))
                (is (null (getf (cddr answer) :numeric))
                    "a number beside a branch the values rule out: ~S" answer))))))))

(test all-branches-is-read-from-the-command-line-and-the-scenario
  "--all-branches and (simulate :all-branches t) are read; :all-branches takes T or NIL."
  (is (eq t (getf (ames::parse-command-line '("run" "a.lisp" "--all-branches")) :all-branches)))
  (is (null (getf (ames::parse-command-line '("run" "a.lisp")) :all-branches)))
  (is (member "--all-branches"
              (ames::child-arguments "a.lisp" (ames::parse-command-line
                                               '("run" "a.lisp" "--all-branches")))
              :test #'equal))
  (is (eq t (ames:scenario-all-branches (pushed-crate '(simulate :states 1 :all-branches t)))))
  (is (null (ames:scenario-all-branches (pushed-crate))))
  (signals ames:scenario-error (pushed-crate '(simulate :all-branches 3))))
