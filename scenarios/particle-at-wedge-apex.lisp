;;;; scenarios/particle-at-wedge-apex.lisp -- the thesis's figure for section 2.6.1: the particle
;;;; released at the apex of the wedge. At the apex the slope and the vertical back face meet
;;;; in a convex corner: their contacts are alternatives, and the particle slides down the
;;;; slope (pressing on the back face as well would wedge it in place, which no convex corner
;;;; can do; falling along the back face, or free, only grazes it).
;;;;
;;;; Expected results: state 0 has the particle on the slope (edge 1) and the wedge on the
;;;; ground; N = mp mw g cos a / (mw + mp sin^2 a) as half-way down; the particle reaches the
;;;; ground at the slope's foot after sqrt(2 h (mw + mp sin^2 a) / (g sin^2 a (mp + mw))),
;;;; at x = mw h / (tan a (mp + mw)) (the horizontal momentum stays zero).

(scenario particle-at-wedge-apex
  "A particle released at the apex of a movable wedge on frictionless ground slides down its slope."
  (parameters (mp :positive (:value 1)) (mw :positive (:value 3)) (g :positive (:value 981/100))
              (h :positive (:value 1)) (a (> a 0) (< a (/ pi 2)) (:value 1/2)))
  (gravity g)
  (body ground   :fixed t :shape (half-plane (1 0) (0 0)))
  (body wedge    :mass mw :position (0 0) :velocity (0 0)
                 :shape (polygon (0 0) ((/ h (tan a)) 0) (0 h)))
  (body particle :mass mp :position (0 h) :velocity (0 0) :shape point)
  (simulate :states 3))
