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

(test bouncing-ball-rest-time-distance-and-more
  "The ball dropped from h bouncing with e = 1/2: it comes to rest for good at the Zeno
sum sqrt(2h/g) (1 + 2 e/(1 - e)) = 3 sqrt(2h/g); it travels h (1 + e^2)/(1 - e^2) = 5h/3
in all, h/2 in its first bounce; it lands with vertical velocity -sqrt(2 g h); state 1
ends at 2 sqrt(2h/g) (asked both as (time (end 1)) and (value (time) :at (end 1))); it
first falls to h/2 at sqrt(h/g) and never reaches 2h."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (with-queries "bouncing-ball"
                        "(query rest (time (:rest ball)))"
                        "(query dist (distance ball))"
                        "(query first-bounce (distance ball :during (start 1)))"
                        "(query vy (value (y (velocity ball)) :at (:collision ball floor)))"
                        "(query vx (value (x (velocity ball)) :at (end 0)))"
                        "(query end-1 (time (end 1)))"
                        "(query clock (value (time) :at (end 1)))"
                        "(query half (time (reaches (y ball) (/ h 2))))"
                        "(query twice (time (reaches (y ball) (* 2 h))))")))
           (history (ames:simulate scenario :bridge bridge)))
      (flet ((x (e) (in-scenario-terms scenario e)))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same bridge "rest" (answer-value history "REST")
                    (x '(* (sqrt (/ (* 2 h) g)) (+ 1 (/ (* 2 1/2) (- 1 1/2))))))
           (is-same bridge "distance" (answer-value history "DIST")
                    (x '(/ (* h (+ 1 (expt 1/2 2))) (- 1 (expt 1/2 2)))))
           (is-same bridge "first bounce" (answer-value history "FIRST-BOUNCE") (x '(* 2 (/ h 4))))
           (is-same bridge "landing velocity" (answer-value history "VY") (x '(- (sqrt (* 2 g h)))))
           (is-same bridge "horizontal velocity" (answer-value history "VX") 0)
           (is-same bridge "end of state 1" (answer-value history "END-1") (x '(* 2 (sqrt (/ (* 2 h) g)))))
           (is-same bridge "clock at the end of state 1" (answer-value history "CLOCK")
                    (x '(* 2 (sqrt (/ (* 2 h) g)))))
           (is-same bridge "half height" (answer-value history "HALF") (x '(sqrt (/ h g))))
           (is (eq :never (first (answer-value history "TWICE"))))))))))

(defun boundary-substitution (bridge scenario facts &optional (names '("W" "H")))
  "For each equation among FACTS (a boundary branch's), the binding of the first of the
parameters NAMES it holds (linearly) that solves it: the values that put the branch
on its boundary, so that answers are compared there."
  (loop for fact in facts
        when (eq (first fact) '=)
          append (let ((unknown (find-if (lambda (name) (mentions-name-p name fact)) names)))
                   (and unknown
                        (let* ((symbol (in-scenario-terms scenario (intern unknown :ames.tests)))
                               (solutions (ames.maxima:solve-equations bridge (list fact) (list symbol))))
                          (is (= 1 (length solutions)) "~S solved for ~A: ~S" fact unknown solutions)
                          (first solutions))))))

(test every-query-kind-answers-per-branch
  "The ball thrown toward a low wall branches on whether it clears the wall and whether
it lands before reaching it. On every path each answer carries its path's facts, and
(on a boundary path, compared on the boundary): it lands at sqrt(2h/g) (the wall's
impulse is horizontal), asked as an event's time and as (value (time) :at EVENT); it falls
to the wall's height at sqrt(2(h - w)/g); its horizontal velocity on landing is 0 after a
(plastic) hit on the wall, else v0; its energy before landing is m g h after the hit, else
m g h + m v0^2/2; it rests for good from the later of its landing and its reaching the
wall (d/v0), and never when it clears the wall (it slides on); its curved path's length
is not answered, saying why; its lowest point in the state that ends on the floor is 0; a
proof and a parameter selection are answered too."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (with-queries "ball-toward-low-wall"
                        "(query lands (time (:collision ball floor)))"
                        "(query clock (value (time) :at (:collision ball floor)))"
                        "(query wall-height (time (reaches (y ball) w)))"
                        "(query vx (value (x (velocity ball)) :at (:collision ball floor)))"
                        "(query energy (value (energy) :at (:collision ball floor)))"
                        "(query rest (time (:rest ball)))"
                        "(query path (distance ball))"
                        "(query falls (prove (<= (y ball) h)))"
                        "(query clears (parameter v0 :such-that (not (:collision ball wall))))"
                        "(query lowest (minimum (y ball) :during (:collision ball floor)))")))
           (history (ames:simulate scenario :bridge bridge))
           (paths (ames.simulator::history-paths history)))
      (is (> (length paths) 1))
      (flet ((x (e) (in-scenario-terms scenario e)))
        (loop for (facts nil . states) in paths
              for k from 0
              for hit = (position-if (lambda (s) (ames.simulator::event-state (list s) '(:collision ball wall))) states)
              for landed = (position-if (lambda (s) (ames.simulator::event-state (list s) '(:collision ball floor))) states)
              for hit-first = (and hit (or (null landed) (< hit landed)))
              do (ames.maxima:with-assumptions
                     (bridge (append (ames:scenario-assumption-relations scenario)
                                     (remove '= facts :key #'first)))
                   (let ((boundary (boundary-substitution bridge scenario facts)))
                     (flet ((entry (name) (nth k (answers-named history name)))
                            (same (what actual expected)
                              (flet ((there (e) (ames.base:substitute-expressions boundary e)))
                                (is-same bridge (format nil "~A on path ~D" what k)
                                         (and actual (not (keywordp actual)) (there actual))
                                         (there (x expected))))))
                       (dolist (name '("LANDS" "CLOCK" "WALL-HEIGHT" "VX" "ENERGY" "REST" "PATH" "FALLS" "LOWEST"))
                         (is (equal facts (getf (cddr (entry name)) :assume)) "~A on path ~D" name k))
                       (when landed
                         (same "landing" (second (entry "LANDS")) '(sqrt (/ (* 2 h) g)))
                         (same "clock" (second (entry "CLOCK")) '(sqrt (/ (* 2 h) g)))
                         (same "vx" (second (entry "VX")) (if hit-first 0 'v0))
                         (same "lowest" (second (entry "LOWEST")) 0)
                         (same "energy" (second (entry "ENERGY"))
                               (if hit-first '(* m g h) '(+ (* m g h) (* 1/2 m (expt v0 2))))))
                       (cond ((and hit landed) (same "rest" (second (entry "REST"))
                                                     (if hit-first '(sqrt (/ (* 2 h) g)) '(/ d v0))))
                             (t (is (eq :unanswered (second (entry "REST"))) "rest ~S" (entry "REST"))))
                       (same "wall height" (second (entry "WALL-HEIGHT")) '(sqrt (/ (* 2 (- h w)) g)))
                       (is (eq :unanswered (second (entry "PATH"))))
                       (is (stringp (getf (cddr (entry "PATH")) :reason)))
                       (is (member (first (second (entry "FALLS"))) '(:true :unknown)) "~S" (entry "FALLS")))))))
      (is (= 1 (length (answers-named history "CLEARS")))))))

(test numbers-people-write
  "(deg 17) is 17 pi/180 in a scenario's expressions and queries; a default may be a
constant expression ((:value (deg 30)) is pi/6, (:value (/ 3 4)) stays exact); a default
naming a parameter is refused. --set takes pi/4, 3*pi/4, -pi, 2pi, 30deg and 2.5deg, and
refuses pi/x and 1/0."
  (let* ((scenario (scenario-from-text
                    "(scenario degrees \"Degrees.\"
                       (parameters (a (> a 0) (< a (/ pi 2)) (:value (deg 30))) (b :positive (:value (/ 3 4)))
                                   (g :positive (:value 10)))
                       (gravity g)
                       (body ground :fixed t :shape (half-plane (1 0) (0 0)))
                       (body p :mass 1 :position (0 (+ 1 (sin (deg 17)))) :velocity ((cos a) (sin (deg 17))) :shape point)
                       (simulate :states 1)
                       (query q (value (+ (x p) (deg 45)) :at (start 0))))"))
         (values (ames:scenario-parameter-values scenario))
         (a (cdr (find "A" values :key (lambda (e) (symbol-name (car e))) :test #'string=)))
         (b (cdr (find "B" values :key (lambda (e) (symbol-name (car e))) :test #'string=))))
    (is (< (abs (- a (/ pi 6))) 1d-15))
    (is (eql 3/4 b))
    (let ((y (second (ames:scenario-body-position (ames:find-scenario-body 'p scenario)))))
      (is (< (abs (- (expression-value y) (+ 1 (sin (/ (* 17 pi) 180))))) 1d-12) "~S" y)))
  (signals ames:scenario-error
    (scenario-from-text "(scenario bad \"Bad.\" (parameters (a :positive) (b :positive (:value (* 2 a))))
                          (body p :mass 1 :position (0 0) :velocity (0 0) :shape point) (simulate :states 1))"))
  (flet ((near (text expected) (let ((v (ames::parse-set-value text)))
                                 (is (and v (< (abs (- v expected)) 1d-12)) "~A gave ~S" text v))))
    (near "pi/4" (/ pi 4)) (near "3*pi/4" (* 3/4 pi)) (near "-pi" (- pi)) (near "2pi" (* 2 pi))
    (near "30deg" (/ pi 6)) (near "2.5deg" (/ (* 2.5d0 pi) 180)))
  (is (eql 1/4 (ames::parse-set-value "1/4")))
  (is (null (ames::parse-set-value "pi/x")))
  (is (null (ames::parse-set-value "1/0")))
  (is (equal (cons "a" 1/2) (ames::parse-setting "a=0.5"))))

(defun sole-relation (condition)
  "The one relation of CONDITION, a disjunction of one conjunction of one relation, or NIL."
  (and (consp condition) (= 1 (length condition)) (= 1 (length (first condition)))
       (first (first condition))))

(test conditions-in-their-simplest-form
  "The angle of repose as three branches' facts (mu cos a - sin a < 0 with a boundary
fact that cannot hold there, > 0, = 0) is one condition, mu - tan a >= 0, i.e. tan a <= mu;
a conjunct the assumptions imply is dropped; a positive factor is cancelled; <, = and >
together leave nothing to ask; a condition the assumptions refute is never."
  (with-fixture simulator-bridge ()
    (let ((assumptions '((> a 0) (< a (/ pi 2)) (> mu 0) (> g 0))))
      (ames.maxima:with-assumptions (bridge assumptions)
        (flet ((simplest (disjunction) (ames.simulator::simplest-condition bridge disjunction assumptions))
               (is-relation (what relation operator expected)
                 (is (and relation (eq operator (first relation))
                          (ames.maxima:equivalent-p bridge `(- ,(second relation) ,(third relation)) expected))
                     "~A: ~S" what relation)))
          (is-relation "angle of repose"
                       (sole-relation
                        (simplest '(((< (- (* mu (cos a)) (sin a)) 0)
                                     (= (/ (* (- (sin a) (* mu (cos a))) (sqrt (* 1000 g (sin a))))
                                           (* (tan a) (sqrt (- (sin a) (* mu (cos a))))))
                                        0))
                                    ((> (- (* mu (cos a)) (sin a)) 0))
                                    ((= (- (* mu (cos a)) (sin a)) 0)))))
                       '>= '(- mu (tan a)))
          (is-relation "implied conjunct dropped"
                       (sole-relation (simplest '(((> g 0) (< (* 2 mu (cos a)) (* 2 (sin a)))))))
                       '< '(- mu (tan a)))
          (is-relation "positive factor cancelled"
                       (sole-relation (simplest '(((> (* g (- mu 1)) 0)))))
                       '> '(- mu 1))
          (is (eq :true (simplest '(((< (- mu 1) 0)) ((= mu 1)) ((> (- 1 mu) -0))  ((> mu 1))))))
          (is (eq :false (simplest '(((< mu 0)) ((< (+ g 1) 0)))))))))))

(test extrema-need-no-time
  "How far is the bumper compressed? The block's least x while pressing it is
l0 - v0 sqrt(m/k) (energy: k c^2 = m v0^2), where its speed is least, 0; its greatest
speed is v0, at the contact's ends (the zeros of each factor of the speed's derivative,
cos and sin, are tried). The spheres' least distance of centres over
their fall is a + b, found over the arc length of their line (no time needed)."
  (with-fixture simulator-bridge ()
    (let* ((bumper (ames:parse-scenario
                    (with-queries "block-hits-bumper" "(query least-x (minimum (x block) :during (start 1)))"
                                  "(query top-speed (maximum (speed block) :during (start 1)))"
                                  "(query least-speed (minimum (speed block) :during (start 1)))")))
           (spheres (ames:parse-scenario
                     (with-queries "spheres-under-gravitation"
                       "(query gap (minimum (- (x second) (x first)) :during (start 0)))")))
           (bumper-history (ames:simulate bumper :bridge bridge))
           (spheres-history (ames:simulate spheres :bridge bridge)))
      (call-with-scenario-facts
       bridge bumper
       (lambda ()
         (is-same bridge "greatest compression" (answer-value bumper-history "LEAST-X")
                  (in-scenario-terms bumper '(- l0 (* v0 (sqrt (/ m k))))))
         (is-same bridge "top speed" (answer-value bumper-history "TOP-SPEED") (in-scenario-terms bumper 'v0))
         (is-same bridge "least speed" (answer-value bumper-history "LEAST-SPEED") 0)))
      (call-with-scenario-facts
       bridge spheres
       (lambda ()
         (is-same bridge "least distance" (answer-value spheres-history "GAP")
                  (in-scenario-terms spheres '(+ a b))))))))

(test an-equality-over-a-state-is-decided
  "The block on a rough incline without a bound on mu forks on mu cos a - sin a: it stays
at rest (speed = 0 throughout) exactly when mu > tan a, the sliding branch's speed being
non-zero at its end."
  (with-fixture simulator-bridge ()
    (let* ((form (with-queries "block-sliding-down-rough-incline"
                   "(query stays (parameter mu :such-that (= (speed block) 0)))"))
           (form (mapcar (lambda (clause)
                           (if (and (consp clause) (same-name-p* (first clause) "PARAMETERS"))
                               (mapcar (lambda (spec) (if (and (consp spec) (same-name-p* (first spec) "MU"))
                                                          (list (first spec) :positive)
                                                          spec))
                                       clause)
                               clause))
                         form))
           (scenario (ames:parse-scenario form))
           (history (ames:simulate scenario :bridge bridge))
           (value (answer-value history "STAYS")))
      (is (eq :when (first value)) "~S" value)
      (call-with-scenario-facts
       bridge scenario
       (lambda ()
         (let ((relation (sole-relation (rest value))))
           (is (and relation (eq '> (first relation))
                    (ames.maxima:equivalent-p bridge `(- ,(second relation) ,(third relation))
                                              (in-scenario-terms scenario '(- mu (tan a)))))
               "~S" value)))))))

(defparameter *belt-text*
  "(scenario box-on-conveyor-belt
     \"A box set down at rest on a conveyor belt moving at constant speed v.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
                 (v :positive (:value 2)) (mu :positive (:value 1/2)))
     (gravity g)
     (body belt :driven t :velocity (v 0) :shape (half-plane (1 0) (0 0)))
     (body box :mass m :position (0 0) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
     (friction box belt :static mu)
     (simulate :states 3)
     (query catches-up (time (end 0)))
     (query slip (value (- (x belt) (x box)) :at (end 0)))
     (query speed (value (x (velocity box)) :at (start 1)))
     (query energy (value (energy) :at (end 0))))"
  "A box on a conveyor belt (a driven half-plane).")

(test box-on-a-conveyor-belt
  "A box set down at rest on a belt driven at v: kinetic friction mu m g accelerates it at
mu g until it moves with the belt, at v/(mu g), having slipped v^2/(2 mu g) behind the belt;
then it sticks and moves at v forever. The belt keeps its velocity; its drive balances the
friction and the box's weight, (mu m g, m g); the system's energy is the box's m v^2/2 (the
belt has no mass). A driven body with a :mass, or :fixed too, is refused."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-from-text *belt-text*))
           (history (ames:simulate scenario :bridge bridge))
           (states (ames::history-states history)))
      (flet ((x (e) (in-scenario-terms scenario e)))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same bridge "catches up" (answer-value history "CATCHES-UP") (x '(/ v (* mu g))))
           (is-same bridge "slip" (answer-value history "SLIP") (x '(/ (expt v 2) (* 2 mu g))))
           (is-same bridge "speed with the belt" (answer-value history "SPEED") (x 'v))
           (is-same bridge "energy" (answer-value history "ENERGY") (x '(* 1/2 m (expt v 2))))
           (is-same-vector bridge "the box's acceleration while it slips"
                           (per-body (ames::state-accelerations (first states)) "BOX") (x '((* mu g) 0)))
           (is-same-vector bridge "the belt's acceleration" (per-body (ames::state-accelerations (first states)) "BELT")
                           '(0 0))
           (let ((drive (find :drive (ames::state-forces-of (first states)) :key #'first)))
             (is-same-vector bridge "the drive's reaction" (third drive) (x '((* mu m g) (* m g)))))
           (is (eq :forever (ames::state-duration (second states))))
           (is-same-vector bridge "sticking" (per-body (ames::state-velocities (second states)) "BOX") (x '(v 0)))))))
    ;; a box thrown on faster than the belt (u > v) is slowed to the belt's speed instead,
    ;; after (u - v)/(mu g), having slipped (u - v)^2/(2 mu g) ahead
    (let* ((text (cl-ppcre:regex-replace
                  ":velocity \\(0 0\\) :shape \\(polygon"
                  (cl-ppcre:regex-replace "\\(mu :positive \\(:value 1/2\\)\\)" *belt-text*
                                          "(mu :positive (:value 1/2)) (u (> u v) (:value 3))")
                  ":velocity (u 0) :shape (polygon"))
           (scenario (scenario-from-text text))
           (history (ames:simulate scenario :bridge bridge)))
      (is (search "(u 0)" text))
      (call-with-scenario-facts
       bridge scenario
       (lambda ()
         (is-same bridge "slowed" (answer-value history "CATCHES-UP")
                  (in-scenario-terms scenario '(/ (- u v) (* mu g))))
         (is-same bridge "ahead" (answer-value history "SLIP")
                  (in-scenario-terms scenario '(- (/ (expt (- u v) 2) (* 2 mu g)))))
         (is-same bridge "with the belt" (answer-value history "SPEED") (in-scenario-terms scenario 'v)))))
    (signals ames:scenario-error
      (scenario-from-text (cl-ppcre:regex-replace "belt :driven t" *belt-text* "belt :driven t :mass 1")))
    (signals ames:scenario-error
      (scenario-from-text (cl-ppcre:regex-replace "belt :driven t" *belt-text* "belt :driven t :fixed t")))))

(test distance-and-state-times-per-branch
  "A block launched up a rough incline at v0 stops after v0/(g (sin a + mu cos a)), having
slid v0^2/(2 g (sin a + mu cos a)) (on every branch of the fork at its stop, asked as
(time (end 0)), (value (time) :at (end 0)) and (distance block :during (start 0))). Where it
sticks (mu cos a - sin a >= 0), that is all it travels and it rests for good from then;
where it slides back, it moves forever: neither is answered."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (with-queries "block-launched-up-rough-incline"
                        "(query up (distance block :during (start 0)))"
                        "(query total (distance block))"
                        "(query stop (time (end 0)))"
                        "(query clock (value (time) :at (end 0)))"
                        "(query rest (time (:rest block)))")))
           (history (ames:simulate scenario :bridge bridge))
           (paths (ames.simulator::history-paths history)))
      (is (= 3 (length paths)))
      (flet ((x (e) (in-scenario-terms scenario e)))
        (loop for (facts) in paths
              for k from 0
              for sticks = (member (first (first facts)) '(> =))
              do (ames.maxima:with-assumptions
                     (bridge (append (ames:scenario-assumption-relations scenario) (remove '= facts :key #'first)))
                   (let ((boundary (boundary-substitution bridge scenario facts '("MU"))))
                   (flet ((entry (name) (nth k (answers-named history name)))
                          (is-same (bridge what actual expected)
                            (flet ((there (e) (ames.base:substitute-expressions boundary e)))
                              (is-same bridge what (and actual (not (keywordp actual)) (there actual))
                                       (there expected)))))
                     (dolist (name '("UP" "TOTAL" "STOP" "CLOCK" "REST"))
                       (is (equal facts (getf (cddr (entry name)) :assume))))
                     (let ((run-up (x '(/ (expt v0 2) (* 2 g (+ (sin a) (* mu (cos a)))))))
                           (stop (x '(/ v0 (* g (+ (sin a) (* mu (cos a))))))))
                       (is-same bridge "run up" (second (entry "UP")) run-up)
                       (is-same bridge "stop" (second (entry "STOP")) stop)
                       (is-same bridge "clock" (second (entry "CLOCK")) stop)
                       (cond (sticks
                              (is-same bridge "total" (second (entry "TOTAL")) run-up)
                              (is-same bridge "rest" (second (entry "REST")) stop))
                             (t (is (eq :unanswered (second (entry "TOTAL"))))
                                (is (eq :unanswered (second (entry "REST")))))))))))))))
