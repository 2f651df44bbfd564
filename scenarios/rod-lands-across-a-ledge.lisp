;;;; scenarios/rod-lands-across-a-ledge.lisp -- a uniform rod falls flat onto a ledge that ends
;;;; under it: its left end lands on the ledge's top, and the ledge's edge strikes the rod's
;;;; underside at the same moment (issue 23: a fixed corner on a rotating body's face).
;;;;
;;;; The ledge's top runs from x = -3 to its edge at (0, 0); the rod (length l) lies
;;;; horizontal with its left end a distance d over the ledge (0 < d < l/2), its centre at
;;;; a = l/2 - d to the right of the edge, and falls from the height h. Its right end, past
;;;; the ledge's edge, is on the line of the ledge's top but touches nothing.
;;;; Expected results (textbook: a plastic impact, I = m l^2 / 12): it arrives at
;;;; v = sqrt(2 g h); only the edge pushes (the left end leaves the ledge upward), so with
;;;; the arm a the impulse is J = m v / (1 + m a^2 / I) = m v / (1 + 12 a^2 / l^2), the
;;;; centre moves on at v' = v - J/m downward and the rod turns clockwise at
;;;; omega' = -J a / I = -12 J a / (m l^2); the left end's velocity just after is
;;;; -v' + 6 J a / (m l)... upward, (J (1 + 6 a / l) / m - v) > 0 for d > 0.
;;;; With l = 2, d = 1/10, h = 1/5, g = 10: J = 0.583 m, v' = 1.417, omega' = -1.574.
;;;; Then the rod pivots and slides on the ledge's edge until its left end slides off it.

(scenario rod-lands-across-a-ledge
  "A horizontal rod falls onto a ledge; the ledge's edge strikes its underside."
  (parameters (m :positive (:value 1)) (g :positive (:value 10))
              (l :positive (< l 4) (:value 2)) (d :positive (< d (/ l 2)) (:value 1/10))
              (h :positive (:value 1/5)))
  (gravity g)
  (body ledge :fixed t :shape (polygon (-3 -1) (0 -1) (0 0) (-3 0)))
  (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
            :position ((- (/ l 2) d) h) :velocity (0 0))
  (restitution rod ledge 0)
  (simulate :states 1))
