;;;; scenarios/awaiting-rotation/disc-launched-sliding.lisp -- a disc (a bowling ball) launched
;;;; sliding without spin on a rough floor slides, spins up, then rolls.
;;;;
;;;; Expected results (textbook): while it slides, kinetic friction mu m g backwards:
;;;; velocity v0 - mu g t, angular velocity -2 mu g t / r; it rolls from
;;;; t = v0 / (3 mu g) ((:stops-sliding disc floor)) at (2/3) v0, angular velocity
;;;; -2 v0 / (3 r), having slid 5 v0^2 / (18 mu g); then it rolls at (2/3) v0 forever.

(scenario disc-launched-sliding
  "A disc launched without spin on a rough floor slides, then rolls at two thirds of its speed."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (r :positive (:value 3/10))
              (v0 :positive (:value 3)) (mu :positive (:value 1/5)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body disc :mass m :inertia :uniform :shape (circle r) :position (0 r) :velocity (v0 0))
  (friction disc floor :static mu)
  (query rolls-at (time (:stops-sliding disc floor)))
  (query rolling-speed (value (speed disc) :at (:stops-sliding disc floor)))
  (simulate :states 2))
