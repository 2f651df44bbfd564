;;;; scenarios/awaiting-rotation/pushed-block-slides.lisp -- a block on a rough floor
;;;; pushed horizontally near its base: it slides.
;;;;
;;;; The block of ../pushed-block-tips-or-slides.lisp (width w, height k, mass m, uniform,
;;;; P > mu m g, 3 mu w k < 4 w^2 + k^2), pushed on its left face at y = -9k/20 below its
;;;; centre. Textbook: it stays flat while y P + (k/2) mu m g <= (w/2) m g (here always
;;;; when mu k <= w) and slides at (P - mu m g) / m. With the values below it slides
;;;; (a_x = 1.095): `bin/ames run --numeric` runs it in about a minute on the loaded
;;;; machine. Symbolically the run forks on the criterion, then on the flat block's front
;;;; normal force (pushed low and hard, -y P > (w/2 + (k/2) mu) m g, it would rock back
;;;; onto its back edge) and on the back corner's friction limit as a pivot (branch 2.2.1
;;;; is the sliding state); its tipping branch (the criterion's other side: mu k > w +
;;;; 9 k p / (10 m g) with p > mu m g and no Painleve paradox, so k^2 > 26 w^2, a thin
;;;; region of the parameters) is where the run spends its time: the numeric witnesses
;;;; find no admissible point there in 2000 draws, and DECIDE tries every strategy on each
;;;; question (see the README's pushed-block section). It stays here until that is fast.

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
