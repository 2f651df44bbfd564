;;;; scenarios/pushed-block-tips-or-slides.lisp -- a block on a rough floor
;;;; pushed horizontally: pushed low it slides, pushed high it tips.
;;;;
;;;; The block: width w, height k, mass m, uniform; a constant push P > mu m g to the right
;;;; acts on its left face at height y above its centre (:at ((- (/ w 2)) y)).
;;;; Expected results (textbook): while it slides without turning, the floor's push acts at
;;;; x_N = (y P + (k/2) mu m g) / (m g) from the centre line; it stays flat (slides at
;;;; (P - mu m g) / m) when x_N <= w / 2, and tips about its front bottom edge (its back
;;;; corner lifts off, (:lift-off block floor)) when y P + (k/2) mu m g > (w/2) m g.
;;;; With the values below (P = 6, mu m g = 4.905, w/2 m g = 4.905): pushed at y = -9/10 it
;;;; slides; at y = 9/10 it tips.
;;;; Assumed, as the textbook does: P > mu m g (the push beats friction), and
;;;; 3 mu w k < 4 w^2 + k^2 (tipping while the front edge slides has a positive effective
;;;; inertia, m (4 w^2 + k^2 - 3 mu w k) / 12: no Painleve paradox). Symbolically the run
;;;; branches first on the textbook's criterion (the flat block's back normal force,
;;;; ((w/2) m g - y P - (k/2) mu m g) / w); where it holds, the front edge cannot stick
;;;; while tipping (DECIDE combines the criterion with P > mu m g). Pushed low and hard
;;;; (-y P > (w/2 + (k/2) mu) m g, y < 0) the block would rock back onto its back edge
;;;; instead: the flat block's front normal force is the run's second branch fact.
;;;; Where it tips, symbolically, the front edge's lower and upper static friction limits
;;;; are the next two forks and the order of two angles the fourth (all in the first
;;;; state's analysis); with the edge sticking it turns about it with
;;;; alpha = (m g w/2 - (y + k/2) P) / I_edge at the start, I_edge = m (w^2 + k^2) / 3, its
;;;; end (the edge sliding or lifting, roots along the angle) found only with values.

(scenario pushed-block-slides
  "A block pushed near its base slides along the rough floor."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (w :positive (:value 1))
              (k :positive (:value 2)) (mu :positive (< mu (/ (+ (* 4 w w) (* k k)) (* 3 w k))) (:value 1/2))
              (p :positive (> p (* mu m g)) (:value 6)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body block :mass m :inertia :uniform :position (0 (/ k 2)) :velocity (0 0)
              :shape (polygon ((- (/ w 2)) (- (/ k 2))) ((/ w 2) (- (/ k 2)))
                              ((/ w 2) (/ k 2)) ((- (/ w 2)) (/ k 2))))
  (force push :on block :at ((- (/ w 2)) (* -9/20 k)) :value (p 0))
  (friction block floor :static mu)
  (simulate :states 2 :until 1))

(scenario pushed-block-tips
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
