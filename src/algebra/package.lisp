;;;; src/algebra/package.lisp -- the algebra that reasons about AMES's prefix expressions: package and exported contract.

(defpackage #:ames.algebra
  (:use #:cl #:ames.base #:ames.maxima)
  ;; What still writes in Maxima's own terms (every other file asks through the
  ;; bridge's exported operations: calculus.lisp, questions.lisp): the earliest root
  ;; (roots.lisp) searches over Maxima forms (solve(), realroots(), the roots of a
  ;; quadratic built as forms and their signs asked by FORM-SIGNS), and the exact test
  ;; of a constant near zero (constant-zero.lisp) ratsubsts sin^2 = 1 - cos^2.
  (:import-from #:ames.maxima
                #:+false+ #:+i+ #:+mequal+ #:+mexpt+ #:+mlist+ #:+mplus+ #:+mtimes+ #:+rat+
                #:contains-symbol-p #:form-signs
                #:from-mx #:to-mx #:maxima-request
                #:mcall #:mdifference #:mform #:mform-p #:mlist #:mlist-items #:mquotient
                #:simplest-form)
  (:documentation "The algebra of AMES's prefix expressions, above the Maxima bridge:
deciding a relation under the facts in force (signs, angles, orders, Sturm sequences,
numeric witnesses, what a physicist knows), numbers before proofs, the earliest root,
and the integrators (travel times, elliptic motion, linear ODEs, trigonometric roots).
It asks Maxima only through the bridge.")
  (:export
   ;; the one sign system: sign sets and the rules of signs (sign-rules.lisp)
   #:number-signs #:negated-signs #:only-signs-p #:sum-signs #:power-signs #:sign-product
   #:constant-sign #:rules-of-signs #:sign-set-signum #:signum-sign-set
   #:relation-signs #:signs-relation #:relation-verdict
   ;; deciding (deciding.lisp)
   #:decide #:holds-p #:sign-varies-p #:refuted-p
   ;; numbers before proofs (values.lisp)
   #:call-with-parameter-values #:with-parameter-values #:current-parameter-values
   #:value-truth #:decide-by-values #:facts-from-values
   ;; the values decide first (values-first.lisp)
   #:call-with-values-first #:values-first-p #:decide-first-cheaply
   #:undecided-witnesses #:explain-undecided
   ;; roots (roots.lisp, trig-roots.lisp)
   #:earliest-root #:earliest-trigonometric-root
   ;; integrators (integrals.lisp, elliptic.lisp, periods.lisp, quadrature.lisp, linear-ode.lisp)
   #:travel-time #:numeric-travel-time #:libration-period #:sinusoid-coefficients
   #:position-over-time #:solve-linear-odes #:linear-ode-failed
   ;; real square roots (radicals.lisp)
   #:real-radicals #:simplify-real))
