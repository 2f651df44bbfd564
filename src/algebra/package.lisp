;;;; src/algebra/package.lisp -- the algebra that reasons about AMES's prefix expressions: package and exported contract.

(defpackage #:ames.algebra
  (:use #:cl #:ames.base #:ames.maxima)
  (:documentation "The algebra of AMES's prefix expressions, above the Maxima bridge:
deciding a relation under the facts in force (signs, angles, orders, Sturm sequences,
numeric witnesses, what a physicist knows), numbers before proofs, the earliest root,
and the integrators (travel times, elliptic motion, linear ODEs, trigonometric roots).
It asks Maxima only through the bridge.")
  (:export
   ;; the one sign system: sign sets and the rules of signs (sign-rules.lisp)
   #:+all-signs+ #:number-signs #:negated-signs #:only-signs-p #:sum-signs #:power-signs #:sign-product
   #:constant-sign #:rules-of-signs
   #:relation-signs #:signs-relation #:relation-verdict
   ;; interval arithmetic (intervals.lisp)
   #:interval-value #:positive-over-interval-p #:constant-relation-by-intervals
   ;; deciding (deciding.lisp)
   #:decide #:substitute-subexpressions #:holds-p #:*combined-bounds-wanted* #:sign-varies-p #:refuted-p
   ;; a relation proven to contradict the facts in force (contradictions.lisp)
   #:contradicts-facts-p #:one-angle-root
   ;; the sign of a quadratic in one sinusoid at every angle (sinusoid-quadratics.lisp)
   #:sign-at-every-angle
   ;; numbers before proofs (values.lisp)
   #:call-with-parameter-values #:with-parameter-values #:current-parameter-values
   #:value-truth #:decide-by-values #:facts-from-values
   ;; the values decide first (values-first.lisp)
   #:call-with-values-first #:values-first-p #:decide-first-cheaply #:cheap-proof #:signs-refuted-by-values
   #:proven-real-p
   #:facts-hold-at-values-p #:*decide-cheaply*
   #:undecided-witnesses #:explain-undecided
   ;; roots (roots.lisp, trig-roots.lisp)
   #:earliest-root #:square-free-part #:earliest-trigonometric-root
   ;; integrators (integrals.lisp, elliptic.lisp, periods.lisp, quadrature.lisp, linear-ode.lisp)
   #:travel-time #:numeric-travel-time #:libration-period #:sinusoid-coefficients
   #:position-over-time #:solve-linear-odes #:linear-ode-failed
   ;; one degree of freedom with a configuration-dependent inertia (one-freedom.lisp)
   #:one-freedom #:make-one-freedom #:generalized-inertia #:one-freedom-coordinate
   #:one-freedom-inertia #:one-freedom-potential #:one-freedom-start #:one-freedom-rate
   #:one-freedom-speed-squared #:one-freedom-acceleration #:one-freedom-direction
   #:along-motion #:earliest-coordinate-root #:coordinate-root-ahead #:decided-or-by-values #:turning-point #:coordinate-travel-time
   #:swing-period
   ;; real square roots (radicals.lisp)
   #:real-radicals #:simplify-real
   ;; the scale of round-off (round-off.lisp)
   #:round-off-scale))
