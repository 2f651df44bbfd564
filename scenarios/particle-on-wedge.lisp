;;;; scenarios/particle-on-wedge.lisp -- thesis section 2.6.1: a particle slides down a movable wedge.
;;;;
;;;; Exactly the example of ../shared/design/scenario-language.md. All bodies start at
;;;; rest; contacts are frictionless; the ground is a fixed half-plane below y = 0.
;;;; The wedge is the right triangle (0 0) (h/tan a, 0) (0 h): its slope, of angle a,
;;;; descends toward +x. The particle starts halfway down the slope.
;;;;
;;;; Expected results (textbook; the simulator's tests assert them):
;;;;   State 0: contacts particle-wedge (on the slope) and wedge-ground (its base).
;;;;     Normal force between particle and wedge:
;;;;       N = mp mw g cos a / (mw + mp sin^2 a)            (thesis 2.6.1)
;;;;     Wedge acceleration (to the left, -x):
;;;;       A_wedge = (-N sin a / mw, 0) = (-mp g sin a cos a / (mw + mp sin^2 a), 0)
;;;;     Particle acceleration in the fixed frame:
;;;;       A_particle = (N sin a / mp, N cos a / mp - g)
;;;;                  = (mw g sin a cos a / (mw + mp sin^2 a),
;;;;                     -(mw + mp) g sin^2 a / (mw + mp sin^2 a))
;;;;     Normal force between wedge and ground:
;;;;       N_ground = mw g + N cos a = mw g (mw + mp) / (mw + mp sin^2 a)
;;;;     N > 0 throughout: the particle never leaves the slope.
;;;;     The particle falls h/2 with constant vertical acceleration, so it reaches the
;;;;     foot of the slope (the wedge's vertex (h/tan a, 0)) at
;;;;       t1 = sqrt(h (mw + mp sin^2 a) / ((mw + mp) g sin^2 a)).
;;;;     There it reaches the end of the wedge's face and, at the same instant, the
;;;;     ground with a downward velocity  vy = -(mw + mp) g sin^2 a t1 / (mw + mp sin^2 a):
;;;;     a collision with the ground (and the end of the particle-wedge contact).
;;;;     Without a collision model the simulation ends there (thesis: "the state ends
;;;;     when ... the particle reaches the ground").
;;;;   Horizontal momentum is conserved: mp vx_particle + mw vx_wedge = 0 at all times.

(scenario particle-on-wedge
  "A particle slides down a movable wedge resting on frictionless ground."
  (parameters (mp :positive) (mw :positive) (g :positive)
              (h :positive) (a (> a 0) (< a (/ pi 2))))
  (gravity g)
  (body ground   :fixed t :shape (half-plane (1 0) (0 0)))
  (body wedge    :mass mw :position (0 0) :velocity (0 0)
                 :shape (polygon (0 0) ((/ h (tan a)) 0) (0 h)))
  ;; halfway down the slope, so it starts on one face and not on a vertex
  (body particle :mass mp :position ((/ h (* 2 (tan a))) (/ h 2))
                 :velocity (0 0) :shape point)
  (simulate :states 3))
