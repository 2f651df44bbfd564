;;;; src/kb/radial-turning.lisp -- turning points along the line of centres: two bodies under
;;;; their mutual gravitation, moving along the line between them, stop and come back
;;;; (the language's "Oscillation and turning points").
;;;;
;;;; While the relative velocity of two bodies lies along their line of centres (no part
;;;; across it at the start of the state: the span keeps its direction u0, spans.lisp),
;;;; their motion has one degree of freedom, their distance l, with rate l' = (v2 - v1).u0.
;;;; A probe launched away from a planet below the escape speed rises until l' reaches
;;;; zero and falls back: the rate changes sign, through zero, which is the event
;;;; (:turns BODY), BODY the free body of the two (the second when both are free). The
;;;; modes are the two ways of motion, with no equations of their own; at rest the pair
;;;; starts approaching (gravitation attracts). Bodies moving across their line (an
;;;; orbit) are in the mode :across, which watches nothing: their distance's turns are
;;;; no turning points of a line motion. The rate is written (v2 - v1).d0, d0 = l0 u0 the
;;;; starting separation: a constant positive multiple of l', so that along the line it
;;;; is the speed along the line times a constant (simulator/turns.lisp finds where the
;;;; energy integral reaches zero ahead of the bodies).

(in-package #:ames.kb)

(defun separation-rate (situation a b)
  "(B' - A').(B0 - A0): the rate of the distance from point A to point B times the
starting distance, while the points move along their line."
  (ames.geometry:dot (span-difference situation a b 'initial-pos) (span-difference situation a b 'vel)))

(defun along-line-p (situation a b)
  "The condition: the relative velocity of A and B has no part across their line at the
start of the state."
  `(<= (expt ,(ames.geometry:cross (span-difference situation a b 'initial-pos)
                        (span-difference situation a b 'vel))
             2)
       0))

(register-template *mechanics* 'separation-rate #'separation-rate
                   :documentation "The rate of two points' distance times their starting distance (along their line).")
(register-template *mechanics* 'separating-along-line
                   (lambda (situation a b)
                     `(and ,(along-line-p situation a b) (> ,(separation-rate situation a b) 0)))
                   :documentation "Two points move apart along their line.")
(register-template *mechanics* 'approaching-along-line
                   (lambda (situation a b)
                     `(and ,(along-line-p situation a b) (<= ,(separation-rate situation a b) 0)))
                   :documentation "Two points move together along their line, or are at rest.")
(register-template *mechanics* 'moving-across-line
                   (lambda (situation a b)
                     (let ((across (ames.geometry:cross (span-difference situation a b 'initial-pos)
                                             (span-difference situation a b 'vel))))
                       `(> (expt ,across 2) 0)))
                   :documentation "Two points' relative velocity has a part across their line.")

(defmacro define-radial-turning (name mover filters documentation)
  "A turning point of the distance of a body pair whose bodies match FILTERS (entity
arguments (?BODY1-or-?BODY2 :ENTITY BODY :WHERE (:FIXED ...))), the event naming MOVER."
  `(defcomponent ,name (:knowledge-base *mechanics*)
     ,documentation
     (:arguments (?pair :entity body-pair :where (:first ?body1 :second ?body2))
                 (?field :entity gravitation-field)
                 ,@filters)
     (:mode :separating
      (:entry (separating-along-line (?body1 (0 0)) (?body2 (0 0))))
      (:transition :to :approaching :when (< (separation-rate (?body1 (0 0)) (?body2 (0 0))) 0)
                   :event (:turns ,mover)))
     (:mode :approaching
      (:entry (approaching-along-line (?body1 (0 0)) (?body2 (0 0))))
      (:transition :to :separating :when (> (separation-rate (?body1 (0 0)) (?body2 (0 0))) 0)
                   :event (:turns ,mover)))
     (:mode :across
      (:entry (moving-across-line (?body1 (0 0)) (?body2 (0 0)))))))

(define-radial-turning turning-along-line-of-centres ?body2 ((?body2 :entity body :where (:fixed nil)))
  "Two bodies under their mutual gravitation moving along their line of centres turn
back where their distance's rate changes sign: event (:turns BODY), the second body of
the pair (free); the next state runs the other way.")

(define-radial-turning turning-toward-fixed-body ?body1 ((?body1 :entity body :where (:fixed nil))
                                                        (?body2 :entity body :where (:fixed t)))
  "As TURNING-ALONG-LINE-OF-CENTRES, for a pair whose second body is fixed: the event
names the first.")
