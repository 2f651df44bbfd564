;;;; src/simulator/choice-clusters.lisp -- the choice search (choice.lisp) factored over bodies
;;;; that do not interact.
;;;;
;;;; The search tries every combination of the corner alternatives' and the modes' options:
;;;; their product over the whole scene. Two bodies that each roll on their own incline add
;;;; their options' counts as a product (a disc at its incline's corner and a hoop rolling
;;;; on: 81 combinations), though neither body's choice bears on the other's. Where the
;;;; product exceeds *COMBINATION-LIMIT*, the choice points are split into CLUSTERS: the
;;;; moving bodies are joined when one instance of the model (active, or a choice point's)
;;;; involves both (a contact, a rope, a spring, gravitation between them; a fixed body
;;;; joins nothing), and each cluster's points are settled apart, by the same search, its
;;;; trials judged by the violations of its own bodies' instances only, the clusters not
;;;; settled yet touching nothing meanwhile (each trial solves the whole model). The assignments
;;;; found are then checked together, as one trial, by the whole model's violations: only
;;;; a consistent whole is taken; otherwise, and where the points do not split (a point
;;;; whose instance involves no moving body, or one cluster), the search refuses as before.
;;;; An ambiguity within a cluster is that cluster's, and is signalled as always.

(in-package #:ames.simulator)

(defvar *cluster-bodies* nil
  "While one cluster of choice points is settled: its moving bodies (the violations of
other bodies' instances are not its), else NIL.")

(defun key-bodies (run key)
  "The moving bodies that the instance KEY involves: named in its arguments, or in the
properties of the entities it names (a contact's observer and obstacle, a rope's ends),
one level deep."
  (let ((names (body-names run))
        (situation (ames.engine:model-situation (run-model run)))
        (bodies '()))
    (labels ((walk (x deep)
               (cond ((consp x) (walk (car x) deep) (walk (cdr x) deep))
                     ((and x (symbolp x) (member x names))
                      (unless (body-fixed-p run x) (pushnew x bodies)))
                     ((and x (symbolp x) (not (keywordp x)) (not deep))
                      (let ((entity (ames.engine:find-entity situation x)))
                        (when entity (walk (ames.engine:entity-properties entity) t)))))))
      (walk (rest key) nil))
    bodies))

(defun in-cluster-violations (run violations)
  "VIOLATIONS (IMMEDIATE-VIOLATIONS' entries, KEY first) less those of instances of
bodies outside *CLUSTER-BODIES* while a cluster is settled; all of them otherwise."
  (if (null *cluster-bodies*)
      violations
      (remove-if (lambda (entry)
                   (let ((bodies (key-bodies run (first entry))))
                     (and bodies (null (intersection bodies *cluster-bodies*)))))
                 violations)))

(defun body-clusters (run keys)
  "The moving bodies joined by the instances KEYS (each involving one or more): a list of
lists of bodies."
  (let ((clusters '()))
    (dolist (key keys clusters)
      (let* ((bodies (key-bodies run key))
             (joined (remove-if-not (lambda (c) (intersection c bodies)) clusters)))
        (when bodies
          (setf clusters (cons (reduce #'union joined :initial-value bodies)
                               (set-difference clusters joined))))))))

(defun point-clusters (run points)
  "POINTS split by the clusters of moving bodies (see the file header): a list of
(BODIES . POINTS), or NIL when they do not split."
  (let* ((keys (append (mapcar #'ames.engine:instance-key
                               (ames.engine:model-active-instances (run-model run)))
                       (mapcar #'ames.engine:choice-point-instance points)))
         (clusters (body-clusters run keys)))
    (when (and (rest clusters)
               (every (lambda (p) (key-bodies run (ames.engine:choice-point-instance p))) points))
      (let ((split (loop for bodies in clusters
                         for own = (remove-if-not
                                    (lambda (p)
                                      (intersection bodies (key-bodies run (ames.engine:choice-point-instance p))))
                                    points)
                         when own collect (cons bodies own))))
        (and (rest split) split)))))

(defun settle-by-clusters (run points)
  "The TRIAL of SETTLE-CHOICES over POINTS settled cluster by cluster and checked whole,
the model left in its assignment; NIL when the points do not split or the whole is not
consistent (see the file header)."
  (let ((split (point-clusters run points)))
    (when split
      ;; the clusters not yet settled touch nothing meanwhile (a free body is always
      ;; solvable; the model is solved whole for each trial)
      (apply-assignment run points
                        (loop for point in points
                              when (eq (ames.engine:choice-point-kind point) :activation)
                                collect (cons (ames.engine:choice-point-instance point) :false)))
      (let ((parts (loop for (bodies . own) in split
                         collect (let ((*cluster-bodies* bodies))
                                   (settle-points run own)))))
        (let ((whole (pivot run points '())))
          (when (eq (trial-verdict whole) :consistent)
            (setf (trial-notes whole)
                  (list :points (mapcar #'ames.engine:choice-point-instance points)
                        :chosen (trial-assignment whole)
                        :tried (loop for part in parts
                                     append (getf (trial-notes part) :tried))))
            whole))))))
