;;;; scenarios/two-blocks-in-corner-segment-wall.lisp -- the two blocks in a corner, the wall a thin segment.
;;;;
;;;; scenarios/two-blocks-in-corner.lisp (thesis section 2.6.2) with its wall, there a
;;;; half-plane, made a thin one-sided segment from (2 l3, 3 l1) down to (2 l3, 0), solid
;;;; on its +x side. Same blocks, same start, same push f. (Once the geometry asked, to
;;;; know whether A's corner touched the segment's line, a fact that could not change the
;;;; answer, since the corner lies outside the segment's span, and the run stopped: issue 9.)
;;;;
;;;; Expected results (those of the half-plane version for state 0; k = (l1 - l2)/l3):
;;;;   State 0: contacts A-floor, B-wall and B's corner on A's inclined face;
;;;;     a_Ax = l3 (f l3 - mb g (l1 - l2)) / (ma l3^2 + mb (l1 - l2)^2),  a_By = k a_Ax.
;;;;     Whether B rises is the sign of f l3 - mb g (l1 - l2), which the assumptions leave
;;;;     open: the run branches there (a fork of zero duration). With the default values
;;;;     (bin/ames run ... --numeric: f l3 = 20 > mb g (l1 - l2) = 19.62) the rising branch
;;;;     is selected: B rises, and its corner reaches the upper end of A's face at
;;;;       t1 = sqrt(l3 / a_Ax) = sqrt((ma l3^2 + mb (l1 - l2)^2) / (f l3 - mb g (l1 - l2))),
;;;;     where the state ends: (:leaves block-a block-b :endpoint).
;;;; One state here. Run on (the test two-blocks-in-a-corner-with-a-segment-wall-to-rest,
;;;; with the defaults and :branch nil), B flies up and lands on A's top corner at
;;;; t1 + 2 v_B/g, v_B = (l1 - l2) sqrt(F/D) (F = f l3 - mb g (l1 - l2), D = ma l3^2 +
;;;; mb (l1 - l2)^2), and A hits the wall with v_A^2 = (3 f l3 - mb (l1 - l2)^2 F/D -
;;;; mb g (l1 - l2))/ma and stops there: at rest from then on. Without values the order of
;;;; those events depends on long polynomial facts, and the tree of branches is deep.

(scenario two-blocks-in-corner-segment-wall
  "Block A, pushed toward a thin wall, lifts block B that rests on its inclined face."
  (parameters (ma :positive (:value 1)) (mb :positive (:value 1))
              (g :positive (:value 981/100)) (f :positive (:value 20))
              (l2 :positive (:value 1)) (l1 (> l1 l2) (:value 3))
              (l3 :positive (:value 1)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (segment ((* 2 l3) (* 3 l1)) ((* 2 l3) 0)))
  (body block-a :mass ma :position ((- (/ l3 2)) 0) :velocity (0 0)
                :shape (polygon (0 0) (l3 0) (l3 l2) (0 l1)))
  (body block-b :mass mb :position (0 (/ (+ l1 l2) 2)) :velocity (0 0)
                :shape (polygon (0 0) ((* 2 l3) 0) ((* 2 l3) l1) (0 l1)))
  (force push :on block-a :value (f 0))
  (simulate :states 1))
