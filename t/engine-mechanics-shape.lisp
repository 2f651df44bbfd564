;;;; t/engine-mechanics-shape.lisp -- the shapes the mechanics knowledge base needs (thesis
;;;; figures 2-6 to 2-9), written with DEFCOMPONENT against stub template functions, to
;;;; show the engine can express them: entities of a kind with filters, forces as
;;;; beliefs, Newton's second law collecting every force on a body after every
;;;; component that asserts one, Newton's third law pairing beliefs, quantitative
;;;; activation of contacts, deactivation on a normal force, and lift-off as an
;;;; incremental transition. The physics is the real knowledge base's business
;;;; (src/kb/); the geometry here is a stub.

(in-package #:ames.tests)

(in-suite engine)

(defun force-term (head)
  "A template function turning a force's name, a list such as (normal c1), into the
quantity term (HEAD normal c1)."
  (lambda (situation force)
    (declare (ignore situation))
    (cons head force)))

(defun sum-of-forces (situation forces axis)
  "Template SUM-OF: the sum of the AXIS (:x or :y) components of FORCES."
  (declare (ignore situation))
  (let ((head (ecase axis (:x 'force-x) (:y 'force-y))))
    (if forces (cons '+ (mapcar (lambda (force) (list head force)) forces)) 0)))

(defun make-mechanics-shape-kb ()
  "The components of the thesis's figures 2-6 to 2-9, in the engine's syntax."
  (let ((kb (ames.engine:make-knowledge-base :name "mechanics shape")))
    (ames.engine:register-template kb 'mass (property-template :mass))
    (ames.engine:register-template kb 'strength (property-template :strength))
    ;; stand-ins for the geometry: the contact's normal angle, and its activation
    ;; test as a relation on the initial positions
    (ames.engine:register-template kb 'normal-direction (property-template :normal-angle))
    (ames.engine:register-template kb 'on-contact
                                   (lambda (situation contact)
                                     (declare (ignore situation))
                                     `(= (contact-distance ,contact) 0)))
    (ames.engine:register-template kb 'force-x (force-term 'fx))
    (ames.engine:register-template kb 'force-y (force-term 'fy))
    (ames.engine:register-template kb 'magnitude-of (force-term 'fmag))
    (ames.engine:register-template kb 'sum-of #'sum-of-forces)

    (ames.engine:defcomponent contact (:knowledge-base kb)
      "Two bodies touching along a simple contact push each other apart along its
normal (figure 2-6)."
      (:arguments (?contact :entity simple-contact :where (:observer ?body1 :obstacle ?body2)))
      (:activation (on-contact ?contact))
      (:deactivation (< (magnitude-of (normal ?contact)) 0))
      (:assert (touching ?body1 ?body2 :along ?contact)
               (force (normal ?contact) :type normal :from ?body2 :on ?body1 :contact ?contact)
               (force (reaction ?contact) :type normal :from ?body1 :on ?body2 :contact ?contact))
      (:equations
       (= (force-x (normal ?contact))
          (* (magnitude-of (normal ?contact)) (cos (normal-direction ?contact))))
       (= (force-y (normal ?contact))
          (* (magnitude-of (normal ?contact)) (sin (normal-direction ?contact))))))

    (ames.engine:defcomponent terrestrial-gravitation (:knowledge-base kb)
      "A gravitational field pulls every free body down with its weight (figure 2-7)."
      (:arguments (?body :entity body :where (:fixed nil))
                  (?field :entity gravity-field))
      (:activation :always)
      (:deactivation :never)
      (:assert (force (gravity ?body) :type gravity :from ?field :on ?body))
      (:equations (= (force-x (gravity ?body)) 0)
                  (= (force-y (gravity ?body)) (- (* (mass ?body) (strength ?field))))))

    (ames.engine:defcomponent fixed-body (:knowledge-base kb)
      "A fixed body does not accelerate in the fixed frame."
      (:arguments (?body :entity body :where (:fixed t)))
      (:equations (= (acc ?body :x) 0) (= (acc ?body :y) 0)))

    (ames.engine:defcomponent newtons-second-law (:knowledge-base kb)
      "The sum of every force on a free body is its mass times its acceleration in
the fixed frame (figure 2-8)."
      (:arguments (?body :entity body :where (:fixed nil))
                  (?forces :collect ?f :matching (force ?f :on ?body)))
      (:equations (= (sum-of ?forces :x) (* (mass ?body) (acc ?body :x)))
                  (= (sum-of ?forces :y) (* (mass ?body) (acc ?body :y)))))

    (ames.engine:defcomponent newtons-third-law (:knowledge-base kb)
      "The two forces of one contact between two bodies are opposite (figure 2-9)."
      (:arguments (?force1 :belief (force ?force1 :type ?type :from ?body1 :on ?body2
                                          :contact ?contact))
                  (?force2 :belief (force ?force2 :type ?type :from ?body2 :on ?body1
                                          :contact ?contact)))
      (:equations (= (force-x ?force1) (- (force-x ?force2)))
                  (= (force-y ?force1) (- (force-y ?force2)))))
    kb))

(defun wedge-situation ()
  "A particle on a wedge on fixed ground, as the simulator would describe it (the
particle could also touch the ground: a potential contact)."
  (ames.engine:make-situation
   '((body ground :fixed t)
     (body wedge :mass mw)
     (body particle :mass mp)
     (gravity-field earth :strength g)
     (simple-contact c1 :observer particle :obstacle wedge :normal-angle (+ a (/ pi 2)))
     (simple-contact c2 :observer wedge :obstacle ground :normal-angle (/ pi 2))
     (simple-contact c3 :observer particle :obstacle ground :normal-angle (/ pi 2)))))

(defparameter +particle-on-wedge+
  '(((contact-distance c1) . 0) ((contact-distance c2) . 0) ((contact-distance c3) . 1))
  "The initial distances: the particle on the wedge, the wedge on the ground.")

(test the-mechanics-shapes-are-expressible
  (let* ((kb (make-mechanics-shape-kb))
         (order (mapcar #'ames.engine:component-name (ames.engine:component-order kb)))
         (model (ames.engine:build-model (ames.engine:make-engine kb) (wedge-situation)
                                         :decider (table-decider +particle-on-wedge+))))
    ;; Newton's second law comes after everything that asserts a force
    (is (< (position 'contact order) (position 'newtons-second-law order)))
    (is (< (position 'terrestrial-gravitation order) (position 'newtons-second-law order)))
    (let ((equations (ames.engine:model-equations model)))
      (dolist (expected
               '((= (+ (fy gravity particle) (fy normal c1)) (* mp (acc particle :y)))
                 (= (+ (fx gravity wedge) (fx normal c2) (fx reaction c1)) (* mw (acc wedge :x)))
                 (= (fy gravity wedge) (- (* mw g)))
                 (= (fx normal c1) (* (fmag normal c1) (cos (+ a (/ pi 2)))))
                 (= (fx normal c1) (- (fx reaction c1)))
                 (= (fy reaction c2) (- (fy normal c2)))
                 (= (acc ground :y) 0)))
        (is (member expected equations :test #'equal) "missing ~S" expected))
      ;; nothing about the potential contact c3, no gravity on the fixed ground
      (is (notany (lambda (e) (search "C3" (prin1-to-string e))) equations))
      (is (null (ames.engine:find-instance model '(terrestrial-gravitation ground earth)))))
    (is (set-equal-p
         '((:deactivation (contact c1) (< (fmag normal c1) 0) (:deactivate (contact c1)))
           (:deactivation (contact c2) (< (fmag normal c2) 0) (:deactivate (contact c2)))
           (:activation (contact c3) (= (contact-distance c3) 0) (:activate (contact c3))))
         (termination-lists model)))
    ;; lift-off: the particle leaves the wedge; only its weight is left on it
    (ames.engine:apply-transition model '((:deactivate (contact c1))))
    (is (member '(= (+ (fy gravity particle)) (* mp (acc particle :y)))
                (ames.engine:model-equations model) :test #'equal))
    (is (null (ames.engine:check-incremental model)))
    ;; it lands on the ground
    (ames.engine:apply-transition model '((:activate (contact c3))))
    (is (member '(= (+ (fy gravity particle) (fy normal c3)) (* mp (acc particle :y)))
                (ames.engine:model-equations model) :test #'equal))
    (is (null (ames.engine:check-incremental model)))
    (is (search "by newtons-second-law"
                (with-output-to-string (s)
                  (ames.engine:explain model '(= (+ (fx gravity particle) (fx normal c3))
                                               (* mp (acc particle :x)))
                                       s))))))
