;;;; scenarios/block-bouncing-on-rough-floor.lisp -- a block slides along a rough floor into a wall, bounces back and slides to a stop.
;;;;
;;;; A fixed floor (y <= 0) and a fixed wall (x >= 2); a unit square block of mass m, its
;;;; reference point its bottom-left corner, at the origin, launched toward the wall at
;;;; 10. Gravity 10, Coulomb friction mu = 1/5 between block and floor, restitution 1/2.
;;;; The impact's impulse is along the wall's normal: it reverses the block's velocity
;;;; along the floor, so the floor's friction must change its sliding direction at once.
;;;;
;;;; Expected results:
;;;;   State 0: sliding toward the wall; N = 10 m, friction 2 m against the motion,
;;;;     acceleration (-2, 0). It reaches the wall (x = 1) at t = 5 - 2 sqrt 6 with speed
;;;;     4 sqrt 6: (:collision block wall ...), impulse 6 sqrt 6 m, energy lost 36 m.
;;;;   State 1: back from the wall at 2 sqrt 6, sliding the other way: friction 2 m along
;;;;     +x, acceleration (2, 0); it stops after sqrt 6, at x = -5: (:stops-sliding block floor).
;;;;   State 2: at rest at (-5, 0), static friction 0, forever.

(scenario block-bouncing-on-rough-floor
  "A block slides on a rough floor into a wall, bounces back and slides to a stop."
  (parameters (m :positive (:value 1)))
  (gravity 10)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall  :fixed t :shape (half-plane (2 1) (2 0)))
  (body block :mass m :position (0 0) :velocity (10 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (friction block floor :static 1/5)
  (restitution 1/2)
  (simulate :states 4))
