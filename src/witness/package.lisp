;;;; src/witness/package.lisp -- the witness layer: AMES checked against Siconos.

(defpackage #:ames.witness
  (:use #:cl #:ames.base #:ames.scenario)
  (:documentation "An independent witness of AMES's results (issue 21). A validated
scenario with parameter values is translated into a model description for
witness/siconos_driver.py, which simulates it with Siconos's event-driven scheme; the
comparator sets the witness's events and states beside AMES's (its s-expression output)
and gives a verdict. The generator makes random valid scenarios by family. This layer
uses only the scenario reader and validation and the base layer: it knows nothing of
AMES's geometry, knowledge base or simulator, so that its answers are independent.")
  (:export
   ;; translation (model.lisp)
   #:witness-unsupported #:scenario-model #:model-json
   ;; the driver (driver.lisp)
   #:*python* #:*driver-path* #:siconos-available-p #:run-witness
   #:witness-status #:witness-events #:witness-end
   ;; the warm server (server.lisp)
   #:with-witness-server #:*witness-server* #:*witness-seconds*
   ;; comparison (compare.lisp)
   #:compare-results #:comparison-verdict #:comparison-rows #:comparison-reason
   #:print-comparison #:*time-tolerance* #:*value-tolerance* #:*accumulation-tolerance* #:*first-order-tolerance*
   #:ames-end-time #:ames-path #:compare-refining
   #:*curved-tolerance* #:witness-sample-times #:witness-horizon-extra
   ;; generation (generate.lisp)
   #:*families* #:*random* #:*symbolic* #:random-scenario #:generator-families
   #:*curved-families* #:*drag-families* #:*rotation-families*
   #:write-disagreement))
