;;;; scenarios/two-blocks-in-corner.lisp -- thesis section 2.6.2 (figure 2-13): two blocks in a corner.
;;;;
;;;; Geometry (the figure is not in our copy of the thesis; this one gives exactly the
;;;; thesis's equations). A fixed floor (y <= 0) and a fixed wall (x >= 2 l3) make the
;;;; corner. Block A slides horizontally on the floor, pushed toward the wall by the
;;;; external force F = (f, 0). Its reference point is its bottom-left corner, and it
;;;; is the trapezoid (0 0) (l3 0) (l3 l2) (0 l1) with l1 > l2 > 0: its top is an
;;;; inclined face that descends toward the wall, from (0 l1) to (l3 l2), of angle a
;;;; with tan a = (l1 - l2)/l3, whose outward normal is (sin a, cos a).
;;;; Block B, a 2 l3 by l1 rectangle whose reference point is its bottom-left corner,
;;;; slides vertically with its right face against the wall, and rests with that
;;;; bottom-left corner on A's inclined face.
;;;; Start, at rest: A at (-l3/2, 0), B at (0, (l1 + l2)/2): B's corner at the middle of
;;;; A's face (parameter 1/2 in the thesis's  D_B = D_A + (0, l1) + s (l3, l2 - l1)).
;;;; A's right end (x = l3/2) is clear of the wall; B is clear of the floor.
;;;;
;;;; Expected results (thesis 2.6.2; k = tan a = (l1 - l2)/l3,
;;;;                   cos a = l3 / sqrt(l3^2 + (l1 - l2)^2)):
;;;;   State 0: contacts A-floor, B-wall (faces) and B's corner on A's inclined face.
;;;;     Position constraint:  D_A = (x_A, 0), D_B = (0, y_B),
;;;;       (0, y_B) = (x_A, 0) + (0, l1) + s (l3, l2 - l1), so x_A = -s l3 and
;;;;       y_B = l1 - (x_A / l3)(l2 - l1) = l1 + k x_A;  hence  a_By = k a_Ax.
;;;;     Newton:  mb a_By = N cos a - mb g,   ma a_Ax = f - N sin a.
;;;;     Solution:
;;;;       a_Ax = (f - mb g k) / (ma + mb k^2)
;;;;            = l3 (f l3 - mb g (l1 - l2)) / (ma l3^2 + mb (l1 - l2)^2)
;;;;       a_By = k a_Ax
;;;;       N    = mb (ma g + k f) / ((ma + mb k^2) cos a)        (between A and B)
;;;;       N_wall = N sin a,  N_floor = ma g + N cos a.
;;;;     B rises iff f > mb g k = mb g (l1 - l2) / l3, falls iff f < mb g (l1 - l2) / l3;
;;;;     at equality both stay at rest forever.
;;;;     If B rises, A moves l3/2 to the right and B's corner reaches the upper end of
;;;;     A's face (A's vertex (0 l1)) at t1 = sqrt(l3 / a_Ax); if B falls, A moves l3/2
;;;;     to the left and B's corner reaches the lower end (A's vertex (l3 l2)) at
;;;;     t1 = sqrt(-l3 / a_Ax). Either way the state ends with
;;;;     (:leaves block-b block-a :endpoint). (A reaches the wall only later, at x_A = l3.)
;;;;     The sign of f - mb g k is not decided by the assumptions; with the default
;;;;     values (f = 20 > mb g k = 9.81) B rises.

(scenario two-blocks-in-corner
  "Block A, pushed toward a wall, lifts block B that rests on its inclined face."
  (parameters (ma :positive (:value 1)) (mb :positive (:value 1))
              (g :positive (:value 981/100)) (f :positive (:value 20))
              (l2 :positive (:value 1)) (l1 (> l1 l2) (:value 2))
              (l3 :positive (:value 1)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (half-plane ((* 2 l3) 1) ((* 2 l3) 0)))
  (body block-a :mass ma :position ((- (/ l3 2)) 0) :velocity (0 0)
                :shape (polygon (0 0) (l3 0) (l3 l2) (0 l1)))
  (body block-b :mass mb :position (0 (/ (+ l1 l2) 2)) :velocity (0 0)
                :shape (polygon (0 0) ((* 2 l3) 0) ((* 2 l3) l1) (0 l1)))
  (force push :on block-a :value (f 0))
  (simulate :states 2))
