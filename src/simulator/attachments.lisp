;;;; src/simulator/attachments.lisp -- the loci of points attached to bodies (the probes the
;;;; knowledge base's phenomena declare), and how relations over the state variables are
;;;; decided at a state's start.
;;;;
;;;; Nothing mechanical is computed here: the phenomena describe their clauses as entities
;;;; and their probes (src/kb/phenomena.lisp), the geometry gives a probe's loci against the
;;;; other bodies, and a relation over the state variables is decided on its values at
;;;; the start of the state.
;;;;
;;;; Generic rules this file adds (see STATE-RELATION-VERDICT and PROBE-VERDICT):
;;;;   - (initial-pos B :x) and (initial-vel B :x), a free body's coordinate and velocity at
;;;;     the start of the current state, are constants of the state: they are replaced by their
;;;;     values before the model is solved and before a condition is examined;
;;;;   - a relation over positions and velocities is decided on their values at the start; an
;;;;     equation X = 0 (or X /= 0) that holds at the start may stop holding at once, as a
;;;;     touching contact may: it is a :CHOICE, settled by consistency (src/simulator/choice.lisp);
;;;;   - a point attached to a body (a probe) has loci on the other bodies' shapes that can be
;;;;     crossed: (<= (contact-gap K) 0) holds while the obstacle reaches or covers the point.

(in-package #:ames.simulator)

;;; Probes: points attached to bodies, and their loci on the other bodies

(defun translated-shape (shape offset)
  "The scenario SHAPE form moved by -OFFSET (its points minus OFFSET), or NIL for a point
(a point has no locus for another point)."
  (flet ((moved (p) (list `(- ,(first p) ,(first offset)) `(- ,(second p) ,(second offset))))
         (arc-moved (form)
           (let ((copy (copy-list form)))
             (setf (getf (cdr copy) :center)
                   (list `(- ,(first (getf (cdr form) :center)) ,(first offset))
                         `(- ,(second (getf (cdr form) :center)) ,(second offset))))
             copy)))
    (ecase (shape-kind shape)
      (:point nil)
      (:circle `(ames-scenario:outline
                 (ames-scenario:arc :center ,(moved '(0 0)) :radius ,(second shape)
                                    :from 0 :to (* 2 pi))))
      ((:polygon :segment :half-plane) (cons (first shape) (mapcar #'moved (rest shape))))
      (:arc (arc-moved shape))
      (:outline (cons (first shape)
                      (mapcar (lambda (piece)
                                (if (string= (symbol-name (first piece)) "LINE")
                                    (cons (first piece) (mapcar #'moved (rest piece)))
                                    (arc-moved piece)))
                              (rest shape)))))))

(defun straight-contact-p (contact)
  "True when the geometry CONTACT is a line or a segment."
  (member (ames.geometry:contact-kind contact) '(:segment :line)))

(defun facing-axis-p (bridge contact axis)
  "True when the geometry CONTACT can be reached by a point retreating along AXIS: a
curved one, or a straight one whose outward normal is against AXIS."
  (or (not (straight-contact-p contact))
      (ames.algebra:holds-p bridge (list '< (ames.geometry:dot axis (ames.geometry:contact-outward-normal contact 0))
                                         0))))

(defun free-body-p (body)
  "True when the scenario BODY moves under the forces on it (neither fixed nor driven)."
  (not (or (scenario-body-fixed-p body) (scenario-body-driven-p body))))

(defun refuse-point-against-probe (probe body)
  "Signal UNSUPPORTED-SITUATION: the free point BODY and the PROBE's point (a point
attached to another body, such as a bumper's free end) have no locus on each other, so a
meeting of the two would go unseen and the body would pass through the probe's point."
  (error 'unsupported-situation
         :datum (scenario-body-name body)
         :detail (format nil "~A is a point, and so is the end of ~A it could press: ~
the model has no contact between two points, so it would pass through it unseen; give ~A a ~
shape (a small polygon or circle)."
                         (scenario-body-name body) (getf probe :point) (scenario-body-name body))))

(defun probe-loci (scenario bridge first-index)
  "The loci of the probes the phenomena declare (AMES.KB:PROBES-OF: points attached to
bodies that retreat along an axis when pressed, such as a bumper's free end) on every
other body: (values CONTACTS KINDS), CONTACTS an alist name -> geometry contact (observer
the probe's body, obstacle the other body, whose shape is moved so that the relative
position of the two bodies is on the locus when the probe's point is on the other body's
boundary; only the faces that can meet a point retreating along the axis), KINDS an
alist name -> (:KIND ENTITY-KIND :POINT PROBE :AXIS (UX UY)). Names continue from
FIRST-INDEX."
  (let ((contacts '()) (kinds '()) (index first-index)
        (point-shape (ames.geometry:parse-shape 'ames-scenario:point :bridge bridge)))
    (dolist (probe (ames.kb:probes-of scenario))
      (let* ((mount (find-scenario-body (getf probe :body) scenario))
             (end (mapcar (lambda (x) (ames.maxima:simplify bridge x)) (getf probe :at)))
             (axis (mapcar (lambda (x) (ames.maxima:simplify bridge x)) (getf probe :axis))))
        (dolist (body (scenario-bodies scenario))
          (let ((shape (translated-shape (scenario-body-shape body) end)))
            (when (and (null shape) (not (eq body mount)) (free-body-p body))
              (refuse-point-against-probe probe body))
            (unless (or (eq body mount) (null shape)
                        (and (scenario-body-fixed-p body) (scenario-body-fixed-p mount)))
              (let ((pair (ames.geometry:make-contact-pair-with-observer
                           (scenario-body-name mount) point-shape
                           (scenario-body-name body) (ames.geometry:parse-shape shape :bridge bridge)
                           :bridge bridge)))
                (dolist (contact (ames.geometry:pair-contacts pair))
                  (when (facing-axis-p bridge contact axis)
                    (let ((name (contact-entity-name index)))
                      (incf index)
                      (push (cons name contact) contacts)
                      (push (list name :kind (getf probe :kind) :point (getf probe :point) :axis axis)
                            kinds))))))))))
    (values (nreverse contacts) (nreverse kinds))))

(defun locus-kind (run contact)
  "The plist (:KIND K ...) of a probe's locus CONTACT, or NIL for a contact of two shapes."
  (cdr (assoc contact (run-locus-kinds run))))

(defun contact-entity (run name geometry)
  "The situation's entity for the contact NAME: a SIMPLE-CONTACT between two shapes, or
the kind its probe's locus has."
  (let ((kind (locus-kind run name)))
    (list* (if kind (getf kind :kind) 'ames.kb:simple-contact) name
           :observer (ames.geometry:contact-observer geometry)
           :obstacle (ames.geometry:contact-obstacle geometry)
           :geometry geometry
           (and kind (list :point (getf kind :point))))))

(defun shape-contact-p (run contact)
  "True when CONTACT is a locus of two bodies' shapes (not of a probe): one a body can touch."
  (null (locus-kind run contact)))

(defun holds-everywhere (run relations)
  "True when every relation of RELATIONS (possibly OR forms) holds under the assumptions."
  (every (lambda (r)
           (if (eq (first r) 'or)
               (some (lambda (part) (holds-everywhere run (list part))) (rest r))
               (holds run r)))
         relations))

(defun probe-verdict (run contact)
  "Whether the obstacle of the probe locus CONTACT reaches or presses the probe's point at
the start of the state, as the decider answers (<= (contact-gap CONTACT) 0). The point
pressed retreats along its axis and stays on the face: on a straight face it is pressed
when its resting point lies behind the face's line and, moved back along the axis onto
it, within the face's ends. :TRUE when pressed, or on the face with the obstacle moving
in; :FALSE when in front of the face, past its ends, or on it moving away; :CHOICE on it
with no normal velocity; :UNKNOWN when a sign is not decided. On a curved face only the
touching case is recognised (a point behind it reads :FALSE)."
  (let* ((geometry (contact-geometry run contact))
         (q (relative-initial-state run contact))
         (axis (getf (locus-kind run contact) :axis)))
    (multiple-value-bind (gap end)
        (if (straight-contact-p geometry)
            (let* ((normal (ames.geometry:contact-outward-normal geometry 0))
                   (start (ames.geometry:contact-point geometry 0))
                   (gap (tidy run (ames.geometry:dot (ames.geometry:v- q start) normal)))
                   (retreat (tidy run `(/ ,gap ,(ames.geometry:dot axis normal)))))
              (values gap (mapcar (lambda (x) (tidy run x)) (ames.geometry:v- q (ames.geometry:vscale retreat axis)))))
            (values (tidy run (ames.geometry:meeting-gap (ames.geometry:contact-meeting geometry q))) q))
      (cond ((not (holds-everywhere run (ames.geometry:meeting-extent
                                         (ames.geometry:contact-meeting geometry end))))
             :false)
            (t (case (one-sign (sign-of run gap))
                 (:negative (if (straight-contact-p geometry) :true :false))
                 (:positive :false)
                 (:zero (case (one-sign (sign-of run (normal-approach run contact)))
                          (:negative :true) (:zero :choice) (:positive :false) (t :unknown)))
                 (t :unknown)))))))

;;; The state's starting values in relations and equations

(defun starting-values (run)
  "Alist of the state terms' values at the start of the state: every free body's
(initial-pos B :x/:y), (pos B :x/:y), (initial-vel B :x/:y) and (vel B :x/:y)."
  (loop for body in (free-body-names run)
        for p = (body-position run body) for v = (body-velocity run body)
        append (loop for axis in '(:x :y)
                     collect (cons (list 'ames.kb:initial-pos body axis) (axis-of p axis))
                     collect (cons (list 'ames.kb:pos body axis) (axis-of p axis))
                     collect (cons (list 'ames.kb:initial-vel body axis) (axis-of v axis))
                     collect (cons (list 'ames.kb:vel body axis) (axis-of v axis)))))

(defun with-initial-positions (run expression)
  "EXPRESSION with every (initial-pos B :x) and (initial-vel B :x) replaced by B's
coordinate or velocity at the start of the state: constants of the state (see
STATE-CONSTANT-TERM-P); then square roots of the constants' perfect squares taken (see
CONSTANT-ROOTS-TAKEN)."
  (constant-roots-taken
   run (if (some #'state-constant-term-p (expression-variables expression))
           (substitute-expressions (remove-if-not #'state-constant-term-p (starting-values run)
                                                  :key #'car)
                                   expression)
           expression)))

(defun state-constant-term-p (term)
  "True when TERM is (initial-pos B :x) or (initial-vel B :x): a free body's coordinate or
velocity at the start of the current state, a constant of the state."
  (and (consp term) (member (first term) '(ames.kb:initial-pos ames.kb:initial-vel)) t))

(defun constant-roots-taken (run expression)
  "EXPRESSION with each square root of a constant (no quantity term in it) whose radicand
is the square of an expression X of decided sign replaced by X or -X (see
TAKE-CONSTANT-ROOTS)."
  (if (find-sqrt expression) (take-constant-roots run expression) expression))

(defun find-sqrt (expression)
  "True when EXPRESSION has a square root."
  (and (consp expression)
       (or (eq (first expression) 'sqrt) (some #'find-sqrt (rest expression)))))

(defun rational-square-root (x)
  "The square root of the positive rational X when it is rational, else NIL."
  (and (rationalp x) (plusp x)
       (let ((n (isqrt (numerator x))) (d (isqrt (denominator x))))
         (and (= (* n n) (numerator x)) (= (* d d) (denominator x)) (/ n d)))))

(defun scaled-square (radicand)
  "When RADICAND is X^2, X^2 / N or N X^2 with N a rational square, (values X SQRT-OF-SCALE);
else NIL."
  (flet ((square-base (x) (and (consp x) (eq (first x) 'expt) (eql (third x) 2) (second x))))
    (cond ((square-base radicand) (values (square-base radicand) 1))
          ((and (consp radicand) (eq (first radicand) '/) (= (length radicand) 3)
                (square-base (second radicand)) (rational-square-root (third radicand)))
           (values (square-base (second radicand)) (/ (rational-square-root (third radicand)))))
          ((and (consp radicand) (eq (first radicand) '*) (= (length radicand) 3)
                (rational-square-root (second radicand)) (square-base (third radicand)))
           (values (square-base (third radicand)) (rational-square-root (second radicand))))
          (t nil))))

(defun take-constant-roots (run expression)
  "EXPRESSION with each square root of a constant (no quantity term in it) whose radicand
is the square of an expression X of decided sign, possibly scaled by a rational square
(SCALED-SQUARE), replaced by X or -X (times the scale's root): the length of a span along
an axis, sqrt((top - h)^2) = top - h when top > h, sqrt((2 top - h)^2/4) = (2 top - h)/2,
which Maxima alone leaves when its sign needs the order of the parameters."
  (cond ((atom expression) expression)
        ((quantity-term-p expression) expression)
        ((and (eq (first expression) 'sqrt)
              (notany #'quantity-term-p (expression-variables (second expression))))
         (multiple-value-bind (base scale) (scaled-square (tidy run (second expression) :full))
           (if base
               (let ((root (if (eql scale 1) base `(* ,scale ,base))))
                 (case (one-sign (sign-of run base))
                   (:positive root)
                   (:negative `(- ,root))
                   (t expression)))
               expression)))
        (t (cons (first expression)
                 (mapcar (lambda (x) (take-constant-roots run x)) (rest expression))))))
