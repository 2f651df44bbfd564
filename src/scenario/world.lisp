;;;; src/scenario/world.lisp -- the world of a checked scenario: its shapes and contact pairs, built once.
;;;;
;;;; Checking a scenario (CHECK-SCENARIO, semantics.lisp) must parse every body's shape
;;;; with the geometry layer and build the configuration-space contacts of every two
;;;; bodies that are not both fixed, to find overlaps at the start. What it built is the
;;;; world the simulation runs in: a WORLD hands it to the run, so the geometry of a
;;;; scenario is derived once. The contacts of a pair are numbered, over the pairs in
;;;; order, by the simulator (WORLD-SIMPLE-CONTACTS gives them in that order).

(in-package #:ames.scenario)

(defvar *pair-screen* nil
  "NIL, or a function of a SCENARIO and two of its scenario bodies that returns true
only when it proves the two apart at the start (their shapes' bounds along an axis
strictly apart): SCENARIO-GEOMETRY then leaves their contact pair out of the world, as a
deferred pairing (see WORLD-DEFERRED-PAIRINGS), which the run proves apart in each
state or builds (the simulator's deferred-pairs.lisp binds it).")

(defclass world ()
  ((scenario :initarg :scenario :reader world-scenario
             :documentation "The validated SCENARIO this world is the geometry of.")
   (shapes :initarg :shapes :reader world-shapes
           :documentation "Alist body name -> the AMES.GEOMETRY shape parsed from the body's
shape form, in the scenario's order of bodies.")
   (pairs :initarg :pairs :reader world-pairs
          :documentation "The AMES.GEOMETRY contact pairs of every two bodies that are not
both fixed, in the scenario's order: the first body with each later one, then the
second with each later one, and so on; less the DEFERRED ones.")
   (ordinals :initarg :ordinals :initform nil :reader world-pair-ordinals
             :documentation "For each of PAIRS, its place in the order of every pairing
(NIL: the pairs are every pairing, in order).")
   (deferred :initarg :deferred :initform '() :reader world-deferred-pairings
             :documentation "The pairings left out of PAIRS because *PAIR-SCREEN* proved
them apart at the start, each (ORDINAL BODY-NAME OTHER-NAME): the run must prove them
apart in each state, or build them (WORLD-WITH-PAIRINGS)."))
  (:documentation "What checking a scenario built of its geometry, handed to the run: the
parsed shapes and the contact pairs. Valid under the assumptions it was built under (the
scenario's, and a branch's extra facts)."))

(defmethod print-object ((world world) stream)
  (print-unreadable-object (world stream :type t)
    (format stream "~A, ~D bod~:@P, ~D pair~:P" (scenario-name (world-scenario world))
            (length (world-shapes world)) (length (world-pairs world)))))

(defun make-world (scenario shapes pairs &key ordinals deferred)
  "The WORLD of SCENARIO with SHAPES (alist body name -> geometry shape) and PAIRS (its
contact pairs in order, see the slot's documentation), ORDINALS their places among every
pairing and DEFERRED the pairings left out (see the slots)."
  (make-instance 'world :scenario scenario :shapes shapes :pairs pairs
                        :ordinals ordinals :deferred deferred))

(defun world-shape (world body-name)
  "The geometry shape of the body called BODY-NAME in WORLD, or NIL."
  (cdr (assoc body-name (world-shapes world))))

(defun world-simple-contacts (world)
  "Every simple contact of WORLD's pairs, pair after pair, each pair's in its own order."
  (loop for pair in (world-pairs world)
        append (ames.geometry:pair-contacts pair)))
