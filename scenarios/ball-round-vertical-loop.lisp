;;;; scenarios/ball-round-vertical-loop.lisp -- a ball launched from the bottom along the inside
;;;; of a fixed vertical circle (a loop of radius r), either way, too slow to loop and fast
;;;; enough to.
;;;;
;;;; Expected results: on the loop the speed squared is v0^2 - 2 g h at height h and the
;;;; loop pushes with N = m (v0^2 - 2 g r + 3 g r sin a) / r, a the angle above the centre's
;;;; height (negative below). Between sqrt(2 g r) and sqrt(5 g r) the ball climbs past the
;;;; centre's height and leaves the loop where N = 0: sin a = (v0^2 - 2 g r) / (3 g r), at
;;;; height (g r + v0^2) / (3 g), on the side it was launched toward, and flies off as a
;;;; projectile (inside the loop, until it lands on it again). Faster than sqrt(5 g r) it
;;;; loops (N > 0 all round) forever.

(scenario ball-in-loop-slow-leftward
  "A ball launched toward -x from the bottom of a vertical loop, too slow to loop."
  (parameters (m :positive (:value 1)) (g :positive (:value 10)) (r :positive (:value 1))
              (v0 :positive (> v0 (sqrt (* 2 g r))) (< v0 (sqrt (* 5 g r))) (:value 6)))
  (gravity g)
  (body loop :fixed t :shape (arc :center (0 r) :radius r :from 0 :to (* 2 pi) :solid :outside))
  (body ball :mass m :position (0 0) :velocity ((- v0) 0) :shape point)
  (simulate :states 1))

(scenario ball-in-loop-slow-rightward
  "A ball launched toward +x from the bottom of a vertical loop, too slow to loop."
  (parameters (m :positive (:value 1)) (g :positive (:value 10)) (r :positive (:value 1))
              (v0 :positive (> v0 (sqrt (* 2 g r))) (< v0 (sqrt (* 5 g r))) (:value 6)))
  (gravity g)
  (body loop :fixed t :shape (arc :center (0 r) :radius r :from 0 :to (* 2 pi) :solid :outside))
  (body ball :mass m :position (0 0) :velocity (v0 0) :shape point)
  (simulate :states 1))

(scenario ball-in-loop-fast-leftward
  "A ball launched toward -x from the bottom of a vertical loop, fast enough to loop."
  (parameters (m :positive (:value 1)) (g :positive (:value 10)) (r :positive (:value 1))
              (v0 :positive (> v0 (sqrt (* 5 g r))) (:value 8)))
  (gravity g)
  (body loop :fixed t :shape (arc :center (0 r) :radius r :from 0 :to (* 2 pi) :solid :outside))
  (body ball :mass m :position (0 0) :velocity ((- v0) 0) :shape point)
  (simulate :states 1))

(scenario ball-in-loop-fast-rightward
  "A ball launched toward +x from the bottom of a vertical loop, fast enough to loop."
  (parameters (m :positive (:value 1)) (g :positive (:value 10)) (r :positive (:value 1))
              (v0 :positive (> v0 (sqrt (* 5 g r))) (:value 8)))
  (gravity g)
  (body loop :fixed t :shape (arc :center (0 r) :radius r :from 0 :to (* 2 pi) :solid :outside))
  (body ball :mass m :position (0 0) :velocity (v0 0) :shape point)
  (simulate :states 1))
