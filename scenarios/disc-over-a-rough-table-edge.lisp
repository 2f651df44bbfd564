;;;; scenarios/disc-over-a-rough-table-edge.lisp -- a uniform disc released just past the top of
;;;; a rough table edge rolls over the corner until it starts to slip.
;;;;
;;;; The table top is the segment from its edge (0, 0) back to (-10 r, 0); the disc (mass m,
;;;; radius r, I = m r^2 / 2) starts at rest touching only the edge, its centre at
;;;; (3 r / 5, 4 r / 5): at the angle th0 from the vertical with cos th0 = 4/5. Friction
;;;; mu = 1 at the edge. Expected results (textbook): rolling over the edge the disc turns
;;;; about it, omega = -v / r (its rotation tied to its path: src/simulator/rolling-path.lisp),
;;;; so that with theta the angle of its centre from the vertical
;;;;   v^2 = (4/3) g r (cos th0 - cos theta)              (energy, with (1/2) I omega^2),
;;;;   N = m g (7 cos theta - 4 cos th0) / 3,  F = m g sin(theta) / 3  (static friction),
;;;; so that were it to keep rolling it would leave the edge where N = 0, at
;;;; cos theta = (4/7) cos th0 = 16/35 (the textbook's "rough edge" answer). But the friction
;;;; rolling needs reaches mu N first, whatever mu (N falls to 0 while F does not): the disc
;;;; starts to slip ((:starts-sliding disc table)) where sin theta = mu (7 cos theta - 4 cos
;;;; th0), here sin theta = 7 cos theta - 16/5, before cos theta = 16/35. The run stops there
;;;; (:states 1): the sliding over the edge that follows is not decided yet (its start forks
;;;; on relations whose exact numbers Maxima cannot compare). The arc length s along the
;;;; contact is measured from the horizontal: cos theta = sin(s/r).

(scenario disc-over-a-rough-table-edge
  "A uniform disc released just past the top of a rough table edge rolls over it until it slips."
  (parameters (m :positive (:value 1)) (r :positive (:value 1/5)) (g :positive (:value 981/100)))
  (gravity g)
  (body table :fixed t :shape (segment (0 0) ((* -10 r) 0)))
  (body disc :mass m :inertia :uniform :shape (circle r) :position ((* 3/5 r) (* 4/5 r))
             :velocity (0 0))
  (friction disc table :static 1)
  (simulate :states 1))
