;;;; src/maxima-bridge/values.lisp -- stub

(in-package #:ames.maxima)
