;;;; src/maxima-bridge/package.lisp -- the only door to Maxima (placeholder until the bridge lands).

(defpackage #:ames.maxima
  (:use #:cl #:ames.base)
  (:documentation "The Maxima bridge: the only code that knows Maxima's syntax or
representation. Speaks AMES's prefix algebra to the rest of the system."))
