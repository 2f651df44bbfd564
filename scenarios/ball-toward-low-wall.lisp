;;;; scenarios/ball-toward-low-wall.lisp -- a ball thrown horizontally toward a low wall: over it or into it.
;;;;
;;;; A particle leaves (0, h) with velocity (v0, 0) over a floor (y <= 0). A thin wall, the
;;;; segment from (d, 0) to (d, w) with 0 < w < h, stands in its way. Collisions are
;;;; plastic (restitution 0, the default). Without values the assumptions do not say
;;;; whether the ball clears the wall, so the run branches (an envisionment).
;;;;
;;;; Expected results (the ball's height at the wall is h - g d^2/(2 v0^2)):
;;;;   Branch "g d^2 - 2 v0^2 (h - w) < 0" (the ball passes above the wall's top):
;;;;     free fall, x = v0 tau, y = h - g tau^2/2, until it lands at t = sqrt(2 h/g) at
;;;;     (v0 sqrt(2 h/g), 0), beyond the wall (this needs the truth layer to see that
;;;;     w > 0 and w < h - g d^2/(2 v0^2) give v0 sqrt(2 h/g) > d); then it slides on the
;;;;     floor with speed v0 forever (nothing ahead of it).
;;;;   Branch "... > 0" (the ball reaches x = d below the wall's top): it branches again
;;;;     on 2 h v0^2 - g d^2, whether it lands before the wall:
;;;;       > 0: it hits the wall's face at t = d/v0 (the impact takes its horizontal
;;;;            speed), falls along the face and lands at its foot at t = sqrt(2 h/g);
;;;;       < 0: it lands at t = sqrt(2 h/g), slides with speed v0 and hits the wall at
;;;;            t = d/v0;
;;;;       = 0: it lands at the wall's foot at t = d/v0.
;;;;   Branch "... = 0" (h - g d^2/(2 v0^2) = w exactly, w substituted): the ball reaches
;;;;     the wall's top at t = d/v0 and hits it there.
;;;;   The default values (w = 1 < 2 - 9.81/18) select the first branch.

(scenario ball-toward-low-wall
  "A particle thrown horizontally from height h toward a thin wall of height w at distance d."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (h :positive (:value 2)) (d :positive (:value 1)) (v0 :positive (:value 3))
              (w :positive (< w h) (:value 1)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body wall :fixed t :shape (segment (d w) (d 0)))
  (body ball :mass m :position (0 h) :velocity (v0 0) :shape point)
  (simulate :states 4))
