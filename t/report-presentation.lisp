;;;; t/report-presentation.lisp -- the presentation step on real runs: equal to the solved forms, numbers, the golden wedge.
;;;;
;;;; Every quantity a report shows is compared with the solved one by Maxima's equivalence
;;;; (AMES.MAXIMA:EQUIVALENT-P under the scenario's assumptions). The one rewrite Maxima cannot
;;;; prove, atan(cos x / sin x) = pi/2 - x where 0 < x < pi is proven, is checked by numeric
;;;; evaluation at points that satisfy the assumptions. The golden wedge report is the only
;;;; comparison of printed text (whitespace normalised), as the issue asks.

(in-package #:ames.tests)

(in-suite report)

(defun arithmetic-p (x) (ames.base:valid-expression-p x :kind :arithmetic))

(defun presentation-pairs (presenter history)
  "Each (SOLVED PRESENTED) pair of expressions a report of HISTORY shows, SOLVED with
the internal names renamed as PRESENTED's are."
  (let ((pairs '()))
    (labels ((add (solved &optional (presented (ames.report:present presenter solved)))
               (when (arithmetic-p solved)
                 (push (list (ames.report::renamed presenter solved) presented) pairs)))
             (add-all (expressions) (mapc #'add expressions)))
      (dolist (state (ames:history-states history) (nreverse pairs))
        (add (ames:state-start state))
        (add (ames:state-duration state))
        (loop for (body acceleration) in (ames:state-accelerations state)
              for position = (ames:body-entry (ames:state-positions state) body)
              do (add-all acceleration)
                 (cond ((ames.report::vector-value-p position)
                        (loop for coordinate in position for a in acceleration for axis in '(:x :y)
                              for shown = (ames.report::coordinate-view presenter coordinate a axis)
                              do (add coordinate (ames.base:substitute-expressions
                                                  (list (cons (ames.report:acceleration-symbol axis)
                                                              (ames.report::renamed presenter a)))
                                                  shown))))
                       ((and (consp position) (eq (first position) :on-path))
                        (add-all (second position)))))
        (dolist (entry (ames::state-forces-of state))
          (let ((value (nth-value 2 (ames.report::force-entry entry))))
            (if (ames.report::vector-value-p value) (add-all value) (add value))))
        (loop for (nil position) in (ames:state-final-positions state) do (add-all position))
        (loop for (nil velocity) in (ames:state-final-velocities state) do (add-all velocity))
        (let ((path (ames.simulator:state-path-coordinates state)))
          (add (getf path :arc-length-from))
          (add (getf path :tangential-acceleration))
          (add (third (getf path :energy-integral))))
        (add (ames.simulator:state-end-arc-length state))))))

(defun admissible-test-points (scenario count)
  "COUNT alists over SCENARIO's parameters (and tau, s) that satisfy its assumptions."
  (let ((state (sb-ext:seed-random-state 42))
        (names (mapcar #'ames:scenario-parameter-name (ames:scenario-parameters scenario)))
        (facts (ames:scenario-assumption-relations scenario))
        (points '()))
    (loop repeat 500 while (< (length points) count)
          do (let ((point (mapcar (lambda (n) (cons n (+ 0.05d0 (random 1.4d0 state)))) names)))
               (when (every (lambda (fact) (ames.report::relation-holds-p fact point)) facts)
                 (push (list* (cons 'tau (random 1d0 state)) point) points))))
    points))

(defun numerically-equal-at (points a b)
  "True when A and B agree wherever both are defined at POINTS, and are at two of them."
  (let ((compared 0))
    (dolist (point points (>= compared 2))
      (let ((x (expression-value a point)) (y (expression-value b point)))
        (when (and (realp x) (realp y))
          (incf compared)
          (unless (< (abs (- x y)) (* 1d-8 (max 1 (abs x) (abs y)))) (return nil)))))))

(defun mentions-inverse-trigonometry-p (expression)
  (intersection '(atan asin acos) (alexandria:flatten expression)))

(defun check-presentation (bridge history)
  "Check every presented quantity of HISTORY against its solved form (see the file header)."
  (ames.report:call-with-presenter
   history bridge
   (lambda (presenter)
     (let* ((scenario (ames:history-scenario history))
            (points (let ((s (ames.report::arc-length-symbol presenter)))
                      (mapcar (lambda (p) (acons s 0.3d0 p)) (admissible-test-points scenario 6))))
            (pairs (presentation-pairs presenter history)))
       (is (plusp (length pairs)))
       (loop for (solved presented) in pairs
             do (is (or (ames.maxima:equivalent-p bridge presented solved)
                        (and (mentions-inverse-trigonometry-p solved)
                             (numerically-equal-at points presented solved)))
                    "~A: ~S is shown as ~S" (ames:scenario-name scenario) solved presented))))))

(defun history-of (name bridge &key parameter-values)
  (simulate-stopping-when-ambiguous (scenario-named name) bridge :parameter-values parameter-values))

(defun normalised-text (text)
  "TEXT with every run of whitespace made one space, trimmed."
  (string-trim " " (cl-ppcre:regex-replace-all "\\s+" text " ")))

(test golden-wedge-report
  "The wedge's text report, from its start to the end of its first state, reads like the
thesis (t/report-golden-wedge.txt; whitespace normalised)."
  (with-fixture simulator-bridge ()
    (let* ((report (with-output-to-string (out)
                     (ames:print-history-text (history-of "particle-on-wedge" bridge) out :bridge bridge)))
           (golden (uiop:read-file-string (asdf:system-relative-pathname "ames" "t/report-golden-wedge.txt")))
           (shown (normalised-text report))
           (expected (normalised-text golden)))
      (is (search "N_1 = mp mw g cos a / (mw + mp sin^2 a)" report))
      (is (eql 0 (search expected shown)) "The wedge report differs from the golden one:~%~A" report))))

(test numbers-beside-every-formula-under-set
  "With parameter values every force, acceleration, trajectory and time has its number."
  (with-fixture simulator-bridge ()
    (let* ((values '(("mp" . 1) ("mw" . 3) ("g" . 981/100) ("h" . 1) ("a" . 1/2)))
           (history (history-of "particle-at-wedge-apex" bridge :parameter-values values))
           (view (ames.report:call-with-presenter
                  history bridge (lambda (presenter) (ames.report:history-view presenter history))))
           (state (first (getf view :states))))
      (dolist (force (getf state :forces))
        (is (getf force :numbers) "no number for ~A" (getf force :label)))
      (let ((normal (find "normal force of wedge on particle" (getf state :forces)
                          :key (lambda (f) (getf f :label)) :test #'string=))
            (a 0.5d0) (g 9.81d0) (mp 1) (mw 3))
        (is (< (abs (- (getf normal :numbers)
                       (/ (* mp mw g (cos a)) (+ mw (* mp (expt (sin a) 2))))))
               1d-9)))
      (dolist (body (getf state :bodies))
        (loop for value in (getf body :acceleration) for number in (getf body :acceleration-numbers)
              do (is (or (realp value) number)))
        (loop for value in (getf body :position) for number in (getf body :position-numbers)
              do (is (or (realp value) number))))
      (is (realp (getf state :duration-number)))
      (let ((text (with-output-to-string (out) (ames:print-history-text history out :bridge bridge))))
        (is (search "= 7.996" text))
        (is (search "(0.8463)" text))))))

(test events-of-any-kind-read-as-phrases
  "Events the knowledge base may name later, and their options, are printed generically."
  (with-fixture simulator-bridge ()
    (let ((history (history-of "projectile-off-table" bridge)))
      (ames.report:call-with-presenter
       history bridge
       (lambda (presenter)
         (flet ((phrase-of (event) (ames.report::phrase-text (ames.report::event-phrase presenter event))))
           (let ((p 'ames-scenario::particle) (f 'ames-scenario::floor) (v0 'ames-scenario::v0)
                 (m 'ames-scenario::m))
             (let ((collision (phrase-of `(:collision ,p ,f :impulse (* ,m ,v0) :energy-lost (* 1/2 ,m (expt ,v0 2))))))
               (is (search "particle collides with floor" collision))
               (is (search "impulse m v0" collision))
               (is (search "energy lost" collision)))
             (is (search "starts sliding" (phrase-of `(:starts-sliding ,p ,f))))
             (is (search "spins up particle" (phrase-of `(:spins-up ,p :rate 3))))
             (is (search "rate 3" (phrase-of `(:spins-up ,p :rate 3))))
             (is (search "nothing more changes" (phrase-of :none))))))))))
