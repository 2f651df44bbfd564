;;;; src/kb/energy.lisp -- kinetic and potential energy and momentum, as quantities a state
;;;; reports (thesis 3.3.2, "Momentum and Energy").
;;;;
;;;; The thesis's "second step": formulae for kinetic energy, the potential energies of the
;;;; conservative forces and momentum as mass times velocity. Each is a quantity defined
;;;; by an equation (eliminated before Maxima solves, like any definition) and reported in
;;;; a section of its own, which the simulator copies into each state's notes:
;;;;   (reported :energy (:kinetic BODY E))          1/2 m |v|^2 of a free body (a driven
;;;;                                                 body has no mass: none)
;;;;   (reported :energy (:potential SOURCE E))       SOURCE (:gravity B), (:spring S),
;;;;                                                 (bumper S B), (gravitation B1 B2)
;;;;   (reported :momentum (:momentum BODY (PX PY)))  m v of a free body
;;;; Their sum is constant over a state with no friction and no impact; momentum is
;;;; conserved where no force from outside the free bodies acts.

(in-package #:ames.kb)

(defcomponent kinetic-energy-and-momentum (:knowledge-base *mechanics*)
  "A free body's kinetic energy is 1/2 m |v|^2 and its momentum m v."
  (:arguments (?body :entity body :where (:fixed nil :driven nil)))
  (:assert (reported :energy (:kinetic ?body (kinetic-energy ?body)))
           (reported :momentum (:momentum ?body ((momentum ?body :x) (momentum ?body :y)))))
  (:equations (= (kinetic-energy ?body)
                 (* 1/2 (mass ?body) (+ (expt (vel ?body :x) 2) (expt (vel ?body :y) 2))))
              (= (momentum ?body :x) (* (mass ?body) (vel ?body :x)))
              (= (momentum ?body :y) (* (mass ?body) (vel ?body :y)))))

(defcomponent gravitational-potential-energy (:knowledge-base *mechanics*)
  "In a terrestrial field a free body's potential energy is m g y."
  (:arguments (?body :entity body :where (:fixed nil :driven nil))
              (?field :entity gravity-field))
  (:assert (reported :energy (:potential (:gravity ?body) (potential-energy gravity ?body))))
  (:equations (= (potential-energy gravity ?body) (* (mass ?body) (strength ?field) (pos ?body :y)))))

(defcomponent elastic-potential-energy (:knowledge-base *mechanics*)
  "A spring's potential energy is 1/2 K (l - L0)^2."
  (:arguments (?spring :entity spring))
  (:assert (reported :energy (:potential (:spring ?spring) (potential-energy spring ?spring))))
  (:equations (= (potential-energy spring ?spring)
                 (* 1/2 (stiffness ?spring) (expt (- (span-length ?spring) (rest-length ?spring)) 2)))))

(defcomponent bumper-potential-energy (:knowledge-base *mechanics*)
  "A compressed bumper's potential energy is 1/2 K c^2, c its compression."
  (:arguments (?contact :belief (pressing ?body ?spring :along ?contact)))
  (:assert (reported :energy (:potential (:bumper ?spring ?body) (potential-energy bumper ?contact))))
  (:equations (= (potential-energy bumper ?contact)
                 (* 1/2 (stiffness ?spring) (expt (compression ?contact) 2)))))

(defcomponent gravitational-binding-energy (:knowledge-base *mechanics*)
  "Two bodies under universal gravitation have the potential energy -G m1 m2 / r."
  (:arguments (?pair :entity body-pair :where (:first ?body1 :second ?body2))
              (?field :entity gravitation-field))
  (:assert (reported :energy (:potential (:gravitation ?body1 ?body2) (potential-energy gravitation ?pair))))
  (:equations (= (potential-energy gravitation ?pair)
                 (- (/ (* (gravitational-constant ?field) (mass ?body1) (mass ?body2))
                       (span-length ?pair))))))
