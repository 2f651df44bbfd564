;;;; t/queries-answers.lisp -- queries that read the knowledge base's terms (issue 20, class 6),
;;;; answers at events that need no time (issue 26, thesis 4.2.2), and queries that fail
;;;; without ending the run; numbers people write, conditions in their simplest form, extrema
;;;; that need no time. Every answer is checked by Maxima equivalence against the
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

(test queries-on-a-run-that-forks-at-its-start
  "A run that forks at its start on mu cos a - sin a: each branch answers the energy at
its state 0 (m g h / 2, the particle at rest at height h/2), and the parameter selection
'the particle's speed is 0' holds where static friction holds it, mu >= tan a: the
boundary mu = tan a is a branch of its own (once left out, because the selection query
named the parameter that branch substitutes), where the particle stays too. (The
sliding branch once ended ambiguous where the particle leaves the slope: the sign of
its exit velocity's factor sqrt(sin a) sqrt(g) (mu cos a - sin a) / sqrt(sin a - mu cos a)
was taken positive, from a linear split in sqrt(sin a) that dropped sin(a)^(3/2).)"
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-from-text
                      (format nil *rough-incline-text*
                              '("(query e (value (energy) :at (start 0)))"
                                "(query stays (parameter mu :such-that (= (speed particle) 0)))"))))
           (history (ames:simulate scenario :bridge bridge)))
      (is (eq :branched (ames::history-outcome history)))
      (let ((energies (answers-named history "E")))
        ;; mu cos a - sin a < 0, > 0, and the boundary mu = tan a
        (is (= 3 (length energies)))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (dolist (entry energies)
             (is (consp (getf (cddr entry) :assume)) "~S" entry)
             (is-same bridge "energy at rest" (second entry)
                      (in-scenario-terms scenario '(* 1/2 m g h)))))))
      (let* ((stays (first (answers-named history "STAYS")))
             (when (and (consp (second stays)) (getf (second stays) :when))))
        (is (and (= 1 (length when)) (eq '>= (first (first when)))) "~S" stays)
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is (eq :true (ames.algebra:decide
                          bridge `(= ,(ames.algebra::relation-difference (first when))
                                     ,(in-scenario-terms scenario '(- mu (tan a)))))))
               "~S" stays))))))

(defun report-total-energy (state at)
  "The report's total T + V of STATE (the sum of its :ENERGY note's terms, as the report
adds them) at AT, :START or :END, or NIL where it has none there in closed form."
  (let* ((terms (mapcar #'third (getf (ames.simulator:state-reported-sections state) :energy)))
         (total (and terms (cons '+ terms)))
         (arc (find "ARC-LENGTH" (alexandria:flatten total) :key (lambda (x) (and (symbolp x) (symbol-name x)))
                                                            :test #'equal)))
    (cond ((null total) nil)
          ;; a motion with no closed form (numbers only): its total is over quantity terms
          ((find-if #'ames.base:quantity-term-p (ames.base:expression-variables total)) nil)
          (arc (let ((s (if (eq at :start)
                            (or (getf (ames.simulator:state-path-coordinates state) :arc-length-from)
                                (let ((lines (ames.simulator:state-line-coordinates state)))
                                  (and (= 1 (length lines)) (getf (first lines) :from))))
                            (ames.simulator:state-end-arc-length state))))
                 (and s (subst s arc total))))
          ((eq at :start) (subst 0 'tau total))
          (t (let ((d (ames.simulator::state-duration state)))
               (and (not (keywordp d)) (not (and (consp d) (keywordp (first d))))
                    (subst d 'tau total)))))))

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
at rest (speed = 0 throughout) exactly when mu >= tan a (at mu = tan a static friction
is just enough), the sliding branch's speed being non-zero at its end."
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
           (is (and relation (eq '>= (first relation))
                    (ames.maxima:equivalent-p bridge `(- ,(second relation) ,(third relation))
                                              (in-scenario-terms scenario '(- mu (tan a)))))
               "~S" value)))))))

(test a-query-names-only-declared-kinds-of-event
  "A query's event pattern names a kind the knowledge base declares: (:zork A B) is
refused when the scenario is read, (:collision A B) is taken."
  (signals ames.scenario:scenario-error
    (scenario-from-text (format nil *rough-incline-text*
                                '("(query q (value (speed particle) :at (:zork particle incline)))"))))
  (is (typep (scenario-from-text (format nil *rough-incline-text*
                                         '("(query q (value (speed particle) :at (:collision particle incline)))")))
             'ames.scenario:scenario)))
