;;;; src/tms/nodes.lisp -- the JTMS's data: the TMS itself, its nodes and justifications.

(in-package #:ames.tms)

(defun print-node-datum (datum stream)
  "The default node printer: DATUM as PRIN1 writes it."
  (prin1 datum stream))

(defstruct (jtms (:constructor %make-jtms))
  "A justification-based TMS: a set of nodes and the justifications between them."
  (title nil)
  (nodes (make-array 64 :adjustable t :fill-pointer 0) :type vector)
  (justification-count 0 :type fixnum)
  (assumptions '() :type list)
  (contradictions '() :type list)
  (node-printer #'print-node-datum :type function)
  ;; While an operation runs (see CALL-WITH-OPERATION): every label flip, newest
  ;; first, as (node . label-before-the-flip).
  (flip-log '() :type list)
  (operation-depth 0 :type fixnum))

(defstruct (node (:constructor %make-node))
  "A TMS node: an opaque DATUM that is believed (label :IN) or not (:OUT)."
  (jtms nil :type (or null jtms))
  (index 0 :type fixnum)
  (datum nil)
  (label :out :type (member :in :out))
  ;; The well-founded reason for an IN node: the justification that brought it in,
  ;; or :ENABLED-ASSUMPTION. NIL when OUT.
  (support nil)
  (justifications '() :type list)       ; justifications concluding this node
  (consequences '() :type list)         ; justifications with this node as antecedent
  (assumption-p nil :type boolean)
  (contradiction-p nil :type boolean)
  ;; For an enabled assumption: the informant given to ENABLE-ASSUMPTION.
  (enabling-reason nil))

(defstruct (justification (:constructor %make-justification
                              (index informant consequence antecedents)))
  "An informant's reason to believe CONSEQUENCE whenever every ANTECEDENT is IN."
  (index 0 :type fixnum)
  (informant nil)
  (consequence nil :type node)
  (antecedents '() :type list))

(setf (documentation 'jtms-title 'function) "The title given to MAKE-JTMS."
      (documentation 'jtms-node-printer 'function)
      "The function (DATUM STREAM) that prints node data in explanations and reports."
      (documentation 'jtms-assumptions 'function)
      "Every node of the JTMS that is an assumption, newest first."
      (documentation 'jtms-contradictions 'function)
      "Every contradiction node of the JTMS, newest first."
      (documentation 'jtms-justification-count 'function)
      "How many justifications the JTMS holds."
      (documentation 'node-jtms 'function) "The JTMS the node belongs to."
      (documentation 'node-index 'function) "The node's creation number within its JTMS."
      (documentation 'node-datum 'function) "The opaque datum the node stands for."
      (documentation 'node-label 'function) ":IN when the node is believed, else :OUT."
      (documentation 'node-support 'function)
      "Why an IN node is believed: the justification that brought it in, or
:ENABLED-ASSUMPTION. NIL for an OUT node."
      (documentation 'node-justifications 'function)
      "The justifications that conclude the node, newest first."
      (documentation 'node-consequences 'function)
      "The justifications in which the node is an antecedent."
      (documentation 'node-assumption-p 'function)
      "True when the node is an assumption (it can be enabled and retracted)."
      (documentation 'node-contradiction-p 'function)
      "True when the node is a contradiction: believing it signals CONTRADICTION."
      (documentation 'node-enabling-reason 'function)
      "For an enabled assumption, the reason given to ENABLE-ASSUMPTION."
      (documentation 'justification-informant 'function)
      "Who or what made the justification (a rule, a component, :PREMISE...)."
      (documentation 'justification-consequence 'function)
      "The node the justification supports."
      (documentation 'justification-antecedents 'function)
      "The nodes that must all be IN for the justification to hold.")

(defun jtms-node-count (jtms)
  "How many nodes JTMS holds."
  (fill-pointer (jtms-nodes jtms)))

(declaim (inline node-in-p node-out-p))
(defun node-in-p (node)
  "True when NODE is believed."
  (eq (node-label node) :in))

(defun node-out-p (node)
  "True when NODE is not believed."
  (eq (node-label node) :out))

(defun node-enabled-p (node)
  "True when NODE is an assumption that is currently enabled."
  (eq (node-support node) :enabled-assumption))

(defun node-premise-p (node)
  "True when NODE is IN by a justification without antecedents."
  (let ((support (node-support node)))
    (and (justification-p support) (null (justification-antecedents support)))))

(defun justification-satisfied-p (justification)
  "True when every antecedent of JUSTIFICATION is IN."
  (every #'node-in-p (justification-antecedents justification)))

(defun node-string (node)
  "NODE's datum as the JTMS's node printer writes it."
  (with-output-to-string (stream)
    (funcall (jtms-node-printer (node-jtms node)) (node-datum node) stream)))

(defmethod print-object ((node node) stream)
  (print-unreadable-object (node stream :type t)
    (format stream "~A ~S" (if (node-jtms node) (node-string node) (node-datum node))
            (node-label node))))

(defmethod print-object ((justification justification) stream)
  (print-unreadable-object (justification stream :type t)
    (format stream "~S => ~A" (justification-informant justification)
            (node-string (justification-consequence justification)))))

(defmethod print-object ((jtms jtms) stream)
  (print-unreadable-object (jtms stream :type t :identity (null (jtms-title jtms)))
    (format stream "~@[~A ~]~D node~:P" (jtms-title jtms) (jtms-node-count jtms))))
