;;;; src/witness/generate.lisp -- random valid scenarios, by family, for the crosscheck.
;;;;
;;;; Each family writes a scenario's text: its lengths, speeds, masses and g are parameters
;;;; (:positive) with random exact (:value N) defaults, so that a run with --numeric goes
;;;; through AMES's closed forms and then its numbers. Every family is built so that its
;;;; assumptions hold (bodies apart, particles on faces, restitution in [0, 1]), and only
;;;; with what the witness models (translating points and polygons, fixed polygons and
;;;; half-planes, gravity, constant forces, Newton restitution).

(in-package #:ames.witness)

(defvar *random* (make-random-state t) "The random state of the generator; bind it (SB-EXT:SEED-RANDOM-STATE) to repeat a run.")

(defun random-ratio (low high &optional (denominator 4))
  "A random rational in [LOW, HIGH] with DENOMINATOR."
  (let ((a (ceiling (* low denominator))) (b (floor (* high denominator))))
    (/ (+ a (random (1+ (- b a)) *random*)) denominator)))

(defun pick (&rest choices) (nth (random (length choices) *random*) choices))

(defun restitution-choice () (pick 0 1/2 1))

(defun parameters-text (&rest names-and-values)
  "The parameters clause: each name :positive with its value."
  (format nil "(parameters ~{(~(~A~) :positive (:value ~A))~^ ~})" names-and-values))

(defun scenario-text (name description parameters clauses states)
  (format nil "(scenario ~(~A~)~%  ~S~%  ~A~%  (gravity g)~%~{  ~A~%~}  (simulate :states ~D))~%"
          name description parameters clauses states))

(defun floor-text () "(body floor :fixed t :shape (half-plane (1 0) (0 0)))")

(defun family-table (name)
  "A particle slides across a table top, off its edge, and lands on the floor."
  (let ((e (restitution-choice)))
    (scenario-text name "A particle slides off a table onto the floor."
                   (parameters-text 'g (random-ratio 5 15) 'w (random-ratio 1 4)
                                    'h (random-ratio 1/2 3) 'v (random-ratio 1/2 5))
                   (list (format nil "(restitution ~A)" e) (floor-text)
                         "(body table :fixed t :shape (polygon (0 0) (w 0) (w h) (0 h)))"
                         "(body particle :mass 1 :position ((/ w 2) h) :velocity (v 0) :shape point)")
                   (if (= e 1/2) 4 3))))

(defun family-ramp (name)
  "A particle starts at rest halfway down a fixed ramp standing on the floor."
  (let ((e (restitution-choice)))
    (scenario-text name "A particle slides down a ramp onto the floor."
                   (parameters-text 'g (random-ratio 5 15) 'l (random-ratio 1 4) 'hh (random-ratio 1/2 3))
                   (list (format nil "(restitution ~A)" e) (floor-text)
                         "(body ramp :fixed t :shape (polygon (0 0) (l 0) (0 hh)))"
                         "(body particle :mass 1 :position ((/ l 2) (/ hh 2)) :velocity (0 0) :shape point)")
                   3)))

(defun family-raised-ramp (name)
  "A particle slides down a ramp whose foot is raised above the floor, off its end."
  (let ((e (restitution-choice)))
    (scenario-text name "A particle slides off a raised ramp and falls to the floor."
                   (parameters-text 'g (random-ratio 5 15) 'l (random-ratio 1 4)
                                    'h0 (random-ratio 1/2 3) 'rise (random-ratio 1/4 3))
                   (list (format nil "(restitution ~A)" e) (floor-text)
                         "(body ramp :fixed t :shape (polygon (0 0) (l 0) (l h0) (0 (+ h0 rise))))"
                         "(body particle :mass 1 :position ((/ l 2) (+ h0 (/ rise 2))) :velocity (0 0) :shape point)")
                   3)))

(defun family-step (name)
  "A particle thrown horizontally toward a step on the floor."
  (let ((e (restitution-choice)))
    (scenario-text name "A particle thrown toward a step on the floor."
                   (parameters-text 'g (random-ratio 5 15) 'a (random-ratio 1/2 3) 'w (random-ratio 1/2 3)
                                    's (random-ratio 1/4 2) 'h (random-ratio 1/2 4) 'v (random-ratio 1/2 6))
                   (list (format nil "(restitution ~A)" e) (floor-text)
                         "(body step :fixed t :shape (polygon (a 0) ((+ a w) 0) ((+ a w) s) (a s)))"
                         "(body particle :mass 1 :position (0 (+ s h)) :velocity (v 0) :shape point)")
                   3)))

(defun family-projectile (name)
  "A particle launched from the floor under gravity and a constant horizontal force."
  (let ((e (pick 0 1)))
    (scenario-text name "A particle launched under gravity and a constant push lands on the floor."
                   (parameters-text 'g (random-ratio 5 15) 'vx (random-ratio 1/4 4) 'vy (random-ratio 1/2 6)
                                    'f (random-ratio 1/4 3) 'm (random-ratio 1/2 3))
                   (list (format nil "(restitution ~A)" e) (floor-text)
                         "(body particle :mass m :position (0 0) :velocity (vx vy) :shape point)"
                         "(force push :on particle :value (f 0))")
                   (if (= e 0) 2 3))))

(defun family-bounce (name)
  "A ball dropped on the floor (with 0 < e < 1 the bounces accumulate)."
  (let ((e (pick 0 1/4 1/2 3/4 1)))
    (scenario-text name "A ball dropped on the floor bounces."
                   (parameters-text 'g (random-ratio 5 15) 'h (random-ratio 1/4 4) 'm (random-ratio 1/2 3))
                   (list (format nil "(restitution ~A)" e) (floor-text)
                         "(body ball :mass m :position (0 h) :velocity (0 0) :shape point)")
                   (if (member e '(0 1)) 2 4))))

(defun family-chain (name)
  "Two to four blocks on a frictionless floor, the first sliding into the others."
  (let* ((count (pick 2 3 4)) (e (restitution-choice))
         (parameters (list 'g (random-ratio 5 15) 'v (random-ratio 1/2 4)))
         (clauses (list (format nil "(restitution ~A)" e) (floor-text)))
         (x 0))
    (dotimes (k count)
      (let ((mass (random-ratio 1/2 3)) (width (random-ratio 1/2 2)) (gap (random-ratio 1/4 2)))
        (setf parameters (append parameters (list (format nil "m~D" k) mass)))
        (push (format nil "(body block~D :mass m~D :position (~A 0) :velocity (~A 0) :shape (polygon (0 0) (~A 0) (~A 1) (0 1)))"
                      k k x (if (zerop k) "v" 0) width width)
              clauses)
        (setf x (+ x width gap))))
    (scenario-text name "A chain of blocks on a frictionless floor."
                   (apply #'parameters-text parameters) (reverse clauses) (+ count 2))))

(defun family-wedge (name)
  "A particle slides down a free wedge resting on a frictionless floor."
  (let ((e (restitution-choice)))
    (scenario-text name "A particle slides down a movable wedge on a frictionless floor."
                   (parameters-text 'g (random-ratio 5 15) 'mw (random-ratio 1/2 4) 'mp (random-ratio 1/4 2)
                                    'b (random-ratio 1 3) 'hh (random-ratio 1/2 3))
                   (list (format nil "(restitution ~A)" e) (floor-text)
                         "(body wedge :mass mw :position (0 0) :velocity (0 0) :shape (polygon (0 0) (b 0) (0 hh)))"
                         "(body particle :mass mp :position ((/ b 2) (/ hh 2)) :velocity (0 0) :shape point)")
                   3)))

(defun terrain-piece (name a)
  "A random fixed convex piece of terrain named NAME standing on the floor from x = A:
a step, a wedge rising either way, or a trapezoid; returns its clause and its width."
  (let ((w (random-ratio 1/2 3)) (h (random-ratio 1/4 2)) (h2 (random-ratio 1/4 2)))
    (values (format nil "(body ~A :fixed t :shape (polygon ~{(~A ~A)~^ ~}))" name
                    (ecase (pick :step :up :down :trapezoid)
                      (:step (list a 0 (+ a w) 0 (+ a w) h a h))
                      (:up (list a 0 (+ a w) 0 (+ a w) h))
                      (:down (list a 0 (+ a w) 0 a h))
                      (:trapezoid (list a 0 (+ a w) 0 (+ a w) h a h2))))
            w)))

(defun family-terrain (name)
  "A particle thrown over random polygonal terrain (one to three steps, wedges and
trapezoids on the floor), Newton restitution 0, 1/2 or 1."
  (let ((clauses (list (format nil "(restitution ~A)" (restitution-choice)) (floor-text)))
        (x (random-ratio 1/2 2)))
    (dotimes (k (pick 1 2 3))
      (multiple-value-bind (clause width) (terrain-piece (format nil "piece~D" k) x)
        (push clause clauses)
        (setf x (+ x width (random-ratio 1/4 2)))))
    (push (format nil "(body particle :mass 1 :position (0 ~A) :velocity (~A ~A) :shape point)"
                  (random-ratio 5/2 5) (random-ratio 1/4 4) (random-ratio -2 3))
          clauses)
    (scenario-text name "A particle thrown over polygonal terrain."
                   (parameters-text 'g (random-ratio 5 15)) (reverse clauses) 4)))

(defun family-spring (name)
  "Two blocks joined by a spring on a frictionless floor (oscillating forever), and, one
time in four, a third block ahead that the pair may hit (restitution 0, 1/2 or 1)."
  (let* ((w1 (random-ratio 1/2 1)) (gap (random-ratio 1/2 2)) (x2 (+ w1 gap))
         (w2 (random-ratio 1/2 1)) (x3 (+ x2 w2 (random-ratio 1/2 3))))
    (scenario-text name "Two blocks on a spring slide toward a third."
                   (parameters-text 'g (random-ratio 5 15) 'm1 (random-ratio 1/2 3) 'm2 (random-ratio 1/2 3)
                                    'm3 (random-ratio 1/2 3) 'k (random-ratio 1 20)
                                    'v1 (random-ratio 0 3) 'v2 (random-ratio 1/4 3))
                   (list (format nil "(restitution ~A)" (restitution-choice)) (floor-text)
                         (format nil "(body first :mass m1 :position (0 0) :velocity (v1 0) :shape (polygon (0 0) (~A 0) (~A 1/2) (0 1/2)))" w1 w1)
                         (format nil "(body second :mass m2 :position (~A 0) :velocity (v2 0) :shape (polygon (0 0) (~A 0) (~A 1/2) (0 1/2)))" x2 w2 w2)
                         ;; a third block only sometimes: AMES cannot order the roots of
                         ;; the oscillation's equations and stops (refused), mostly
                         (if (zerop (random 4 *random*))
                             (format nil "(body third :mass m3 :position (~A 0) :velocity (0 0) :shape (polygon (0 0) (1/2 0) (1/2 1/2) (0 1/2)))" x3)
                             "")
                         (format nil "(spring coupling :from (first (~A 1/4)) :to (second (0 1/4)) :stiffness k~@[ :rest-length ~A~])"
                                 w1 (pick nil (random-ratio 1/4 3))))
                   3)))

(defun family-atwood (name)
  "An Atwood machine: two masses over two pulleys on a support, the heavier above the floor."
  (let* ((h (random-ratio 1/2 3)) (r (random-ratio 1/10 1/2)) (top (+ (* 2 h) (random-ratio 1/2 3))))
    (scenario-text name "An Atwood machine: the heavier mass falls to the floor."
                   (parameters-text 'g (random-ratio 5 15) 'm1 (random-ratio 2 4) 'm2 (random-ratio 1/2 19/10))
                   (list (format nil "(restitution ~A)" (restitution-choice)) (floor-text)
                         (format nil "(body support :fixed t :position (0 ~A) :shape point)" top)
                         (format nil "(body heavy :mass m1 :position (~A ~A) :velocity (0 0) :shape point)" (- r) h)
                         (format nil "(body light :mass m2 :position (~A 0) :velocity (0 0) :shape point)" r)
                         (format nil "(pulley left-wheel :on support :at (~A 0))" (- r))
                         (format nil "(pulley right-wheel :on support :at (~A 0))" r)
                         (format nil "(rope rope :length ~A :through ((heavy (0 0)) left-wheel right-wheel (light (0 0))))"
                                 (+ (- top h) (* 2 r) top)))
                   3)))

(defun family-incline-pulley (name)
  "A particle on a fixed incline (a Pythagorean triangle, so that lengths stay rational)
tied over a pulley on the slope's line, beyond its top, to a mass hanging below it."
  (destructuring-bind (a b c) (pick '(4 3 5) '(3 4 5) '(12 5 13) '(8 15 17))
    (let* ((scale (random-ratio 1/4 1)) (l (* a scale)) (hh (* b scale))
           (beyond (+ 1 (random-ratio 1/20 1/4))) (f (random-ratio 1/4 3/4))
           (hang (random-ratio 1/2 2)))
      (scenario-text name "A particle on an incline pulled over a pulley by a hanging mass."
                     (parameters-text 'g (random-ratio 5 15) 'm1 (random-ratio 1/2 3) 'm2 (random-ratio 1/2 3))
                     (list (format nil "(body incline :fixed t :shape (polygon (0 0) (~A 0) (~A ~A)))" l l hh)
                           (format nil "(body particle :mass m1 :position (~A ~A) :velocity (0 0) :shape point)"
                                   (* f l) (* f hh))
                           (format nil "(pulley top :on incline :at (~A ~A))" (* beyond l) (* beyond hh))
                           (format nil "(body weight :mass m2 :position (~A ~A) :velocity (0 0) :shape point)"
                                   (* beyond l) (- (* beyond hh) hang))
                           (format nil "(rope line :length ~A :through ((particle (0 0)) top (weight (0 0))))"
                                   (+ (* (- beyond f) c scale) hang)))
                     2))))

(defun family-rough-floor (name)
  "A block sliding on a rough floor (Coulomb friction, one coefficient), sometimes toward
a wall it may reach (restitution 0, 1/2 or 1)."
  (let ((wall (zerop (random 2 *random*))))
    (scenario-text name "A block slides on a rough floor."
                   (parameters-text 'g (random-ratio 5 15) 'm (random-ratio 1/2 3)
                                    'v (random-ratio 1/2 6) 'mu (random-ratio 1/10 1 20))
                   (remove nil
                           (list (format nil "(restitution ~A)" (restitution-choice)) (floor-text)
                                 (and wall (format nil "(body wall :fixed t :shape (polygon (~A 0) (~A 0) (~A 2) (~A 2)))"
                                                   (let ((x (random-ratio 3/2 4))) (setf wall x))
                                                   (+ wall 1) (+ wall 1) wall))
                                 "(body block :mass m :position (0 0) :velocity (v 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))"
                                 "(friction block floor :static mu)"))
                   3)))

(defun family-rough-incline (name)
  "A particle on a rough fixed incline (a Pythagorean triangle), launched up it or left at
rest: it sticks, slides down, or stops and then sticks or slides back."
  (destructuring-bind (a b) (pick '(4 3) '(3 4) '(12 5) '(8 15) '(15 8))
    (let* ((scale (random-ratio 1/2 1)) (l (* a scale)) (hh (* b scale)) (f (random-ratio 1/4 1/2)))
      ;; the slope descends toward +x from (0 hh) to (l 0); up the slope is (-a, b)
      (scenario-text name "A particle on a rough incline."
                     (parameters-text 'g (random-ratio 5 15) 'mu (random-ratio 1/10 1 20)
                                      'v (random-ratio 1/4 3))
                     (list (format nil "(body incline :fixed t :shape (polygon (0 0) (~A 0) (0 ~A)))" l hh)
                           (format nil "(body particle :mass 1 :position (~A ~A) :velocity ~A :shape point)"
                                   (* (- 1 f) l) (* f hh)
                                   (if (zerop (random 3 *random*))
                                       "(0 0)"
                                       (format nil "((* -~A v) (* ~A v))" (/ a (isqrt (+ (* a a) (* b b))))
                                               (/ b (isqrt (+ (* a a) (* b b)))))))
                           "(friction particle incline :static mu)")
                     3))))

(defparameter *families*
  '((:table . family-table) (:ramp . family-ramp) (:raised-ramp . family-raised-ramp)
    (:step . family-step) (:projectile . family-projectile) (:bounce . family-bounce)
    (:chain . family-chain) (:wedge . family-wedge) (:terrain . family-terrain)
    (:spring . family-spring) (:atwood . family-atwood) (:incline-pulley . family-incline-pulley)
    (:rough-floor . family-rough-floor) (:rough-incline . family-rough-incline))
  "The families of random scenarios: (KEYWORD . FUNCTION of the scenario's name).")

(defun generator-families () (mapcar #'car *families*))

(defvar *symbolic* nil
  "When true, random scenarios keep their parameters (with (:value N) defaults, run with
--numeric: AMES goes through closed forms in the parameters, which is slow); when false,
the values are written into the scenario as exact numbers.")

(defun substitute-values (text)
  "TEXT (a scenario written by a family) with every parameter replaced by its value and
the parameters clause dropped."
  (let* ((form (let ((*package* (find-package '#:ames-scenario)) (*read-eval* nil))
                 (read-from-string text)))
         (parameters (find-if (lambda (clause) (and (consp clause)
                                                    (string-equal (symbol-name (first clause)) "PARAMETERS")))
                              form))
         (bindings (loop for (name nil (nil value)) in (rest parameters) collect (cons name value))))
    (let ((*package* (find-package '#:ames-scenario)) (*print-case* :downcase)
          (*print-pretty* t) (*print-right-margin* 100))
      (format nil "~S~%" (sublis bindings (remove parameters form))))))

(defun random-scenario (family index)
  "The text of a random scenario of FAMILY (a key of *FAMILIES*), named after it and INDEX;
its values as exact numbers unless *SYMBOLIC*."
  (let ((function (cdr (assoc family *families*))))
    (unless function (error "no family ~S" family))
    (let ((text (funcall function (format nil "~(~A~)-~D" family index))))
      (if *symbolic* text (substitute-values text)))))

(defun write-disagreement (directory name text result)
  "Write the scenario TEXT and both results (RESULT, a plist of WITNESS-CHECK) under
DIRECTORY as NAME.lisp: the scenario first, then AMES's and the witness's answers and
the verdict as comments, so that the file can become a regression test."
  (let ((path (merge-pathnames (format nil "~A.lisp" name) directory)))
    (ensure-directories-exist path)
    (with-open-file (out path :direction :output :if-exists :supersede)
      (with-standard-io-syntax
        (let ((*print-readably* nil) (*print-right-margin* 100) (*print-pretty* t))
          ;; every line of the reason (printed pretty, it may have several) a comment
          (format out ";;;; ~A -- a disagreement found by the witness (make crosscheck).~%;;;; verdict: ~(~A~)~%;;;; reason: ~{~A~^~%;;;;   ~}~%;;;; Run: bin/ames check ~A --numeric~%~%~A~%"
                  name (getf result :verdict)
                  (with-input-from-string (lines (format nil "~A" (getf result :reason)))
                    (loop for line = (read-line lines nil) while line collect line))
                  path text)
          (dolist (part (list (cons "AMES's answer" (getf result :answer))
                              (cons "witness's answer" (getf result :witness))))
            (format out "~%;; ~A:~%" (car part))
            (with-input-from-string (lines (prin1-to-string (cdr part)))
              (loop for line = (read-line lines nil) while line
                    do (format out ";;   ~A~%" line)))))))
    path))
