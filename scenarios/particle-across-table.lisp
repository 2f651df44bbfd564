;;;; scenarios/particle-across-table.lisp -- a particle starts at the top-left corner of a table
;;;; moving right: it slides along the top (the left face is only grazed at the corner, never
;;;; hit), leaves the far edge, flies and lands on the floor.
;;;;
;;;; Expected results: state 0 on the top, N = m g, ends after w / v0 past the far edge;
;;;; state 1 free fall, lands after sqrt(2 h / g) at x = w + v0 sqrt(2 h / g).

(scenario particle-across-table
  "A particle slides across a table from its top-left corner, off the far edge, to the floor."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (h :positive (:value 1)) (w :positive (:value 2)) (v0 :positive (:value 3)))
  (gravity g)
  (body floor    :fixed t :shape (half-plane (1 0) (0 0)))
  (body table    :fixed t :position (0 0) :shape (polygon (0 0) (w 0) (w h) (0 h)))
  (body particle :mass m :position (0 h) :velocity (v0 0) :shape point)
  (simulate :states 4))
