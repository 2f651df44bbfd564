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
;;;; conserved where no force from outside the free bodies acts. Each potential energy is
;;;; defined beside its force, in its phenomenon's file: the weight's in mechanics.lisp, a
;;;; spring's and a bumper's in springs.lisp, gravitation's in gravitation.lisp. The kinds
;;;; of terms, with their words and the queries they answer, are declared below (see
;;;; terms.lisp): the report and the queries list what is declared.

(in-package #:ames.kb)

(define-reported-term :kinetic :section :energy :label "kinetic K" :symbol "K"
                               :query :kinetic-energy :shown :always)
(define-reported-term :potential :section :energy :label "potential U" :symbol "U"
                                 :shown :always)
(define-reported-term :momentum :section :momentum :label "total" :vector t
                                :query :momentum :shown :always)

(defcomponent kinetic-energy-and-momentum (:knowledge-base *mechanics*)
  "A free body's kinetic energy is 1/2 m |v|^2 and its momentum m v."
  (:arguments (?body :entity body :where (:fixed nil :driven nil)))
  (:assert (reported :energy (:kinetic ?body (kinetic-energy ?body)))
           (reported :momentum (:momentum ?body ((momentum ?body :x) (momentum ?body :y)))))
  (:equations (= (kinetic-energy ?body)
                 (* 1/2 (mass ?body) (+ (expt (vel ?body :x) 2) (expt (vel ?body :y) 2))))
              (= (momentum ?body :x) (* (mass ?body) (vel ?body :x)))
              (= (momentum ?body :y) (* (mass ?body) (vel ?body :y)))))
