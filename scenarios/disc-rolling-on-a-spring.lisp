;;;; scenarios/disc-rolling-on-a-spring.lisp -- a disc rolling on a rough floor, tied at its
;;;; centre by a spring, starts to slip where static friction no longer holds it rolling.
;;;;
;;;; A uniform disc (mass m, radius r, I = m r^2 / 2) rolls on a rough floor; a spring
;;;; (stiffness k, rest length l) ties its centre to the point (0, r) of the floor. It is
;;;; launched from the rest length at v0, rolling (omega0 = -v0 / r). Expected results
;;;; (textbook): rolling, the spring acts on the mass m + I / r^2 = 3 m / 2, so the disc
;;;; oscillates at w = sqrt(2 k / (3 m)): x = l + (v0 / w) sin(w t); the static friction
;;;; that keeps it rolling is a third of the spring's pull, k (x - l) / 3, against the
;;;; stretch. It grows with the stretch: where v0 / w > 3 mu m g / k (the assumption on mu
;;;; below) it reaches mu m g before the disc turns back, at the stretch
;;;; x - l = 3 mu m g / k, at t = asin(3 mu m g w / (k v0)) / w, when the disc moves at
;;;; sqrt(v0^2 - 6 mu^2 m g^2 / k) (energy: (3/4) m v^2 + (1/2) k (x - l)^2 is conserved
;;;; while it rolls). Then it slides (kinetic friction mu m g against its slip), its spin
;;;; slowing at alpha = 2 mu g / r. The run stops there (:states 1). The bound on v0 keeps
;;;; the rolling swing's amplitude v0 / w below l, so that the spring never shrinks to zero
;;;; length (a disc driven through its anchor, (:spring-closes s)); without it the run forks
;;;; at the start on 3 m v0^2 < 2 k l^2, each branch slipping first all the same: the
;;;; closing could only come on the way back, after the slip.

(scenario disc-rolling-on-a-spring
  "A disc rolling on a rough floor, tied by a spring, slips where friction can no longer hold it."
  (parameters (m :positive (:value 1)) (r :positive (:value 1/5)) (g :positive (:value 981/100))
              (k :positive (:value 30)) (l :positive (:value 2)) (v0 :positive (< v0 (* l (sqrt (/ (* 2 k) (* 3 m))))) (:value 3))
              (mu :positive (< mu (/ (* v0 (sqrt (* 2 k m))) (* 3 (sqrt 3) m g))) (:value 1/5)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body disc :mass m :inertia :uniform :shape (circle r) :position (l r) :velocity (v0 0)
             :angular-velocity (- (/ v0 r)))
  (spring s :from (floor (0 r)) :to (disc (0 0)) :stiffness k :rest-length l)
  (friction disc floor :static mu)
  (query slips-at (time (:starts-sliding disc floor)))
  (query speed-then (value (speed disc) :at (:starts-sliding disc floor)))
  (simulate :states 1))
