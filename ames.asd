;;;; ames.asd -- system definitions for AMES, the Algebraic MEchanics Simulator.
;;;;
;;;; One module, one folder and one package per layer; dependencies point down only:
;;;;   base  <-  maxima-bridge, tms  <-  geometry  <-  engine  <-  kb
;;;;   geometry, maxima-bridge  <-  scenario;   kb, scenario  <-  simulator  <-  report
;;;;   <-  interface (package AMES: the REPL API and bin/ames)
;;;; Only Debian's CL packages are used (cl-alexandria, cl-fiveam, cl-ppcre).

(defsystem "ames"
  :description "AMES: a knowledge-based simulator that predicts in closed form how
frictionless translating rigid bodies evolve (after Leon Wong's 1994 MIT thesis)."
  :version "0.1.0"
  :license "MIT"
  :depends-on ("alexandria" "cl-ppcre")
  :components
  ((:module "base" :pathname "src/base/" :serial t
    :components ((:file "package")
                 (:file "conditions")
                 (:file "algebra")
                 (:file "evaluation")))
   (:module "maxima-bridge" :pathname "src/maxima-bridge/" :serial t
    :depends-on ("base")
    :components ((:file "package")
                 (:file "conditions")
                 (:file "translation")
                 (:file "bridge")
                 (:file "assumptions")
                 (:file "angles")
                 (:file "operations")
                 (:file "witnesses")
                 (:file "deciding")
                 (:file "signs")
                 (:file "truth")
                 (:file "values")
                 (:file "roots")
                 (:file "ode")
                 (:static-file "maxima-server.lisp")))
   (:module "tms" :pathname "src/tms/" :serial t
    :depends-on ("base")
    :components ((:file "package")
                 (:file "nodes")
                 (:file "conditions")
                 (:file "jtms")
                 (:file "explain")))
   (:module "geometry" :pathname "src/geometry/" :serial t
    :depends-on ("base" "maxima-bridge")
    :components ((:file "package")
                 (:file "conditions")
                 (:file "expressions")
                 (:file "decide")
                 (:file "vectors")
                 (:file "pieces")
                 (:file "shapes")
                 (:file "minkowski")
                 (:file "decompose")
                 (:file "union")
                 (:file "contacts")
                 (:file "obstacle")
                 (:file "events")))
   (:module "engine" :pathname "src/engine/" :serial t
    :depends-on ("base" "tms" "maxima-bridge")
    :components ((:file "package")
                 (:file "conditions")
                 (:file "patterns")
                 (:file "situation")
                 (:file "components")
                 (:file "grammar")
                 (:file "knowledge-base")
                 (:file "instances")
                 (:file "decisions")
                 (:file "refresh")
                 (:file "transitions")))
   (:module "kb" :pathname "src/kb/" :serial t
    :depends-on ("engine" "geometry")
    :components ((:file "package")
                 (:file "mechanics")))
   (:module "scenario" :pathname "src/scenario/" :serial t
    :depends-on ("base" "maxima-bridge" "geometry")
    :components ((:file "package")
                 (:file "conditions")
                 (:file "numbers")
                 (:file "objects")
                 (:file "validation")
                 (:file "shapes")
                 (:file "clauses")
                 (:file "reader")
                 (:file "semantics")
                 (:file "values")))
   (:module "simulator" :pathname "src/simulator/" :serial t
    :depends-on ("kb" "scenario")
    :components ((:file "package")
                 (:file "history")
                 (:file "simulator")))
   (:module "report" :pathname "src/report/" :serial t
    :depends-on ("simulator")
    :components ((:file "package")
                 (:file "report")))
   (:module "interface" :pathname "src/interface/" :serial t
    :depends-on ("report")
    :components ((:file "package")
                 (:file "cli"))))
  :in-order-to ((test-op (test-op "ames/tests"))))

(defsystem "ames/tests"
  :description "FiveAM test suites for every AMES layer."
  :depends-on ("ames" "fiveam")
  :pathname "t/"
  :serial t
  :components ((:file "package")
               (:file "base")
               (:file "bridge")
               (:file "bridge-roots")
               (:file "bridge-safety")
               (:file "bridge-shortcuts")
               (:file "bridge-truth")
               (:file "truth-table")
               (:file "scenario")
               (:file "scenario-reader")
               (:file "scenario-fuzz")
               (:file "scenario-semantics")
               (:file "tms")
               (:file "engine-toy-kb")
               (:file "engine")
               (:file "engine-defcomponent")
               (:file "engine-mechanics-shape")
               (:file "geometry")
               (:file "geometry-properties")
               (:file "geometry-symbolic")
               (:file "simulator-scenarios")
               (:file "simulator-more-scenarios")
               (:file "simulator-fuzz")
               (:file "truth-scenarios")
               (:file "cli")
               (:file "runner"))
  :perform (test-op (o c)
             (declare (ignore o c))
             (uiop:symbol-call :ames.tests :run-ames-tests)))
