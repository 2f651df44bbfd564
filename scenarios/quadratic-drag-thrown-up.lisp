;;;; scenarios/quadratic-drag-thrown-up.lisp -- a ball thrown straight up through air (quadratic
;;;; drag): it rises, stops and falls back.
;;;;
;;;; Expected results: rising (m v' = -m g - k v^2), with V = sqrt(m g / k) and
;;;; w = sqrt(g k / m), v(t) = V tan(atan(v0 / V) - w t) until it stops at
;;;; t1 = atan(v0 / V) / w, at the height h + (m / (2 k)) ln(1 + v0^2 / V^2) (event (:turns ball));
;;;; then it falls from rest: v = -V tanh(w tau).

(scenario quadratic-drag-thrown-up
  "A ball thrown straight up through air, quadratic drag -k |v| v."
  (parameters (m :positive (:value 1)) (g :positive (:value 981/100))
              (k :positive (:value 1/10)) (h :nonnegative (:value 0)) (v0 :positive (:value 20)))
  (gravity g)
  (body ball :mass m :position (0 h) :velocity (0 v0) :shape point)
  (drag air :on ball :quadratic k)
  (simulate :states 2))
