;;;; src/engine-package.lisp -- the model-component engine (placeholder until it lands).

(defpackage #:ames.engine
  (:use #:cl #:ames.base)
  (:documentation "DEFCOMPONENT and the engine that instantiates model components in
dependency order, recording every belief with its justification in the JTMS."))
