;;;; t/queries-explain.lisp -- ask, branch and explain (thesis 3.2.4): queries answered from a
;;;; run's history, the run's tree when it branches, and explanations from the justifications.

(in-package #:ames.tests)

(in-suite simulator)

(defun with-queries (scenario-name &rest queries)
  "The form of scenarios/SCENARIO-NAME.lisp with the (query ...) clauses QUERIES added,
its symbols read into the scenario package."
  (let ((form (first (ames:read-scenario-forms
                      (uiop:read-file-string
                       (find scenario-name (scenario-files) :key #'pathname-name :test #'string=))))))
    (append form (first (ames:read-scenario-forms
                         (format nil "(~{~A~^ ~})" queries))))))

(defun answer (history name)
  "The answers of HISTORY to the query NAME."
  (remove-if-not (lambda (entry) (string= (symbol-name (first entry)) name))
                 (ames:history-answers history)))

(test wedge-queries-answered-in-closed-form
  "The particle's speed when it leaves the wedge is sqrt(2 g h (mw + mp) ... ) as the
energy and momentum give it; the landing time is the state's end; the wedge's normal
force is proven positive during state 0; an unknown name is a scenario error naming it."
  (with-fixture simulator-bridge ()
    (let* ((form (with-queries "particle-on-wedge"
                   "(query speed-leaving (value (speed particle) :at (:leaves particle wedge)))"
                   "(query landing (time (:collision particle ground)))"
                   "(query pushes (prove (> (normal-force particle wedge) 0) :during (start 0)))"
                   "(query floating (value (speed particle) :at (:lift-off particle wedge)))"))
           (scenario (ames:parse-scenario form))
           (history (simulate-stopping-when-ambiguous scenario bridge)))
      (flet ((x (e) (in-scenario-terms scenario e)))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           ;; energy: mp g h/2 = (mp vp^2 + mw vw^2)/2 with mp vpx + mw vw = 0 and the slope's
           ;; direction relative to the wedge: the particle's speed squared is
           ;; g h (mw^2 + mp^2 sin^2 a + 2 mp mw sin^2 a) / ((mp + mw)(mw + mp sin^2 a))
           (is-same bridge "speed leaving the wedge"
                    `(expt ,(second (first (answer history "SPEED-LEAVING"))) 2)
                    (x '(/ (* g h (+ (expt mw 2) (* (expt mp 2) (expt (sin a) 2)) (* 2 mp mw (expt (sin a) 2))))
                           (* (+ mp mw) (+ mw (* mp (expt (sin a) 2)))))))
           (is-same bridge "landing time" (second (first (answer history "LANDING")))
                    (x '(sqrt (/ (* h (+ mw (* mp (expt (sin a) 2)))) (* (+ mp mw) g (expt (sin a) 2))))))
           (is (eq :true (first (second (first (answer history "PUSHES"))))))
           (is (eq :unanswered (second (first (answer history "FLOATING")))))))
        (signals ames:undeclared-symbol-error
          (ames:parse-scenario (with-queries "particle-on-wedge"
                                 "(query bad (value (speed no-such-body) :at (end 0)))")))
        (signals ames:scenario-error
          (ames:parse-scenario (with-queries "particle-on-wedge" "(query bad (guess (speed particle)))")))))))

(test projectile-landing-time-query
  "A projectile off a table: the time it lands is d/v0 + sqrt(2 h / g), with a number
beside it under the default values."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (with-queries "projectile-off-table" "(query lands (time (:collision particle floor)))")))
           (history (simulate-stopping-when-ambiguous scenario bridge
                                                      :parameter-values (ames:scenario-parameter-values scenario)))
           (entry (first (answer history "LANDS"))))
      (call-with-scenario-facts
       bridge scenario
       (lambda ()
         (is-same bridge "landing time" (second entry)
                  (in-scenario-terms scenario '(+ (/ d v0) (sqrt (/ (* 2 h) g)))))))
      (is (< (abs (- (getf (cddr entry) :numeric) (+ 1/4 (sqrt (/ 2 9.81d0))))) 1d-9)))))

(test explain-names-the-components-and-the-end
  "EXPLAIN on the wedge names the contact, normal force, gravity, Newton and frame
conversion components behind its equations, with the thesis's figures, and says why the
state ends at the ground."
  (with-fixture simulator-bridge ()
    (let* ((history (simulate-stopping-when-ambiguous (scenario-named "particle-on-wedge") bridge))
           (text (with-output-to-string (stream) (ames:explain history :state 0 :stream stream))))
      (dolist (word '("normal-force" "terrestrial-gravitation" "newtons-second-law" "newtons-third-law"
                      "reference-frame-conversion" "path-coordinate-conversion" "kinematic-restriction"
                      "figure 2-8" "figure 2-7" "particle on wedge"
                      "Why these contacts and modes" "Why the state ends then" "particle collides with ground"))
        (is (search word text) "the explanation does not mention ~S:~%~A" word text)))))

(test under-plane-explains-the-dropped-contact
  "Under the plane the contact is tried and dropped because its normal force would pull:
the explanation says so."
  (with-fixture simulator-bridge ()
    (let* ((history (simulate-stopping-when-ambiguous (scenario-named "particle-under-plane") bridge))
           (text (with-output-to-string (stream) (ames:explain history :stream stream))))
      (is (search "turned contact (particle on ceiling) off because particle lifts off ceiling" text)
          "~A" text))))

(test corner-branches-on-the-sign-of-the-push
  "The corner without values (issue 13): the run forks at the start on the push against
mb g (l1 - l2)/l3: B rises (f above it: a_Ax > 0, B's corner reaches the upper end of A's
face at t1 = sqrt(l3 / a_Ax)), B falls (f below: t1 = sqrt(-l3 / a_Ax)), and at the
boundary both stay at rest forever. Each branch's fact selects the right side of the
threshold (checked at sample values), and its first state's results are Maxima-checked."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "two-blocks-in-corner"))
           (history (ames:simulate scenario :bridge bridge))
           (fork (first (ames::history-states history)))
           (branches (and fork (ames::state-branches fork))))
      (flet ((x (form) (in-scenario-terms scenario form))
             (side (branch)
               ;; the branch's fact at two sample points, one on each side of the threshold
               (let ((relation (getf branch :assume)))
                 (flet ((holds-at (f)
                          (let* ((values (in-scenario-terms
                                          scenario `((ma . 1) (mb . 1) (g . 10) (l1 . 2) (l2 . 1)
                                                     (l3 . 1) (f . ,f))))
                                 (difference (expression-value
                                              `(- ,(second relation) ,(third relation)) values)))
                            (ecase (first relation)
                              ((> >=) (> difference 0)) ((< <=) (< difference 0))
                              (= (< (abs difference) 1d-9))))))
                   (cond ((eq (first relation) '=) :boundary)
                         ((and (holds-at 15) (not (holds-at 5))) :rises)
                         ((and (holds-at 5) (not (holds-at 15))) :falls))))))
        (is (eq :branched (ames::history-outcome history)))
        (is (equal '(:branch) (and fork (ames::state-end-event fork))))
        (is (= 3 (length branches)))
        (is (set-equal-p '(:rises :falls :boundary) (mapcar #'side branches)))
        (dolist (branch branches)
          (let ((state (first (getf branch :states)))
                (a-ax (x '(/ (* l3 (- (* f l3) (* mb g (- l1 l2))))
                           (+ (* ma (expt l3 2)) (* mb (expt (- l1 l2) 2)))))))
            (is (not (null state)))
            (when state
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (ames.maxima:with-assumptions
                     (bridge (if (getf branch :substitution) '() (list (getf branch :assume))))
                   (case (side branch)
                     (:rises
                      (is-same bridge "a_Ax, rising" (first (per-body (ames::state-accelerations state) "BLOCK-A")) a-ax)
                      (is-same bridge "t1, rising" (ames::state-duration state) `(sqrt (/ ,(x 'l3) ,a-ax))))
                     (:falls
                      (is-same bridge "a_Ax, falling" (first (per-body (ames::state-accelerations state) "BLOCK-A")) a-ax)
                      ;; compared through the squares: Maxima does not merge the quotient of
                      ;; roots of two negatives into one root
                      (is-same bridge "t1^2, falling" `(expt ,(ames::state-duration state) 2)
                               `(- (/ ,(x 'l3) ,a-ax))))
                     (:boundary
                      (is (eq :forever (ames::state-duration state)))
                      (is (equal '(0 0) (per-body (ames::state-accelerations state) "BLOCK-A")))))))))))))))

(test largest-pull-for-which-the-block-stays-on-the-cart
  "A parameter selection (issue 13): the block stays on the pulled cart (never leaves it)
exactly while f < mu g (m + mc), the threshold of static friction; the answer is a
condition on f, checked on both sides of the threshold."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (with-queries "block-on-cart-pulled"
                        "(query largest-pull (parameter f :such-that (not (:leaves block cart))))")))
           (history (ames:simulate scenario :bridge bridge))
           (value (second (first (answer history "LARGEST-PULL")))))
      (is (eq :when (first value)) "answer ~S" value)
      (when (eq :when (first value))
        (flet ((holds-at (f)
                 ;; some branch's conditions all hold at these values (threshold 2.5)
                 (let ((values (in-scenario-terms scenario `((m . 1) (mc . 4) (g . 10) (mu . 1/20)
                                                             (l . 2) (c . 1/2) (b . 1/2) (f . ,f)))))
                   (some (lambda (conditions)
                           (every (lambda (relation)
                                    (let ((difference (expression-value
                                                       `(- ,(second relation) ,(third relation)) values)))
                                      (ecase (first relation)
                                        (< (< difference 0)) (<= (<= difference 0))
                                        (> (> difference 0)) (>= (>= difference 0)))))
                                  conditions))
                         (rest value)))))
          (is-true (holds-at 2))
          (is-true (holds-at 49/20))
          (is-false (holds-at 51/20))
          (is-false (holds-at 5)))))))

(test a-failed-branch-names-the-form-at-fault
  "A branch that fails on an undecidable geometric fact says which fact: the reason
holds the condition's detail and its datum, on one line."
  (let* ((fact '(= (* w (+ (- d) (sqrt h))) 0))
         (text (ames.simulator::failure-text
                (make-condition 'ames.geometry:undecidable-geometric-fact
                                :fact fact :datum fact
                                :detail "neither exact arithmetic nor Maxima can decide it"))))
    (is (search "neither exact arithmetic nor Maxima can decide it" text))
    (is (search "(= (* w (+ (- d) (sqrt h))) 0)" (string-downcase text)))
    (is (not (find #\Newline text)))))
