;;;; src/geometry/package.lisp -- shapes, C-space contacts, path coordinates (placeholder).

(defpackage #:ames.geometry
  (:use #:cl #:ames.base)
  (:documentation "Shapes, configuration-space obstacles split into simple contacts,
and path coordinates."))
