;;;; scenarios/atwood-massive-pulley.lisp -- an Atwood machine whose pulley is
;;;; a disc of inertia I hinged at its centre: a rope wound on each side.
;;;;
;;;; Expected results (textbook): a = (m1 - m2) g / (m1 + m2 + I / R^2) (m1 down, m2 up),
;;;; the pulley's angular acceleration a / R (counter-clockwise: m1 hangs on its left), the
;;;; tensions T1 = m1 (g - a) and T2 = m2 (g + a), different since the pulley has inertia;
;;;; the hinge holds M g + T1 + T2 (the query hinge-holds). m1 reaches the floor after
;;;; sqrt(2 h / a). The landing (the floor plastic: no restitution clause) stops m1 and lets
;;;; its rope go slack: m2 and the pulley keep their speeds, and the impact dissipates m1's
;;;; kinetic energy (1/2) m1 v^2 = m1 (m1 - m2) g h R^2 / (I + (m1 + m2) R^2).
;;;; After the landing m2 and the pulley turn on together on the taut right rope (not m2 in
;;;; free flight: the pulley would wind the rope in faster than m2 rises), slowed by m2's
;;;; weight alone: m2's acceleration -m2 g / (m2 + I/R^2), the tension m2 I g / (I + m2 R^2).
;;;; Whether m2 climbs to the pulley is a fact over the parameters, the run's branch: its
;;;; highest point, 3 h / 2 + (m1 - m2) h (I + m2 R^2) / (m2 (I + (m1 + m2) R^2)), below
;;;; top or not. Below it (the values), m2 stops after v / a, falls back, and the slack
;;;; rope is taut again when the pulley is back at its angle of the landing: a plastic jerk
;;;; lifts m1, the angular momentum about the axle kept, at v (I + m2 R^2) / (I + (m1 + m2) R^2)
;;;; (the run's third state ends there, with the jerk; with more states m1 then rises
;;;; h (I + m2 R^2)^2 / (I + (m1 + m2) R^2)^2, both ropes taut). Above it (e.g. --set
;;;; top=11/5) m2 reaches the pulley's rim at the rope's tangent point (R, top), at the
;;;; speed sqrt(v^2 - 2 a (top - 3 h / 2)): that state is reported, and what follows, m2
;;;; carried round the rim on its rope wound in to nothing, is not modelled (the branch
;;;; ends failed, the run exits 3). The boundary, the highest point at top exactly, is
;;;; listed unsimulated. Under the values the run exits 0, its self-check passing, and the
;;;; witness (bin/ames check --numeric, Siconos) agrees on the three states.

(scenario atwood-massive-pulley
  "An Atwood machine over a disc pulley of inertia I."
  (parameters (m1 :positive (:value 3)) (m2 :positive (< m2 m1) (:value 1))
              (big-m :positive (:value 2)) (big-r :positive (:value 1/5))
              (i :positive (:value 1/25)) (g :positive (:value 981/100))
              (h :positive (:value 1)) (top :positive (> top (* 2 h)) (> top big-r) (:value 3)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body pulley :mass big-m :inertia i :shape (circle big-r) :position (0 top) :velocity (0 0))
  (hinge axle :body pulley :at (0 0))
  (body heavy :mass m1 :shape point :position ((- big-r) h) :velocity (0 0))
  (body light :mass m2 :shape point :position (big-r (/ h 2)) :velocity (0 0))
  (rope left :length (- top h) :through ((heavy (0 0)) (pulley ((- big-r) 0) :wound)))
  (rope right :length (- top (/ h 2)) :through ((light (0 0)) (pulley (big-r 0) :wound)))
  (query hinge-holds (value (y (hinge-force axle)) :at (start 0)))
  (simulate :states 3))
