;;;; scenarios/awaiting-rotation/disc-rolling-down-incline.lisp -- a uniform disc released on a
;;;; rough incline rolls down without slipping.
;;;;
;;;; The incline is a fixed right triangle of height h and angle a; the disc (radius r, mass
;;;; m, I = m r^2 / 2) touches the middle of its slope, at rest. Friction mu_s = mu > tan(a)/3.
;;;; Expected results (textbook):
;;;;   rolling (static friction): acceleration (2/3) g sin a down the slope, friction
;;;;   m g sin a / 3 up the slope, normal force m g cos a, angular acceleration
;;;;   -(2/3) g sin a / r (clockwise while it rolls down to the right); it reaches the foot
;;;;   of the slope after t = sqrt(3 L / (g sin a)), L = h / (2 sin a) the half slope.
;;;;   With mu < tan(a)/3 it slips (the branch the assumptions below exclude).
;;;; The run stops there (:states 1): past the foot the disc leaves the triangle over its
;;;; corner, which AMES does not follow for a rotating disc (no closed form).

(scenario disc-rolling-down-incline
  "A uniform disc rolls without slipping down a rough incline."
  (parameters (m :positive (:value 2)) (g :positive (:value 981/100)) (r :positive (:value 1/5))
              (h :positive (> h r) (:value 2)) (a (> a 0) (< a (/ pi 2)) (:value (deg 30)))
              (mu :positive (> mu (/ (tan a) 3)) (:value 1/2)))
  (gravity g)
  (body incline :fixed t :shape (polygon (0 0) ((/ h (tan a)) 0) (0 h)))
  (body disc :mass m :inertia :uniform :shape (circle r)
             :position ((+ (/ h (* 2 (tan a))) (* r (sin a))) (+ (/ h 2) (* r (cos a))))
             :velocity (0 0))
  (friction disc incline :static mu)
  (query speed-at-foot (value (speed disc) :at (end 0)))
  (query spin-at-foot (value (angular-velocity disc) :at (end 0)))
  (simulate :states 1))

;;;; The same disc where friction is too weak to hold it rolling (mu < tan(a)/3): it rolls
;;;; with slipping. Expected results (textbook): kinetic friction mu m g cos a up the slope,
;;;; acceleration g (sin a - mu cos a) down the slope, angular acceleration
;;;; -2 mu g cos a / r; it never rolls without slipping on the slope. The slope here is
;;;; unbounded (a half-plane through the same two points), so that the slipping lasts.

(scenario disc-slipping-down-incline
  "A uniform disc on an incline too slippery for rolling slides while it spins up."
  (parameters (m :positive (:value 2)) (g :positive (:value 981/100)) (r :positive (:value 1/5))
              (h :positive (> h r) (:value 2)) (a (> a 0) (< a (/ pi 2)) (:value (deg 30)))
              (mu :positive (< mu (/ (tan a) 3)) (:value 1/10)))
  (gravity g)
  (body incline :fixed t :shape (half-plane ((/ h (tan a)) 0) (0 h)))
  (body disc :mass m :inertia :uniform :shape (circle r)
             :position ((+ (/ h (* 2 (tan a))) (* r (sin a))) (+ (/ h 2) (* r (cos a))))
             :velocity (0 0))
  (friction disc incline :static mu)
  (simulate :states 2))
