;;;; scenarios/block-rocking-on-an-edge.lisp -- a block standing on a rough floor is set turning
;;;; about its front bottom edge; it rises on that edge, turns back, falls back onto its face,
;;;; strikes the floor with its other edge and rocks on that one (Housner's rocking block).
;;;;
;;;; The block: width w = 1, height k = 2, mass m = 1, uniform (about an edge I_edge =
;;;; m (w^2 + k^2) / 3 = 5/3), standing on a floor rough enough (mu = 1) for the edge it
;;;; turns on to stick; g = 9.81. It starts turning clockwise about its right bottom edge
;;;; with angular speed w0 (omega = -w0), its centre moving as that pivot makes it,
;;;; v = omega k x (c - p) = (w0 k / 2, w0 w / 2).
;;;; Expected results (textbook): on the edge, its angle s (s < 0, clockwise) rises until its
;;;; kinetic energy has gone into lifting the centre, whose height over the edge is
;;;; (k/2) cos s - (w/2) sin s:
;;;;   (1/2) I_edge w0^2 = m g ((k/2) cos s - (w/2) sin s - k/2),
;;;; provided w0 is too small to bring the centre over the edge (w0^2 < 3 g (sqrt(w^2 + k^2)
;;;; - k) / (w^2 + k^2) = 1.393). There its angular velocity changes sign ((:turns block), a
;;;; turning point of a rotation held by a corner: src/kb/turning.lisp), and the next state
;;;; rocks it back about the same edge until its left edge strikes the floor at s = 0 with
;;;; the speed it started with ((:collision block floor)). The impact (no bounce) transfers
;;;; the pivot to the left edge; angular momentum about that edge is conserved, so the block
;;;; rocks on with omega' = omega (1 - (3/2) w^2 / (w^2 + k^2)) = (7/10) omega (Housner,
;;;; 1963), and rises on the left edge to (k/2) cos s + (w/2) sin s - k/2 = (49/100) of the
;;;; first rise, where it turns again.
;;;; The numbers: w0^2 = 11772/10000 = 2 m g (1/10) / I_edge, so that the first turning
;;;; angle is s = -2 atan(1/7) (sin s = -7/25, cos s = 24/25: the centre rises by 1/10).
;;;; Symbolically (w, k, m, g, w0 parameters) the run forks at its start on the facts that
;;;; decide which corner and friction modes hold (the choice search's, as for the tipping
;;;; blocks of awaiting-rotation/): not yet the textbook's one state
;;;; (awaiting-rotation/block-rocking-symbolic.lisp, and its README's "Rocking session").

(scenario block-rocking-on-an-edge
  "A block set turning about its bottom edge rises on it, turns back and rocks on its other edge."
  (gravity 981/100)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body block :mass 1 :inertia :uniform :position (0 1)
              :velocity ((sqrt 11772/10000) (/ (sqrt 11772/10000) 2))
              :angular-velocity (- (sqrt 11772/10000))
              :shape (polygon (-1/2 -1) (1/2 -1) (1/2 1) (-1/2 1)))
  (friction block floor :static 1)
  (query first-turning-angle (value (angle block) :at (:turns block)))
  (simulate :states 3))
