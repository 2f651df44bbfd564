;;;; scenarios/ladder-on-rough-floor.lisp -- a uniform ladder against a frictionless wall, its
;;;; foot on a rough floor, stays at rest when the friction suffices.
;;;;
;;;; The ladder is a thin uniform rod of length l at angle a with the floor (as in
;;;; ladder-against-wall.lisp). Expected results (textbook statics): the floor holds it up
;;;; with N = m g, the wall pushes with m g / (2 tan a) (the moments of the weight and of
;;;; the wall's push about the foot balance), and static friction at the foot balances
;;;; that push, F = m g / (2 tan a): it suffices when mu >= 1 / (2 tan a). Then nothing
;;;; changes: the state lasts forever. (With less friction the foot slides: one degree of
;;;; freedom again, but with an inertia term in omega^2, no closed form here yet.)

(scenario ladder-on-rough-floor
  "A ladder against a smooth wall stays up on a rough floor when mu >= 1 / (2 tan a)."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1))
              (a (> a 0) (< a (/ pi 2)) (:value (deg 60)))
              (mu :positive (> mu (/ 1 (* 2 (tan a)))) (:value 1)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (half-plane (0 0) (0 1)))
  (body ladder :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
               :position ((* (/ l 2) (cos a)) (* (/ l 2) (sin a))) :angle (- pi a)
               :velocity (0 0))
  (friction ladder floor :static mu)
  (simulate :states 1))
