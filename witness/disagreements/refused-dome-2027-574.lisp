;;;; refused-dome-2027-574 -- a refusal make crosscheck N=1000 SEED=2027 finds (#574, family
;;;; dome), examined by hand: honest, but an exact zero Maxima cannot prove.
;;;; verdict: refused
;;;; reason: Cannot decide the geometric fact (= ... 0) about (FLOOR :SEEN-BY PARTICLE)
;;;; (neither exact arithmetic nor Maxima can decide it under the current assumptions).
;;;; A particle at rest on a dome (r = 2) one radian from its top slides off (lift-off where
;;;; cos theta = (2/3) cos 1), flies and lands on the floor elastically (e = 1). The run stops
;;;; (56 s, nothing printed) on a constant fact about the floor seen by the particle: a sum
;;;; of products of sin/cos of 2 atan((sqrt(5 + 4 sin^2 1) - 3 sin 1) / (5 cos 1)) (the
;;;; lift-off angle's half-angle form) and square roots, whose value is 3.6e-161 at
;;;; fpprec 160 (Maxima's bfloat): an exact zero (a point on the floor's line, by
;;;; construction of the landing) that Maxima's ratsimp/radcan do not reduce to 0. The
;;;; double-float path rightly declines (|v| < 1e-9) and the zero-to-round-off proof (issue
;;;; 21's refusals work) did not close it. Not AMES wrong. To fix in general: a position
;;;; reached by solving for a contact (the landing's root) should carry that it lies on the
;;;; face, rather than the face's geometry asking it again; or the exact-zero proof should
;;;; substitute the lift-off angle's defining relation (cos t = (2/3) cos 1).
;;;; Run: bin/ames run witness/disagreements/refused-dome-2027-574.lisp

(scenario dome-574 "A particle slides off a dome onto the floor." (gravity 55/4) (restitution 1)
 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body dome :fixed t :shape (arc :center (0 0) :radius 2 :from 0 :to pi :solid :inside))
 (body particle :mass 1 :position ((* -1 2 (sin 1)) (* 2 (cos 1))) :velocity (0 0) :shape point)
 (simulate :states 3))
