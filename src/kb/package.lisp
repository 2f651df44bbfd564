;;;; src/kb/package.lisp -- the mechanics knowledge base's package.

(defpackage #:ames.kb
  (:use #:cl #:ames.base)
  (:import-from #:ames.engine #:defcomponent #:make-knowledge-base #:register-template
                #:find-entity #:entity-property #:situation-data)
  (:documentation "Mechanics as data: one DEFCOMPONENT per piece of the thesis's
knowledge (contact, kinematic restriction, normal force, gravitation, external force,
fixed body, Newton's second and third laws, derivative relations, reference-frame and
path-coordinate conversions), and the template functions that read the situation the
simulator describes.")
  (:export
   #:*mechanics* #:mechanics-knowledge-base
   ;; the quantity terms the components speak of (heads of terms such as (acc particle :x))
   #:acc #:vel #:pos #:vel0 #:pos0 #:rel-acc #:fx #:fy #:normal-force
   #:path-acc #:path-position #:path-speed #:contact-gap
   ;; the entity kinds and properties the simulator must describe
   #:body #:gravity-field #:external-force #:simple-contact
   ;; names used in beliefs and force names
   #:normal #:reaction #:gravity #:external #:environment))
