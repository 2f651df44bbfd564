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

;;; Turning points of a rotating body held by corners
;;;
;;; A rotating body whose corner contacts leave it one degree of freedom, its angle (a
;;; block rocking on an edge that sticks, a rod pivoting on a corner, a ladder sliding on
;;; its wall and floor), turns back where its angular velocity changes sign (its energy
;;; integral over the angle reaches zero ahead). The watch compares the angular velocity
;;; with the direction the state starts turning in, the state constant (initial-turn B):
;;; the sign of the first derivative of omega that is not zero at the start (omega0
;;; itself, or from rest the angular acceleration's). omega times it is positive from the
;;; start on and reaches zero at the turning point: event (:turns B). It is a watch, not
;;; a mode: a body at rest has no direction to choose, and the next state, from rest at
;;; the turning point, starts turning the other way by its own angular acceleration. A
;;; body that does not turn (at rest in equilibrium) has (initial-turn B) = 0: nothing
;;; fires. Its degrees of freedom are counted from what holds it: 3, less one for each
;;; corner on a face and one for each such corner that sticks (static friction: the
;;; corner is a pivot). Hinged bodies have their own watch above.

(defun corner-held-freedoms (corners sticking)
  "A rotating body's degrees of freedom left by its CORNERS on faces (each fixes its
gap) and the STICKING ones among them (each also fixes the corner's slip)."
  (- 3 (length corners) (length sticking)))

(register-template *mechanics* 'turning-back
                   (lambda (situation body corners sticking hinges)
                     (declare (ignore situation))
                     (if (and (null hinges) (= 1 (corner-held-freedoms corners sticking)))
                         `(< (* (angvel ,body) (initial-turn ,body)) 0)
                         '(or)))
                   :documentation "The angular velocity of a body held by corners with one degree of
freedom left turns against the direction the state started turning in; never otherwise.")

(defcomponent turning-point-of-a-body-on-corners (:knowledge-base *mechanics*)
  "A rotating body held by corners with one degree of freedom left (its angle) swings
back where its angular velocity changes sign relative to the direction the state starts
turning in (its energy integral over the angle reaches zero): event (:turns BODY). A
watch: it changes no mode, and the next state turns the other way."
  (:arguments (?body :entity body :where (:fixed nil :rotating t))
              (?corners :collect ?k :matching (corner-in-contact ?body ?_ :at ?k))
              (?sticking :collect ?k :matching (corner-sticks ?body ?_ :at ?k))
              (?hinges :collect ?f :matching (force ?f :type hinge :on ?body)))
  (:activation (:believes (corner-in-contact ?body ?_ :at ?_)))
  (:watch (:when (turning-back ?body ?corners ?sticking ?hinges) :event (:turns ?body))))

(define-phenomenon turning
  "Turning points of a motion of one degree of freedom (this file, radial-turning.lisp,
rope-swing.lisp):
the speed along the path or the line changes sign (named generically)."
  (:event :turns))
