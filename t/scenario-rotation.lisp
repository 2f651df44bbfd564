;;;; t/scenario-rotation.lisp -- the rotation section of the scenario language (issue 23):
;;;; inertia from the shape against textbook values (checked by Maxima equivalence), every
;;;; rotation key and clause validated with a condition naming the form at fault, the facts
;;;; the assumptions decide, the scenarios of scenarios/awaiting-rotation/, and the
;;;; simulator's refusal of a rotating body.

(in-package #:ames.tests)

(def-suite scenario-rotation :in all-tests
  :description "Rotation syntax: inertia, hinges, forces at points, wound ropes (issue 23).")

(in-suite scenario-rotation)

(defun rotating-scenario (&rest clauses)
  "A scenario with the parameters m, r, w, h, l, g (positive) and CLAUSES."
  `(scenario s (parameters (m :positive) (r :positive) (w :positive) (h :positive)
                           (l :positive) (g :positive))
             ,@clauses))

(defun rotating-body-inertia (form name)
  "The inertia of the body NAME in the scenario FORM."
  (ames.scenario:scenario-body-inertia (ames:find-scenario-body name (ames:parse-scenario form))))

(defun maxima-equivalent-p (bridge a b)
  "True when Maxima simplifies A - B to 0."
  (eql 0 (ames.maxima:simplify bridge `(- ,a ,b) :strategy :full)))

(test uniform-inertia-is-the-textbook-one
  "The :uniform and :ring inertias of a disc (m r^2/2), a hoop (m r^2), a w by h rectangle
(m (w^2 + h^2)/12), a rod of length l (m l^2/12) and a right triangle with legs w and h
about its centroid (m (w^2 + h^2)/18), and a numeric 2 by 1 rectangle (exactly 5 m/12)."
  (call-with-scenario-bridge
   (lambda (bridge)
     (flet ((check (shape kind expected)
              (let ((inertia (rotating-body-inertia (rotating-scenario `(body b :mass m :position (0 0) :velocity (0 0)
                                                                      :shape ,shape :inertia ,kind))
                                           'b)))
                (is (maxima-equivalent-p bridge inertia expected) "~S ~S gave ~S, not ~S" shape kind inertia expected))))
       (check '(circle r) :uniform '(/ (* m (expt r 2)) 2))
       (check '(circle r) :ring '(* m (expt r 2)))
       (check '(polygon ((- (/ w 2)) (- (/ h 2))) ((/ w 2) (- (/ h 2))) ((/ w 2) (/ h 2)) ((- (/ w 2)) (/ h 2)))
              :uniform '(/ (* m (+ (expt w 2) (expt h 2))) 12))
       (check '(segment ((- (/ l 2)) 0) ((/ l 2) 0)) :uniform '(/ (* m (expt l 2)) 12))
       (check '(polygon ((- (/ w 3)) (- (/ h 3))) ((* 2/3 w) (- (/ h 3))) ((- (/ w 3)) (* 2/3 h)))
              :uniform '(/ (* m (+ (expt w 2) (expt h 2))) 18))))
   )
  (is (equal '(* 5/12 m) (rotating-body-inertia (rotating-scenario '(body b :mass m :position (0 0) :velocity (0 0) :inertia :uniform
                                                               :shape (polygon (-1 -1/2) (1 -1/2) (1 1/2) (-1 1/2))))
                                       'b))))

(test rotation-keys-are-kept
  "A rotating body keeps its inertia, angle and angular velocity (0 by default); a force its
:at; a rope its wound ends; a hinge its body and point; a translating body has no inertia."
  (let* ((scenario (ames:parse-scenario
                    (rotating-scenario
                     '(gravity g)
                     '(body ceiling :fixed t :shape (half-plane (0 l) (1 l)))
                     '(body wheel :mass m :position (0 0) :velocity (0 0) :shape (circle r)
                       :inertia (* 2 m) :angle (/ pi 6) :angular-velocity 3)
                     '(body box :mass m :position (5 0) :velocity (0 0) :inertia :uniform
                       :shape (polygon (-1 -1) (1 -1) (1 1) (-1 1)))
                     '(body bead :mass m :position (9 0) :velocity (0 0) :shape point)
                     '(force push :on box :at (1 1/2) :value (1 0))
                     '(hinge axle :body wheel :at (0 0))
                     '(rope string :length l :through ((ceiling (0 l)) (wheel ((- r) 0) :wound))))))
         (wheel (ames:find-scenario-body 'wheel scenario))
         (box (ames:find-scenario-body 'box scenario)))
    (is (equal '(* 2 m) (ames.scenario:scenario-body-inertia wheel)))
    (is (equal '(/ pi 6) (ames.scenario:scenario-body-angle wheel)))
    (is (eql 3 (ames.scenario:scenario-body-angular-velocity wheel)))
    (is (eql 0 (ames.scenario:scenario-body-angle box)))
    (is (eq :uniform (ames.scenario:scenario-body-inertia-kind box)))
    (is (null (ames.scenario:scenario-body-inertia (ames:find-scenario-body 'bead scenario))))
    (is (equal '(1 1/2) (ames.scenario:scenario-force-point (first (ames:scenario-forces scenario)))))
    (is (equal '(:last) (ames.scenario:scenario-rope-wound-ends (first (ames.scenario:scenario-ropes scenario)))))
    (let ((hinge (first (ames.scenario:scenario-hinges scenario))))
      (is (string= "WHEEL" (symbol-name (ames.scenario:scenario-hinge-body hinge))))
      (is (equal '(0 0) (ames.scenario:scenario-hinge-point hinge))))
    (is (equal (list "WHEEL" "BOX")
               (mapcar (lambda (b) (symbol-name (ames:scenario-body-name b)))
                       (ames.scenario:scenario-rotating-bodies scenario))))))

(defparameter *rotation-mistakes*
  '(;; (CONDITION-TYPE LOCATION DATUM-OR-NIL CLAUSE ...)
    (ames:scenario-syntax-error "body B" 1
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle r) :angle 1))
    (ames:scenario-syntax-error "body B" 2
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle r) :angular-velocity 2))
    (ames:scenario-syntax-error "body B" :spin
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle r) :inertia :spin))
    (ames:scenario-syntax-error "body B" :ring
     (body b :mass m :position (0 0) :velocity (0 0) :shape (polygon (-1 -1) (1 -1) (0 1)) :inertia :ring))
    (ames:scenario-syntax-error "body B" :uniform
     (body b :mass m :position (0 0) :velocity (0 0) :shape point :inertia :uniform))
    (ames:scenario-syntax-error "body B" 1
     (body b :fixed t :shape (circle r) :inertia 1))
    (ames:scenario-expression-error "body B" -1
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle r) :inertia -1))
    (ames:scenario-shape-error "body B" :uniform
     (body b :mass m :position (0 0) :velocity (0 0) :shape (polygon (0 0) (2 0) (2 1) (0 1)) :inertia :uniform))
    (ames:undeclared-symbol-error "hinge PIN" c
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle r) :inertia 1)
     (hinge pin :body c :at (0 0)))
    (ames:scenario-syntax-error "hinge PIN" b
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle r))
     (hinge pin :body b :at (0 0)))
    (ames:scenario-syntax-error "hinge PIN2" nil
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle r) :inertia 1)
     (hinge pin1 :body b :at (0 0)) (hinge pin2 :body b :at (1/2 0)))
    (ames:scenario-syntax-error "hinge PIN" (-1 0)
     (body b :mass m :position (1 0) :velocity (0 1) :shape (segment (-1 0) (1 0)) :inertia 1)
     (hinge pin :body b :at (-1 0)))
    (ames:missing-property-error "hinge PIN" nil
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle r) :inertia 1)
     (hinge pin :body b))
    (ames:scenario-syntax-error "force F" (2 0)
     (body b :mass m :position (0 0) :velocity (0 0) :shape (polygon (-1 -1) (1 -1) (1 1) (-1 1)) :inertia 1)
     (force f :on b :at (2 0) :value (1 0)))
    (ames:scenario-syntax-error "force F" (1 0)
     (body b :mass m :position (0 0) :velocity (0 0) :shape (polygon (-1 -1) (1 -1) (1 1) (-1 1)))
     (force f :on b :at (1 0) :value (1 0)))
    (ames:scenario-syntax-error "rope S" (b (1/2 0) :wound)
     (body top :fixed t :shape (half-plane (0 5) (1 5)))
     (body b :mass m :position (0 0) :velocity (0 0) :shape (polygon (-1 -1) (1 -1) (1 1) (-1 1)) :inertia 1)
     (rope s :length 5 :through ((top (1/2 5)) (b (1/2 0) :wound))))
    (ames:scenario-syntax-error "rope S" (b (2 0) :wound)
     (body top :fixed t :shape (half-plane (0 5) (1 5)))
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle 1) :inertia 1)
     (rope s :length 5 :through ((top (2 5)) (b (2 0) :wound))))
    (ames:scenario-syntax-error "rope S" (b (0 0) :wound)
     (body top :fixed t :shape (half-plane (0 5) (1 5)))
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle 1) :inertia 1)
     (rope s :length 5 :through ((top (0 5)) (b (0 0) :wound))))
    (ames:scenario-syntax-error "clause QUERY" b
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle r))
     (query q (value (angle b) :at (end 0))))
    (ames:undeclared-symbol-error "clause QUERY" b
     (body b :mass m :position (0 0) :velocity (0 0) :shape (circle r) :inertia 1)
     (query q (value (hinge-force b) :at (end 0)))))
  "Rotation mistakes, each with the condition, location and datum its message must name.")

(test rotation-mistakes-are-named
  "Each mistake of *ROTATION-MISTAKES* signals its condition (an AMES-ERROR), at the body or
clause at fault, the datum named, with a message."
  (loop for (type location datum . clauses) in *rotation-mistakes*
        for condition = (scenario-condition (apply #'rotating-scenario clauses))
        do (is (typep condition type) "~S gave ~A, not a ~A" clauses condition type)
           (when condition
             (is (typep condition 'ames-error))
             (is (equal location (ames:scenario-error-location condition)) "~S: location ~S"
                 clauses (ames:scenario-error-location condition))
             (when datum
               (is (same-by-name-p datum (ames-error-datum condition)) "~S: datum ~S" clauses
                   (ames-error-datum condition)))
             (is (plusp (length (princ-to-string condition)))))))

(test centroid-error-names-the-centroid
  "With :uniform and the reference point off the centroid, the message gives the centroid."
  (let ((condition (scenario-condition
                    (rotating-scenario '(body b :mass m :position (0 0) :velocity (0 0) :inertia :uniform
                                         :shape (polygon (0 0) (2 0) (2 1) (0 1)))))))
    (is (search "(1 1/2)" (princ-to-string condition)))))

(test rotation-facts-decided-by-the-assumptions
  "What symbols leave open goes to Maxima: a symbolic polygon off its centroid, a disc whose
inertia exceeds m r^2, a hinge whose pin moves; the textbook shapes pass."
  (call-with-scenario-bridge
   (lambda (bridge)
     (flet ((condition-of (&rest clauses) (semantic-condition bridge (apply #'rotating-scenario clauses))))
       (is (typep (condition-of '(body b :mass m :position (0 0) :velocity (0 0) :inertia :uniform
                                  :shape (polygon (0 0) (w 0) (w h) (0 h))))
                  'ames:scenario-shape-error))
       (is (typep (condition-of '(body b :mass m :position (0 0) :velocity (0 0) :shape (circle r)
                                  :inertia (* 2 m (expt r 2))))
                  'ames:scenario-expression-error))
       (is (null (condition-of '(body b :mass m :position (0 0) :velocity (0 0) :shape (circle r)
                                 :inertia (* 1/3 m (expt r 2))))))
       (is (null (condition-of '(body b :mass m :position (0 0) :velocity (0 0) :inertia :uniform
                                 :shape (polygon ((- (/ w 2)) (- (/ h 2))) ((/ w 2) (- (/ h 2)))
                                                 ((/ w 2) (/ h 2)) ((- (/ w 2)) (/ h 2)))))))
       (is (typep (condition-of '(body b :mass m :position (l 0) :velocity (0 l) :inertia :uniform
                                  :shape (segment ((- l) 0) (l 0)))
                                '(hinge pin :body b :at ((- l) 0)))
                  'ames:scenario-syntax-error))))))

(test awaiting-rotation-scenarios-validate
  "Every scenario of scenarios/awaiting-rotation/ reads, validates and passes the Maxima
checks, with at least one rotating body."
  (call-with-scenario-bridge
   (lambda (bridge)
     (let ((files (directory (merge-pathnames (make-pathname :directory '(:relative "scenarios" "awaiting-rotation")
                                                              :name :wild :type "lisp")
                                               (asdf:system-source-directory "ames")))))
      (is (<= 1 (length files)) "scenarios/awaiting-rotation/ holds ~D files" (length files))
      (dolist (file files)
       (multiple-value-bind (scenarios conditions) (ames:read-scenario-file file :on-error :collect)
         (is (null conditions) "~A: ~{~A~}" (pathname-name file) conditions)
         (dolist (scenario scenarios)
           (is (ames.scenario:scenario-rotating-bodies scenario))
           (is (eq scenario (ames:check-scenario-assumptions scenario bridge))
               "~A failed the Maxima checks" (pathname-name file)))))))))

(test simulator-refuses-rotation
  "The simulator refuses a scenario with a rotating body it does not simulate yet
(UNSUPPORTED-SITUATION naming the body), rather than simulating it as a translating one:
a rotating block on a floor beside a free ball (a polygon's contacts with another free body
turn with it), a disc with a rope tied off its centre (not wound), a disc with a spring
attached off its centre. A rotating disc on the floor is simulated."
  (with-fixture simulator-bridge ()
    (flet ((refusal (&rest clauses)
             (handler-case (progn (ames:simulate (apply #'rotating-scenario '(gravity g) clauses)
                                                 :bridge bridge)
                                  nil)
               (ames-error (c) c))))
      (loop for (body . clauses)
              in '(("BLOCK" (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                    (body block :mass m :position (0 h) :velocity (0 0) :inertia :uniform
                     :shape (polygon ((- w) (- h)) (w (- h)) (w h) ((- w) h)))
                    ;; a free body it could touch: its corners on fixed faces alone are simulated
                    (body ball :mass m :position ((* 4 w) (* 4 h)) :velocity (0 0) :shape (circle w)))
                   ("DRUM" (body anchor :fixed t :shape point :position (0 h))
                    (body drum :mass m :position (0 0) :velocity (0 0) :shape (circle r)
                     :inertia :uniform)
                    (rope cord :length (+ h r) :through ((drum (r 0)) (anchor (0 0)))))
                   ("WHEEL" (body wall :fixed t :shape (half-plane (0 1) (0 0)))
                    (body wheel :mass m :position (h (* 2 r)) :velocity (0 0) :shape (circle r)
                     :inertia :uniform)
                    (spring s :from (wheel (r 0)) :to (wall (0 (* 2 r))) :stiffness m)))
            do (let ((condition (apply #'refusal clauses)))
                 (is (typep condition 'ames:unsupported-situation) "~A: ~A" body condition)
                 (when (typep condition 'ames:unsupported-situation)
                   (is (string= body (symbol-name (ames-error-datum condition))))
                   (is (search "rotat" (princ-to-string condition)))))))
    (is (null (handler-case
                  (progn (ames:simulate (rotating-scenario
                                         '(gravity g)
                                         '(body floor :fixed t :shape (half-plane (1 0) (0 0)))
                                         '(body wheel :mass m :position (0 r) :velocity (0 0)
                                           :shape (circle r) :inertia :uniform :angular-velocity 0))
                                        :bridge bridge)
                         nil)
                (ames-error (c) c))))))

(test start-shape-is-turned-by-the-angle
  "A rotating body's start shape is its shape turned by its :angle: a 2 by 1 rectangle
turned by pi/2 has its vertices at (1/2 -1) (1/2 1) (-1/2 1) (-1/2 -1), numerically; a
translating body's is its own."
  (let* ((scenario (ames:parse-scenario
                    (rotating-scenario '(body b :mass m :position (0 0) :velocity (0 0) :inertia :uniform
                                         :angle (/ pi 2) :shape (polygon (-1 -1/2) (1 -1/2) (1 1/2) (-1 1/2)))
                                       '(body c :mass m :position (5 0) :velocity (0 0) :shape (circle 1)))))
         (turned (ames.scenario:scenario-body-start-shape (ames:find-scenario-body 'b scenario))))
    (loop for (x y) in (rest turned)
          for (ex ey) in '((1/2 -1) (1/2 1) (-1/2 1) (-1/2 -1))
          do (is (< (abs (- (ames.base:expression-value x) ex)) 1d-12))
             (is (< (abs (- (ames.base:expression-value y) ey)) 1d-12)))
    (let ((c (ames:find-scenario-body 'c scenario)))
      (is (eq (ames:scenario-body-shape c) (ames.scenario:scenario-body-start-shape c))))))

(test simulator-answers-a-value-at-reaches
  "A value query whose WHEN is (reaches QUANTITY VALUE) (the language's rotation section)
validates, as (:reaches QUANTITY VALUE), and is answered where the quantity first takes
the value: a ball dropped from the height h has the speed sqrt(2 g h) where its height
reaches 0, the time sqrt(2 h / g) then."
  (let* ((form (rotating-scenario '(gravity g)
                                  '(body ball :mass m :position (0 h) :velocity (0 0) :shape point)
                                  '(query speed-at-ground (value (speed ball) :at (reaches (y ball) 0)))
                                  '(query time-at-ground (value (time) :at (reaches (y ball) 0)))))
         (scenario (ames:parse-scenario form))
         (query (first (ames:scenario-queries scenario))))
    (is (eq :reaches (first (getf (cddr (second query)) :at))))
    (with-fixture simulator-bridge ()
      (let* ((history (ames:simulate form :bridge bridge))
             (answers (ames::history-answers history)))
        (flet ((x (form) (in-scenario-terms (ames::history-scenario history) form)))
          (call-with-scenario-facts
           bridge (ames::history-scenario history)
           (lambda ()
             (is-same bridge "speed at the ground"
                      (second (assoc "SPEED-AT-GROUND" answers :test #'same-name-p*))
                      (x '(sqrt (* 2 g h))))
             (is-same bridge "time at the ground"
                      (second (assoc "TIME-AT-GROUND" answers :test #'same-name-p*))
                      (x '(sqrt (/ (* 2 h) g)))))))))))
