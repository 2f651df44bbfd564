;;;; scenarios/particle-on-sphere.lisp -- thesis section 2.6.3: a particle slides off a fixed sphere.
;;;;
;;;; A fixed circle ("sphere") of radius r centred at the origin; a particle at rest on
;;;; it at angle theta0 from the top (measured clockwise from +y, toward +x), i.e. at
;;;; (r sin theta0, r cos theta0), exactly on the circle. 0 < theta0 < pi/2, so it is
;;;; not at the unstable top and slides toward +x. Gravity points down.
;;;;
;;;; Expected results (energy method; thesis 2.6.3 gives the equations of motion):
;;;;   State 0: contact particle-sphere, on the circle. With theta the angle from the top:
;;;;     tangential acceleration  g sin theta,
;;;;     speed  v^2 = 2 g r (cos theta0 - cos theta)            (energy integral)
;;;;     normal force  N = m g cos theta - m v^2 / r = m g (3 cos theta - 2 cos theta0).
;;;;     The ODE theta'' = (g/r) sin theta has no elementary closed-form time: the
;;;;     state says so (:no-closed-form), and gives the energy integral.
;;;;     N reaches zero (lift-off) where  cos theta1 = (2/3) cos theta0,
;;;;     at position (r sin theta1, r cos theta1) with v^2 = (2/3) g r cos theta0,
;;;;     moving along the tangent (cos theta1, -sin theta1).
;;;;     With the default values (r = 1, theta0 = 1/10, g = 9.81) a numeric time exists.
;;;;     End event (:lift-off particle sphere).
;;;;   State 1: free fall from there: acceleration (0, -g); the parabola stays outside
;;;;     the sphere and nothing lies below, so it lasts forever.

(scenario particle-on-sphere
  "A particle starts at rest near the top of a fixed sphere, slides, and flies off."
  (parameters (m :positive (:value 1))
              (g :positive (:value 981/100))
              (r :positive (:value 1))
              (theta0 (> theta0 0) (< theta0 (/ pi 2)) (:value 1/10)))
  (gravity g)
  (body sphere :fixed t :position (0 0) :shape (circle r))
  (body particle :mass m
                 :position ((* r (sin theta0)) (* r (cos theta0)))
                 :velocity (0 0) :shape point)
  (simulate :states 3))
