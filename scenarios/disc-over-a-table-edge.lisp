;;;; scenarios/disc-over-a-table-edge.lisp -- a uniform disc released just past the top of a
;;;; table's smooth edge rolls over the corner and leaves it.
;;;;
;;;; The table top is the segment from its edge (0, 0) back to (-w, 0) (solid below); the
;;;; disc (mass m, radius r, I = m r^2 / 2) starts at rest touching only the edge, its
;;;; centre at the angle th0 from the vertical through the edge. The edge is smooth: its
;;;; force passes through the disc's centre, so nothing turns the disc (it keeps omega = 0,
;;;; tied to its path with the factor 0: src/simulator/rolling-path.lisp) and its centre
;;;; moves on the circle of radius r round the edge like a particle on a sphere.
;;;; Expected results (textbook): with theta the angle of the centre from the vertical,
;;;; v^2 = 2 g r (cos th0 - cos theta), N = m g (3 cos theta - 2 cos th0); the disc leaves
;;;; the edge ((:lift-off disc table)) at cos theta = (2/3) cos th0, moving at
;;;; sqrt(2 g r cos(th0) / 3), still not turning; then it falls freely. (On a rough edge it
;;;; would roll: v^2 = (4/3) g r (cos th0 - cos theta), N = m g (7 cos theta - 4 cos th0)/3,
;;;; so that rolling would last to cos theta = (4/7) cos th0; but the friction it needs,
;;;; m g sin(theta) / 3, exceeds mu N before N reaches 0 whatever mu: it slips first.)
;;;; The arc length s along the contact is measured from the horizontal: sin(s/r) =
;;;; cos theta.

(scenario disc-over-a-table-edge
  "A uniform disc released just past the top of a smooth table edge rolls over it and leaves it."
  (parameters (m :positive (:value 1)) (r :positive (:value 1/5)) (g :positive (:value 981/100))
              (w :positive (> w (* 2 r)) (:value 1))
              (th0 (> th0 0) (< th0 (/ pi 4)) (:value 1/10)))
  (gravity g)
  (body table :fixed t :shape (segment (0 0) ((- w) 0)))
  (body disc :mass m :inertia :uniform :shape (circle r)
             :position ((* r (sin th0)) (* r (cos th0))) :velocity (0 0))
  (query speed-at-lift-off (value (speed disc) :at (:lift-off disc table)))
  (simulate :states 2))
