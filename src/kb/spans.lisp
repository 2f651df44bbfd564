;;;; src/kb/spans.lisp -- straight spans between points of bodies: the geometry springs, ropes and
;;;; universal gravitation act along (thesis 3.3.2).
;;;;
;;;; A SPAN is the straight line from a point A of one body to a point B of another, each
;;;; written (BODY (X Y)) with (X Y) in the body's own frame. Springs act along their span,
;;;; each straight piece of a rope is a span, and gravitation acts along the span between
;;;; two bodies' reference points. Components that need one assert the belief
;;;;   (span NAME :from A :to B)
;;;; and the STRAIGHT-SPAN component below then defines its quantities:
;;;;   (span-length NAME)           |B - A|
;;;;   (span-direction NAME :x)     the unit vector from A toward B
;;;;   (span-acceleration NAME)     the second time derivative of the length
;;;; in one of two modes. While the two points move along the span's line (their relative
;;;; velocity and acceleration across it are zero), the direction is the one the state
;;;; starts with, u0, and the length is the projection (B - A).u0: linear in the positions,
;;;; so springs have closed forms in time and ropes constant accelerations (the thesis's
;;;; "springs along fixed directions"). Otherwise the span turns: the length is the square
;;;; root, the direction B - A over it, and the length's acceleration has its centripetal
;;;; part. The fixed-direction mode is entered when the relative velocity across the span
;;;; is zero at the start of a state; when the points leave the line at once (a relative
;;;; acceleration across it), its exit fires at once and the span turns from the start (the
;;;; simulator leaves a mode whose exit holds at once: src/simulator/choice.lisp). Both
;;;; descriptions are exact where they hold; the turning one is always right, the fixed one
;;;; is simpler. A span that starts at zero length (its points met at the end of the state
;;;; before: a spring shrunk to nothing, springs.lisp) has no B - A to take a direction from:
;;;; it opens along the points' relative velocity w0 (the limit of d/|d| as they separate),
;;;; mode :SEPARATING, its length (B - A).w0; with no relative velocity either its direction
;;;; is 0/0 and the span is refused by name (UNMODELLED-SITUATION). While a span keeps to
;;;; its line (both modes along it) it asserts (aligned-span NAME :from A :to B :opening O),
;;;; and (line-span-length A B O) is its length along the line, signed: it changes sign
;;;; where the points meet, which springs and ropes watch.
;;;;
;;;; Quantity terms used here that the simulator provides: (pos B :x), (vel B :x), (acc B :x)
;;;; and (initial-pos B :x), a free body's position at the start of the state. A fixed body's
;;;; points are constants: its entity carries its :position.

(in-package #:ames.kb)

;;; Points of bodies, as the components see them

(defun point-body (point) "The body of POINT, (BODY (X Y))." (first point))
(defun point-offset (point) "The offset (X Y) of POINT in its body's frame." (second point))

(defun fixed-body-p (situation body)
  "True when BODY is glued to the fixed frame."
  (entity-property (entity-named situation body) :fixed))

(defun point-term (situation point axis head)
  "The AXIS coordinate of POINT, a (BODY (X Y)), in the fixed frame: the body's state
quantity HEAD (POS or INITIAL-POS) plus the offset; for a fixed body, a constant."
  (let ((offset (axis-component (point-offset point) axis))
        (body (point-body point)))
    (if (fixed-body-p situation body)
        `(+ ,(axis-component (entity-property (entity-named situation body) :position '(0 0)) axis)
            ,offset)
        `(+ (,head ,body ,axis) ,offset))))

(defun point-rate (situation point axis head)
  "The AXIS component of POINT's velocity (HEAD VEL) or acceleration (HEAD ACC)."
  (if (fixed-body-p situation (point-body point))
      0
      (list head (point-body point) axis)))

(defun span-difference (situation a b head)
  "The vector from point A to point B, (DX DY), over the quantity HEAD: POS (now),
INITIAL-POS (at the state's start), VEL or ACC (its rates)."
  (mapcar (lambda (axis)
            (if (member head '(pos initial-pos))
                `(- ,(point-term situation b axis head) ,(point-term situation a axis head))
                `(- ,(point-rate situation b axis head) ,(point-rate situation a axis head))))
          '(:x :y)))

(defun initial-direction (situation a b)
  "The unit vector from A to B at the start of the state."
  (let* ((d0 (span-difference situation a b 'initial-pos))
         (norm (ames.geometry:vector-length d0)))
    (mapcar (lambda (x) `(/ ,x ,norm)) d0)))

(defun register-span-templates (kb)
  "Register in KB the template functions of spans measured along their starting direction,
their length and their starting sizes."
  (flet ((reg (head function documentation)
           (register-template kb head function :documentation documentation)))
    (reg 'initial-span-direction
         (lambda (situation a b axis) (axis-component (initial-direction situation a b) axis))
         "A component of the unit vector from A to B at the start of the state.")
    (reg 'aligned-span-length
         (lambda (situation a b)
           (ames.geometry:dot (span-difference situation a b 'pos) (initial-direction situation a b)))
         "The span's length while it keeps its starting direction: (B - A).u0.")
    (reg 'aligned-span-acceleration
         (lambda (situation a b)
           (ames.geometry:dot (span-difference situation a b 'acc) (initial-direction situation a b)))
         "The second derivative of that length: (B'' - A'').u0.")
    (reg 'span-transverse-rate
         (lambda (situation a b)
           (ames.geometry:cross (span-difference situation a b 'initial-pos) (span-difference situation a b 'vel)))
         "The relative velocity across the starting direction (times the starting length).")
    (reg 'span-offset
         (lambda (situation a b)
           (ames.geometry:cross (span-difference situation a b 'initial-pos) (span-difference situation a b 'pos)))
         "How far B - A has turned off the starting direction (times the starting length).")
    (reg 'current-span-length
         (lambda (situation a b) (ames.geometry:vector-length (span-difference situation a b 'pos)))
         "The span's length, |B - A|.")
    (reg 'span-vector
         (lambda (situation a b axis) (axis-component (span-difference situation a b 'pos) axis))
         "A component of B - A.")
    (reg 'turning-span-acceleration
         (lambda (situation a b span)
           (let ((d (span-difference situation a b 'pos))
                 (v (span-difference situation a b 'vel))
                 (w (span-difference situation a b 'acc))
                 (l `(span-length ,span)))
             `(- (/ (+ ,(ames.geometry:dot v v) ,(ames.geometry:dot d w)) ,l)
                 (/ (expt ,(ames.geometry:dot d v) 2) (expt ,l 3)))))
         "The second derivative of |B - A|: (|v|^2 + d.a)/l - (d.v)^2/l^3.")
    (reg 'span-start-length-squared
         (lambda (situation a b)
           (let ((d0 (span-difference situation a b 'initial-pos))) (ames.geometry:dot d0 d0)))
         "The square of the span's length at the start of the state.")
    (reg 'span-start-speed-squared
         (lambda (situation a b)
           (let ((v0 (span-difference situation a b 'initial-vel))) (ames.geometry:dot v0 v0)))
         "The square of the points' relative speed at the start of the state.")))

(defun register-separating-span-templates (kb)
  "Register in KB the template functions of spans that open from zero length along their
points' relative velocity, of spans that keep to their line, and the refusal of a span
whose direction is undefined."
  (flet ((reg (head function documentation)
           (register-template kb head function :documentation documentation)))
    (reg 'separating-span-direction
         (lambda (situation a b axis) (axis-component (separating-direction situation a b) axis))
         "A component of the unit vector along which a span of zero length at the start opens: its relative velocity's.")
    (reg 'separating-span-length
         (lambda (situation a b)
           (ames.geometry:dot (span-difference situation a b 'pos) (separating-direction situation a b)))
         "The length of a span opening from zero along the relative velocity w0: (B - A).w0.")
    (reg 'separating-span-acceleration
         (lambda (situation a b)
           (ames.geometry:dot (span-difference situation a b 'acc) (separating-direction situation a b)))
         "The second derivative of that length: (B'' - A'').w0.")
    (reg 'separating-span-offset
         (lambda (situation a b)
           (ames.geometry:cross (span-difference situation a b 'initial-vel) (span-difference situation a b 'pos)))
         "How far B - A has turned off the line it opened along (times the starting speed).")
    (reg 'line-span-length
         (lambda (situation a b opening)
           (ames.geometry:dot (span-difference situation a b 'pos)
                              (if opening
                                  (separating-direction situation a b)
                                  (initial-direction situation a b))))
         "The length of a span that keeps to its line, signed along it (it changes sign where
the points meet): (B - A).u0 along its starting direction, (B - A).w0 along its relative
velocity when OPENING (it started at zero length).")
    (reg 'span-direction-undefined #'undefined-span-direction
         "Signals UNMODELLED-SITUATION: a span of zero length whose points do not move apart.")))

(defun separating-direction (situation a b)
  "The unit vector of the relative velocity of B from A at the start of the state: the
direction a span of zero length opens along."
  (let* ((v0 (span-difference situation a b 'initial-vel))
         (norm (ames.geometry:vector-length v0)))
    (mapcar (lambda (x) `(/ ,x ,norm)) v0)))

(defun undefined-span-direction (situation span)
  "Signal UNMODELLED-SITUATION naming SPAN: its points coincide at the start of the state
and do not move apart, so its direction (Hooke's d/|d|, a tension's) is 0/0."
  (declare (ignore situation))
  (error 'unmodelled-situation
         :datum span
         :detail (format nil "~(~A~) has zero length, and its ends are at rest relative to each other: its direction is undefined (0/0); which way it opens is not modelled."
                         span)))

(register-span-templates *mechanics*)
(register-separating-span-templates *mechanics*)

(defcomponent straight-span (:knowledge-base *mechanics*)
  "A straight span from point A to point B (see the file header): its length, unit
direction and the length's second derivative, with the direction fixed at its starting
value while the points move along the span's line, turning otherwise. A span that starts
at zero length (its points met at the end of the state before) takes the direction they
separate along, that of their relative velocity; with no relative velocity either, its
direction is undefined and the span is refused, named (UNMODELLED-SITUATION)."
  (:arguments (?span :belief (span ?span :from ?a :to ?b)))
  (:mode :fixed-direction
   (:entry (<= (expt (span-transverse-rate ?a ?b) 2) 0) (> (span-start-length-squared ?a ?b) 0))
   (:assert (aligned-span ?span :from ?a :to ?b :opening nil))
   (:equations (= (span-length ?span) (aligned-span-length ?a ?b))
               (= (span-direction ?span :x) (initial-span-direction ?a ?b :x))
               (= (span-direction ?span :y) (initial-span-direction ?a ?b :y))
               (= (span-acceleration ?span) (aligned-span-acceleration ?a ?b)))
   (:transition :to :turning :when (> (expt (span-offset ?a ?b) 2) 0) :event (:turns ?span)))
  (:mode :turning
   (:entry (> (expt (span-transverse-rate ?a ?b) 2) 0))
   (:equations (= (span-length ?span) (current-span-length ?a ?b))
               (= (span-direction ?span :x) (/ (span-vector ?a ?b :x) (span-length ?span)))
               (= (span-direction ?span :y) (/ (span-vector ?a ?b :y) (span-length ?span)))
               (= (span-acceleration ?span) (turning-span-acceleration ?a ?b ?span))))
  (:mode :separating
   (:entry (<= (span-start-length-squared ?a ?b) 0) (> (span-start-speed-squared ?a ?b) 0))
   (:assert (aligned-span ?span :from ?a :to ?b :opening t))
   (:equations (= (span-length ?span) (separating-span-length ?a ?b))
               (= (span-direction ?span :x) (separating-span-direction ?a ?b :x))
               (= (span-direction ?span :y) (separating-span-direction ?a ?b :y))
               (= (span-acceleration ?span) (separating-span-acceleration ?a ?b)))
   (:transition :to :turning :when (> (expt (separating-span-offset ?a ?b) 2) 0) :event (:turns ?span)))
  (:mode :undefined-direction
   (:entry (<= (span-start-length-squared ?a ?b) 0) (<= (span-start-speed-squared ?a ?b) 0))
   (:equations (= (span-direction-undefined ?span) 0))))
