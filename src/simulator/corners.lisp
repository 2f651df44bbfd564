;;;; src/simulator/corners.lisp -- the corner contacts of rotating polygons and segments with
;;;; the fixed bodies' straight faces, described as entities for the knowledge base.
;;;;
;;;; A rotating body that is not a disc touches a fixed body at its corners: its contact
;;;; points turn with it, and the configuration-space obstacles of translating shapes do
;;;; not describe them. For each corner of such a body (a polygon's vertex, a segment's
;;;; end) and each straight face of each fixed body (a polygon's edge, a segment, a
;;;; half-plane's line), ames.geometry's VERTEX-ON-FACE gives the contact's gap, normal,
;;;; place along the face and arm as expressions of the body's (pos B :x), (pos B :y) and
;;;; (angle B); the situation gets one (corner-contact K :observer B :obstacle F :geometry
;;;; C) entity per pair (src/kb/corners.lisp says what it means); so does each corner of a
;;;; fixed polygon or segment with each straight face of the rotating body (the geometry's
;;;; ROTATING-BODY-CONTACTS gives both; which kind it is, only the geometry knows). A corner
;;;; touches only within its face (gap 0, place between the face's ends: CORNER-TOUCHING-NOW,
;;;; the knowledge base's activation). A rotating corner is described only on the fixed
;;;; faces it is in front of or on at the scenario's start (gap >= 0 decided): a fixed face
;;;; whose line the corner is behind (the underside of an incline under a block on its
;;;; slope) cannot be reached before another face of that convex body. A fixed corner is
;;;; described on every face of the rotating body: the body turns its faces, so one whose
;;;; line the corner is behind at the start may come round to it (a block spinning off a
;;;; ledge's edge strikes it with the face that was on the far side: block-step 2027 #650,
;;;; witness/disagreements/ames-wrong-block-step-2027-650.lisp). The corners of one
;;;; body touching one face at a state's start are each other's MATES (friction on such a
;;;; resting face is statically indeterminate: src/kb/friction.lisp, CORNER-FRICTION).

(in-package #:ames.simulator)

(defun corner-contact-name (index)
  "The symbol naming the INDEXth corner contact in the engine's situation."
  (intern (format nil "CORNER-~D" index) '#:ames.simulator))

(defun corner-body-p (body)
  "True when the scenario BODY is a free rotating polygon or segment: it touches with
its corners."
  (and (scenario-body-rotating-p body) (not (scenario-body-fixed-p body))
       (member (shape-kind (scenario-body-shape body)) '(:polygon :segment))))

(defun faced-body-p (body)
  "True when the scenario BODY is fixed and bounded by straight faces only."
  (and (scenario-body-fixed-p body)
       (member (shape-kind (scenario-body-shape body)) '(:polygon :segment :half-plane))))

(defun corner-configuration (body)
  "The configuration of the rotating BODY over its state terms."
  (let ((name (scenario-body-name body)))
    (ames.geometry:make-configuration `(ames.kb:pos ,name :x) `(ames.kb:pos ,name :y)
                                      `(ames.kb:angle ,name))))

(defun at-scenario-start (body expression)
  "EXPRESSION with BODY's state terms replaced by their values at the scenario's start."
  (let ((name (scenario-body-name body))
        (position (scenario-body-position body)))
    (substitute-expressions (list (cons `(ames.kb:pos ,name :x) (first position))
                                  (cons `(ames.kb:pos ,name :y) (second position))
                                  (cons `(ames.kb:angle ,name) (scenario-body-angle body)))
                            expression)))

(defvar *corner-contacts* (make-hash-table :test #'eq :weakness :key)
  "The corner contacts of each run, found once: run -> alist name -> geometry.")

(defun run-corner-contacts (run)
  "The alist name -> AMES.GEOMETRY:ROTATING-CONTACT of RUN's corner contacts (see the
file header), found at the first call."
  (multiple-value-bind (contacts found) (gethash run *corner-contacts*)
    (if found
        contacts
        (setf (gethash run *corner-contacts*) (find-corner-contacts run)))))

(defun find-corner-contacts (run)
  "RUN's corner contacts, numbered from 0 (see RUN-CORNER-CONTACTS)."
  (let ((scenario (run-scenario run)) (index 0) (contacts '()))
    (dolist (body (remove-if-not #'corner-body-p (scenario-bodies scenario)))
      (dolist (fixed (remove-if-not #'faced-body-p (scenario-bodies scenario)))
        (dolist (contact (ames.geometry:rotating-body-contacts
                          (run-bridge run) (run-shape run (scenario-body-name body))
                          (corner-configuration body) (run-shape run (scenario-body-name fixed))
                          :fixed-position (scenario-body-position fixed)))
          (when (or (eq (ames.geometry:rotating-contact-kind contact) :face-on-vertex)
                    (holds run `(>= ,(at-scenario-start body (ames.geometry:rotating-contact-gap contact)) 0)))
            (push (list* (corner-contact-name index) (scenario-body-name body)
                         (scenario-body-name fixed) contact)
                  contacts)
            (incf index)))))
    (nreverse contacts)))

(defun run-shape (run name)
  "The geometry shape of RUN's body NAME."
  (cdr (assoc name (run-shapes run))))

(defun touching-now-p (run body geometry)
  "True when the corner contact GEOMETRY of the rotating BODY (a name) touches at the start
of the current state, decided (CORNER-TOUCHING-NOW)."
  (eq (corner-touching-now run body geometry) :true))

(defun corner-touching-now (run body geometry)
  "Whether the corner contact GEOMETRY of the rotating BODY (a name) touches at the start
of the current state: its gap 0 and its point within the face (see the file header).
:TRUE, :FALSE, or (values :UNKNOWN RELATION) when the gap is 0 and the algebra does not
decide whether the point is within the face (RELATION, over the parameters, that would)."
  (let* ((position (body-position run body))
         (now (lambda (x)
                (substitute-expressions
                 (list (cons `(ames.kb:pos ,body :x) (first position))
                       (cons `(ames.kb:pos ,body :y) (second position))
                       (cons `(ames.kb:angle ,body) (body-angle run body)))
                 x))))
    (if (not (holds run `(= ,(funcall now (ames.geometry:rotating-contact-gap geometry)) 0)))
        :false
        (dolist (relation (ames.geometry:contact-extent-relations geometry) :true)
          (let ((relation (funcall now relation)))
            (case (decide run relation)
              (:true)
              (:false (return :false))
              (t (return (values :unknown relation)))))))))

(defun face-mates (run)
  "Alist corner contact name -> the names of the corner contacts of the same rotating
body on the same face that touch at the start of the current state (itself first when
it touches), in order: a flat face resting on a face is two of them."
  (let ((touching (loop for (name body nil . geometry) in (run-corner-contacts run)
                        when (touching-now-p run body geometry)
                          collect name)))
    (loop for (name body obstacle . geometry) in (run-corner-contacts run)
          collect (cons name
                        (loop for (other other-body other-obstacle . other-geometry) in (run-corner-contacts run)
                              when (and (member other touching)
                                        (eq other-body body) (eq other-obstacle obstacle)
                                        (equal (ames.geometry:rotating-contact-other-feature other-geometry)
                                               (ames.geometry:rotating-contact-other-feature geometry)))
                                collect other)))))

(defun corner-contact-entities (run)
  "The situation's CORNER-CONTACT entities of RUN (see the file header), each with
:MATES, the corners of its body touching its face now (FACE-MATES; itself alone when it
does not touch); and a RESTING-FACE entity (resting-face F :observer B :obstacle O
:corners (K1 K2)) for each two corners of one body touching one face now."
  (let ((mates (face-mates run)) (faces '()) (index 0))
    (append
     (loop for (name observer obstacle . geometry) in (run-corner-contacts run)
           for face-mates = (cdr (assoc name mates))
           when (and (eq name (first face-mates)) (rest face-mates))
             do (loop for other in (rest face-mates)
                      do (push (list 'ames.kb:resting-face
                                     (intern (format nil "FACE-~D" (incf index)) '#:ames.simulator)
                                     :observer observer :obstacle obstacle :corners (list name other))
                               faces))
           collect (list 'ames.kb:corner-contact name :observer observer :obstacle obstacle
                         :geometry geometry :mates (or face-mates (list name))))
     (reverse faces))))
