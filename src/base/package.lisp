;;;; src/base/package.lisp -- the bottom layer: the root condition and the prefix algebra.

(defpackage #:ames.base
  (:use #:cl)
  (:documentation "What every AMES layer shares: the root condition AMES-ERROR,
the budget of a scenario run (time, and the size of exact numbers and expressions), the
prefix algebra (expressions such as (= (* mp (acc particle :x)) f)) that every
layer speaks, and the numeric value of its constant expressions. Only the Maxima
bridge translates the algebra to anything else.")
  (:export
   ;; conditions
   #:ames-error #:ames-error-datum #:ames-error-detail
   #:malformed-expression #:malformed-expression-expression
   #:format-report
   #:error-context #:make-error-context #:error-context-p #:error-context-file
   #:error-context-line #:error-context-scenario #:error-context-location
   #:ames-error-context #:ames-error-full-report #:*full-reports*
   ;; the budget of a scenario run (limits.lisp)
   #:limits #:make-limits #:change-limits #:limits-p #:limits-time-limit
   #:limits-maxima-timeout #:limits-integer-bits #:limits-expression-size
   #:*limits* #:current-limits #:invalid-limit
   #:call-with-budget #:with-budget #:*budget* #:budget-subject #:budget-time-left #:current-time-limit
   #:*stop-requested* #:signal-budget-exceeded
   #:check-budget #:check-deadline #:check-number-size #:check-rational-size
   #:rational-bits #:check-expression-size
   #:budget-exceeded #:budget-exceeded-quantity #:budget-exceeded-limit
   #:budget-exceeded-amount #:budget-exceeded-subject #:budget-exceeded-asynchronous-p
   ;; the algebra
   #:tau
   #:+arithmetic-operators+ #:+relation-operators+ #:+logical-operators+
   #:arithmetic-operator-p #:relation-operator-p #:logical-operator-p #:operator-p
   #:constant-symbol-p #:variable-symbol-p #:quantity-term-p
   #:compound-expression-p
   #:expression-operator #:expression-arguments #:make-expression
   #:relation-lhs #:relation-rhs #:make-relation
   #:expression-variables #:free-of-p #:substitute-expressions
   #:check-expression #:valid-expression-p #:finite-real-p
   ;; numeric values of constant expressions
   #:expression-value #:rational-root
   #:exact-interval #:exact-constant-sign #:accurate-value #:big-number-p
   ;; special functions: operators of the algebra, and their numeric values
   #:elliptic-f #:elliptic-k #:elliptic-e #:jacobi-sn #:jacobi-cn #:jacobi-dn #:jacobi-am
   #:gamma-function
   #:special-function-value))
