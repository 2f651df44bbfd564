;;;; src/kb/package.lisp -- the mechanics knowledge base's package.

(defpackage #:ames.kb
  (:use #:cl #:ames.base)
  (:import-from #:ames.engine #:defcomponent #:make-knowledge-base #:register-template
                #:find-entity #:entity-property #:entity-name #:situation-data)
  (:documentation "Mechanics as data: one DEFCOMPONENT per piece of the thesis's
knowledge (contact, kinematic restriction, normal force, gravitation, external force,
fixed body, Newton's second and third laws, the kinematics of a body, reference-frame
and path-coordinate conversions; Coulomb friction, friction.lisp), and the template functions that read the situation
the simulator describes. The components own their events (what each termination
condition is, for the report), their dynamics (DERIVATIVE beliefs: the ODEs of the
state variables) and their report (REPORTED beliefs: what a state lists, such as its
forces). See mechanics.lisp's header for the vocabulary the simulator and the
components share.")
  (:export
   #:*mechanics* #:mechanics-knowledge-base #:contact-geometry
   #:*impacts* #:impact-knowledge-base
   ;; the impact model's quantities and entities (impacts.lisp)
   #:vel-after #:jx #:jy #:normal-impulse #:separation-after #:energy-lost #:touching-contact
   #:impulse
   ;; the quantity terms the components speak of (heads of terms such as (acc particle :x))
   #:acc #:vel #:pos #:rel-acc #:fx #:fy #:normal-force
   #:path-acc #:path-position #:path-speed #:contact-gap #:friction-force
   ;; the entity kinds and properties the simulator must describe
   #:body #:gravity-field #:external-force #:simple-contact #:friction-coefficients
   ;; the beliefs the simulator reads
   #:derivative #:reported #:force #:in-contact #:path-coordinates
   ;; names used in beliefs and force names
   #:normal #:reaction #:gravity #:external #:environment
   ;; springs, ropes, universal gravitation, energy (spans.lisp, springs.lisp, ropes.lisp,
   ;; gravitation.lisp, energy.lisp): the entity kinds the simulator describes, the
   ;; quantities it provides (a free body's position at the state's start) and reads
   #:spring #:bumper #:point-contact #:rope #:rope-segment #:gravitation-field #:body-pair
   #:initial-pos #:initial-vel #:span #:span-length #:span-direction #:span-acceleration #:tension
   #:kinetic-energy #:momentum #:potential-energy #:pressing #:taut
   #:unmodelled-situation
   ;; the entities of clauses the kb reads itself (clause-entities.lisp; drag.lisp)
   #:clause-entity))
