;;;; src/base/package.lisp -- the bottom layer: the root condition and the prefix algebra.

(defpackage #:ames.base
  (:use #:cl)
  (:documentation "What every AMES layer shares: the root condition AMES-ERROR,
the prefix algebra (expressions such as (= (* mp (acc particle :x)) f)) that every
layer speaks, and the numeric value of its constant expressions. Only the Maxima
bridge translates the algebra to anything else.")
  (:export
   ;; conditions
   #:ames-error #:ames-error-datum #:ames-error-detail
   #:malformed-expression #:malformed-expression-expression
   #:format-report
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
   ;; special functions: operators of the algebra, and their numeric values
   #:elliptic-f #:elliptic-k #:elliptic-e #:jacobi-sn #:jacobi-cn #:jacobi-dn #:jacobi-am
   #:gamma-function
   #:special-function-value))
