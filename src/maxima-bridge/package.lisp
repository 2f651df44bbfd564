;;;; src/maxima-bridge/package.lisp -- the only door to Maxima: package and exported contract.

(defpackage #:ames.maxima
  (:use #:cl #:ames.base)
  (:documentation "The Maxima bridge: the only code that knows Maxima's syntax or
representation. Speaks AMES's prefix algebra to the rest of the system. One persistent
Debian `maxima` process per BRIDGE, started lazily, answering framed requests built
only by this package's own translation (see translation.lisp and maxima-server.lisp).
The algebra that reasons about prefix expressions (deciding, roots, integrators) is the
layer above, AMES.ALGEBRA: it asks through the exported operations only.")
  (:export
   ;; the bridge object
   #:bridge #:make-bridge #:close-bridge #:bridge-timeout #:bridge-alive-p #:bridge-process-id
   #:bridge-statistics #:reset-bridge-statistics #:clear-bridge-cache #:reset-bridge
   #:bridge-in-scope-p #:prestart-bridge
   #:*reply-limit*
   ;; operations
   #:simplify #:prefetch-simplifications #:prefetch-solutions #:expression-size #:solve-equations #:equivalent-p
   #:call-with-assumptions #:with-assumptions #:current-assumptions #:flatten-facts
   #:bridge-frames ; the scopes in force: their identity keys a cache of what they imply
   ;; the algebra layer's hooks into the assumptions (assumptions.lisp)
   #:*derived-facts* #:*told-fact*
   #:solve-autonomous-ode #:ode-solution #:ode-solution-kind #:ode-solution-position
   #:ode-solution-velocity #:ode-solution-speed-squared
   #:numeric-value #:latex
   #:solve-script
   ;; the calculus the integrators ask (calculus.lisp)
   #:call-or-nil #:auxiliary-variable #:keyed-auxiliary-variable #:maxima-derivative #:polynomial-coefficients-in
   #:zero-after-trigexpand-p #:taylor-coefficients #:one-sided-taylor-coefficients #:maxima-antiderivative
   #:inverse-laplace-transform #:maxima-root-count
   ;; the questions the deciding algebra asks (questions.lisp)
   #:maxima-is #:maxima-is-opposite #:maxima-signs #:maxima-difference-signs
   #:prefetch-opposite-and-signs #:prefetch-requests #:*prefetch-signs* #:fact-sign-requests
   #:maxima-fact-signs #:square-root-part-signs #:square-root-parts #:ratsimp-with-sines #:cached-answer #:cache-answer #:assumption-key
   #:weaker-assumption-keys
   ;; the requests of the earliest-root search, over opaque root forms (root-forms.lisp)
   #:offset-polynomial #:square-free-polynomial #:numeric-root-form-p #:complex-root-form-p #:root-form-signs #:root-form-imaginary-part
   #:root-form-expression #:root-at-offset #:linear-root-offset #:vieta-forms
   #:root-form-sum #:root-form-difference #:rational-radicand #:real-square-root-form
   #:radicand-denominator #:cleared-square-root-form
   #:solved-root-offsets #:real-root-offsets
   ;; what the translation accepts, for the algebra's checks (translation.lisp, assumptions.lisp)
   #:check-translatable #:subject-p #:negate-condition
   ;; presentation (presentation.lisp)
   #:presentation-candidates #:polynomial-coefficients #:presentation-latex
   ;; conditions
   #:maxima-condition #:maxima-error #:maxima-error-message
   #:maxima-question #:maxima-question-text #:maxima-question-expressions
   #:maxima-timeout #:maxima-timeout-seconds
   #:maxima-process-died #:maxima-budget-exceeded
   #:maxima-output-overflow #:maxima-output-overflow-limit
   #:solve-failed #:inconsistent-assumptions #:inconsistent-assumptions-fact
   #:untranslatable-expression #:untranslatable-result
   #:numeric-evaluation-failed #:invalid-bridge-argument #:untranslatable-result-form
   ;; restarts
   #:retract-assumption #:assume-and-retry))

(defpackage #:ames.maxima.wire
  (:use)
  (:documentation "Maxima's internal symbols as the bridge writes and reads them on the
pipe (MPLUS, %SIN, $AMESVB, ...). Uses no package, so nothing read from Maxima can name
a Lisp function or variable of AMES."))
