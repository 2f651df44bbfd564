;;;; src/simulator/face-end-corners.lisp -- a corner that reaches a fixed body's face exactly
;;;; at the face's end, at a speed, at the end of a numerically integrated state.
;;;;
;;;; A corner of a rotating body that crosses the line of a fixed face at one of its ends
;;;; meets the fixed body's vertex there, where the adjoining face begins. Locally the
;;;; fixed body (convex there) is the intersection of the two faces' half-planes: the
;;;; corner enters it only if it moves inside both lines. With g1 the reached face's gap
;;;; (closing at the speed found, r1 < 0) and g2 the adjoining face's (0 at the vertex),
;;;; of rate r2 there:
;;;;   r2 = 0 -- the corner moves along the adjoining face's line, into that face's extent
;;;;             (so the vertex is convex: at a concave one, a floor meeting a wall, it
;;;;             would be leaving the floor's end for the wall): it enters no solid, it
;;;;             slides onto the adjoining face at no normal speed (a block sliding flat
;;;;             on a ledge whose far corner comes onto the ledge's top at its edge). No
;;;;             impact: the meeting is a touching reached at no speed, and the next
;;;;             state's start settles which face holds the corner (choice.lisp: at a
;;;;             corner that is not concave it enters only inside every face);
;;;;   r2 < 0 -- it moves inside both: a corner strikes the vertex, whose normal is
;;;;             undefined: refused, named;
;;;;   r2 > 0 -- it passes outside the adjoining face: it misses the reached face beyond
;;;;             its end, but the search stopped there: refused, named.
;;;; The corner is not the only feature there: the fixed body's vertex meets the rotating
;;;; body's faces at the corner (a block's leading face sliding into a wedge's toe strikes
;;;; it while its corner runs along the wedge's base). So the slide is taken only when no
;;;; other corner contact of the two bodies that touches there (gap zero to round-off) is
;;;; closing; else refused.
;;;; "r2 = 0" is judged to the round-off of the integration (1e-9, relative to the
;;;; approach speed), as CORNER-AT-FACE-END-P judges the place. The adjoining face is the
;;;; corner contact of the same corner on the same fixed body whose gap is zero there
;;;; (to 1e-9): the corner contacts (corners.lisp) name the rotating body's feature and
;;;; the fixed body's face.

(in-package #:ames.simulator)

(defparameter *face-end-round-off* 1d-9
  "How near zero (relative to the approach speed, at least 1) a gap and its rate at a
face's end are judged zero: the numeric integration's round-off.")

(defun condition-corner-contact (run condition)
  "The entry (NAME OBSERVER OBSTACLE . GEOMETRY) of RUN's corner contact that the
termination CONDITION's instance names, or NIL."
  (let ((entries (run-corner-contacts run)))
    (labels ((walk (x)
               (cond ((and x (symbolp x)) (assoc x entries))
                     ((consp x) (or (walk (car x)) (walk (cdr x)))))))
      (walk (ames.engine:termination-condition-instance condition)))))

(defun adjoining-corner-contacts (run entry)
  "The corner contacts of the same corner of ENTRY's rotating body on other faces of the
same fixed body."
  (destructuring-bind (name observer obstacle . geometry) entry
    (loop for other in (run-corner-contacts run)
          for (other-name other-observer other-obstacle . other-geometry) = other
          when (and (not (eq other-name name)) (eq other-observer observer) (eq other-obstacle obstacle)
                    (eq (ames.geometry:rotating-contact-kind other-geometry)
                        (ames.geometry:rotating-contact-kind geometry))
                    (equal (ames.geometry:rotating-contact-feature other-geometry)
                           (ames.geometry:rotating-contact-feature geometry))
                    (not (equal (ames.geometry:rotating-contact-other-feature other-geometry)
                                (ames.geometry:rotating-contact-other-feature geometry))))
            collect other)))

(defun numeric-of-state (run solved groups terms expression)
  "EXPRESSION (over state terms) as a numeric function of the state vector and time."
  (numeric-function (numeric-expression run groups (over-state-terms run solved expression) terms)
                    (append (mapcar #'state-symbol terms) (list 'tau))))

(defun numeric-point (run solved groups terms point state time)
  "The contact POINT (two expressions over state terms) in the numeric STATE at TIME:
a list of two doubles, or NIL."
  (let* ((vector (concatenate 'simple-vector state (vector time)))
         (values (mapcar (lambda (x) (safe-value (numeric-of-state run solved groups terms x) vector))
                         point)))
    (and (every #'realp values) values)))

(defun numeric-gap-and-rate (run solved groups terms gap rates state time)
  "The value and the rate (central difference along RATES) of GAP (over state terms) in
the numeric STATE at TIME: two doubles, or NIL."
  (let* ((f (numeric-of-state run solved groups terms gap))
         (epsilon 1d-7)
         (velocity (funcall rates state)))
    (flet ((at (sign)
             (safe-value f (concatenate 'simple-vector
                                        (map 'simple-vector (lambda (y d) (+ y (* sign epsilon d))) state velocity)
                                        (vector (+ time (* sign epsilon)))))))
      (let ((value (at 0)) (ahead (at 1)) (behind (at -1)))
        (and value ahead behind (values value (/ (- ahead behind) (* 2 epsilon))))))))

(defun pair-corner-contacts (run entry)
  "The corner contacts other than ENTRY between ENTRY's two bodies (either kind: the
rotating body's corners on the fixed faces, the fixed corners on its faces)."
  (destructuring-bind (name observer obstacle . geometry) entry
    (declare (ignore geometry))
    (loop for other in (run-corner-contacts run)
          for (other-name other-observer other-obstacle) = other
          when (and (not (eq other-name name)) (eq other-observer observer) (eq other-obstacle obstacle))
            collect other)))

(defun touching-at-the-corner (run solved groups terms entry state time tolerance)
  "PAIR-CORNER-CONTACTS of ENTRY whose contact point is, in STATE at TIME, ENTRY's own
(to TOLERANCE): the features that meet where the corner meets the face's end (a corner
crossing a face's line far past its end is elsewhere)."
  (let ((here (numeric-point run solved groups terms
                             (ames.geometry:rotating-contact-point (cdddr entry)) state time)))
    (when here
      (remove-if-not (lambda (other)
                       (let ((there (numeric-point run solved groups terms
                                                   (ames.geometry:rotating-contact-point (cdddr other))
                                                   state time)))
                         (and there (every (lambda (a b) (<= (abs (- a b)) tolerance)) here there))))
                     (pair-corner-contacts run entry)))))

(defun enters-extent-p (run solved groups terms entry rates state time tolerance)
  "True when the corner of the corner contact ENTRY moves into its face's extent: every
end it is at (its margin zero to TOLERANCE) it leaves inward (the margin's rate above
TOLERANCE). At a convex vertex of the fixed body the corner sliding along the adjoining
face comes onto it from past its end; at a concave one (a floor meeting a wall) it
would leave that face toward the wall, which it strikes."
  (every (lambda (relation)
           (multiple-value-bind (margin speed)
               (numeric-gap-and-rate run solved groups terms (extent-margin relation) rates state time)
             (and margin (or (> (abs margin) tolerance) (> speed tolerance)))))
         (ames.geometry:contact-extent-relations (cdddr entry))))

(defun face-end-verdict (run solved groups terms condition rate rates state time)
  "How the corner of CONDITION's meeting, reached at the speed RATE (< 0) exactly at an
end of its face, goes on (see the file header): :SLIDES-ON (onto the adjoining face, no
impact), :STRIKES (the adjoining face closes too, or another corner contact of the two
bodies touching there closes: a fixed corner on the rotating body's face), or NIL (the
adjoining face is not found, or the corner passes beside it)."
  (let ((entry (condition-corner-contact run condition))
        (tolerance (* *face-end-round-off* (max 1d0 (abs rate))))
        (adjoining-slides nil))
    (when entry
      (let ((adjoining (same-corner-contacts run entry)))
        (dolist (other (touching-at-the-corner run solved groups terms entry state time tolerance))
          (multiple-value-bind (gap speed)
              (numeric-gap-and-rate run solved groups terms
                                    (ames.geometry:rotating-contact-gap (cdddr other))
                                    rates state time)
            (when (and gap (<= (abs gap) tolerance))
              (cond ((< speed (- tolerance)) (return-from face-end-verdict :strikes))
                    ((and (<= (abs speed) tolerance) (member other adjoining :test #'eq)
                          (enters-extent-p run solved groups terms other rates state time tolerance))
                     (setf adjoining-slides t))))))
        (and adjoining-slides :slides-on)))))

;;; A corner at a fixed body's convex vertex at the start of a state

(defun convex-vertex-partners (run name)
  "The corner contacts of the same corner as the :VERTEX-ON-FACE corner contact NAME, on
the other faces of the same fixed body, touching now at the same vertex with it, where
that vertex is convex (the fixed body there the intersection of the two faces'
half-planes: going from the vertex into the partner's face is going inside NAME's face's
line, n1 . t2 < 0, decided)."
  (let ((entry (assoc name (run-corner-contacts run))))
    ;; (a fixed corner at the rotating body's vertex, leaving one face for the other,
    ;; is not taken here: its inactive touchings then fire at once, state after state)
    (when (and entry (eq (ames.geometry:rotating-contact-kind (cdddr entry)) :vertex-on-face)
               (touching-now-p run (second entry) (cdddr entry)))
      (loop for other in (adjoining-corner-contacts run entry)
            for geometry = (cdddr other)
            when (and (touching-now-p run (second other) geometry)
                      (eq :true (decide run `(< ,(into-face-dot run entry other) 0))))
              collect other))))

(defun into-face-dot (run entry other)
  "n1 . t2: ENTRY's face's outward normal against the direction from the vertex into
OTHER's face (its tangent when the vertex is OTHER's face's start, else minus it), at
the start of the state (see CONVEX-VERTEX-PARTNERS)."
  (let* ((body (second entry))
         (now (lambda (x)
                (substitute-expressions
                 (list (cons `(ames.kb:pos ,body :x) (first (body-position run body)))
                       (cons `(ames.kb:pos ,body :y) (second (body-position run body)))
                       (cons `(ames.kb:angle ,body) (body-angle run body)))
                 x)))
         (g1 (cdddr entry)) (g2 (cdddr other))
         (at-start (holds run `(= ,(funcall now (ames.geometry:rotating-contact-place g2)) 0)))
         (tangent (ames.geometry:rotating-contact-tangent g2))
         (into (if at-start tangent (ames.geometry:vneg tangent))))
    (tidy run (funcall now (ames.geometry:dot (ames.geometry:rotating-contact-normal g1) into)))))

(defun enters-beside-convex-vertex-p (run solved key)
  "True when the inactive corner contact instance KEY, whose touching holds just after
the start, has its corner at a convex vertex of the fixed body (CONVEX-VERTEX-PARTNERS)
with a partner face whose gap does not turn negative at once: the corner goes inside
KEY's face's line beside the fixed body, along or outside the partner face, and enters
no solid (a block's corner sliding off the edge of a ledge's vertical side onto its
top). Such a corner does not penetrate; as a shape contact's touching alternatives
\(choice.lisp, PENETRATES-AT-ONCE): it enters only inside every face there."
  (let ((name (find-if (lambda (x) (and (symbolp x) (assoc x (run-corner-contacts run))))
                       (if (consp key) key (list key)))))
    (and name
         (some (lambda (partner)
                 (eq :false (goes-negative-at-once
                             run solved (ames.geometry:rotating-contact-gap (cdddr partner)))))
               (convex-vertex-partners run name)))))

(defun corner-verdict-at-vertex (run solved key verdict &optional fact)
  "VERDICT (and FACT) of whether the inactive instance KEY's touching holds just after
the start, as the choice search takes it: :FALSE instead of :TRUE for a corner that
goes beside a convex vertex (ENTERS-BESIDE-CONVEX-VERTEX-P)."
  (if (and (eq verdict :true) (enters-beside-convex-vertex-p run solved key))
      :false
      (values verdict fact)))

;;; The same meeting in closed form (guarded-meetings.lisp)

(defun shared-corner-feature (geometry)
  "The corner a corner contact's GEOMETRY is about: the rotating body's vertex (FEATURE)
for :VERTEX-ON-FACE, the fixed body's (OTHER-FEATURE) for :FACE-ON-VERTEX."
  (if (eq (ames.geometry:rotating-contact-kind geometry) :vertex-on-face)
      (ames.geometry:rotating-contact-feature geometry)
      (ames.geometry:rotating-contact-other-feature geometry)))

(defun same-corner-contacts (run entry)
  "The pair's other corner contacts of ENTRY's kind about the same corner (on other
faces): the faces adjoining at that corner, whichever body has it."
  (let ((geometry (cdddr entry)))
    (remove-if-not (lambda (other)
                     (let ((g (cdddr other)))
                       (and (eq (ames.geometry:rotating-contact-kind g)
                                (ames.geometry:rotating-contact-kind geometry))
                            (equal (shared-corner-feature g) (shared-corner-feature geometry)))))
                   (pair-corner-contacts run entry))))

(defun at-face-end-p (run guards at)
  "True when one of GUARDS (extent relations) holds with equality where AT puts it:
the meeting is exactly at an end of the face."
  (some (lambda (guard)
          (and (member (first guard) '(<= >= < >))
               (eq :true (decide run `(= ,(funcall at (extent-margin guard)) 0)))))
        guards))

(defun closed-form-face-end-verdict (run entry over-time time)
  "FACE-END-VERDICT for a closed-form motion (OVER-TIME gives an expression over state
terms as a function of TAU) at TIME, decided exactly: :SLIDES-ON, :STRIKES or NIL."
  (let ((adjoining (same-corner-contacts run entry))
        (point (ames.geometry:rotating-contact-point (cdddr entry)))
        (slides nil))
    (flet ((at (x) (tidy run (at-time (funcall over-time x) time)))
           (rate (x) (tidy run (at-time (time-derivative (funcall over-time x)) time))))
      (dolist (other (pair-corner-contacts run entry) (and slides :slides-on))
        (let ((g (cdddr other)))
          (when (and (eq :true (decide run `(= ,(at (ames.geometry:rotating-contact-gap g)) 0)))
                     (every (lambda (a b) (eq :true (decide run `(= ,(at `(- ,a ,b)) 0))))
                            (ames.geometry:rotating-contact-point g) point))
            (let ((speed (rate (ames.geometry:rotating-contact-gap g))))
              (case (decide run `(= ,speed 0))
                (:true (when (and (member other adjoining :test #'eq)
                                  (every (lambda (relation)
                                           (let ((margin (extent-margin relation)))
                                             (or (not (eq :true (decide run `(= ,(at margin) 0))))
                                                 (eq :true (decide run `(> ,(rate margin) 0))))))
                                         (ames.geometry:contact-extent-relations g)))
                         (setf slides t)))
                (t (return :strikes))))))))))

(defun closed-form-face-end (run condition guards at over-time time rate)
  "The answer (values :AT TIME RATE) of a guarded meeting of CONDITION that holds at TIME
with GUARDS (AT puts an expression there): as it is, unless the corner meets the face
exactly at its end; there, at RATE 0 (a touching, no impact) when it slides onto the
adjoining face (FACE-END-VERDICT's reasoning, decided exactly), else refused: main took
such a meeting for an impact on the face, and a block sliding flat off a ledge's edge
got an upward velocity from it."
  (let ((entry (condition-corner-contact run condition)))
    (cond ((or (null entry) (not (at-face-end-p run guards at))) (values :at time rate))
          ((eq (closed-form-face-end-verdict run entry over-time time) :slides-on) (values :at time 0))
          (t (error 'unsupported-situation
                    :datum (condition-event condition nil)
                    :detail "A corner meets a face exactly at the face's end, moving into the adjoining face too (or beside it): a corner striking the other body's vertex is not modelled.")))))
