;;;; src/scenario/world.lisp -- the world of a checked scenario: its shapes and contact pairs, built once.
;;;;
;;;; Checking a scenario (CHECK-SCENARIO, semantics.lisp) must parse every body's shape
;;;; with the geometry layer and build the configuration-space contacts of every two
;;;; bodies that are not both fixed, to find overlaps at the start. What it built is the
;;;; world the simulation runs in: a WORLD hands it to the run, so the geometry of a
;;;; scenario is derived once. The contacts of a pair are numbered, over the pairs in
;;;; order, by the simulator (WORLD-SIMPLE-CONTACTS gives them in that order).

(in-package #:ames.scenario)

(defclass world ()
  ((scenario :initarg :scenario :reader world-scenario
             :documentation "The validated SCENARIO this world is the geometry of.")
   (shapes :initarg :shapes :reader world-shapes
           :documentation "Alist body name -> the AMES.GEOMETRY shape parsed from the body's
shape form, in the scenario's order of bodies.")
   (pairs :initarg :pairs :reader world-pairs
          :documentation "The AMES.GEOMETRY contact pairs of every two bodies that are not
both fixed, in the scenario's order: the first body with each later one, then the
second with each later one, and so on."))
  (:documentation "What checking a scenario built of its geometry, handed to the run: the
parsed shapes and the contact pairs. Valid under the assumptions it was built under (the
scenario's, and a branch's extra facts)."))

(defmethod print-object ((world world) stream)
  (print-unreadable-object (world stream :type t)
    (format stream "~A, ~D bod~:@P, ~D pair~:P" (scenario-name (world-scenario world))
            (length (world-shapes world)) (length (world-pairs world)))))

(defun make-world (scenario shapes pairs)
  "The WORLD of SCENARIO with SHAPES (alist body name -> geometry shape) and PAIRS (its
contact pairs in order, see the slot's documentation)."
  (make-instance 'world :scenario scenario :shapes shapes :pairs pairs))

(defun world-shape (world body-name)
  "The geometry shape of the body called BODY-NAME in WORLD, or NIL."
  (cdr (assoc body-name (world-shapes world))))

(defun world-simple-contacts (world)
  "Every simple contact of WORLD's pairs, pair after pair, each pair's in its own order."
  (loop for pair in (world-pairs world)
        append (ames.geometry:pair-contacts pair)))
