;;;; t/package.lisp -- the test package and the root FiveAM suite.

(defpackage #:ames.tests
  (:use #:cl #:fiveam #:ames.base)
  (:shadow #:run-all-tests)
  (:documentation "FiveAM suites for every AMES layer, under the root suite ALL-TESTS.")
  (:export #:all-tests #:run-ames-tests #:tests-failed))

(in-package #:ames.tests)

(def-suite all-tests :description "Every AMES test suite.")

(def-suite base :in all-tests :description "The base layer: root condition and algebra.")
