;;;; src/kb/ropes.lisp -- ropes over pulleys (thesis 3.3.2, "Ropes"): massless, inextensible,
;;;; the same tension all along; taut or slack; jerked tight at an impact.
;;;;
;;;; The rope phenomenon (below) describes each rope, its pulleys resolved into points of bodies:
;;;;   (rope R :length L :segments (S0 S1 ...))
;;;;   (rope-segment Si :rope R :from (B (X Y)) :to (B' (X' Y')) [:within-one-body T])
;;;;                                        the straight pieces, in order from the rope's
;;;;                                        first end to its last; the pulls of a piece
;;;;                                        between two points of one body cancel
;;;; Each segment is a span (src/kb/spans.lisp). The rope has the thesis's two modes:
;;;;   TAUT   its length, the sum of its spans', is L: at the acceleration level the sum of the
;;;;          spans' length accelerations is zero, which the tension T (a compensating
;;;;          force, like a normal force) makes true; each segment pulls the bodies at its
;;;;          ends toward each other with T (so a pulley's body feels T toward both
;;;;          neighbours). It ends when T would turn negative: (:slackens R).
;;;;   SLACK  no tension. It ends when the length reaches L again: (:tightens R), an impulsive
;;;;          event when reached with a velocity.
;;;; A rope may be taut at the start of a state only when its length is L and not changing;
;;;; whether it is, is settled by consistency (T >= 0 when taut, not stretched when slack).
;;;; Reported in :forces as (:tension R T) (0 when slack).
;;;;
;;;; At an impact (src/kb/impacts.lisp) a rope at its full length takes part like a contact
;;;; with e = 0 (a plastic jerk): an impulse J >= 0 along each segment, the same all along,
;;;; with the rope's length not growing just after; it is consistent not to jerk only when the
;;;; length does not grow. The impact situation describes the same rope and segment
;;;; entities, and each body with its :position and :velocity just before (a rope wound on
;;;; a disc: wound-rope-impacts.lisp).

(in-package #:ames.kb)

(defun rope-segments (situation rope)
  "The segment entity names of ROPE, in order."
  (entity-property (entity-named situation rope) :segments))

(defun segment-points (situation segment)
  "The two points (:FROM and :TO) of a rope SEGMENT."
  (let ((entity (entity-named situation segment)))
    (values (entity-property entity :from) (entity-property entity :to))))

(defun sum-over-segments (situation rope function)
  "The sum over ROPE's segments of FUNCTION's value (a function of the segment's name)."
  (cons '+ (mapcar function (rope-segments situation rope))))

(defun register-rope-templates (kb)
  "Register in KB the template functions of ropes in a state."
  (register-template kb 'rope-length
                     (lambda (situation rope) (entity-property (entity-named situation rope) :length))
                     :documentation "A rope's length L.")
  (register-template kb 'rope-span-length
                     (lambda (situation rope)
                       (sum-over-segments situation rope (lambda (s) `(span-length ,s))))
                     :documentation "The sum of a rope's spans' lengths.")
  (register-template kb 'rope-span-acceleration
                     (lambda (situation rope)
                       (sum-over-segments situation rope (lambda (s) `(span-acceleration ,s))))
                     :documentation "The second derivative of a rope's length.")
  (register-template kb 'rope-slack-now
                     (lambda (situation rope sense zero)
                       `(- (rope-length ,rope)
                           ,(sum-over-segments
                             situation rope
                             (lambda (s)
                               (cond ((wound-segment-p situation s)
                                      (wound-piece-length-now situation s sense))
                                     ((eq s zero) 0)
                                     (t (multiple-value-bind (a b) (segment-points situation s)
                                          (ames.geometry:vector-length (span-difference situation a b 'pos)))))))))
                     :documentation "L minus the rope's length, from the positions (and the
angle of a disc it is wound on, turning the way SENSE says: see wound-ropes.lisp); the
piece ZERO (or NIL), of zero length at the state's start, counts 0 (closed-rope-pieces.lisp).")
  (register-template kb 'rope-rate-now
                     (lambda (situation rope sense zero)
                       (sum-over-segments
                        situation rope
                        (lambda (s)
                          (cond ((wound-segment-p situation s)
                                 (wound-piece-rate-now situation s sense))
                                ((eq s zero) (zero-piece-rate-now situation s))
                                (t (multiple-value-bind (a b) (segment-points situation s)
                                     (let ((d (span-difference situation a b 'pos)))
                                       `(/ ,(ames.geometry:dot d (span-difference situation a b 'vel)) ,(ames.geometry:vector-length d)))))))))
                     :documentation "The rate of the rope's length, from the positions and
velocities; the piece ZERO (or NIL), of zero length at the state's start, opens at its
ends' relative speed (0 when it is closed: closed-rope-pieces.lisp)."))

(register-rope-templates *mechanics*)

(defcomponent rope-segment-span (:knowledge-base *mechanics*)
  "Each straight piece of a rope is a span, but one closed at its pulley (zero length
and its ends at rest relative to each other at the state's start: a span with no
direction; closed-rope-pieces.lisp holds it)."
  (:arguments (?segment :entity rope-segment :where (:from ?a :to ?b)))
  (:activation (> (+ (span-start-length-squared ?a ?b) (span-start-speed-squared ?a ?b)) 0))
  (:assert (span ?segment :from ?a :to ?b)))

(defcomponent taut-or-slack-rope (:knowledge-base *mechanics*)
  "A massless inextensible rope is taut (its length held at L by whatever tension that
needs, never negative) or slack (no tension, shorter than L). Its winding SENSE (0 for a
rope wound on no disc, see wound-ropes.lisp) says how a disc it is wound on pays it out;
its ZERO piece, the one at zero length at the state's start (a body at its pulley), or
NIL, how its length is read then (closed-rope-pieces.lisp)."
  (:arguments (?rope :entity rope)
              (?sense :belief (rope-winding ?rope :sense ?sense))
              (?zero :belief (rope-start ?rope :zero-piece ?zero)))
  (:mode :slack
   (:entry (rope-may-slacken ?zero))
   (:assert (reported :forces (:tension ?rope 0)))
   (:transition :to :taut :when (> (rope-span-length ?rope) (rope-length ?rope))
                :event (:tightens ?rope) :impact (:tightens ?rope)))
  (:mode :taut
   (:entry (= (rope-slack-now ?rope ?sense ?zero) 0) (= (rope-rate-now ?rope ?sense ?zero) 0))
   (:assert (taut ?rope)
            (reported :forces (:tension ?rope (tension ?rope))))
   (:equations (= (rope-span-acceleration ?rope) 0))
   (:transition :to :slack :when (< (tension ?rope) 0) :event (:slackens ?rope))))

(defcomponent rope-tension (:knowledge-base *mechanics*)
  "A taut rope's segment pulls the bodies at its two ends toward each other with the
rope's tension (the same all along a frictionless rope over massless pulleys); Newton's
third law gives the pull at its far end. A piece closed at its pulley, which has no span
(no direction), pulls with no tension: the pulley holds its body (closed-rope-pieces.lisp)."
  (:arguments (?segment :entity rope-segment
                        :where (:rope ?rope :from (?body1 ?_) :to (?body2 ?_) :within-one-body nil))
              (?a :belief (span ?segment :from ?a :to ?_)))
  (:activation (:believes (taut ?rope)))
  (:assert (force (tension ?segment ?body1) :type tension :from ?body2 :on ?body1 :contact ?segment)
           (force (tension ?segment ?body2) :type tension :from ?body1 :on ?body2 :contact ?segment))
  (:equations (= (force-x (tension ?segment ?body1)) (* (tension ?rope) (span-direction ?segment :x)))
              (= (force-y (tension ?segment ?body1)) (* (tension ?rope) (span-direction ?segment :y)))))

;;; At an impact

(defun impact-point (situation point)
  "POINT's position just before the impact, from its body's :position."
  (mapcar (lambda (p x) `(+ ,p ,x))
          (entity-property (entity-named situation (point-body point)) :position)
          (point-offset point)))

(defun impact-segment-direction (situation segment)
  "The unit vector along SEGMENT (from its :from point to its :to point) at the impact;
for a piece whose closing is the impact (its entity :REACHED ROPE-PIECE-CLOSING, zero
length), the limit of that vector as it closed: minus its ends' relative velocity just
before, over its size (closed-rope-pieces.lisp)."
  (if (eq (entity-property (entity-named situation segment) :reached) 'rope-piece-closing)
      (closing-piece-direction situation segment)
      (multiple-value-bind (a b) (segment-points situation segment)
        (let ((d (mapcar (lambda (q p) `(- ,q ,p)) (impact-point situation b) (impact-point situation a))))
          (mapcar (lambda (x) `(/ ,x ,(ames.geometry:vector-length d))) d)))))

(defun register-rope-impact-templates (kb)
  "Register in KB the template functions of ropes at an impact."
  (register-template kb 'rope-at-length
                     (lambda (situation rope)
                       `(>= ,(sum-over-segments
                              situation rope
                              (lambda (s)
                                (multiple-value-bind (a b) (segment-points situation s)
                                  (ames.geometry:vector-length (mapcar (lambda (q p) `(- ,q ,p))
                                                   (impact-point situation b)
                                                   (impact-point situation a))))))
                            ,(entity-property (entity-named situation rope) :length)))
                     :documentation "The rope is at its full length at the impact.")
  (register-template kb 'rope-shortening-after
                     (lambda (situation rope)
                       `(- ,(sum-over-segments
                             situation rope
                             (lambda (s)
                               (multiple-value-bind (a b) (segment-points situation s)
                                 (ames.geometry:dot (impact-segment-direction situation s)
                                         (mapcar (lambda (axis)
                                                   `(- (vel-after ,(point-body b) ,axis)
                                                       (vel-after ,(point-body a) ,axis)))
                                                 '(:x :y))))))))
                     :documentation "Minus the rate of the rope's length just after the impact.")
  (register-template kb 'segment-direction
                     (lambda (situation segment axis)
                       (axis-component (impact-segment-direction situation segment) axis))
                     :documentation "A component of a segment's unit vector at the impact."))

(register-rope-impact-templates *impacts*)

(defcomponent rope-kinematics-at-impact (:knowledge-base *impacts*)
  "How fast a rope's length shrinks just after the impact (its separation: negative when
it would stretch)."
  (:arguments (?rope :entity rope :where (:wound nil)))
  (:equations (= (separation-after ?rope) (rope-shortening-after ?rope))))

(defcomponent rope-jerk (:knowledge-base *impacts*)
  "A rope at its full length may jerk: an impulse J >= 0 along it that leaves its length
not changing just after (a plastic impact); without one its length must not grow. (A
rope wound on a disc: wound-ropes.lisp.)"
  (:arguments (?rope :entity rope :where (:wound nil)))
  (:activation (rope-at-length ?rope) (approaching-after ?rope)
               (:event (:jerk ?rope)))
  (:deactivation (:when (< (rope-impulse ?rope) 0) :event (:would-push ?rope)))
  (:assert (jerked ?rope)
           (reported :impulses (:rope-impulse ?rope (rope-impulse ?rope))))
  (:equations (= (separation-after ?rope) 0)))

(defcomponent rope-segment-jerk (:knowledge-base *impacts*)
  "A jerked rope's segment pulls the bodies at its ends toward each other with the
rope's impulse; Newton's third law gives the far end's."
  (:arguments (?segment :entity rope-segment
                        :where (:rope ?rope :from (?body1 ?_) :to (?body2 ?_) :within-one-body nil)))
  (:activation (:believes (jerked ?rope)))
  (:assert (impulse (rope-pull ?segment ?body1) :from ?body2 :on ?body1 :contact ?segment)
           (impulse (rope-pull ?segment ?body2) :from ?body1 :on ?body2 :contact ?segment))
  (:equations (= (impulse-x (rope-pull ?segment ?body1)) (* (rope-impulse ?rope) (segment-direction ?segment :x)))
              (= (impulse-y (rope-pull ?segment ?body1)) (* (rope-impulse ?rope) (segment-direction ?segment :y)))))

;;; The clause and the names (see phenomena.lisp)

(defun rope-segment-names (scenario)
  "Alist rope name -> the names of its segments (SEGMENT-i), numbered across SCENARIO's
ropes."
  (let ((index -1))
    (mapcar (lambda (rope)
              (cons (ames.scenario:scenario-rope-name rope)
                    (loop repeat (1- (length (ames.scenario:scenario-rope-through rope)))
                          collect (indexed-entity-name "SEGMENT" (incf index)))))
            (ames.scenario:scenario-ropes scenario))))

(defun rope-entities (scenario)
  "The entities of SCENARIO's ropes: each rope and its straight segments between
consecutive points, pulleys resolved into points of their bodies; a segment between two
points of one body says so (:WITHIN-ONE-BODY T). A rope with an end wound on a turning
disc says which of its segments ends there (:WOUND, see wound-ropes.lisp), and that
segment is a WOUND-ROPE-SEGMENT. The same in a state and at an impact."
  (loop for rope in (ames.scenario:scenario-ropes scenario)
        for (nil . segments) in (rope-segment-names scenario)
        for points = (mapcar (lambda (p) (ames.scenario:rope-point-position scenario p))
                             (ames.scenario:scenario-rope-through rope))
        for wound = (wound-segment-of rope segments)
        collect (list* 'rope (ames.scenario:scenario-rope-name rope)
                       :length (ames.scenario:scenario-rope-length rope) :segments segments
                       :wound (and wound t)
                       (and wound (wound-rope-properties scenario rope points)))
        append (loop for segment in segments
                     for (from to) on points
                     for index from 0
                     collect (if (eq segment wound)
                                 (wound-segment-entity scenario rope segment index from to)
                                 (list* 'rope-segment segment :rope (ames.scenario:scenario-rope-name rope)
                                        :index index :from from :to to
                                        (and (eq (first from) (first to)) (list :within-one-body t)))))))

(defun rope-impact-entities (scenario)
  "The entities of SCENARIO's ropes at an impact: those of a state (ROPE-ENTITIES), each
straight piece with the :RESTITUTION of its two ends' bodies (a body striking its pulley:
closed-rope-pieces.lisp); a rope wound on a disc jerks as wound-ropes.lisp says."
  (mapcar (lambda (entity)
            (if (eq (first entity) 'rope-segment)
                (append entity
                        (list :restitution
                              (ames.scenario:scenario-restitution
                               scenario (point-body (getf (cddr entity) :from))
                               (point-body (getf (cddr entity) :to)))))
                entity))
          (rope-entities scenario)))

(defun segment-phrases (scenario)
  "An alist rope segment entity -> its phrase (\"rope, piece 1\") for SCENARIO's ropes."
  (loop for (rope . segments) in (rope-segment-names scenario)
        append (loop for segment in segments for k from 1
                     collect (cons segment (format nil "~(~A~), piece ~D" rope k)))))

(define-phenomenon rope
  "Massless inextensible ropes over pulleys, taut or slack, jerked tight at an impact (the
rope and pulley clauses)."
  (:entities #'rope-entities)
  (:impact-entities #'rope-impact-entities)
  (:entity-phrases #'segment-phrases)
  (:force :tension :names 1 :words "tension in ~A" :symbol "T")
  (:impulse :rope-impulse :names 1 :words "impulse of the jerk along ~A")
  (:event :slackens :words "~A goes slack")
  (:event :tightens :words "~A becomes taut")
  (:event :rope-piece-closes
   :words "~A closes up between ~A and ~A (a body reaches its pulley), or that piece has turned a right angle")
  (:event :strikes-pulley
   :words "~A and ~A meet with a speed at the pulley between them: the rope's piece closes up")
  (:event :leaves-pulley :words "~A's piece between ~A and ~A would open from rest: the pulley no longer holds the body")
  (:force :pulley-hold :names 2 :words "hold of ~A's pulley on ~A")
  (:impulse :pulley-stop :names 2 :words "impulse of the pulley stop between ~A and ~A")
  (:quantity :tension :force :tension))

;;; A taut rope's piece closing up: a body reaching its pulley

(defun caught-at-pulley (situation segment)
  "Signal UNMODELLED-SITUATION: SEGMENT, a piece of a taut rope, has closed up (the body
at one end reached the point at the other, its pulley) with no impact to stop it: at
zero speed, or at the end of a state integrated numerically (no rate to call it an
impact). What follows is not modelled."
  (let ((entity (entity-named situation segment)))
    (multiple-value-bind (a b) (segment-points situation segment)
      (error 'unmodelled-situation
             :datum segment
             :detail (format nil "The piece of rope ~(~A~) between ~(~A~) and ~(~A~) closes up with no impact modelled to stop it (reached at zero speed, or at the end of a state integrated numerically): a body reaches the pulley its rope runs over (or the piece turns past a right angle); what follows is not modelled."
                             (entity-property entity :rope) (point-body a) (point-body b))))))

(register-template *mechanics* 'rope-piece-caught #'caught-at-pulley
                   :documentation "Signals UNMODELLED-SITUATION: a taut rope's piece closed up.")

(defcomponent rope-piece-closing (:knowledge-base *mechanics*)
  "A taut rope's straight piece shortens to nothing when the body at one end reaches the
point at the other (a weight pulled up into its pulley). Its length is watched along its
starting direction, (B - A).u0 (or, opening from zero length, along its ends' relative
velocity), which changes sign there (the distance |B - A| only touches zero) while the
piece keeps its direction (its span's fixed direction, the only motion in which it can
close up): the event (:rope-piece-closes ROPE A B) ends the state; reached with a speed,
it is an impact, (:strikes-pulley A B): the pulley stops the body
(closed-rope-pieces.lisp), the rope is jerked, and a piece stopped dead is held at its
pulley in the next state. Closed otherwise (at zero speed, or at the end of a state
integrated numerically), the next state is not modelled (an honest stop, not the body
passing through the pulley). A piece that turns (a pendulum
swinging on it) keeps its length, and its projection on its starting direction changing
sign is no closing."
  (:arguments (?segment :entity rope-segment
                        :where (:rope ?rope :from (?body1 ?_) :to (?body2 ?_) :within-one-body nil))
              (?opening :belief (aligned-span ?segment :from ?a :to ?b :opening ?opening)))
  (:activation (:believes (taut ?rope)))
  (:mode :apart
   (:entry (>= (line-span-length ?a ?b ?opening) 0))
   (:transition :to :closed-up :when (< (line-span-length ?a ?b ?opening) 0)
                :event (:rope-piece-closes ?rope ?body1 ?body2)
                :impact (:strikes-pulley ?body1 ?body2)))
  ;; never at a state's start: the length along the line starts at |d0| >= 0
  (:mode :closed-up
   (:entry (< (line-span-length ?a ?b ?opening) 0))
   (:equations (= (rope-piece-caught ?segment) 0))))
