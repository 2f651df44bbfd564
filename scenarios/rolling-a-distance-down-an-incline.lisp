;;;; scenarios/rolling-a-distance-down-an-incline.lisp -- a disc, a hoop and a solid sphere,
;;;; each released from rest on a long rough incline of angle a, roll a distance d down it.
;;;;
;;;; Source type: the standard first-year textbook problem on rolling without slipping
;;;; (energy with rotation, or the torque about the contact point). Expected results
;;;; (textbook), for a body of inertia I = k m r^2 about its centre:
;;;;   acceleration g sin a / (1 + k) down the slope, static friction k m g sin a / (1 + k)
;;;;   up it, normal force m g cos a, angular acceleration -g sin a / ((1 + k) r);
;;;;   after the distance d (a drop h = d sin a): time sqrt(2 d (1 + k) / (g sin a)),
;;;;   speed sqrt(2 g h / (1 + k)), kinetic energy m g h;
;;;;   disc (k = 1/2): a = (2/3) g sin a, t = sqrt(3 d / (g sin a)), v = sqrt(4 g h / 3);
;;;;   hoop (k = 1, :inertia :ring): a = g sin a / 2, t = 2 sqrt(d / (g sin a)), v = sqrt(g h);
;;;;   sphere (k = 2/5, :inertia (* 2/5 m r r)): a = (5/7) g sin a, v = sqrt(10 g h / 7),
;;;;   angular momentum about a point of the slope -(7/5) m r v = -m g r sin(a) t.
;;;; Rolling needs mu >= k tan(a) / (1 + k) (tan(a)/3, tan(a)/2, 2 tan(a)/7): each
;;;; scenario declares it. The slope is a half-plane through the origin, so nothing ends
;;;; the roll: the queries ask where the centre has dropped by h.

(scenario disc-rolls-a-distance
  "A uniform disc rolls from rest a distance d down a long rough incline."
  (parameters (m :positive (:value 2)) (g :positive (:value 981/100)) (r :positive (:value 1/10))
              (d :positive (:value 3)) (a (> a 0) (< a (/ pi 2)) (:value (deg 25)))
              (mu :positive (> mu (/ (tan a) 3)) (:value 1/2)))
  (gravity g)
  (body slope :fixed t :shape (half-plane ((cos a) (- (sin a))) (0 0)))
  (body disc :mass m :inertia :uniform :shape (circle r)
        :position ((* r (sin a)) (* r (cos a))) :velocity (0 0))
  (friction disc slope :static mu)
  (query time-down-d (time (reaches (y disc) (- (* r (cos a)) (* d (sin a))))))
  (query speed-down-d (value (speed disc) :at (reaches (y disc) (- (* r (cos a)) (* d (sin a))))))
  (query kinetic-down-d (value (kinetic-energy disc) :at (reaches (y disc) (- (* r (cos a)) (* d (sin a))))))
  (simulate :states 1))

(scenario hoop-rolls-a-distance
  "A hoop rolls from rest a distance d down a long rough incline."
  (parameters (m :positive (:value 2)) (g :positive (:value 981/100)) (r :positive (:value 1/10))
              (d :positive (:value 3)) (a (> a 0) (< a (/ pi 2)) (:value (deg 25)))
              (mu :positive (> mu (/ (tan a) 2)) (:value 1/2)))
  (gravity g)
  (body slope :fixed t :shape (half-plane ((cos a) (- (sin a))) (0 0)))
  (body hoop :mass m :inertia :ring :shape (circle r)
        :position ((* r (sin a)) (* r (cos a))) :velocity (0 0))
  (friction hoop slope :static mu)
  (query time-down-d (time (reaches (y hoop) (- (* r (cos a)) (* d (sin a))))))
  (query spin-down-d (value (angular-velocity hoop) :at (reaches (y hoop) (- (* r (cos a)) (* d (sin a))))))
  (simulate :states 1))

(scenario sphere-rolls-a-distance
  "A solid sphere (I = 2 m r^2 / 5) rolls from rest down a long rough incline."
  (parameters (m :positive (:value 2)) (g :positive (:value 981/100)) (r :positive (:value 1/10))
              (d :positive (:value 3)) (a (> a 0) (< a (/ pi 2)) (:value (deg 25)))
              (mu :positive (> mu (* 2/7 (tan a))) (:value 1/2)))
  (gravity g)
  (body slope :fixed t :shape (half-plane ((cos a) (- (sin a))) (0 0)))
  (body ball :mass m :inertia (* 2/5 m r r) :shape (circle r)
        :position ((* r (sin a)) (* r (cos a))) :velocity (0 0))
  (friction ball slope :static mu)
  (query speed-down-d (value (speed ball) :at (reaches (y ball) (- (* r (cos a)) (* d (sin a))))))
  (query kinetic-at-1 (value (kinetic-energy ball) :at 1))
  (query angular-momentum-at-1 (value (angular-momentum ball) :at 1))
  (simulate :states 1))
