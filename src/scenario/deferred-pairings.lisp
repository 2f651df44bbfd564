;;;; src/scenario/deferred-pairings.lisp -- contact pairs left out of the world while their bodies are proven apart.
;;;;
;;;; The world holds a contact pair for every two bodies not both fixed: N^2 pairs, each
;;;; with its configuration-space contacts, their loci and the model's beliefs about them.
;;;; Most of them never matter: in a chain of blocks, the first and the third cannot touch
;;;; while the second is between them. When *PAIR-SCREEN* (bound by the simulator) proves
;;;; two bodies apart at the start, SCENARIO-GEOMETRY leaves their pair out (a deferred
;;;; pairing: its place in the order of every pairing and the two names). The run proves
;;;; each deferred pairing apart over each state, or builds it (WORLD-WITH-PAIRINGS) and
;;;; starts again: a pair is left out only while it is proven that it cannot touch.

(in-package #:ames.scenario)

(defun screened-pairings (scenario pairings)
  "The places (an EQL hash table ordinal -> T) of PAIRINGS ((BODY SHAPE OTHER
OTHER-SHAPE) ...) that *PAIR-SCREEN* proves apart at the start, or NIL when none is."
  (when *pair-screen*
    (let ((deferred (make-hash-table)))
      (loop for (body nil other) in pairings
            for ordinal from 0
            when (funcall *pair-screen* scenario body other)
              do (setf (gethash ordinal deferred) t))
      (and (plusp (hash-table-count deferred)) deferred))))

(defun pairing-ordinals (pairings deferred)
  "The places of PAIRINGS that the hash table DEFERRED does not hold, in order."
  (loop for nil in pairings
        for ordinal from 0
        unless (gethash ordinal deferred) collect ordinal))

(defun world-with-pairings (world bridge pairings)
  "A WORLD like WORLD with the contact pairs of the deferred PAIRINGS (a sublist of
WORLD-DEFERRED-PAIRINGS) built (through BRIDGE, under the assumptions in force, as
SCENARIO-GEOMETRY builds them) in their places among its pairs; the other deferred
pairings stay deferred."
  (let* ((scenario (world-scenario world))
         (new (loop for (ordinal name other-name) in pairings
                    collect (let ((body (find-scenario-body name scenario))
                                  (other (find-scenario-body other-name scenario)))
                              (cons ordinal
                                    (scenario-pair scenario bridge
                                                   body (world-shape world name)
                                                   other (world-shape world other-name))))))
         (merged (merge 'list
                        (mapcar #'cons
                                (or (world-pair-ordinals world)
                                    (loop for nil in (world-pairs world) for k from 0 collect k))
                                (world-pairs world))
                        (sort new #'< :key #'car)
                        #'< :key #'car)))
    (make-world scenario (world-shapes world) (mapcar #'cdr merged)
                :ordinals (mapcar #'car merged)
                :deferred (let ((built (make-hash-table)))
                            (dolist (entry pairings) (setf (gethash (first entry) built) t))
                            (remove-if (lambda (entry) (gethash (first entry) built))
                                       (world-deferred-pairings world))))))
