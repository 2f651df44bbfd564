;;;; scenarios/balls-launched-with-spin.lisp -- a bowling ball launched with backspin, a disc
;;;; launched with topspin, and a disc set down spinning in place, each on a rough floor:
;;;; each slides until it rolls.
;;;;
;;;; Expected results (textbook), below. Source type: the textbook's "ball that slides
;;;; then rolls" problems (first-year mechanics; the angular momentum about the contact
;;;; point is kept, since friction acts there and the normal force and the weight pass
;;;; through it). A body of inertia I, launched at v0 with angular velocity w
;;;; (counter-clockwise positive: for motion to +x rolling is w = -v/r, backspin is
;;;; w > 0), ends rolling at
;;;;   v = (m r^2 v0 - I r w) / (m r^2 + I),
;;;; after a time |v - v0| / (mu g) (kinetic friction mu m g throughout the slide):
;;;;   sphere (I = (2/5) m r^2) with backspin w0: v = (5 v0 - 2 r w0) / 7 at
;;;;     t = 2 (v0 + r w0) / (7 mu g) (it rolls forward when 5 v0 > 2 r w0, declared);
;;;;   disc (I = m r^2 / 2) with topspin w = -w0, r w0 > v0: v = (2 v0 + r w0) / 3 at
;;;;     t = (r w0 - v0) / (3 mu g) (friction pushes it forward);
;;;;   disc spun in place (v0 = 0, w = w0): v = -r w0 / 3, t = r w0 / (3 mu g), kinetic
;;;;     energy m r^2 w0^2 / 12 left of m r^2 w0^2 / 4 (two thirds lost to friction).
;;;; The angular momentum about the origin (a point of the floor) is constant throughout.

(scenario sphere-launched-with-backspin
  "A bowling ball launched with backspin on a rough floor slides, then rolls."
  (parameters (m :positive (:value 7)) (g :positive (:value 981/100)) (r :positive (:value 1/10))
              (v0 :positive (:value 8)) (w0 :positive (< w0 (/ (* 5 v0) (* 2 r))) (:value 20))
              (mu :positive (:value 1/5)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body ball :mass m :inertia (* 2/5 m r r) :shape (circle r) :position (0 r) :velocity (v0 0)
        :angular-velocity w0)
  (friction ball floor :static mu)
  (query rolls-at (time (:stops-sliding ball floor)))
  (query rolling-speed (value (x (velocity ball)) :at (:stops-sliding ball floor)))
  (query spin-then (value (angular-velocity ball) :at (:stops-sliding ball floor)))
  (query angular-momentum-then (value (angular-momentum ball) :at (:stops-sliding ball floor)))
  (simulate :states 2))

(scenario disc-launched-with-topspin
  "A disc launched with topspin faster than rolling speeds up, then rolls."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (r :positive (:value 1/5))
              (v0 :positive (:value 2)) (w0 :positive (> w0 (/ v0 r)) (:value 30))
              (mu :positive (:value 1/4)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body disc :mass m :inertia :uniform :shape (circle r) :position (0 r) :velocity (v0 0)
        :angular-velocity (- w0))
  (friction disc floor :static mu)
  (query rolls-at (time (:stops-sliding disc floor)))
  (query rolling-speed (value (x (velocity disc)) :at (:stops-sliding disc floor)))
  (simulate :states 2))

(scenario disc-spun-in-place
  "A disc set down spinning without translation on a rough floor moves off, then rolls."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (r :positive (:value 1/5))
              (w0 :positive (:value 30)) (mu :positive (:value 1/4)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body disc :mass m :inertia :uniform :shape (circle r) :position (0 r) :velocity (0 0)
        :angular-velocity w0)
  (friction disc floor :static mu)
  (query rolls-at (time (:stops-sliding disc floor)))
  (query rolling-speed (value (speed disc) :at (:stops-sliding disc floor)))
  (query kinetic-energy-lost (value (- (* 1/4 m r r w0 w0) (kinetic-energy disc)) :at (:stops-sliding disc floor)))
  (simulate :states 2))
