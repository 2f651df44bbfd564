;;;; t/witness-hinged.lisp -- the witness's families of bodies turning on hinges, against
;;;; corners and on wound ropes (src/witness/generate-hinged.lisp), their comparison
;;;; (turning points of a periodic swing, a state ended by the scenario's time limit:
;;;; src/witness/compare-time-limit.lisp), and the exact zero of a constant with sines and
;;;; cosines of rational multiples of pi (src/algebra/constant-zero.lisp), which a ladder
;;;; at 51 degrees needed to touch its floor and wall. The witness's tests are skipped,
;;;; with a message, when /usr/bin/python3 cannot import Siconos.

(in-package #:ames.tests)

(def-suite witness-hinged :in all-tests
  :description "Witness families with hinges, corners and wound ropes; octant reduction of trig constants.")

(in-suite witness-hinged)

(test first-octant-trigonometry-keeps-values
  "sin, cos and tan of q pi (q from -3 to 3 in steps of 1/60) rewritten with the sine or
cosine of an angle in [0, pi/4] keep their values (to 1e-12)."
  (loop for k from -180 to 180
        for q = (/ k 60)
        do (dolist (function '(sin cos tan))
             (let* ((form `(,function (* ,q pi)))
                    (rewritten (ames.algebra::first-octant-trigonometry form))
                    (before (ames.base:expression-value form '()))
                    (after (ames.base:expression-value rewritten '())))
               (unless (and (eq function 'tan) (zerop (mod (- q 1/2) 1)))
                 (is (and before after (< (abs (- before after)) (* 1d-12 (max 1 (abs before)))))
                     "~S: ~S gives ~S, ~S ~S" form rewritten after function before))))))

(test trig-constants-of-pi-multiples-decided-zero
  "cos(17 pi/60) + cos(43 pi/60) = 0, sin(43 pi/60) = cos(13 pi/60), tan(43 pi/60) = -tan(17 pi/60), which Maxima
does not see (it keeps cos(43 pi/60)): a ladder at 51 degrees has its ends exactly on the
floor and the wall. A constant that is not 0 stays undecided or false."
  (call-with-bridge
   (lambda (b)
     (is (eq :true (ames.algebra:decide b '(= (+ (* 7/8 (cos (/ (* 17 pi) 60))) (* 7/8 (cos (/ (* 43 pi) 60)))) 0))))
     (is (eq :true (ames.algebra:decide b '(= (sin (/ (* 43 pi) 60)) (cos (/ (* 13 pi) 60))))))
     (is (eq :true (ames.algebra:decide b '(= (tan (/ (* 43 pi) 60)) (- (tan (/ (* 17 pi) 60)))))))
     (is (not (eq :true (ames.algebra:decide b '(= (+ (cos (/ (* 17 pi) 60)) (cos (/ (* 41 pi) 60))) 0)))))))) 

(defun hinged-family-check (family index)
  "WITNESS-CHECK's result for the INDEXth random scenario of FAMILY with seed 21, its rows'
names."
  (let* ((*package* (find-package '#:ames-scenario))
         (text (ames::crosscheck-scenario-text family 21 index))
         (result (ames::witness-check (first (ames.scenario:read-scenarios-from-string text)) :numeric t)))
    (values result
            (mapcar #'second (and (getf result :comparison)
                                  (ames.witness:comparison-rows (getf result :comparison))))
            text)))

(defun rows-named (rows prefix)
  (count-if (lambda (name) (and (stringp name) (eql 0 (search prefix name)))) rows))

(test witness-hinged-swing-turns-at-half-periods
  "A random body hinged at a point and swinging (seed 21): AMES's one periodic state, and
the witness's first two turning points at P/2 and P, its samples on AMES's path."
  (with-siconos
    (multiple-value-bind (result rows text) (hinged-family-check :hinged-swing 0)
      (is (eq :agree (getf result :verdict)) "~A~%~A" text (getf result :reason))
      (is (= 2 (rows-named rows "turning point")))
      (is (plusp (rows-named rows "path x"))))))

(test witness-ladder-leaves-wall-or-stays
  "Random ladders (seed 21): on a smooth floor it leaves the wall ((:lift-off ladder
wall), the end event compared), on a rough one it stays (its values at the witness's end
compared)."
  (with-siconos
    (loop for index below 3
          do (multiple-value-bind (result rows text) (hinged-family-check :ladder index)
               (is (eq :agree (getf result :verdict)) "~A~%~A" text (getf result :reason))
               (is (= 1 (+ (rows-named rows "end event") (rows-named rows "angle at the witness's end"))))))))

(test witness-yoyo-until-its-time-limit
  "A random yo-yo (seed 21) falls until the scenario's time limit: AMES's end values
beside the witness's at that time; AMES's final speed made 10 % faster is AMES wrong."
  (with-siconos
    (multiple-value-bind (result rows text) (hinged-family-check :yoyo 0)
      (is (eq :agree (getf result :verdict)) "~A~%~A" text (getf result :reason))
      (is (= 1 (rows-named rows "end time (time limit)")))
      (let* ((answer (copy-tree (getf result :answer)))
             (state (first (getf answer :states))))
        ;; the yo-yo's final velocity 10 % faster, in its closed form and its number (if any)
        (dolist (entries (list (getf state :final-velocities)
                               (getf (getf state :numeric) :final-velocities)))
          (let ((velocity (second (find "yoyo" entries :key (lambda (e) (symbol-name (first e)))
                                                       :test #'string-equal))))
            (when velocity
              (setf (second velocity) `(* 11/10 ,(second velocity))))))
        (when (getf state :numeric) (setf (getf state :numeric) nil))
        (is (eq :ames-wrong (ames.witness:comparison-verdict
                             (ames.witness:compare-results
                              answer (getf result :witness)
                              (ames.scenario:run-parameter-values
                               (let ((*package* (find-package '#:ames-scenario)))
                                 (first (ames.scenario:read-scenarios-from-string text)))
                               :numeric t)))))))))

(test witness-wound-atwood-lands
  "A random Atwood machine over a massive pulley (seed 21): the heavier weight lands
((:collision WEIGHT floor)) at AMES's time, the pulley's angle and spin compared."
  (with-siconos
    (multiple-value-bind (result rows text) (hinged-family-check :wound-atwood 0)
      (is (eq :agree (getf result :verdict)) "~A~%~A" text (getf result :reason))
      (is (= 1 (rows-named rows "end event")))
      (is (= 1 (rows-named rows "final angular velocity pulley"))))))

(test quadratic-drag-slide-never-turns
  "A block sliding alone under quadratic drag -c |v| v (witness/disagreements/
refused-drag-slide-quadratic.lisp, once refused: abs(9 + 2 tau) > 0 undecided) slides
forever at v = v0 / (1 + c v0 tau / m) (m dv/dt = -c v^2), here 9 / (9 + 2 tau)."
  (let* ((scenario (first (ames:read-scenario-file
                           (asdf:system-relative-pathname
                            "ames" "witness/disagreements/refused-drag-slide-quadratic.lisp"))))
         (answer (ames::ames-answer scenario))
         (state (first (getf answer :states)))
         (velocity (second (find "block" (getf state :velocities)
                                 :key (lambda (e) (symbol-name (first e))) :test #'string-equal))))
    (is (eq :none (getf state :end-event)))
    (dolist (time '(0 1/3 1 7/2 20))
      (is (< (abs (- (ames.base:expression-value (first velocity) (list (cons 'ames.base:tau time)))
                     (/ 9 (+ 9 (* 2 time)))))
             1d-12)))))

(defparameter *spring-pulls-apart*
  "(scenario spring-pull \"\" (gravity 9) (restitution 0)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body first :mass 1 :position (0 0) :velocity (0 0) :shape (polygon (0 0) (1/2 0) (1/2 1/2) (0 1/2)))
     (body second :mass 1 :position (2 0) :velocity (3 0) :shape (polygon (0 0) (1/2 0) (1/2 1/2) (0 1/2)))
     (body third :mass 1 :position (27/10 0) :velocity (0 0) :shape (polygon (0 0) (1/2 0) (1/2 1/2) (0 1/2)))
     (spring coupling :from (first (1/2 1/4)) :to (second (0 1/4)) :stiffness 4 :rest-length 1/2)
     (simulate :states 3))"
  "Second, held back by a stretched spring, hits third plastically; the spring pulls it
off third at once.")

(test witness-plastic-collision-a-spring-pulls-apart
  "A plastic collision that a spring pulls apart at once: the witness goes on (it stopped
with 'a contact opened without a nonsmooth event'), with the collision and no lift-off
(the contact never held), third then sliding at half second's speed before the impact."
  (with-siconos
    (let* ((scenario (witness-scenario *spring-pulls-apart*))
           (answer (ames.witness:run-witness
                    (ames.witness:scenario-model scenario (ames.scenario:run-parameter-values scenario :numeric t) 1/5)))
           (kinds (loop for event in (ames.witness:witness-events answer)
                        append (mapcar #'first (getf event :pairs))))
           (collision (first (ames.witness:witness-events answer))))
      (is (eq :ok (ames.witness:witness-status answer)) "~S" answer)
      (is (equal '(:collision) (remove-duplicates kinds)) "events ~S" kinds)
      (when collision
        (is (< (abs (- (/ (first (state-entry collision :velocities "second")) 2)
                       (first (state-entry (ames.witness:witness-end answer) :velocities "third"))))
               1d-9))))))
