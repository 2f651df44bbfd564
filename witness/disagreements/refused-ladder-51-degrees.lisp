;;;; refused-ladder-51-degrees -- a ladder against a wall at 51 degrees (numbers written
;;;; in: no parameters), from the ladder family's first version (make crosscheck SEED=7).
;;;; verdict: refused (was ames-wrong before the fix below)
;;;; Run: bin/ames check witness/disagreements/refused-ladder-51-degrees.lisp --numeric
;;;;
;;;; The ladder's ends touch the floor and the wall exactly, but the gaps are
;;;; (7/8) (cos(17 pi/60) + cos(43 pi/60)) and the like, which Maxima does not reduce to 0
;;;; (it keeps cos(43 pi/60) as it is). AMES took the undecided gaps for no contact, and
;;;; the ladder fell freely through the floor (AMES wrong). The algebra layer now brings
;;;; sines and cosines of rational multiples of pi to the first octant before deciding a
;;;; constant is 0 (FIRST-OCTANT-TRIGONOMETRY in src/algebra/constant-zero.lisp): the
;;;; contacts are found; but the closed forms that follow still carry sin(43 pi/60) beside
;;;; sin(17 pi/60), and the order of the events is undecided: an honest refusal
;;;; ("ambiguous", missing fact the roots of the wall's normal force). The ladder family
;;;; now uses angles with rational cosines (Pythagorean triples, atan(b/c)).

(scenario ladder-0 "A ladder against a wall." (gravity 11)
 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
 (body wall :fixed t :shape (half-plane (0 0) (0 1)))
 (body ladder :mass 3/4 :inertia :uniform :shape (segment ((- (/ 7/4 2)) 0) ((/ 7/4 2) 0))
  :position ((* (/ 7/4 2) (cos (deg 51))) (* (/ 7/4 2) (sin (deg 51)))) :angle (- pi (deg 51)) :velocity
  (0 0))
 (simulate :states 1))
