;;;; scenarios/pushed-block-tips-or-slides.lisp -- a block on a rough floor pushed
;;;; horizontally near its top: does it tip or slide?
;;;;
;;;; The block: width w, height k, mass m, uniform; a constant push P > mu m g to the right
;;;; acts on its left face at height y = 9k/20 above its centre (:at ((- (/ w 2)) y)).
;;;; Expected results (textbook): while it slides without turning, the floor's push acts at
;;;; x_N = (y P + (k/2) mu m g) / (m g) from the centre line; it stays flat (slides at
;;;; (P - mu m g) / m) when x_N <= w / 2, and tips about its front bottom edge (its back
;;;; corner lifts off) when y P + (k/2) mu m g > (w/2) m g, turning at the start with
;;;; alpha = (m g w/2 - (y + k/2) P) / I_edge, I_edge = m (w^2 + k^2) / 3.
;;;; With the values below (P = 6, mu m g = 4.905, w/2 m g = 4.905, y = 9/10) it tips.
;;;; Assumed, as the textbook does: P > mu m g (the push beats friction), and
;;;; 3 mu w k < 4 w^2 + k^2 (tipping while the front edge slides has a positive effective
;;;; inertia, m (4 w^2 + k^2 - 3 mu w k) / 12: no Painleve paradox).
;;;; Symbolically the run answers the textbook's question with its first fork, on the
;;;; criterion (the flat block's back normal force, ((w/2) m g - y P - (k/2) mu m g) / w,
;;;; written 9 k p + 10 m g k mu - 10 m g w against 0): where it is negative the block
;;;; slides flat at (P - mu m g) / m until the run's time limit; where it is positive it
;;;; tips, and the front edge's lower and upper static friction limits are the next two
;;;; forks. With the edge sticking (branch 1.2.2) the block turns about it, its centre on
;;;; its arc about the edge and alpha, omega, N and F in closed form along the angle s
;;;; (alpha at s = 0 the textbook's); where that state ends (the edge starting to slide,
;;;; or lifting off) is a root along the angle with no closed form: undecided without
;;;; values (exit 3). With the edge sliding forward or back (branches 1.1, 1.2.1) the
;;;; motion has no closed form. Under --numeric the values select branch 1.2.2: it tips
;;;; until its edge starts to slide at t = 0.4288, then lifts off 0.0547 s later.
;;;; The block pushed low (y = -9k/20), which slides, is
;;;; awaiting-rotation/pushed-block-slides.lisp (its symbolic run is still too slow).

(scenario pushed-block-tips-or-slides
  "A block pushed near its top tips over its front edge."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (w :positive (:value 1))
              (k :positive (:value 2)) (mu :positive (< mu (/ (+ (* 4 w w) (* k k)) (* 3 w k))) (:value 1/2))
              (p :positive (> p (* mu m g)) (:value 6)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body block :mass m :inertia :uniform :position (0 (/ k 2)) :velocity (0 0)
              :shape (polygon ((- (/ w 2)) (- (/ k 2))) ((/ w 2) (- (/ k 2)))
                              ((/ w 2) (/ k 2)) ((- (/ w 2)) (/ k 2))))
  (force push :on block :at ((- (/ w 2)) (* 9/20 k)) :value (p 0))
  (friction block floor :static mu)
  (simulate :states 2 :until 1))
