;;;; t/witness-crosscheck.lisp -- the machinery of make crosscheck: the warm witness server
;;;; (src/witness/server.lisp), the shard's records and their resumption after a Lisp that
;;;; died (src/interface/crosscheck.lisp), the comparator's values of closed forms with
;;;; complex intermediates (src/witness/complex-values.lisp), drag in the witness, and the
;;;; angles compared per state (src/witness/compare-angles.lisp).

(in-package #:ames.tests)

(def-suite witness-crosscheck :in all-tests
  :description "make crosscheck's machinery: the warm witness, records, complex values, drag, angles.")

(in-suite witness-crosscheck)

(defparameter *warm-witness-drop*
  "(scenario drop \"\" (parameters (g :positive (:value 981/100)) (h :positive (:value 1)))
     (gravity g) (restitution 1/2) (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body ball :mass 1 :position (0 h) :velocity (0 0) :shape point) (simulate :states 2))"
  "A ball dropped from 1 m: it lands at sqrt(2 h / g) = 0.4515236409857309 s.")

(defun dropped-ball-model (horizon)
  (let* ((scenario (witness-scenario *warm-witness-drop*))
         (values (ames.scenario:run-parameter-values scenario :numeric t)))
    (ames.witness:scenario-model scenario values horizon)))

(test warm-witness-answers-as-a-new-python-and-survives-a-timeout
  "The warm server's answer is the one-off driver's (the first impact at sqrt(2 h / g));
a model that overruns its time limit is an error, and the next model gets a new server."
  (with-siconos
    (let ((cold (ames.witness:run-witness (dropped-ball-model 1/2))))
      (ames.witness:with-witness-server ()
        (let ((warm (ames.witness:run-witness (dropped-ball-model 1/2))))
          (is (eq :ok (ames.witness:witness-status warm)))
          (is (near (sqrt (/ 2 9.81d0)) (first (event-times warm)) 1d-11))
          (is (equal (event-times cold) (event-times warm))))
        (let ((late (ames.witness:run-witness (dropped-ball-model 200) :timeout 1/1000)))
          (is (eq :error (ames.witness:witness-status late)))
          (is (search "no answer" (getf late :message))))
        (let ((again (ames.witness:run-witness (dropped-ball-model 1/2))))
          (is (eq :ok (ames.witness:witness-status again)))
          (is (near (sqrt (/ 2 9.81d0)) (first (event-times again)) 1d-11)))))))

(test a-shard-resumes-after-a-lisp-that-died
  "A records file with a scenario started and never finished (its Lisp died) gives that
scenario a crash record, written to the file and as a disagreement; the counts follow the
records."
  (uiop:with-temporary-file (:pathname path :type "sexp")
    (let ((directory (uiop:ensure-directory-pathname
                      (merge-pathnames (format nil "ames-crosscheck-~D/" (random 1000000))
                                       (uiop:default-temporary-directory)))))
      (ames::append-crosscheck-record path '(:index 0 :family :bounce :verdict :agree :seconds 1d0 :witness-seconds 0d0))
      (ames::append-crosscheck-record path '(:started 2 :family :bounce))
      (let* ((*package* (find-package '#:ames-scenario))
             (records (ames::resumed-records path 7 directory))
             (crash (find 2 records :key (lambda (r) (getf r :index)))))
        (is (= 2 (length records)))
        (is (eq :crash (getf crash :verdict)))
        (is (find 2 (ames::read-crosscheck-records path) :key (lambda (f) (getf f :index))))
        (is (probe-file (merge-pathnames "crash-bounce-7-2.lisp" directory)))
        (is (equal '((:bounce (:agree . 1) (:crash . 1))) (ames::crosscheck-counts records))))
      (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore))))

(test closed-forms-through-complex-numbers-have-their-real-values
  "sqrt(-d) sinh(sqrt(-d) u) = -sqrt(d) sin(sqrt(d) u) and cosh(sqrt(-d) u) = cos(sqrt(d)
u), as AMES may write a spring's motion; a value that is not real has none."
  (flet ((value (form) (ames.witness::number-of form '((d . 3) (u . 7/10)))))
    (is (near (- (* (sqrt 3d0) (sin (* (sqrt 3d0) 0.7d0))))
              (value '(* (sqrt (- d)) (sinh (* (sqrt (- d)) u)))) 1d-12))
    (is (near (cos (* (sqrt 3d0) 0.7d0)) (value '(cosh (* (sqrt (- d)) u))) 1d-12))
    (is (null (value '(sqrt (- d)))))))

(test witness-linear-drag-falls-as-the-textbook
  "A ball dropped from h through a viscous medium (m v' = -m g - b v) reaches, at t, the
height h - (m g / b) t + (m^2 g / b^2)(1 - exp(-b t / m)) and the velocity -(m g / b)(1 -
exp(-b t / m)): the witness's end state at its horizon."
  (with-siconos
    (let* ((answer (witness-run "(scenario f \"\" (gravity 981/100)
                                   (body ball :mass 2 :position (0 100) :velocity (0 0) :shape point)
                                   (drag air :on ball :linear 1/2) (simulate :states 1))" 3))
           (end (ames.witness:witness-end answer))
           (m 2d0) (g 9.81d0) (b 0.5d0) (time (getf end :time)))
      (is (eq :ok (ames.witness:witness-status answer)))
      (is (near (+ 100 (- (* (/ (* m g) b) time)) (* (/ (* m m g) (* b b)) (- 1 (exp (- (/ (* b time) m))))))
                (second (second (assoc "ball" (getf end :positions) :test #'string=))) 1d-8))
      (is (near (- (* (/ (* m g) b) (- 1 (exp (- (/ (* b time) m))))))
                (second (second (assoc "ball" (getf end :velocities) :test #'string=))) 1d-8)))))

(test angles-are-compared-per-state
  "A rotating body's final angle and angular velocity are set beside the witness's: equal,
the state agrees; an angular velocity off by 1 %, AMES is wrong."
  (flet ((verdict (omega)
           (let* ((ames `(:states ((:index 0 :start 0 :duration 1 :end-event (:collision disc floor)
                                    :final-positions ((disc (1 0))) :final-velocities ((disc (2 0)))
                                    :final-angles ((disc -3)) :final-angular-velocities ((disc ,omega))))))
                  (witness '(:status :ok :events ((:time 1d0 :pairs ((:collision "disc" "floor"))
                                                   :positions (("disc" (1d0 0d0))) :velocities (("disc" (2d0 0d0)))
                                                   :angles (("disc" -3d0)) :angular-velocities (("disc" -6d0))))
                             :end (:time 1d0))))
             (ames.witness:comparison-verdict (ames.witness:compare-results ames witness '() :t-end 1)))))
    (is (eq :agree (verdict -6)))
    (is (eq :ames-wrong (verdict -606/100)))))

(test first-order-events-at-one-instant-are-one
  "Moreau-Jean (step h) may report a disc's impact on the floor and its lift-off from the
slope a step apart, the lift-off first with the state after the impact: they are one
event, compared with the state before the impact, to 20 h."
  (flet ((verdict (witness-vx)
           (let* ((ames '(:states ((:index 0 :start 0 :duration 1 :end-event (:collision disc floor)
                                    :final-positions ((disc (2 1/5))) :final-velocities ((disc (7 -14)))))))
                  (witness `(:status :ok :scheme :moreau-jean :step 1d-3
                             :events ((:time 1.0005d0 :pairs ((:lift-off "disc" "incline"))
                                       :positions (("disc" (2d0 0.2d0))) :velocities (("disc" (6.2d0 0d0))))
                                      (:time 1.0015d0 :pairs ((:collision "disc" "floor"))
                                       :positions (("disc" (2d0 0.195d0))) :velocities (("disc" (,witness-vx -14d0)))))
                             :end (:time 1.1d0))))
             (ames.witness:comparison-verdict (ames.witness:compare-results ames witness '() :t-end 1)))))
    (is (eq :agree (verdict 7.01d0)))
    (is (eq :ames-wrong (verdict 7.5d0)))))

(test rotation-witness-mixes-rough-and-smooth-contacts
  "A disc rolling down a rough incline (3-4-5, mu above tan(a)/3) onto a smooth floor: the
witness's Coulomb problem takes the floor as a contact with mu = 0 (Siconos failed with
an std::exception on the mixed laws); the disc reaches the floor in the corner rolling,
its speed there sqrt(4 g sin(a) d / 3) after rolling a distance d from rest (sin a = 3/5)."
  (with-siconos
    (let* ((answer (witness-run "(scenario c \"\" (gravity 10)
                                   (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                                   (body incline :fixed t :shape (polygon (0 0) (4 0) (0 3)))
                                   (body disc :mass 1 :inertia :uniform :shape (circle 1/10)
                                         :position (103/50 79/50) :velocity (0 0))
                                   (friction disc incline :static 1/2) (simulate :states 2))" 3/2))
           (impact (find-if (lambda (e) (assoc :collision (getf e :pairs)))
                            (ames.witness:witness-events answer))))
      (is (eq :ok (ames.witness:witness-status answer)) "~S" (getf answer :message))
      (is (not (null impact)))
      (when impact
        ;; the centre r = 1/10 off the slope's point (2, 3/2), down the slope to the
        ;; corner's (4 + 1/30, 1/10): d = (79/50 - 1/10) / (3/5) = 37/15
        (let ((v (second (assoc "disc" (getf impact :velocities) :test #'string=))))
          (is (near (sqrt (/ (* 4 10 3/5 37/15) 3d0)) (sqrt (+ (expt (first v) 2) (expt (second v) 2))) 5d-3)))))))
