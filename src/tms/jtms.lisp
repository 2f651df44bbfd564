;;;; src/tms/jtms.lisp -- building a JTMS, and incremental label propagation.
;;;;
;;;; The invariant: a node is IN exactly when it has well-founded support, that is
;;;; when it is an enabled assumption or some justification of it has every
;;;; antecedent IN, with no circularity. NODE-SUPPORT records that support, and the
;;;; supports of all IN nodes form an acyclic graph (a node's support only names
;;;; nodes that were IN before it). Enabling adds support and propagates IN-ness
;;;; forward; retracting takes OUT exactly the nodes whose support chain passed
;;;; through the assumption, then lets them find other support (Forbus & de Kleer,
;;;; Building Problem Solvers, section 7.4).

(in-package #:ames.tms)

(defun make-jtms (&key title (node-printer #'print-node-datum))
  "A fresh, empty JTMS. TITLE names it in printouts. NODE-PRINTER is a function of
a node datum and a stream that writes the datum for people; it is used by WHY,
EXPLANATION's callers and condition reports (default: PRIN1)."
  (check-type node-printer function)
  (%make-jtms :title title :node-printer node-printer))

(defun make-node (jtms datum &key assumption contradiction)
  "A new OUT node of JTMS standing for DATUM (any object; the JTMS never looks into
it). With ASSUMPTION true the node can be enabled and retracted; with CONTRADICTION
true, its coming IN signals CONTRADICTION. Each call makes a new node: keeping one
node per datum is the caller's business."
  (let ((node (%make-node :jtms jtms :index (jtms-node-count jtms) :datum datum
                          :assumption-p (and assumption t)
                          :contradiction-p (and contradiction t))))
    (vector-push-extend node (jtms-nodes jtms))
    (when assumption (push node (jtms-assumptions jtms)))
    (when contradiction (push node (jtms-contradictions jtms)))
    node))

;;; Operations and their record of label changes

(defun flip-label (node label support)
  "Set NODE's LABEL and SUPPORT, logging the flip for the running operation."
  (let ((jtms (node-jtms node)))
    (unless (eq (node-label node) label)
      (push (cons node (node-label node)) (jtms-flip-log jtms)))
    (setf (node-label node) label
          (node-support node) support)))

(defun net-changes (log-entries end)
  "From LOG-ENTRIES (newest first) down to the tail END, the nodes whose label now
differs from what it was before the first logged flip: (values came-in went-out),
each in node-index order."
  (let ((before (make-hash-table :test #'eq)) (came-in '()) (went-out '()))
    (loop for cell on log-entries until (eq cell end)
          do (setf (gethash (car (car cell)) before) (cdr (car cell))))
    (maphash (lambda (node label)
               (unless (eq label (node-label node))
                 (if (node-in-p node) (push node came-in) (push node went-out))))
             before)
    (values (sort came-in #'< :key #'node-index)
            (sort went-out #'< :key #'node-index))))

(defun call-with-operation (jtms thunk)
  "Run THUNK as one JTMS operation: after it, signal CONTRADICTION for each
contradiction node that came IN, then return two lists, the nodes that came IN and
the nodes that went OUT during the operation (net: a node taken out and brought
back by another justification is in neither)."
  (let ((start (jtms-flip-log jtms)))
    (incf (jtms-operation-depth jtms))
    (unwind-protect
         (progn
           (funcall thunk)
           (check-contradictions jtms start)
           (net-changes (jtms-flip-log jtms) start))
      (when (zerop (decf (jtms-operation-depth jtms)))
        (setf (jtms-flip-log jtms) '())))))

(defun check-node (jtms node)
  "Signal FOREIGN-NODE unless NODE is a node of JTMS."
  (unless (and (node-p node) (eq (node-jtms node) jtms))
    (error 'foreign-node :datum node
                         :detail (if (node-p node)
                                     "This node belongs to another JTMS."
                                     "A TMS node was expected."))))

(defun check-assumption (node)
  "Signal NOT-AN-ASSUMPTION unless NODE is an assumption node."
  (check-node (and (node-p node) (node-jtms node)) node)
  (unless (node-assumption-p node)
    (error 'not-an-assumption :datum node
                              :detail "Only an assumption can be enabled or retracted.")))

;;; Propagation

(defun propagate-inness (node)
  "Bring IN every node that NODE's coming IN makes derivable."
  (let ((queue (list node)))
    (loop while queue
          do (dolist (justification (node-consequences (pop queue)))
               (let ((consequence (justification-consequence justification)))
                 (when (and (node-out-p consequence)
                            (justification-satisfied-p justification))
                   (flip-label consequence :in justification)
                   (push consequence queue)))))))

(defun propagate-outness (node)
  "Take OUT every node whose support chain passes through NODE (already OUT);
return them."
  (let ((stack (list node)) (taken-out '()))
    (loop while stack
          do (dolist (justification (node-consequences (pop stack)))
               (let ((consequence (justification-consequence justification)))
                 (when (eq (node-support consequence) justification)
                   (flip-label consequence :out nil)
                   (push consequence taken-out)
                   (push consequence stack)))))
    taken-out))

(defun find-alternative-support (nodes)
  "Give each of NODES that is still OUT another satisfied justification, if it
has one, and propagate. One pass suffices: a node whose only satisfied
justification rests on another of NODES is brought in by that node's propagation."
  (dolist (node nodes)
    (when (node-out-p node)
      (dolist (justification (node-justifications node))
        (when (justification-satisfied-p justification)
          (flip-label node :in justification)
          (propagate-inness node)
          (return))))))

;;; The operations

(defun justify-node (informant consequence antecedents)
  "Record that INFORMANT believes CONSEQUENCE whenever every node of ANTECEDENTS is
IN, and propagate. With no antecedents CONSEQUENCE becomes a premise. Returns the
new justification, and as second and third values the nodes that came IN and went
OUT. Signals FOREIGN-NODE when the nodes belong to different JTMSs, and
CONTRADICTION when a contradiction comes IN."
  (let ((jtms (and (node-p consequence) (node-jtms consequence))))
    (check-node jtms consequence)
    (dolist (antecedent antecedents) (check-node jtms antecedent))
    (let* ((antecedents (remove-duplicates antecedents :test #'eq))
           (justification (%make-justification (jtms-justification-count jtms)
                                               informant consequence antecedents)))
      (incf (jtms-justification-count jtms))
      (push justification (node-justifications consequence))
      (dolist (antecedent antecedents)
        (push justification (node-consequences antecedent)))
      (multiple-value-bind (came-in went-out)
          (call-with-operation
           jtms (lambda ()
                  (when (and (node-out-p consequence)
                             (justification-satisfied-p justification))
                    (flip-label consequence :in justification)
                    (propagate-inness consequence))))
        (values justification came-in went-out)))))

(defun make-premise (jtms datum &optional (informant :premise))
  "A new node of JTMS for DATUM, believed unconditionally: justified by INFORMANT
with no antecedents."
  (let ((node (make-node jtms datum)))
    (justify-node informant node '())
    node))

(defun enable-assumption (node &optional reason)
  "Enable the assumption NODE and propagate. REASON (any object) is kept as the
node's NODE-ENABLING-REASON and shown by WHY. Enabling an enabled assumption only
updates the reason. Returns the nodes that came IN and went OUT. Signals
NOT-AN-ASSUMPTION when NODE is not an assumption, and CONTRADICTION when a
contradiction comes IN."
  (check-assumption node)
  (call-with-operation
   (node-jtms node)
   (lambda ()
     (setf (node-enabling-reason node) reason)
     (cond ((node-enabled-p node))
           ((node-in-p node) (setf (node-support node) :enabled-assumption))
           (t (flip-label node :in :enabled-assumption)
              (propagate-inness node))))))

(defun retract-assumption (node)
  "Retract the assumption NODE: take OUT exactly what loses all well-founded
support, and keep IN (re-supported) what still has another justification.
Retracting an assumption that is not enabled does nothing. Returns the nodes that
came IN and went OUT. Signals NOT-AN-ASSUMPTION when NODE is not an assumption."
  (check-assumption node)
  (call-with-operation
   (node-jtms node)
   (lambda ()
     (when (node-enabled-p node)
       (setf (node-enabling-reason node) nil)
       (flip-label node :out nil)
       (find-alternative-support (cons node (propagate-outness node)))))))

;;; Contradictions

(defun check-contradictions (jtms start)
  "Signal CONTRADICTION for each contradiction node that came IN since the log
tail START and is still IN, offering the restarts RETRACT-CULPRIT and CONTINUE."
  (let ((contradictions '()))
    (loop for cell on (jtms-flip-log jtms)
          until (eq cell start)
          do (let ((node (car (car cell))))
               (when (and (node-contradiction-p node) (node-in-p node))
                 (pushnew node contradictions :test #'eq))))
    (dolist (node (sort contradictions #'< :key #'node-index))
      (signal-contradiction node))))

(defun signal-contradiction (node)
  "While NODE (a contradiction) is IN, signal CONTRADICTION with its assumptions.
RETRACT-CULPRIT retracts the assumption it is given and checks again; CONTINUE
returns, leaving NODE believed."
  (loop while (node-in-p node)
        do (let ((assumptions (assumptions-of node)))
             (restart-case
                 (error 'contradiction :node node :assumptions assumptions
                                       :datum (node-datum node))
               (retract-culprit (assumption)
                 :report "Retract one of the assumptions under the contradiction."
                 :interactive (lambda () (list (choose-culprit assumptions)))
                 (unless (member assumption assumptions :test #'eq)
                   (error 'not-an-assumption
                          :datum assumption
                          :detail "This is not an enabled assumption under the contradiction."))
                 (retract-assumption assumption))
               (continue ()
                 :report "Leave the contradiction believed and go on."
                 (return))))))

(defun choose-culprit (assumptions)
  "Ask on *QUERY-IO* which of ASSUMPTIONS to retract; return it."
  (loop
    (format *query-io* "~&Retract which assumption?~%")
    (loop for assumption in assumptions for i from 0
          do (format *query-io* "  ~D: ~A~%" i (node-string assumption)))
    (format *query-io* "Number: ")
    (finish-output *query-io*)
    (let ((answer (parse-integer (read-line *query-io*) :junk-allowed t)))
      (when (and answer (< -1 answer (length assumptions)))
        (return (nth answer assumptions))))))
