;;;; scenarios/block-sliding-on-rough-floor.lisp -- a block launched along a rough floor slows down and stops.
;;;;
;;;; A fixed floor (y <= 0) and a square block of side b resting on it, its reference
;;;; point the middle of its bottom face, launched along +x with speed v0. Coulomb
;;;; friction between them, MU-K = MU-S = mu.
;;;;
;;;; Expected results (textbook):
;;;;   State 0: contact block-floor, face on face, sliding forward.
;;;;     Normal force N = m g; friction mu m g against the motion (on the block, -mu m g
;;;;     along +x): acceleration (-mu g, 0). Velocity v0 - mu g tau.
;;;;     It stops at t1 = v0 / (mu g), after sliding v0^2 / (2 mu g):
;;;;     (:stops-sliding block floor).
;;;;   State 1: at rest at x = v0^2 / (2 mu g): static, friction 0, N = m g, forever.

(scenario block-sliding-on-rough-floor
  "A block launched along a rough floor slides to a stop and stays."
  (parameters (m :positive) (g :positive) (b :positive)
              (v0 :positive) (mu :positive))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body block :mass m :position (0 0) :velocity (v0 0)
              :shape (polygon ((- (/ b 2)) 0) ((/ b 2) 0) ((/ b 2) b) ((- (/ b 2)) b)))
  (friction block floor :static mu)
  (simulate :states 3))
