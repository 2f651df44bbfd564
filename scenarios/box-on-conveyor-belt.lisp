;;;; scenarios/box-on-conveyor-belt.lisp -- a box dropped on a conveyor belt that moves at a
;;;; constant speed (a driven body).
;;;;
;;;; Expected results: the box falls for sqrt(2 h / g) and lands on the belt (a plastic
;;;; impact: its vertical velocity is lost, its horizontal one is still 0); kinetic friction
;;;; mu m g then accelerates it at mu g until it moves with the belt, after v/(mu g),
;;;; having slipped v^2/(2 mu g) on it; then static friction holds it and it moves at v
;;;; forever. The belt keeps its velocity; its drive balances the friction and the box's
;;;; weight on it, (mu m g, m g) while the box slips.

(scenario box-on-conveyor-belt
  "A box dropped on a conveyor belt moving at constant speed v."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (v :positive (:value 2)) (mu :positive (:value 1/2)) (h :positive (:value 1/2)))
  (gravity g)
  (body belt :driven t :velocity (v 0) :shape (half-plane (1 0) (0 0)))
  (body box :mass m :position (0 h) :velocity (0 0) :shape (polygon (0 0) (1 0) (1 1) (0 1)))
  (friction box belt :static mu)
  (simulate :states 4))
