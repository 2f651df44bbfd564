;;;; scenarios/awaiting-rotation/block-rocking-symbolic.lisp -- the rocking block of
;;;; ../block-rocking-on-an-edge.lisp with its values taken away.
;;;;
;;;; A uniform block (width w, height k, mass m) standing on a rough floor (mu) is set
;;;; turning clockwise about its right bottom edge at w0, its centre moving as that pivot
;;;; makes it. w0 is below the speed that brings the centre over the edge: (1/2) I_edge w0^2
;;;; < m g (sqrt(w^2 + k^2) - k) / 2, I_edge = m (w^2 + k^2) / 3. Expected (textbook, for a
;;;; floor rough enough that the edge sticks): it rises until (1/2) I_edge w0^2 = m g (rise of
;;;; the centre), (k/2) cos s - (w/2) sin s - k/2, turns back, strikes the floor with its
;;;; other edge at the speed it started with and rocks on at omega (1 - (3/2) w^2 / (w^2 +
;;;; k^2)) (Housner).
;;;; On the edge (p the angle of the centre from the vertical through it, c = cos p =
;;;; (k cos s - w sin s)/D, D^2 = w^2 + k^2, b = k/D + D w0^2/(3 g) its value at the turning
;;;; point, b < 1 by the bound on w0): N = (m g / 4)((3 c - b)^2 + 1 - b^2) > 0 at every
;;;; angle, and the friction F = -(3 m g / 4) sin p (2 b - 3 c).
;;;; "Rough enough", declared as a textbook would ("the floor is rough enough that the
;;;; block does not slide"), here in a form the algebra can use: mu (1 - b^2) > 9/2 + 6 b,
;;;; i.e. mu above the largest friction, (m g / 4)(9/2 + 6 b) harmonic by harmonic, over
;;;; the least normal force, (m g / 4)(1 - b^2), at any angle. It is sufficient, not
;;;; necessary (far stronger than the rise needs: for w = 1, k = 2 and the valued file's
;;;; w0 it asks mu > 325, where the rise needs 0.33). Its consequences at the start (the
;;;; friction there within mu N) and at the strike (a plastic impact about the new edge
;;;; needs mu >= 3 w k / (w^2 + 4 k^2)) are declared too, for DECIDE.
;;;; With them the start is the textbook's one state (no fork) and its end along the rise
;;;; is proven (README.md, "Rocking session 3").

(scenario block-rocking-symbolic
  "A block set turning about its bottom edge rises on it, turns back and rocks on its other edge."
  (parameters (m :positive) (g :positive) (w :positive) (k :positive)
              (w0 :positive (< w0 (sqrt (/ (* 3 g (- (sqrt (+ (expt w 2) (expt k 2))) k))
                                          (+ (expt w 2) (expt k 2))))))
              ;; rough enough (see the header): at every angle, then at the start and at
              ;; the strike, which follow from it
              (mu :positive
                  (> mu (/ (+ 9/2 (* 6 (/ (+ (* 3 g k) (* (+ (expt w 2) (expt k 2)) (expt w0 2)))
                                          (* 3 g (sqrt (+ (expt w 2) (expt k 2)))))))
                           (- 1 (expt (/ (+ (* 3 g k) (* (+ (expt w 2) (expt k 2)) (expt w0 2)))
                                         (* 3 g (sqrt (+ (expt w 2) (expt k 2)))))
                                      2))))
                  (> mu (/ (- (* 3 g w k) (* 2 w (+ (expt w 2) (expt k 2)) (expt w0 2)))
                           (- (* g (+ (expt w 2) (* 4 (expt k 2))))
                              (* 2 k (+ (expt w 2) (expt k 2)) (expt w0 2)))))
                  (> mu (/ (- (* 2 w (+ (expt w 2) (expt k 2)) (expt w0 2)) (* 3 g w k))
                           (- (* g (+ (expt w 2) (* 4 (expt k 2))))
                              (* 2 k (+ (expt w 2) (expt k 2)) (expt w0 2)))))
                  (> mu (/ (* 3 w k) (+ (expt w 2) (* 4 (expt k 2)))))))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body block :mass m :inertia :uniform :position (0 (/ k 2))
              :velocity ((/ (* w0 k) 2) (/ (* w0 w) 2))
              :angular-velocity (- w0)
              :shape (polygon ((- (/ w 2)) (- (/ k 2))) ((/ w 2) (- (/ k 2)))
                              ((/ w 2) (/ k 2)) ((- (/ w 2)) (/ k 2))))
  (friction block floor :static mu)
  (query first-turning-angle (value (angle block) :at (:turns block)))
  (simulate :states 3))
