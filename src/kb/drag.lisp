;;;; src/kb/drag.lisp -- drag: a body moving through a medium at rest (the language's "Drag";
;;;; thesis 3.3.2 asks for new force laws to be knowledge-base additions).
;;;;
;;;; The scenario's (drag NAME :on BODY :linear B) and (drag NAME :on BODY :quadratic C)
;;;; clauses (src/scenario/drag.lisp) come to the situation as the entities
;;;;   (drag NAME :on BODY :law :linear :coefficient B)
;;;;   (drag NAME :on BODY :law :quadratic :coefficient C)
;;;; The force on BODY is -B v (viscous, Stokes) or -C |v| v (air resistance, Newton), v its
;;;; velocity in the fixed frame, where the medium is at rest. A drag on a fixed or driven
;;;; body does nothing. Drag is not conservative: it has no potential energy, and the
;;;; reported total K + U falls over a state by the energy the drag dissipates.
;;;; Reported in :forces as (:drag NAME BODY (FX FY)).
;;;;
;;;; Nothing else is needed for the dynamics: the force depends on the velocities, so the
;;;; state's rates do, and the simulator's integrators take them as they come. Linear drag
;;;; keeps the rates linear with constant coefficients: closed forms (the exponential
;;;; approach to the terminal velocity m g / B; with a spring, the damped oscillator, under-,
;;;; critically or over-damped as the assumptions decide, a branch where they do not).
;;;; Quadratic drag along a fixed line is a first-order Riccati equation in the speed along
;;;; it (tanh falling, tan rising); in two dimensions it has no closed form (numbers under
;;;; values).
;;;;
;;;; Turning back: along a line, |v| v changes its form where the velocity changes sign, so
;;;; a quadratic drag on a body that starts moving watches v.v0 + |v| |v0|, v0 the velocity
;;;; the state starts with (the state's constant (initial-vel BODY :x)): positive while v has
;;;; a part along v0, it reaches zero when the body stops and stays there once it moves
;;;; back: event (:turns BODY), and the next state starts from rest there (a ball thrown up
;;;; stops at the top of its flight, then falls). In two dimensions it stays positive (v is
;;;; never opposite to v0 without passing through rest): nothing is watched in effect. A
;;;; body that starts from rest watches nothing (its velocity grows along the force: it
;;;; never turns back within the state).

(in-package #:ames.kb)

(defun drag-entities (scenario)
  "The entities (drag NAME :on BODY :law LAW :coefficient K) of SCENARIO's drag clauses
(their data, src/scenario/drag.lisp)."
  (loop for data in (ames.scenario:scenario-kb-clauses scenario)
        when (eq (first data) :drag)
          collect (cons 'drag (rest data))))

(define-phenomenon drag
  "A body moving through a medium at rest: linear (-B v, viscous) or quadratic (-C |v| v,
air) drag, the language's drag clause. No energy term: the total K + U falls by what it
dissipates."
  (:entities #'drag-entities)
  (:force :drag :names 2 :words "drag ~A on ~A"))

(register-template *mechanics* 'drag-coefficient
                   (lambda (situation drag) (entity-property (entity-named situation drag) :coefficient))
                   :documentation "A drag's coefficient: B of -B v, or C of -C |v| v.")

(defcomponent linear-drag (:knowledge-base *mechanics*)
  "A viscous medium at rest pushes a body against its velocity with B times it: F = -B v."
  (:arguments (?drag :entity drag :where (:on ?body :law :linear))
              (?body :entity body :where (:fixed nil :driven nil)))
  (:assert (force (drag ?drag) :type drag :from environment :on ?body)
           (reported :forces (:drag ?drag ?body ((fx drag ?drag) (fy drag ?drag)))))
  (:equations (= (force-x (drag ?drag)) (* -1 (drag-coefficient ?drag) (vel ?body :x)))
              (= (force-y (drag ?drag)) (* -1 (drag-coefficient ?drag) (vel ?body :y)))))

(defcomponent quadratic-drag (:knowledge-base *mechanics*)
  "Air at rest pushes a body against its velocity with C times its speed squared:
F = -C |v| v."
  (:arguments (?drag :entity drag :where (:on ?body :law :quadratic))
              (?body :entity body :where (:fixed nil :driven nil)))
  (:assert (force (drag ?drag) :type drag :from environment :on ?body)
           (reported :forces (:drag ?drag ?body ((fx drag ?drag) (fy drag ?drag)))))
  (:equations (= (force-x (drag ?drag))
                 (* -1 (drag-coefficient ?drag)
                    (sqrt (+ (expt (vel ?body :x) 2) (expt (vel ?body :y) 2))) (vel ?body :x)))
              (= (force-y (drag ?drag))
                 (* -1 (drag-coefficient ?drag)
                    (sqrt (+ (expt (vel ?body :x) 2) (expt (vel ?body :y) 2))) (vel ?body :y)))))

(register-template *mechanics* 'reversal-margin
                   (lambda (situation body)
                     (declare (ignore situation))
                     `(+ (* (vel ,body :x) (initial-vel ,body :x)) (* (vel ,body :y) (initial-vel ,body :y))
                         (* (sqrt (+ (expt (vel ,body :x) 2) (expt (vel ,body :y) 2)))
                            (sqrt (+ (expt (initial-vel ,body :x) 2) (expt (initial-vel ,body :y) 2))))))
                   :documentation "v.v0 + |v| |v0|, v a body's velocity and v0 its velocity at the start of
the state: positive while v has a part along v0, zero once v is at rest or reversed.")
(register-template *mechanics* 'start-speed-squared
                   (lambda (situation body)
                     (declare (ignore situation))
                     `(+ (expt (initial-vel ,body :x) 2) (expt (initial-vel ,body :y) 2)))
                   :documentation "The square of a body's speed at the start of the state.")

(defcomponent drag-turning-point (:knowledge-base *mechanics*)
  "A body moving against quadratic drag turns where its velocity's component along its
starting velocity changes sign (a ball thrown up stops at the top): event (:turns BODY);
the next state starts from rest. A body starting from rest watches nothing."
  (:arguments (?drag :entity drag :where (:on ?body :law :quadratic))
              (?body :entity body :where (:fixed nil :driven nil)))
  (:mode :moving
   (:entry (> (start-speed-squared ?body) 0))
   (:transition :to :from-rest :when (<= (reversal-margin ?body) 0)
                :event (:turns ?body)))
  (:mode :from-rest
   (:entry (<= (start-speed-squared ?body) 0))))
