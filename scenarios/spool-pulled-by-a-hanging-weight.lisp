;;;; scenarios/spool-pulled-by-a-hanging-weight.lisp -- a spool on a rough table, its string
;;;; wound on the axle and leaving the top of it horizontally, over a pulley at the table's
;;;; edge to a hanging weight.
;;;;
;;;; Source type: the textbook spool (first-year rotational dynamics: a string wound on an
;;;; axle of radius r, the spool's rim R rolling on the table). Expected results (textbook):
;;;; rolling, the string's point at the top of the axle moves at v (1 + r/R), so the weight
;;;; falls at a (1 + r/R) where
;;;;   a = M g R (R + r) / (I + m R^2 + M (R + r)^2)
;;;; is the spool's acceleration (toward the pulley), the tension T = M g (I + m R^2) /
;;;; (I + m R^2 + M (R + r)^2), the angular acceleration -a/R; it rolls while
;;;; friction can hold it (a fact over mu: AMES branches on it, slipping forward or back on
;;;; either side, in closed form too), and the spool reaches the table's edge after
;;;; sqrt(2 l / a). The values (mu = 1) select the rolling branch.
;;;; The same spool with the string leaving the bottom of its axle: r becomes -r,
;;;;   a = M g R (R - r) / (I + m R^2 + M (R - r)^2), T = M g (I + m R^2) / (I + m R^2 + M (R - r)^2),
;;;; still toward the pull (R > r), friction now backwards, M g (I + m R r) / (I + m R^2 + M (R - r)^2).

(scenario spool-pulled-by-a-hanging-weight
  "A spool on a rough table pulled by a hanging weight on a string wound on its axle."
  (parameters (m :positive (:value 2)) (big-m :positive (:value 1/2)) (g :positive (:value 981/100))
              (big-r :positive (:value 1/5)) (r :positive (< r big-r) (:value 1/10))
              (i :positive (:value 1/50)) (l :positive (:value 2)) (mu :positive (:value 1)))
  (gravity g)
  (body table :fixed t :shape (polygon (-10 -1) (l -1) (l 0) (-10 0)))
  (body spool :mass m :inertia i :shape (circle big-r) :position (0 big-r) :velocity (0 0))
  (body weight :mass big-m :shape point :position ((+ l 1/10) -1/2) :velocity (0 0))
  (pulley edge :on table :at ((+ l 1/10) (+ big-r r)))
  (rope string :length (+ l 1/10 big-r r 1/2) :through ((spool (0 r) :wound) edge (weight (0 0))))
  (friction spool table :static mu)
  (query accel (value (x (acceleration spool)) :at (start 0)))
  (query tension (value (tension string) :at (start 0)))
  (simulate :states 1))

(scenario spool-pulled-from-under-its-axle
  "The spool with its string leaving the bottom of its axle."
  (parameters (m :positive (:value 2)) (big-m :positive (:value 1/2)) (g :positive (:value 981/100))
              (big-r :positive (:value 1/5)) (r :positive (< r big-r) (:value 1/10))
              (i :positive (:value 1/50)) (l :positive (:value 2)) (mu :positive (:value 1)))
  (gravity g)
  (body table :fixed t :shape (polygon (-10 -1) (l -1) (l 0) (-10 0)))
  (body spool :mass m :inertia i :shape (circle big-r) :position (0 big-r) :velocity (0 0))
  (body weight :mass big-m :shape point :position ((+ l 1/10) -1/2) :velocity (0 0))
  (pulley edge :on table :at ((+ l 1/10) (- big-r r)))
  (rope string :length (+ l 1/10 (- big-r r) 1/2) :through ((spool (0 (- r)) :wound) edge (weight (0 0))))
  (friction spool table :static mu)
  (query accel (value (x (acceleration spool)) :at (start 0)))
  (query tension (value (tension string) :at (start 0)))
  (simulate :states 1))
