;;;; t/truth-scenarios.lisp -- stub
(in-package #:ames.tests)
