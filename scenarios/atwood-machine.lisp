;;;; scenarios/atwood-machine.lisp -- an Atwood machine: two masses hang from a rope over two
;;;; pulleys (a wheel of radius r); the heavier one, at height h, falls to the floor, the
;;;; lighter one, on the floor, rises.
;;;;
;;;; Expected results: while the rope is taut both accelerate at g (m1 - m2)/(m1 + m2), the
;;;; tension is 2 g m1 m2/(m1 + m2), and the heavier mass reaches the floor after
;;;; sqrt(2 h (m1 + m2) / (g (m1 - m2))), moving at v = sqrt(2 g h (m1 - m2)/(m1 + m2)). It
;;;; stops there (a plastic impact); the rope goes slack and the lighter mass keeps rising, in
;;;; free flight, until the rope tightens again ((:tightens rope)) after 2 v / g, when it
;;;; jerks the heavier mass off the floor: both then move at m2 v/(m1 + m2).

(scenario atwood-machine
  "Two masses over a pulley: the heavier falls to the floor, the lighter keeps rising."
  (parameters (m1 :positive (:value 3)) (m2 :positive (> m2 0) (< m2 m1) (:value 1))
              (g :positive (:value 981/100)) (h :positive (:value 1)) (r :positive (:value 1/10))
              (top :positive (> top (* 2 h)) (:value 3)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body support :fixed t :position (0 top) :shape point)
  (body heavy :mass m1 :position ((- r) h) :velocity (0 0) :shape point)
  (body light :mass m2 :position (r 0) :velocity (0 0) :shape point)
  (pulley left-wheel :on support :at ((- r) 0))
  (pulley right-wheel :on support :at (r 0))
  (rope rope :length (+ (- top h) (* 2 r) top)
        :through ((heavy (0 0)) left-wheel right-wheel (light (0 0))))
  (simulate :states 3))
