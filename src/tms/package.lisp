;;;; src/tms/package.lisp -- a justification-based TMS (placeholder until the TMS lands).

(defpackage #:ames.tms
  (:use #:cl #:ames.base)
  (:documentation "A justification-based truth maintenance system. Knows nothing of
mechanics: node data are opaque."))
