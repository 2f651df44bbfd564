;;;; src/kb/turning.lisp -- turning points: a body moving along a curved contact stops and
;;;; comes back (the language's "Oscillation and turning points").
;;;;
;;;; Along a curved contact the observer's motion relative to the obstacle has one degree
;;;; of freedom, the arc length s, with its speed s' = (path-speed K). A conservative
;;;; motion along it keeps the energy integral s'^2 = E(s); where E reaches zero ahead of
;;;; the body and would turn negative, the body cannot go on: it stops there and the
;;;; tangential force brings it back: the speed along the path changes sign, through
;;;; zero, which is the event (:turns BODY). The modes are the two ways of motion, with
;;;; no equations of their own; a body at rest starts in the one its tangential
;;;; acceleration is consistent with (the other's exit condition holds at once), as the
;;;; modes of friction are chosen. The simulator finds the speed's sign change where
;;;; the energy integral reaches zero ahead of the body (simulator/turns.lisp). A body on
;;;; a hinge has one degree of freedom too, its angle: its angular velocity changes sign
;;;; where the energy integral over the angle vanishes (a physical pendulum), the same
;;;; event.

(in-package #:ames.kb)

(defcomponent turning-point (:knowledge-base *mechanics*)
  "A body moving along a curved contact turns back where its speed along the path
changes sign (its energy integral reaches zero): event (:turns BODY), and the next
state runs the other way."
  (:arguments (?contact :belief (in-contact ?body1 ?body2 :along ?contact))
              (?speed :belief (derivative (path-position ?contact) ?speed)))
  (:mode :forward
   (:entry (> (path-speed ?contact) 0))
   (:transition :to :backward :when (< (path-speed ?contact) 0)
                :event (:turns ?body1)))
  (:mode :backward
   (:entry (< (path-speed ?contact) 0))
   (:transition :to :forward :when (> (path-speed ?contact) 0)
                :event (:turns ?body1))))

(defcomponent turning-point-of-a-hinged-body (:knowledge-base *mechanics*)
  "A body turning on a hinge swings back where its angular velocity changes sign (its
energy integral over the angle reaches zero, a physical pendulum at the top of its
swing): event (:turns BODY), and the next state turns the other way. The angle is the
hinged body's one degree of freedom, as the arc length is a curved contact's."
  (:arguments (?hinge :entity hinge :where (:body ?body :at (?px ?py))))
  (:mode :forward
   (:entry (> (angvel ?body) 0))
   (:transition :to :backward :when (< (angvel ?body) 0)
                :event (:turns ?body)))
  (:mode :backward
   (:entry (< (angvel ?body) 0))
   (:transition :to :forward :when (> (angvel ?body) 0)
                :event (:turns ?body))))

(define-phenomenon turning
  "Turning points of a motion of one degree of freedom (this file, radial-turning.lisp):
the speed along the path or the line changes sign (named generically)."
  (:event :turns))
