;;;; src/kb/package.lisp -- the mechanics knowledge base (placeholder until it lands).

(defpackage #:ames.kb
  (:use #:cl #:ames.base)
  (:documentation "Mechanics as data: one DEFCOMPONENT per piece of the thesis's
knowledge (contact, gravity, Newton's laws, frames, coordinate systems)."))
