;;;; scenarios/block-pulled-over-table-edge.lisp -- a block on a frictionless table is pulled by
;;;; a hanging mass whose rope runs over a pulley at the table's edge.
;;;;
;;;; Expected results: both accelerate at g m2 / (m1 + m2) (the block toward the pulley, the
;;;; hanging mass down), the tension is g m1 m2 / (m1 + m2), and the block, starting a distance
;;;; d from the pulley, reaches it after sqrt(2 d (m1 + m2) / (g m2)): the state ends as the
;;;; block's front meets the block holding the pulley ((:collision block stop)), the weight
;;;; having fallen d, still clear of the table.

(scenario block-pulled-over-table-edge
  "A block on a table pulled by a hanging mass over a pulley at the edge."
  (parameters (m1 :positive (:value 2)) (m2 :positive (:value 1)) (g :positive (:value 981/100))
              (d :positive (< d 5) (:value 1)) (w :positive (< w 1) (:value 1/2)))
  (gravity g)
  (body table :fixed t :shape (polygon (-10 -10) (0 -10) (0 0) (-10 0)))
  (body stop :fixed t :position (0 0) :shape (polygon (0 0) (1/10 0) (1/10 1/10) (0 1/10)))
  (body block :mass m1 :position ((- (+ d w)) 0) :velocity (0 0)
        :shape (polygon (0 0) (w 0) (w w) (0 w)))
  (body weight :mass m2 :position ((/ 1 20) -1) :velocity (0 0) :shape point)
  (pulley edge :on stop :at ((/ 1 20) (/ 1 20)))
  (rope cord :length (+ d (/ 1 20) 1 (/ 1 20))
        :through ((block (w (/ 1 20))) edge (weight (0 0))))
  (simulate :states 1))
