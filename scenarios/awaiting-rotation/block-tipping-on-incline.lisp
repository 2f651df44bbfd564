;;;; scenarios/awaiting-rotation/block-tipping-on-incline.lisp -- a tall block on a rough incline
;;;; tips over its downhill edge instead of sliding.
;;;;
;;;; The block (width w along the slope, height k, uniform: m (w^2 + k^2) / 12) stands on the
;;;; middle of the slope, turned by -a to sit flat on it. With mu > tan a it cannot slide;
;;;; with tan a > w / k its weight's line falls outside its base (downhill of its downhill
;;;; edge), so it tips at once: its uphill corner lifts off ((:lift-off block incline)) and
;;;; it turns about its downhill edge, at the start with the angular acceleration
;;;; -m g ((k/2) sin a - (w/2) cos a) / I_edge (clockwise), I_edge = m (w^2 + k^2) / 3 the
;;;; inertia about that edge and m g ((k/2) sin a - (w/2) cos a) the torque of its weight.
;;;; Its edge sticks as it starts to tip when the friction it needs there, m g ((4 w^2 + k^2)
;;;; sin a + 3 w k cos a) / (4 (w^2 + k^2)) up the slope, is within mu times the normal
;;;; force, m g ((w^2 + 4 k^2) cos a + 3 w k sin a) / (4 (w^2 + k^2)): assumed, as the
;;;; textbook's "rough enough" (mu > tan a alone does not give it). Turning about the edge,
;;;; omega^2 = 3 g (w sin a + k cos a + w sin s - k cos s) / (w^2 + k^2) along its angle s
;;;; (from -a, clockwise); the state ends where the edge starts sliding (mu N + F = 0, a
;;;; root without closed form: s = -1.12404 with the values), before the block would lift
;;;; off its edge (N = 0) or land on its downhill face (s = -(a + pi/2)). The run stops
;;;; there (:states 1): the textbook's question is the tipping and what ends it.

(scenario block-tipping-on-incline
  "A tall block on a rough incline tips over its downhill edge rather than sliding."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (h :positive (:value 3)) (a (> a 0) (< a (/ pi 2)) (:value (deg 30)))
              ;; (< w h): the block must fit on the slope (w <= h / sin a) for its two
              ;; bottom corners to be proven on it at the start
              (w :positive (< w h) (:value 1/5))
              ;; (< k (- (/ h (* 2 (sin a))) (/ w 2))): the slope below the block is long
              ;; enough for its downhill face to land on it (the downhill edge stands w/2
              ;; below the slope's middle, h / (2 sin a) above its foot)
              (k :positive (> k (/ w (tan a))) (< k h) (< k (- (/ h (* 2 (sin a))) (/ w 2)))
                 (:value 1))
              (mu :positive (> mu (tan a))
                  (> mu (/ (+ (* (+ (* 4 w w) (* k k)) (sin a)) (* 3 w k (cos a)))
                           (+ (* (+ (* w w) (* 4 k k)) (cos a)) (* 3 w k (sin a)))))
                  (:value 1)))
  (gravity g)
  (body incline :fixed t :shape (polygon (0 0) ((/ h (tan a)) 0) (0 h)))
  (body block :mass m :inertia :uniform :angle (- a)
              :shape (polygon ((- (/ w 2)) (- (/ k 2))) ((/ w 2) (- (/ k 2)))
                              ((/ w 2) (/ k 2)) ((- (/ w 2)) (/ k 2)))
              :position ((+ (/ h (* 2 (tan a))) (* (/ k 2) (sin a))) (+ (/ h 2) (* (/ k 2) (cos a))))
              :velocity (0 0))
  (friction block incline :static mu)
  (simulate :states 1))
