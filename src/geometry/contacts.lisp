;;;; src/geometry/contacts.lisp -- simple contacts: parametrization, path coordinates, conditions.
;;;;
;;;; A simple contact is one directed piece of the boundary of a configuration-space
;;;; obstacle: the relative positions q = position(observer) - position(obstacle) at
;;;; which two particular features of the bodies touch. It is a segment (:SEGMENT), an
;;;; unbounded line (:LINE, from a half-plane), an arc (:ARC) or a whole circle (:CIRCLE).
;;;; It is directed with the obstacle on its LEFT: the exterior (where the observer may
;;;; be) is on the right, and the outward normal, the direction in which the normal force
;;;; pushes the observer, is the unit tangent turned a quarter turn clockwise.
;;;;
;;;; Arc length s runs from 0 at the contact's start to its LENGTH at its end (on a line,
;;;; over all reals from the line's reference point; on a circle, modulo its length).
;;;;
;;;; Path coordinates (thesis section 2.5.7). With T(s) the unit tangent and K the signed
;;;; curvature, positive when the contact bends toward the obstacle (a convex arc of
;;;; radius r: K = 1/r; a concave one, the inside of a bowl: K = -1/r; a segment: 0):
;;;;   velocity     v = sdot T(s)
;;;;   acceleration a = sddot T(s) + sdot^2 K N(s)
;;;; where N(s) = T(s) turned a quarter turn counter-clockwise is the INWARD normal
;;;; (toward the obstacle's side). On a circle of radius R, a . N = sdot^2 / R: the
;;;; centripetal acceleration points at the centre.

(in-package #:ames.geometry)

(defclass simple-contact ()
  ((observer :initarg :observer :reader contact-observer
             :documentation "The name of the observer body.")
   (obstacle :initarg :obstacle :reader contact-obstacle
             :documentation "The name of the obstacle body.")
   (observer-feature :initarg :observer-feature :reader contact-observer-feature
                     :documentation "The observer's feature, e.g. (:point :of particle).")
   (obstacle-feature :initarg :obstacle-feature :reader contact-obstacle-feature
                     :documentation "The obstacle's feature, e.g. (:edge 2 :of wedge).")
   (piece :initarg :piece :reader contact-piece
          :documentation "The geometric piece (LINE-PIECE or ARC-PIECE).")
   (index :initarg :index :reader contact-index
          :documentation "The contact's position in its pair's list, from 0.")
   (length :initarg :length :reader contact-length
           :documentation "The arc length: an expression, or :INFINITE for a line.")
   (tangent :initarg :tangent :initform nil :reader contact-segment-tangent
            :documentation "For a straight contact, its unit tangent.")
   (tangent-angle :initarg :tangent-angle :initform nil :reader contact-segment-angle
                  :documentation "For a straight contact, the angle of its tangent.")
   (decider :initarg :decider :reader contact-decider)
   (neighbours :initform '() :accessor contact-neighbours
               :documentation "Alist: :START / :END -> the contact continuing past that end."))
  (:documentation "One simple contact between an observer and an obstacle body."))

(defun contact-kind (contact)
  "The kind of CONTACT: :SEGMENT, :LINE, :ARC or :CIRCLE."
  (let ((piece (contact-piece contact)))
    (etypecase piece
      (line-piece (if (line-piece-infinite piece) :line :segment))
      (arc-piece (if (arc-piece-full piece) :circle :arc)))))

(defun feature-description (feature)
  "A phrase naming FEATURE, e.g. \"edge 2 of WEDGE\" for (:edge 2 :of wedge)."
  (destructuring-bind (kind &rest more) feature
    (let* ((of (getf (if (integerp (first more)) (rest more) more) :of))
           (index (and (integerp (first more)) (first more))))
      (case kind
        (:point (format nil "~A (a point)" of))
        (:circle (format nil "the rim of ~A" of))
        (t (format nil "~(~A~)~@[ ~D~] of ~A" kind index of))))))

(defun contact-description (contact)
  "A sentence naming the features of CONTACT, for reports."
  (format nil "~A against ~A"
          (feature-description (contact-observer-feature contact))
          (feature-description (contact-obstacle-feature contact))))

(defmethod print-object ((contact simple-contact) stream)
  (print-unreadable-object (contact stream :type t)
    (format stream "~D ~(~A~): ~A" (contact-index contact) (contact-kind contact)
            (contact-description contact))))

(defun named-feature (name body)
  "The feature NAME, such as (:edge 2), of the body named BODY: (:edge 2 :of BODY)."
  (append name (list :of body)))

(defun decided-length (decider v)
  "The length of the vector V, exact when V is axis-aligned."
  (cond ((eql (vx v) 0) (if (positive-p decider (vy v)) (vy v) (e- (vy v))))
        ((eql (vy v) 0) (if (positive-p decider (vx v)) (vx v) (e- (vx v))))
        (t (vector-length v))))

(defun tidy-piece (decider piece)
  "PIECE with its defining expressions tidied (see TIDY)."
  (etypecase piece
    (line-piece (make-line-piece (tidy-vector decider (line-piece-start piece))
                                 (tidy-vector decider (line-piece-end piece))
                                 :name (line-piece-name piece)
                                 :infinite (line-piece-infinite piece)))
    (arc-piece (let ((from (tidy decider (arc-piece-from piece))))
                 (make-arc-piece (tidy-vector decider (arc-piece-center piece))
                                 (tidy decider (arc-piece-radius piece))
                                 from
                                 (tidy decider (e+ from (arc-signed-sweep piece)))
                                 (arc-piece-sense piece)
                                 :name (arc-piece-name piece)
                                 :full (arc-piece-full piece))))))

(defun simple-contact-measures (decider piece)
  "The measures of the simple contact along PIECE (a tidied piece), before they are
tidied: a plist of :TANGENT (a vector, or NIL for an arc), :TANGENT-ANGLE (or NIL) and
:LENGTH (:INFINITE for an infinite line)."
  (let ((straight (line-piece-p piece)))
    (list :tangent (and straight (unit-vector decider (line-direction piece)))
          :tangent-angle (and straight (angle-of-vector decider (line-direction piece)))
          :length (etypecase piece
                    (line-piece (if (line-piece-infinite piece)
                                    :infinite
                                    (decided-length decider (line-direction piece))))
                    (arc-piece (e* (arc-piece-radius piece)
                                   (if (arc-piece-full piece)
                                       (e* 2 'pi)
                                       (let ((sweep (arc-signed-sweep piece)))
                                         (if (eq (arc-piece-sense piece) :ccw)
                                             sweep (e- sweep))))))))))

(defun make-simple-contact (decider piece &key observer obstacle observer-feature
                                              obstacle-feature index)
  "The simple contact along PIECE between the features OBSERVER-FEATURE of the body
OBSERVER and OBSTACLE-FEATURE of OBSTACLE, its expressions tidied by the bridge."
  (let* ((piece (tidy-piece decider piece))
         (measures (simple-contact-measures decider piece))
         (tangent (getf measures :tangent))
         (angle (getf measures :tangent-angle))
         (length (getf measures :length)))
    (make-instance
     'simple-contact
     :observer observer :obstacle obstacle
     :observer-feature (named-feature observer-feature observer)
     :obstacle-feature (named-feature obstacle-feature obstacle)
     :piece piece :index index :decider decider
     :tangent (and tangent (tidy-vector decider tangent))
     :tangent-angle (and angle (tidy decider angle))
     :length (if (eq length :infinite) :infinite (tidy decider length)))))

;;; Geometry of a contact

(defun contact-sense (contact)
  "+1 when CONTACT turns counter-clockwise (a convex arc), -1 clockwise, 0 straight."
  (let ((piece (contact-piece contact)))
    (if (line-piece-p piece) 0 (if (eq (arc-piece-sense piece) :ccw) 1 -1))))

(defun contact-start (contact)
  "The point where s = 0 (a line's reference point; a circle's starting point)."
  (piece-start (contact-piece contact)))

(defun contact-end (contact)
  "The point at the end of CONTACT, or NIL for a line or a whole circle."
  (and (member (contact-kind contact) '(:segment :arc))
       (piece-end (contact-piece contact))))

(defun contact-center (contact)
  "The centre of an arc or circle CONTACT (NIL for straight contacts)."
  (let ((piece (contact-piece contact)))
    (and (arc-piece-p piece) (arc-piece-center piece))))

(defun contact-radius (contact)
  "The radius of an arc or circle CONTACT (NIL for straight contacts)."
  (let ((piece (contact-piece contact)))
    (and (arc-piece-p piece) (arc-piece-radius piece))))

(defun contact-curvature (contact)
  "The signed curvature: 1/r on a convex arc (bending toward the obstacle), -1/r on a
concave arc, 0 on a straight contact."
  (let ((piece (contact-piece contact)))
    (if (line-piece-p piece)
        0
        (e/ (contact-sense contact) (arc-piece-radius piece)))))

(defun contact-position-angle (contact s)
  "On an arc contact, the angle from the centre to the point at arc length S."
  (let ((piece (contact-piece contact)))
    (e+ (arc-piece-from piece) (e* (contact-sense contact) (e/ s (arc-piece-radius piece))))))

(defun segment-unit-tangent (contact)
  (contact-segment-tangent contact))

(defun contact-point (contact s)
  "The relative position (X Y) at arc length S along CONTACT."
  (let ((piece (contact-piece contact)))
    (etypecase piece
      (line-piece (v+ (line-piece-start piece) (vscale s (segment-unit-tangent contact))))
      (arc-piece (v+ (arc-piece-center piece)
                     (vscale (arc-piece-radius piece) (polar (contact-position-angle contact s))))))))

(defun contact-unit-tangent (contact s)
  "The unit tangent (direction of increasing s) at arc length S."
  (let ((piece (contact-piece contact)))
    (etypecase piece
      (line-piece (segment-unit-tangent contact))
      (arc-piece (vscale (contact-sense contact)
                         (rot-ccw (polar (contact-position-angle contact s))))))))

(defun contact-outward-normal (contact s)
  "The unit outward normal at arc length S: the direction in which the obstacle pushes
the observer."
  (rot-cw (contact-unit-tangent contact s)))

(defun contact-inward-normal (contact s)
  "The unit normal at S pointing toward the obstacle's side (the path-coordinate N)."
  (rot-ccw (contact-unit-tangent contact s)))

(defun contact-tangent-angle (contact s)
  "The angle of the unit tangent at arc length S, measured counter-clockwise from +x."
  (let ((piece (contact-piece contact)))
    (etypecase piece
      (line-piece (contact-segment-angle contact))
      (arc-piece (e+ (contact-position-angle contact s)
                     (e* (contact-sense contact) (e* 1/2 'pi)))))))

(defun contact-normal-angle (contact s)
  "The angle of the outward normal at arc length S (tangent angle minus a quarter turn)."
  (e- (contact-tangent-angle contact s) (e* 1/2 'pi)))

(defun path-velocity (contact s sdot)
  "The cartesian relative velocity of an observer moving along CONTACT at arc length S
with speed SDOT: SDOT T(S)."
  (declare (ignorable s))
  (vscale sdot (contact-unit-tangent contact s)))

(defun path-acceleration (contact s sdot sddot)
  "The cartesian relative acceleration of an observer moving along CONTACT at arc length
S, speed SDOT and tangential acceleration SDDOT: SDDOT T(S) + SDOT^2 K N(S), N the
inward normal and K the signed curvature."
  (v+ (vscale sddot (contact-unit-tangent contact s))
      (vscale (e* (esquare sdot) (contact-curvature contact))
              (contact-inward-normal contact s))))

;;; Where a relative position lies

(defun position-on-contact-p (contact q)
  "True when the relative position Q (a list (X Y)) lies on CONTACT, ends included."
  (point-on-piece-p (contact-decider contact) q (contact-piece contact)))

(defun contact-parameter (contact q)
  "The arc length s at which the relative position Q lies on CONTACT. Signals
POSITION-NOT-ON-CONTACT when it does not lie on it."
  (unless (position-on-contact-p contact q)
    (error 'position-not-on-contact :datum q :contact contact))
  (let ((piece (contact-piece contact)) (decider (contact-decider contact)))
    (tidy decider
          (etypecase piece
            (line-piece (dot (v- q (line-piece-start piece)) (segment-unit-tangent contact)))
            (arc-piece (e* (arc-piece-radius piece)
                           (angle-from-direction decider (polar (arc-piece-from piece))
                                                 (v- q (arc-piece-center piece))
                                                 :sense (arc-piece-sense piece))))))))

;;; Meeting a contact, leaving it

(defstruct (meeting (:constructor make-meeting (contact gap rate extent)))
  "How a relative trajectory q(tau) meets CONTACT: GAP is positive on the exterior side
of the contact's line or circle and zero on it (for a segment, the distance times the
segment's length; for an arc, |q - c|^2 - r^2 with the sign making the exterior
positive); RATE is d GAP / d tau; EXTENT lists the relations saying that q lies within
the contact's ends. The trajectory meets the contact from outside at the first time
tau > 0 with GAP = 0, RATE <= 0 and every EXTENT relation true."
  contact gap rate extent)

(defun meeting-conditions (meeting)
  "The conjunction, as a list of relations over tau, under which MEETING happens."
  (list* (list '= (meeting-gap meeting) 0)
         (list '<= (meeting-rate meeting) 0)
         (meeting-extent meeting)))

(defun arc-extent-relations (decider piece w)
  "Relations saying that the vector W from the centre points within the arc PIECE."
  (if (arc-piece-full piece)
      '()
      (let* ((range (arc-position-range piece))
             (lo (direction-vector (angular-range-from range)))
             (hi (direction-vector (angular-range-to range))))
        (ecase (range-sweep-class decider range)
          (:below-pi (list (list '>= (cross lo w) 0) (list '>= (cross w hi) 0)))
          (:pi (list (list '>= (cross lo w) 0)))
          (:above-pi (list (list 'or (list '>= (cross lo w) 0) (list '>= (cross w hi) 0))))))))

(defun contact-meeting (contact trajectory &key (time tau))
  "The MEETING of the relative trajectory TRAJECTORY, a list (X(tau) Y(tau)) of
expressions in the variable TIME, with CONTACT."
  (let* ((piece (contact-piece contact))
         (decider (contact-decider contact))
         (q (mapcar #'normalize-expression trajectory))
         (gap (etypecase piece
                (line-piece (dot (line-normal piece) (v- q (line-piece-start piece))))
                (arc-piece (let ((excess (e- (norm-squared (v- q (arc-piece-center piece)))
                                             (esquare (arc-piece-radius piece)))))
                             (if (eq (arc-piece-sense piece) :ccw) excess (e- excess))))))
         (extent (etypecase piece
                   (line-piece (if (line-piece-infinite piece)
                                   '()
                                   (let ((along (dot (v- q (line-piece-start piece))
                                                     (line-direction piece))))
                                     (list (list '>= along 0)
                                           (list '<= along (norm-squared (line-direction piece)))))))
                   (arc-piece (arc-extent-relations decider piece (v- q (arc-piece-center piece)))))))
    (make-meeting contact gap (differentiate gap time) extent)))

(defstruct (leaving (:constructor make-leaving (contact endpoint point equation direction neighbour)))
  "How an observer moving along CONTACT leaves it past an end: ENDPOINT is :START or
:END, POINT the relative position there, EQUATION the relation s = 0 or s = length,
DIRECTION the relation on the speed (sdot < 0 at the start, > 0 at the end), and
NEIGHBOUR the contact that continues past that end, or NIL."
  contact endpoint point equation direction neighbour)

(defun contact-leavings (contact s sdot)
  "The ways of leaving CONTACT past one of its ends, for an observer at arc length S
moving at speed SDOT (expressions, typically in tau): a list of LEAVING. A line or a
whole circle has no ends."
  (if (member (contact-kind contact) '(:line :circle))
      '()
      (list (make-leaving contact :start (contact-start contact)
                          (list '= s 0) (list '< sdot 0)
                          (cdr (assoc :start (contact-neighbours contact))))
            (make-leaving contact :end (contact-end contact)
                          (list '= s (contact-length contact)) (list '> sdot 0)
                          (cdr (assoc :end (contact-neighbours contact)))))))
