;;;; src/tms/package.lisp -- the package of the justification-based TMS (domain-free).

(defpackage #:ames.tms
  (:use #:cl #:ames.base)
  (:documentation "A justification-based truth maintenance system in the manner of
Forbus and de Kleer's JTMS (Building Problem Solvers, ch. 7), knowing nothing of
mechanics. A node carries an opaque datum and is believed (IN) or not (OUT). A
justification is an informant plus antecedent nodes: when every antecedent is IN,
its consequence is IN. Assumptions are nodes that can be enabled and retracted;
propagation after either is incremental and keeps every IN node's support
well-founded. A contradiction node that comes IN signals the condition
CONTRADICTION, with restarts to retract one of the assumptions under it or to
continue. WHY prints the justification tree of a node, ASSUMPTIONS-OF gives the
enabled assumptions it rests on.")
  (:export
   ;; the TMS
   #:jtms #:make-jtms #:jtms-p #:jtms-title #:jtms-node-count #:jtms-justification-count
   #:jtms-nodes #:jtms-assumptions #:jtms-contradictions #:jtms-node-printer
   ;; nodes
   #:node #:node-p #:make-node #:make-premise #:node-jtms #:node-datum #:node-index
   #:node-label #:node-in-p #:node-out-p #:node-premise-p
   #:node-assumption-p #:node-contradiction-p #:node-enabled-p #:node-enabling-reason
   #:node-support #:node-justifications #:node-consequences
   #:print-node-datum
   ;; justifications
   #:justification #:justification-p #:justify-node
   #:justification-informant #:justification-consequence #:justification-antecedents
   #:justification-satisfied-p
   ;; assumptions
   #:enable-assumption #:retract-assumption
   ;; explanations
   #:why #:why-node #:explanation #:assumptions-of
   ;; conditions and restarts
   #:tms-error #:contradiction #:contradiction-node #:contradiction-assumptions
   #:not-an-assumption #:foreign-node
   #:retract-culprit))
