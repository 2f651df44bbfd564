;;;; src/kb/friction.lisp -- Coulomb friction on a contact: the model component the thesis proposes
;;;; (section 3.3.2, "Friction"), with its static and sliding modes.
;;;;
;;;; The friction phenomenon (below) describes each (friction A B :static MU-S :kinetic MU-K) clause of the
;;;; scenario with the entity
;;;;   (friction-coefficients NAME :between (A B) :static MU-S :kinetic MU-K)
;;;; and every contact between A and B (whichever is the contact's observer) becomes rough.
;;;; On a rough contact K, with body1 the observer and body2 the obstacle, the friction on
;;;; body1 lies along the contact's unit tangent t (the direction of increasing arc length
;;;; s); its signed component along t is the quantity (friction-force K). The reaction on
;;;; body2 is its negation (Newton's third law pairs them as it pairs normal forces). The
;;;; relative tangential velocity is (slip-speed K): that of body1's contact point relative
;;;; to body2's along t, the template SLIP-SPEED of rotation.lisp. For bodies that do not
;;;; rotate it is (path-speed K), the rate of s (body1's velocity relative to body2 along
;;;; t), and its rate (slip-acc K) is (path-acc K :tangential); on a rotating disc it adds
;;;; the rim's speed, so that the static mode is rolling without slipping and the sliding
;;;; modes rolling with slipping ((:stops-sliding A B): a sliding disc starts to roll).
;;;;
;;;; Modes (the thesis's two, the sliding one split by its direction, which cannot change
;;;; within a state):
;;;;   :static            no relative tangential acceleration, (slip-acc K) = 0;
;;;;                      the friction is whatever that needs. Ends when it would exceed
;;;;                      MU-S N either way: (:starts-sliding A B), into the sliding mode
;;;;                      the other forces drive.
;;;;   :sliding-forward   s increases: the friction is -MU-K N. Ends when the relative
;;;;                      tangential velocity reaches zero: (:stops-sliding A B).
;;;;   :sliding-backward  s decreases: the friction is +MU-K N; likewise.
;;;; The entry conditions speak of the relative tangential velocity at the start of a state
;;;; and are exclusive and exhaustive. At rest (velocity zero) the state's initial values
;;;; do not say which mode holds: the simulator's decider leaves them open and its
;;;; consistency search settles them (static is consistent when |friction| <= MU-S N, a
;;;; sliding mode when the relative tangential acceleration it gives is along its own
;;;; direction). The modes are listed in the order of preference the search uses when
;;;; several are consistent (MU-K < MU-S): a pair that can stick does not start sliding.

(in-package #:ames.kb)

(defcomponent rough-contact-pair (:knowledge-base *mechanics*)
  "A friction clause makes every contact between its two bodies rough, whichever order
it names them in: it asserts the pair's coefficients both ways."
  (:arguments (?pair :entity friction-coefficients
                     :where (:between (?a ?b) :static ?mu-s :kinetic ?mu-k)))
  (:assert (rough ?a ?b :by ?pair :static ?mu-s :kinetic ?mu-k)
           (rough ?b ?a :by ?pair :static ?mu-s :kinetic ?mu-k)))

(defcomponent coulomb-friction (:knowledge-base *mechanics*)
  "Friction on a rough contact (thesis section 3.3.2): an action-reaction pair of
forces along the contact's tangent. Static, it is the compensating force that keeps
the relative tangential acceleration zero, up to MU-S N; sliding, its magnitude is
MU-K N against the relative tangential velocity. Static ends when the friction would
exceed MU-S N (the pair starts sliding the way the other forces drive it); sliding ends
when the relative tangential velocity reaches zero (stick or slide back is then chosen
by consistency)."
  (:arguments (?contact :belief (in-contact ?body1 ?body2 :along ?contact))
              (?pair :belief (rough ?body1 ?body2 :by ?pair :static ?mu-s :kinetic ?mu-k)))
  (:assert (force (friction ?contact) :type friction :from ?body2 :on ?body1 :contact ?contact)
           (force (friction-reaction ?contact) :type friction :from ?body1 :on ?body2
                  :contact ?contact))
  (:equations (= (force-x (friction ?contact))
                 (* (friction-force ?contact) (unit-tangent ?contact :x)))
              (= (force-y (friction ?contact))
                 (* (friction-force ?contact) (unit-tangent ?contact :y))))
  (:mode :static
   (:entry (= (slip-speed ?contact) 0))
   (:assert (reported :forces (:friction ?body1 ?body2 (friction-force ?contact) :mode :static)))
   (:equations (= (slip-acc ?contact) 0))
   (:transition :to :sliding-backward
                :when (> (friction-force ?contact) (* ?mu-s (normal-force ?contact)))
                :event (:starts-sliding ?body1 ?body2))
   (:transition :to :sliding-forward
                :when (< (friction-force ?contact) (- (* ?mu-s (normal-force ?contact))))
                :event (:starts-sliding ?body1 ?body2)))
  (:mode :sliding-forward
   (:entry (> (slip-speed ?contact) 0))
   (:assert (reported :forces (:friction ?body1 ?body2 (friction-force ?contact) :mode :sliding)))
   (:equations (= (friction-force ?contact) (- (* ?mu-k (normal-force ?contact)))))
   (:transition :to :static :when (<= (slip-speed ?contact) 0)
                :event (:stops-sliding ?body1 ?body2)))
  (:mode :sliding-backward
   (:entry (< (slip-speed ?contact) 0))
   (:assert (reported :forces (:friction ?body1 ?body2 (friction-force ?contact) :mode :sliding)))
   (:equations (= (friction-force ?contact) (* ?mu-k (normal-force ?contact))))
   (:transition :to :static :when (>= (slip-speed ?contact) 0)
                :event (:stops-sliding ?body1 ?body2))))

(defcomponent corner-friction (:knowledge-base *mechanics*)
  "Friction where a rotating body's corners touch a rough fixed face (corners.lisp): the
same law as COULOMB-FRICTION along the face's tangent, the slip being the corner's own
velocity along it. Two corners of one body touching one rough face share their friction
as RESTING-FACE-FRICTION says."
  (:arguments (?contact :belief (corner-in-contact ?body1 ?body2 :at ?contact))
              (?pair :belief (rough ?body1 ?body2 :by ?pair :static ?mu-s :kinetic ?mu-k)))
  (:assert (force (friction ?contact) :type friction :from ?body2 :on ?body1 :contact ?contact))
  (:equations (= (force-x (friction ?contact))
                 (* (friction-force ?contact) (corner-tangent ?contact :x)))
              (= (force-y (friction ?contact))
                 (* (friction-force ?contact) (corner-tangent ?contact :y))))
  (:mode :static
   (:entry (= (corner-slip-speed ?contact) 0))
   (:assert (reported :forces (:friction ?body1 ?body2 (friction-force ?contact) :mode :static))
            (corner-sticks ?body1 ?body2 :at ?contact))
   (:equations (= (corner-slip-acc ?contact) 0))
   (:transition :to :sliding-backward
                :when (> (friction-force ?contact) (* ?mu-s (normal-force ?contact)))
                :event (:starts-sliding ?body1 ?body2))
   (:transition :to :sliding-forward
                :when (< (friction-force ?contact) (- (* ?mu-s (normal-force ?contact))))
                :event (:starts-sliding ?body1 ?body2)))
  (:mode :sliding-forward
   (:entry (> (corner-slip-speed ?contact) 0))
   (:assert (reported :forces (:friction ?body1 ?body2 (friction-force ?contact) :mode :sliding)))
   (:equations (= (friction-force ?contact) (- (* ?mu-k (normal-force ?contact)))))
   (:transition :to :static :when (<= (corner-slip-speed ?contact) 0)
                :event (:stops-sliding ?body1 ?body2)))
  (:mode :sliding-backward
   (:entry (< (corner-slip-speed ?contact) 0))
   (:assert (reported :forces (:friction ?body1 ?body2 (friction-force ?contact) :mode :sliding)))
   (:equations (= (friction-force ?contact) (* ?mu-k (normal-force ?contact))))
   (:transition :to :static :when (>= (corner-slip-speed ?contact) 0)
                :event (:stops-sliding ?body1 ?body2))))

(defcomponent resting-face-friction (:knowledge-base *mechanics*)
  "Two corners of one body on one rough face, both touching (a flat face resting on it):
their frictions act on one line, so only their sum moves or turns the body and nothing in
the motion tells the share of each (statically indeterminate). Each corner's friction is
taken in proportion to its normal force, F1 N2 = F2 N1: the share with which each corner
holds exactly when their sum does (|F_i| <= MU N_i for both iff |F1 + F2| <= MU (N1 + N2)),
so that neither starts sliding before the face does."
  (:arguments (?face :entity resting-face :where (:observer ?body1 :obstacle ?body2
                                                  :corners (?k1 ?k2)))
              (?k1 :belief (corner-in-contact ?body1 ?body2 :at ?k1))
              (?k2 :belief (corner-in-contact ?body1 ?body2 :at ?k2))
              (?pair :belief (rough ?body1 ?body2 :by ?pair :static ?mu-s :kinetic ?mu-k)))
  (:equations (= (* (friction-force ?k1) (normal-force ?k2))
                 (* (friction-force ?k2) (normal-force ?k1)))))

(defun friction-entities (scenario)
  "Each (friction A B :static MU-S :kinetic MU-K) clause of SCENARIO as the entity
(friction-coefficients FRICTION-i :between (A B) :static MU-S :kinetic MU-K)."
  (loop for friction in (ames.scenario:scenario-frictions scenario)
        for index from 0
        collect (list 'friction-coefficients (indexed-entity-name "FRICTION" index)
                      :between (ames.scenario:scenario-friction-bodies friction)
                      :static (ames.scenario:scenario-friction-static friction)
                      :kinetic (ames.scenario:scenario-friction-kinetic friction))))

(define-phenomenon friction
  "Coulomb friction on every contact between two bodies (the friction clause)."
  (:entities #'friction-entities)
  (:force :friction :names 2 :words "friction of ~*~A on ~:*~:*~A" :symbol "F")
  (:event :starts-sliding :words "~A starts sliding on ~A")
  (:event :stops-sliding :words "~A stops sliding on ~A")
  (:quantity :friction :force :friction))
