;;;; src/kb/closed-rope-pieces.lisp -- a rope's piece closed up at its pulley (the rope
;;;; phenomenon of ropes.lisp, its closing part): a weight pulled up into its pulley, a
;;;; particle dragged up an incline to the pulley at its top.
;;;;
;;;; The closing (ropes.lisp's ROPE-PIECE-CLOSING) reached with a speed is an impact. The
;;;; piece's length is a unilateral constraint there: the pulley's body stops the body at
;;;; the piece's other end with an impulse P >= 0 along the piece, Newton's law of
;;;; restitution on the piece's rate (the pair's restitution, 0 by default), and the rope,
;;;; at its full length, is jerked at once (ROPE-JERK: one impulse J >= 0 all along). The
;;;; impact's situation marks the piece whose closing it is (its entity :REACHED
;;;; ROPE-PIECE-CLOSING, the component whose condition was reached); its
;;;; length is zero, and its direction the limit of d/|d| as it closed: minus its ends'
;;;; relative velocity just before, over its size.
;;;;
;;;; After a plastic stop the piece has zero length and its ends are at rest relative to
;;;; each other: it has no direction (a span with no direction: ROPE-SEGMENT-SPAN asserts
;;;; none for it). While the rope is taut the body is held at the pulley's point: its
;;;; point's acceleration is the pulley point's, by a hold force F of unknown components
;;;; from the pulley's body (Newton's third law on it), which replaces the tension along
;;;; the piece; the piece counts length 0 and length acceleration 0 in the rope's sum. The
;;;; pulley pushes along the piece with P >= 0 and the rope pulls with T, so F = (P - T) u
;;;; for the piece's direction u either way: consistent when |F| <= T (P = T -+ |F|). The
;;;; state ends when F.F would exceed T^2, (:leaves-pulley ROPE A B): the piece would
;;;; open from rest along a direction nothing gives (not modelled: the refusal names the
;;;; piece, at once or in the next state). A closed piece at a rotating body (its point
;;;; pinned is a hinge) and a piece held at a later impact are refused, named. A rope with
;;;; a closed piece is never slack (ROPE-MAY-SLACKEN): its tension turning negative, or
;;;; two pieces of one rope closed at once, leave no consistent model (the run stops,
;;;; not modelled). After a stop with restitution the piece opens again along its ends'
;;;; relative velocity (spans.lisp's :SEPARATING mode).
;;;;
;;;; The rope component reads its length at a state's start with the piece at zero length
;;;; counted as such: the belief (rope-start ROPE :zero-piece S) names it (NIL: none).

(in-package #:ames.kb)

;;; The piece at zero length at a state's start

(defun straight-pieces (situation rope)
  "ROPE's straight pieces between two bodies (not wound, not within one body)."
  (remove-if (lambda (s)
               (let ((entity (entity-named situation s)))
                 (or (not (eq (ames.engine:entity-kind entity) 'rope-segment))
                     (entity-property entity :within-one-body))))
             (rope-segments situation rope)))

(defun start-length-squared (situation segment)
  "The square of SEGMENT's length at the state's start."
  (multiple-value-bind (a b) (segment-points situation segment)
    (let ((d0 (span-difference situation a b 'initial-pos))) (ames.geometry:dot d0 d0))))

(defun start-speed-squared (situation segment)
  "The square of SEGMENT's ends' relative speed at the state's start."
  (multiple-value-bind (a b) (segment-points situation segment)
    (let ((v0 (span-difference situation a b 'initial-vel))) (ames.geometry:dot v0 v0))))

(defun zero-piece-rate-now (situation segment)
  "The rate at which SEGMENT, of zero length at the state's start, opens then: its ends'
relative speed (the limit of d.v/|d| as it opens along v; 0 when it is closed at rest)."
  `(sqrt ,(start-speed-squared situation segment)))

(defun piece-end-rotating-p (situation segment)
  "The body at an end of SEGMENT that rotates (not fixed), or NIL."
  (multiple-value-bind (a b) (segment-points situation segment)
    (find-if (lambda (body)
               (let ((entity (entity-named situation body)))
                 (and (entity-property entity :rotating) (not (entity-property entity :fixed)))))
             (list (point-body a) (point-body b)))))

(defun refuse-closed-piece (situation segment why)
  "Signal UNMODELLED-SITUATION naming SEGMENT, closed at its pulley, and WHY (a string)."
  (let ((entity (entity-named situation segment)))
    (multiple-value-bind (a b) (segment-points situation segment)
      (error 'unmodelled-situation
             :datum segment
             :detail (format nil "The piece of rope ~(~A~) between ~(~A~) and ~(~A~) is closed up at its pulley: ~A is not modelled."
                             (entity-property entity :rope) (point-body a) (point-body b) why)))))

(defun register-closed-piece-templates (kb)
  "Register in KB the template functions of rope pieces at zero length in a state."
  (flet ((reg (head function documentation)
           (register-template kb head function :documentation documentation)))
    (reg 'rope-pieces-apart
         (lambda (situation rope)
           (let ((pieces (straight-pieces situation rope)))
             (if pieces
                 `(> (* ,@(mapcar (lambda (s) (start-length-squared situation s)) pieces)) 0)
                 '(> 1 0))))
         "Every straight piece of the rope has a length at the state's start.")
    (reg 'piece-at-zero-length
         (lambda (situation segment) `(<= ,(start-length-squared situation segment) 0))
         "The piece has zero length at the state's start.")
    (reg 'piece-closed-at-start
         (lambda (situation segment)
           `(<= (+ ,(start-length-squared situation segment) ,(start-speed-squared situation segment)) 0))
         "The piece has zero length and its ends are at rest relative to each other at the state's start.")
    (reg 'rope-may-slacken
         (lambda (situation zero)
           (if zero `(> ,(start-speed-squared situation zero) 0) '(> 1 0)))
         "The rope may be slack at the state's start: it has no piece closed at its pulley
(ZERO, its piece at zero length, or NIL, opens).")
    (reg 'closed-piece-length
         (lambda (situation segment)
           (when (piece-end-rotating-p situation segment)
             (refuse-closed-piece situation segment "a rotating body held at a pulley by its point (a hinge)"))
           `(span-length ,segment))
         "The length of a piece closed at its pulley (a rotating body at its end is refused, named).")
    (reg 'closed-piece-released
         (lambda (situation segment)
           (refuse-closed-piece situation segment "its body pulled off the pulley (the hold would exceed the tension), the piece opening from rest along a direction nothing gives,"))
         "Signals UNMODELLED-SITUATION: a closed piece's body pulled off its pulley.")
    (reg 'closed-piece-relative-acceleration
         (lambda (situation segment axis)
           (multiple-value-bind (a b) (segment-points situation segment)
             (axis-component (span-difference situation a b 'acc) axis)))
         "A component of the acceleration of the piece's end point relative to its start point.")))

(register-closed-piece-templates *mechanics*)

(defcomponent rope-pieces-apart (:knowledge-base *mechanics*)
  "A rope whose straight pieces all have a length at the state's start has no piece at
zero length (the rope's length is read as ropes.lisp says)."
  (:arguments (?rope :entity rope))
  (:activation (rope-pieces-apart ?rope))
  (:assert (rope-start ?rope :zero-piece nil)))

(defcomponent rope-piece-at-zero-length (:knowledge-base *mechanics*)
  "A rope's straight piece of zero length at the state's start (its body at its pulley:
stopped there, or bouncing off) counts 0 in the rope's length, and opens at its ends'
relative speed."
  (:arguments (?segment :entity rope-segment :where (:rope ?rope :within-one-body nil)))
  (:activation (piece-at-zero-length ?segment))
  (:assert (rope-start ?rope :zero-piece ?segment)))

(defcomponent held-at-pulley (:knowledge-base *mechanics*)
  "A taut rope's piece closed at its pulley (zero length, its ends at rest relative to
each other) holds its body there: the two end points accelerate alike, by a hold force
F of unknown components from the pulley's body on the body (Newton's third law on the
pulley's body) in place of the tension along the piece; the piece counts length 0 and
length acceleration 0 in the rope's sum. It holds while the pulley's push along the
piece is possible, F.F <= T^2; beyond, (:leaves-pulley ROPE A B): the piece would open
from rest along a direction nothing gives, refused (named) at once or in the next state.
A rotating body at the piece's end (its point pinned: a hinge) is refused, named."
  (:arguments (?segment :entity rope-segment
                        :where (:rope ?rope :from (?body1 ?_) :to (?body2 ?_) :within-one-body nil)))
  (:activation (piece-closed-at-start ?segment) (:believes (taut ?rope)))
  (:mode :held
   (:entry :always)
   (:assert (held-at-pulley ?segment :rope ?rope)
            (force (pulley-hold ?segment ?body2) :type pulley-hold :from ?body1 :on ?body2 :contact ?segment)
            (force (pulley-hold ?segment ?body1) :type pulley-hold :from ?body2 :on ?body1 :contact ?segment)
            (reported :forces (:pulley-hold ?rope ?body1 ((fx pulley-hold ?segment ?body1)
                                                          (fy pulley-hold ?segment ?body1))))
            (reported :forces (:pulley-hold ?rope ?body2 ((fx pulley-hold ?segment ?body2)
                                                          (fy pulley-hold ?segment ?body2)))))
   (:equations (= (closed-piece-length ?segment) 0)
               (= (span-acceleration ?segment) 0)
               (= (closed-piece-relative-acceleration ?segment :x) 0)
               (= (closed-piece-relative-acceleration ?segment :y) 0))
   (:transition :to :released
                :when (> (- (+ (expt (force-x (pulley-hold ?segment ?body2)) 2)
                               (expt (force-y (pulley-hold ?segment ?body2)) 2))
                            (expt (tension ?rope) 2))
                         0)
                :event (:leaves-pulley ?rope ?body1 ?body2)))
  ;; entered only by that transition (never at a state's start)
  (:mode :released
   (:entry (< 1 0))
   (:equations (= (closed-piece-released ?segment) 0))))

;;; At the impact of the closing

(defun closing-piece-direction (situation segment)
  "The unit vector along SEGMENT, from its :FROM point toward its :TO point, in the limit
as it closed: minus the relative velocity of its :TO body from its :FROM body just
before, over its size. A rotating body at an end, and positions known only as numbers
(the end of a state integrated numerically), are refused, named."
  (when (piece-end-rotating-p situation segment)
    (refuse-closed-piece situation segment "a rotating body striking a pulley by its point"))
  (multiple-value-bind (a b) (segment-points situation segment)
    ;; the end of a state integrated numerically: the body is at its pulley only to
    ;; round-off, and the next state could not tell the piece closed
    (when (some #'floatp (alexandria:flatten (list (impact-point situation a) (impact-point situation b))))
      (refuse-closed-piece situation segment "a closing found with numbers (the body at its pulley only to round-off)")))
  (multiple-value-bind (a b) (segment-points situation segment)
    (let* ((v (mapcar (lambda (q p) `(- ,q ,p))
                      (entity-property (entity-named situation (point-body b)) :velocity '(0 0))
                      (entity-property (entity-named situation (point-body a)) :velocity '(0 0))))
           (speed (ames.geometry:vector-length v)))
      (mapcar (lambda (x) `(- (/ ,x ,speed))) v))))

(defun closing-piece-rate (situation segment head)
  "The rate of SEGMENT's length just before (HEAD :BEFORE, minus its ends' relative speed)
or just after (:AFTER) the impact of its closing, along its direction then."
  (multiple-value-bind (a b) (segment-points situation segment)
    (flet ((velocity (point)
             (let ((body (point-body point)))
               (ecase head
                 (:before (entity-property (entity-named situation body) :velocity '(0 0)))
                 (:after (list `(vel-after ,body :x) `(vel-after ,body :y)))))))
      (ames.geometry:dot (closing-piece-direction situation segment)
                         (mapcar (lambda (q p) `(- ,q ,p)) (velocity b) (velocity a))))))

(defun impact-piece-closed (situation segment)
  "Template IMPACT-PIECE-CLOSED: SEGMENT has zero length at the impact and its closing is
not the impact's (a piece held at its pulley since an earlier state); never for a
piece whose closing the impact is."
  (if (eq (entity-property (entity-named situation segment) :reached) 'rope-piece-closing)
      '(< 1 0)
      (multiple-value-bind (a b) (segment-points situation segment)
        (let ((d (mapcar (lambda (q p) `(- ,q ,p)) (impact-point situation b) (impact-point situation a))))
          `(<= ,(ames.geometry:dot d d) 0)))))

(defun register-closing-impact-templates (kb)
  "Register in KB the template functions of a rope piece closing at an impact."
  (register-template kb 'closing-piece-rate #'closing-piece-rate
                     :documentation "The rate of a closing piece's length just before or after the impact.")
  (register-template kb 'impact-piece-closed #'impact-piece-closed
                     :documentation "A piece is closed at its pulley at the impact, not by it.")
  (register-template kb 'held-piece-at-impact
                     (lambda (situation segment)
                       (refuse-closed-piece situation segment "an impact while it holds its body there (its direction undefined)"))
                     :documentation "Signals UNMODELLED-SITUATION: an impact with a piece held at its pulley."))

(defcomponent held-piece-at-a-later-impact (:knowledge-base *impacts*)
  "A piece held closed at its pulley since an earlier state has no direction for the
rope's jerk at a later impact (and its pin's impulse is not modelled): refused, named."
  (:arguments (?segment :entity rope-segment :where (:within-one-body nil)))
  (:activation (impact-piece-closed ?segment))
  (:equations (= (held-piece-at-impact ?segment) 0)))

(register-closing-impact-templates *impacts*)

(defcomponent closing-piece-kinematics (:knowledge-base *impacts*)
  "How fast the piece whose closing is the impact opens just after it (its separation:
negative when the body would pass through the pulley)."
  (:arguments (?segment :entity rope-segment :where (:reached rope-piece-closing)))
  (:equations (= (separation-after ?segment) (closing-piece-rate ?segment :after))))

(defcomponent pulley-stop (:knowledge-base *impacts*)
  "The pulley stops a body striking it along the closing piece: an impulse P >= 0 from
the pulley's body that pushes the body back along the piece, with Newton's law of
restitution on the piece's rate (the pair's restitution, 0 by default: the body stops
dead); without one the body must not pass through the pulley."
  (:arguments (?segment :entity rope-segment
                        :where (:reached rope-piece-closing :from (?body1 ?_) :to (?body2 ?_))))
  (:activation (approaching-after ?segment)
               (:event (:impulse ?body1 ?body2)))
  (:deactivation (:when (< (stop-impulse ?segment) 0) :event (:would-pull ?body1 ?body2)))
  ;; paired by their own :contact key (the rope's pulls along the piece have theirs)
  (:assert (impulse (pulley-stop ?segment ?body2) :from ?body1 :on ?body2 :contact (stop ?segment))
           (impulse (pulley-stop ?segment ?body1) :from ?body2 :on ?body1 :contact (stop ?segment))
           (reported :impulses (:pulley-stop ?body1 ?body2 (stop-impulse ?segment))))
  (:equations (= (impulse-x (pulley-stop ?segment ?body2)) (* (stop-impulse ?segment) (segment-direction ?segment :x)))
              (= (impulse-y (pulley-stop ?segment ?body2)) (* (stop-impulse ?segment) (segment-direction ?segment :y)))
              (= (separation-after ?segment)
                 (* -1 (restitution ?segment) (closing-piece-rate ?segment :before)))))
