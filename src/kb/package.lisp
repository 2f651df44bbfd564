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
components share.

Each phenomenon (contact, gravity, external force, friction, spring, rope, gravitation,
impact, turning) is declared once with DEFINE-PHENOMENON beside its components
(phenomena.lisp): the entities it makes of its scenario clause, the points attached to
bodies whose loci the geometry gives, how its forces, impulses and events are named in
every report, and the query quantities it answers. The simulator, the queries, the
reports and `explain` look these up and name no force, event or mode. To add a
phenomenon: a new file here (listed in ames.asd) with its DEFCOMPONENTs (reporting its
forces in :FORCES and its energy in :ENERGY) and one DEFINE-PHENOMENON; the clause's
syntax in src/scenario/.")
  (:export
   #:*mechanics* #:mechanics-knowledge-base #:contact-geometry
   #:*impacts* #:impact-knowledge-base #:knowledge-bases
   ;; the registry of phenomena (phenomena.lisp)
   #:define-phenomenon #:phenomenon #:phenomenon-name #:phenomenon-documentation
   #:*phenomena* #:find-phenomenon
   #:situation-entities-of #:impact-entities-of #:probes-of #:entity-phrases-of
   #:force-description #:impulse-description #:event-description #:quantity-description
   #:touching-contact-entity
   ;; the kinds of terms reported in the energy and momentum sections (terms.lisp)
   #:define-reported-term #:reported-term #:reported-terms #:query-reported-term
   #:term-kind #:term-section #:term-label #:term-symbol #:term-vector #:term-query
   #:term-shown #:term-entries #:term-subject-body
   ;; the impact model's quantities and entities (impacts.lisp)
   #:vel-after #:jx #:jy #:normal-impulse #:separation-after #:energy-lost #:touching-contact
   #:impulse
   ;; impacts of rotating bodies (rotating-impacts.lisp)
   #:angvel-after #:angular-impulse #:impulse-acts-at
   ;; the quantity terms the components speak of (heads of terms such as (acc particle :x))
   #:acc #:vel #:pos #:rel-acc #:fx #:fy #:normal-force
   #:path-acc #:path-position #:path-speed #:contact-gap #:friction-force
   ;; the entity kinds the simulator describes itself (the phenomena make the others)
   #:body #:simple-contact
   ;; the beliefs the simulator reads
   #:derivative #:reported #:force #:in-contact #:path-coordinates
   ;; names used in beliefs and force names
   #:normal #:reaction #:gravity #:external #:environment
   ;; springs, ropes, universal gravitation, energy (spans.lisp, springs.lisp, ropes.lisp,
   ;; gravitation.lisp, energy.lisp): the quantities the simulator provides (a free body's
   ;; position and velocity at the state's start) and reads
   #:initial-pos #:initial-vel #:span #:span-length #:span-direction #:span-acceleration #:tension
   #:kinetic-energy #:momentum #:potential-energy #:pressing #:taut
   ;; rotation (rotation.lisp): a rotating body's state variables and what it reports
   #:angle #:angvel #:angacc #:moment #:acts-at #:rotational-energy #:angular-momentum
   ;; the direction a rotating body starts turning in over a state (turning.lisp)
   #:initial-turn
   ;; corners of rotating polygons and segments on fixed faces (corners.lisp)
   #:corner-contact #:resting-face
   #:unmodelled-situation))
