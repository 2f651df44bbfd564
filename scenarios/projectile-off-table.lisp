;;;; scenarios/projectile-off-table.lisp -- a particle slides off a table top and falls to the floor.
;;;;
;;;; A fixed table, the rectangle (-2d 0) (0 0) (0 h) (-2d h), stands on a fixed floor
;;;; (the half-plane y <= 0). A particle slides on the table top with speed v0 toward
;;;; the edge at x = 0, starting at (-d h), the middle of the top face (on the face, not
;;;; on a vertex). Frictionless; gravity points down. (The table touches the floor;
;;;; fixed bodies do not interact.)
;;;;
;;;; Expected results (textbook):
;;;;   State 0: contact particle-table on the top face. Acceleration (0 0), normal
;;;;     force N = m g, velocity (v0 0). It reaches the edge (the vertex (0 h)) at
;;;;       t1 = d / v0,
;;;;     end event (:leaves particle table :endpoint).
;;;;   State 1: projectile: position (v0 tau, h - g tau^2 / 2), acceleration (0, -g).
;;;;     It lands on the floor after
;;;;       t2 = sqrt(2 h / g),  at x = v0 sqrt(2 h / g),
;;;;     with velocity (v0, -sqrt(2 g h)): a collision with the floor, where the
;;;;     simulation ends (end event (:collision particle floor)).

(scenario projectile-off-table
  "A particle slides along a table top, off its edge, and falls to the floor."
  (parameters (m :positive) (g :positive (:value 981/100))
              (h :positive (:value 1)) (d :positive (:value 1/2))
              (v0 :positive (:value 2)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body table :fixed t :position (0 0)
              :shape (polygon ((* -2 d) 0) (0 0) (0 h) ((* -2 d) h)))
  (body particle :mass m :position ((- d) h) :velocity (v0 0) :shape point)
  (simulate :states 4))
