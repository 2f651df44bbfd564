;;;; scenarios/rolling-bodies-bounce-off-a-wall.lisp -- a disc and a ball, rolling on a rough
;;;; floor, bounce elastically off a smooth wall, slide, and roll back.
;;;;
;;;; Source type: the textbook's ball rebounding from a cushion (first-year rotational
;;;; dynamics: the smooth wall reverses the velocity and leaves the spin; then the angular
;;;; momentum about the contact point is kept while it slides). Expected results
;;;; (textbook): rolling at v0 into the wall, it comes off at -v0 still spinning at -v0/r,
;;;; slides under kinetic friction mu m g, and rolls back at
;;;;   v = -v0 (m r^2 - I) / (m r^2 + I):
;;;; -v0/3 for the disc after 2 v0 / (3 mu g), -(3/7) v0 for the solid ball after
;;;; 4 v0 / (7 mu g); the impulse of the wall 2 m v0, no energy lost at the wall.

(scenario rolling-disc-bounces-off-a-wall
  "A disc rolling on a rough floor bounces elastically off a smooth wall, slides, then rolls back."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (r :positive (:value 1/5))
              (v0 :positive (:value 2)) (d :positive (:value 1)) (mu :positive (:value 1/4)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (half-plane (0 1) (0 0)))
  (body disc :mass m :inertia :uniform :shape (circle r) :position ((- (+ d r)) r) :velocity (v0 0)
        :angular-velocity (- (/ v0 r)))
  (friction disc floor :static mu)
  (restitution disc wall 1)
  (query rolls-back-at (value (x (velocity disc)) :at (:stops-sliding disc floor)))
  (query slides-for (value (- (time) (/ d v0)) :at (:stops-sliding disc floor)))
  (simulate :states 4))

(scenario rolling-ball-bounces-off-a-wall
  "A solid ball rolling on a rough floor bounces elastically off a smooth wall, then rolls back."
  (parameters (m :positive (:value 1/5)) (g :positive (:value 981/100)) (r :positive (:value 3/100))
              (v0 :positive (:value 2)) (d :positive (:value 1)) (mu :positive (:value 1/5)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (half-plane (0 1) (0 0)))
  (body ball :mass m :inertia (* 2/5 m r r) :shape (circle r) :position ((- (+ d r)) r) :velocity (v0 0)
        :angular-velocity (- (/ v0 r)))
  (friction ball floor :static mu)
  (restitution ball wall 1)
  (query rolls-back-at (value (x (velocity ball)) :at (:stops-sliding ball floor)))
  (query slides-for (value (- (time) (/ d v0)) :at (:stops-sliding ball floor)))
  (simulate :states 4))
