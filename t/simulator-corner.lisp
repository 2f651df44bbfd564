;;;; t/simulator-corner.lisp -- the two blocks in a corner (thesis 2.6.2), explanations of a
;;;; model's equations, and parameter values (helpers are in t/simulator-scenarios.lisp).

(in-package #:ames.tests)

(in-suite simulator)

;;; Two blocks in a corner (thesis 2.6.2)

(test corner-stops-on-the-undecided-sign-of-the-push
  "Whether B rises or falls depends on f against mb g (l1 - l2)/l3, which the
assumptions do not decide: with (simulate :branch nil) the run stops :AMBIGUOUS, naming
the missing fact."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario
                      (mapcar (lambda (clause)
                                (if (and (consp clause) (same-name-p* (first clause) "SIMULATE"))
                                    (append clause (list :branch nil))
                                    clause))
                              (ames:scenario-form (scenario-named "two-blocks-in-corner")))))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (condition (getf (ames::history-notes history) :stopped-by)))
      (is (eq :ambiguous (ames::history-outcome history)))
      (is (typep condition 'ames::ambiguous-transition))
      (when (typep condition 'ames::ambiguous-transition)
        (is (typep condition 'ames-error))
        (is (mentions-name-p "F" (ames::ambiguous-transition-missing-fact condition))
            "the missing fact does not mention f: ~S"
            (ames::ambiguous-transition-missing-fact condition))
        (is (consp (ames::ambiguous-transition-candidates condition)))
        (is (plusp (length (princ-to-string condition)))))
      (is (null (ames::history-rederived history)))
      ;; the machine-readable output says so too
      (let ((sexp (ames::history-sexp history)))
        (is (eq :ambiguous (getf sexp :outcome)))
        (is (mentions-name-p "F" (getf (getf sexp :ambiguity) :missing-fact)))))))

(test corner-first-state-model
  "The first state of the corner: contacts A-floor, B-wall and B's corner on A's face;
a_Ax = l3 (f l3 - mb g (l1 - l2)) / (ma l3^2 + mb (l1 - l2)^2), a_By = k a_Ax with
k = (l1 - l2)/l3 (the position constraint through the inclined face), A moves only
horizontally and B only vertically, and N = mb (ma g + k f) / ((ma + mb k^2) cos a)
between the blocks, N_wall = N sin a, N_floor = ma g + N cos a."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "two-blocks-in-corner")))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (call-with-first-state-model
         scenario bridge
         (lambda (run solution)
           (let* ((a (body-symbol scenario "BLOCK-A"))
                  (b (body-symbol scenario "BLOCK-B"))
                  (k (x '(/ (- l1 l2) l3)))
                  (cos-a (x '(/ l3 (sqrt (+ (expt l3 2) (expt (- l1 l2) 2))))))
                  (sin-a (x '(/ (- l1 l2) (sqrt (+ (expt l3 2) (expt (- l1 l2) 2))))))
                  (between (contact-between run "BLOCK-A" "BLOCK-B"))
                  (wall (contact-between run "BLOCK-B" "WALL"))
                  (floor (contact-between run "BLOCK-A" "FLOOR"))
                  (a-ax (solved solution `(ames.kb:acc ,a :x)))
                  (n (and between (solved solution `(ames.kb:normal-force ,between)))))
             (is (= 3 (length (ames.simulator::active-contacts run))))
             (is (and between wall floor) "contacts: ~S"
                 (mapcar (lambda (c) (ames.simulator::contact-bodies run c)) (ames.simulator::active-contacts run)))
             (is-same bridge "a_Ax" a-ax
                      (x '(/ (* l3 (- (* f l3) (* mb g (- l1 l2))))
                           (+ (* ma (expt l3 2)) (* mb (expt (- l1 l2) 2))))))
             (is-same bridge "a_Ax from the thesis" a-ax
                      (x `(/ (- f (* mb g ,k)) (+ ma (* mb (expt ,k 2))))))
             (when a-ax
               (is-same bridge "a_By = k a_Ax" (solved solution `(ames.kb:acc ,b :y))
                        `(* ,k ,a-ax)))
             (is-same bridge "A stays on the floor" (solved solution `(ames.kb:acc ,a :y)) 0)
             (is-same bridge "B stays against the wall" (solved solution `(ames.kb:acc ,b :x)) 0)
             (is-same bridge "N between the blocks" n
                      (x `(/ (* mb (+ (* ma g) (* ,k f))) (* (+ ma (* mb (expt ,k 2))) ,cos-a))))
             (when n
               (is-same bridge "N_wall" (and wall (solved solution `(ames.kb:normal-force ,wall)))
                        `(* ,n ,sin-a))
               (is-same bridge "N_floor" (and floor (solved solution `(ames.kb:normal-force ,floor)))
                        (x `(+ (* ma g) (* ,n ,cos-a)))))
             ;; Newton for B along y, as the thesis writes it: mb a_By = N cos a - mb g
             (when (and n a-ax)
               (is-same bridge "mb a_By = N cos a - mb g" (x `(* mb ,k ,a-ax))
                        (x `(- (* ,n ,cos-a) (* mb g))))))))))))

(test corner-condition-for-b-to-rise
  "B rises (a_By > 0) exactly when f > mb g (l1 - l2)/l3: a_By is (f - mb g (l1 - l2)/l3)
times a positive factor; its sign is undecided under the file's assumptions, positive
with f twice the threshold and negative with f half of it."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "two-blocks-in-corner")))
      (flet ((x (form) (in-scenario-terms scenario form)))
        (call-with-first-state-model
         scenario bridge
         (lambda (run solution)
           (declare (ignore run))
           (let* ((b (body-symbol scenario "BLOCK-B"))
                  (a-by (solved solution `(ames.kb:acc ,b :y)))
                  (threshold (x '(/ (* mb g (- l1 l2)) l3))))
             (flet ((with-push (value)
                      (substitute-expressions (list (cons (x 'f) value)) a-by)))
               (is (not (null a-by)))
               (when a-by
                 (is (eq :unknown (ames.algebra:decide bridge `(> ,a-by 0))))
                 (is-same bridge "a_By against the threshold"
                          a-by (x `(/ (* (- l1 l2) (- f ,threshold))
                                      (+ (* ma l3) (/ (* mb (expt (- l1 l2) 2)) l3)))))
                 (is (eq :true (ames.algebra:decide bridge `(> ,(with-push `(* 2 ,threshold)) 0))))
                 (is (eq :true (ames.algebra:decide bridge `(< ,(with-push `(/ ,threshold 2)) 0))))
                 (is-same bridge "at the threshold B stays put" (with-push threshold) 0))))))))))

;;; Explanations

(test model-equations-are-explained-by-their-components
  "Every equation of the wedge's first model is explained (AMES.ENGINE:EXPLAIN) by a
justification that names a component contributing it."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "particle-on-wedge")))
      (call-with-first-state-model
       scenario bridge
       (lambda (run solution)
         (declare (ignore solution))
         (let* ((model (ames.simulator::run-model run))
                (instances (ames.engine:model-active-instances model))
                (equations (ames.engine:model-equations model)))
           (is (< 10 (length equations)))
           (dolist (equation equations)
             (let ((components (loop for instance in instances
                                     when (member equation (ames.engine:instance-equations instance)
                                                  :test #'equal)
                                       collect (ames.engine:component-name
                                                (ames.engine:instance-component instance))))
                   (text (with-output-to-string (stream)
                           (ames.engine:explain model equation stream))))
               (is (consp components) "no instance contributes ~S" equation)
               (is (some (lambda (component)
                           (search (symbol-name component) text :test #'char-equal))
                         components)
                   "the explanation of ~S names none of ~S:~%~A" equation components text)))
           ;; one by name: Newton's second law for the particle
           (let* ((particle (body-symbol scenario "PARTICLE"))
                  (newton (find-if (lambda (equation)
                                     (equal (third equation)
                                            `(* ,(ames:scenario-body-mass
                                                  (ames:find-scenario-body particle scenario))
                                                (ames.kb:acc ,particle :y))))
                                   equations)))
             (is (not (null newton)))
             (when newton
               (is (search "NEWTONS-SECOND-LAW"
                           (with-output-to-string (stream)
                             (ames.engine:explain model newton stream))
                           :test #'char-equal))))))))))

;;; Parameter values

(test parameter-values-must-name-parameters
  "A numeric value for a name that is not a parameter of the scenario is a scenario
error naming it."
  (with-fixture simulator-bridge ()
    (let ((scenario (scenario-named "projectile-off-table")))
      (handler-case (progn (ames::simulate scenario :bridge bridge :parameter-values '((zork . 1)))
                           (fail "a value for ZORK was accepted"))
        (ames:undeclared-symbol-error (condition)
          (is (same-name-p* (ames-error-datum condition) "ZORK"))
          (is (search "ZORK" (princ-to-string condition))))))))
