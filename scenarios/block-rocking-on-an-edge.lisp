;;;; scenarios/block-rocking-on-an-edge.lisp -- a block standing on a rough floor is given a
;;;; small spin about its front bottom edge; it rises on that edge, turns back and falls back
;;;; onto its face.
;;;;
;;;; The block: width w, height k, mass m, uniform (I_edge = m (w^2 + k^2) / 3 about an
;;;; edge), standing on the floor; it starts turning clockwise about its right bottom edge
;;;; with angular speed w0 (omega = -w0), its centre moving as that edge's pivot makes it,
;;;; v = omega k x (c - p) = (w0 k / 2, w0 w / 2). The floor is rough enough for the edge to
;;;; stick.
;;;; Expected results (textbook): the block pivots about the edge; its angle s (clockwise
;;;; turn -s) rises until its kinetic energy has gone into lifting the centre:
;;;;   (1/2) I_edge w0^2 = m g (d cos(b + s) - k/2),  d = sqrt(w^2 + k^2)/2, tan b = w/k
;;;; (the centre at height d cos(b + s) over the edge, s < 0), provided w0 is too small to
;;;; bring the centre over the edge (w0^2 < 3 g (sqrt(w^2 + k^2) - k) / (w^2 + k^2)).
;;;; There its angular velocity changes sign, (:turns block), and the next state rocks it
;;;; back from rest about the same edge until its other edge strikes the floor
;;;; ((:collision block floor)) after the same time.
;;;; With the values below (w = 1, k = 2, w0 = 1, g = 9.81): w0^2 = 1 < 3 g (sqrt 5 - 2) / 5
;;;; = 1.39, so it turns back.

(scenario block-rocking-on-an-edge
  "A block set turning about its bottom edge rises on it, turns back and falls back."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (w :positive (:value 1))
              (k :positive (:value 2))
              (w0 :positive (< w0 (sqrt (/ (* 3 g (- (sqrt (+ (* w w) (* k k))) k)) (+ (* w w) (* k k)))))
                  (:value 1)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body block :mass m :inertia :uniform :position (0 (/ k 2))
              :velocity ((/ (* w0 k) 2) (/ (* w0 w) 2)) :angular-velocity (- w0)
              :shape (polygon ((- (/ w 2)) (- (/ k 2))) ((/ w 2) (- (/ k 2)))
                              ((/ w 2) (/ k 2)) ((- (/ w 2)) (/ k 2))))
  (friction block floor :static 1)
  (query turning-angle (value (angle block) :at (:turns block)))
  (simulate :states 2))
