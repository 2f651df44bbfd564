;;;; scenarios/spheres-under-gravitation.lisp -- two spheres released from rest in empty space fall
;;;; toward each other under their mutual gravitation.
;;;;
;;;; Expected results: they move along the line of their centres; their distance r obeys
;;;; r'' = -G (m1 + m2) / r^2, with the energy integral r'^2 = 2 G (m1 + m2) (1/r - 1/d) from the
;;;; distance d at rest; they touch when r = a + b, after
;;;; sqrt(d^3 / (2 G (m1 + m2))) (sqrt(s (1 - s)) + acos(sqrt(s))), s = (a + b)/d, each
;;;; having moved a share of d - (a + b) inversely proportional to its mass. Momentum stays
;;;; zero; kinetic minus G m1 m2 / r stays -G m1 m2 / d.

(scenario spheres-under-gravitation
  "Two spheres released from rest attract each other."
  (parameters (m1 :positive (:value 2)) (m2 :positive (:value 1)) (big-g :positive (:value 1))
              (a :positive (:value 1/2)) (b :positive (:value 1/4))
              (d :positive (> d (+ a b)) (:value 3)))
  (gravitation big-g)
  (body first :mass m1 :position (0 0) :velocity (0 0) :shape (circle a))
  (body second :mass m2 :position (d 0) :velocity (0 0) :shape (circle b))
  (simulate :states 1))
