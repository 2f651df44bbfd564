;;;; t/tms.lisp -- tests of the JTMS: labels, retraction, contradictions, explanations,
;;;; and random networks checked against propagation from scratch.

(in-package #:ames.tests)

(def-suite tms :in all-tests :description "The justification-based TMS (src/tms/).")

(in-suite tms)

(defun tms-labels (nodes)
  "The labels of NODES, in order."
  (mapcar #'ames.tms:node-label nodes))

(test chains-come-in-and-go-out
  (let* ((jtms (ames.tms:make-jtms :title "chain"))
         (a (ames.tms:make-node jtms 'a :assumption t))
         (b (ames.tms:make-node jtms 'b :assumption t))
         (c (ames.tms:make-node jtms 'c))
         (d (ames.tms:make-node jtms 'd)))
    (ames.tms:justify-node 'conjunction c (list a b))
    (ames.tms:justify-node 'step d (list c))
    (is (equal '(:out :out :out :out) (tms-labels (list a b c d))))
    (ames.tms:enable-assumption a)
    (is (equal '(:in :out :out :out) (tms-labels (list a b c d))))
    (multiple-value-bind (came-in went-out) (ames.tms:enable-assumption b 'because)
      (is (equal (list b c d) came-in))
      (is (null went-out)))
    (is (equal (list a b) (ames.tms:assumptions-of d)))
    (is (eq 'because (ames.tms:node-enabling-reason b)))
    (multiple-value-bind (came-in went-out) (ames.tms:retract-assumption a)
      (is (null came-in))
      (is (equal (list a c d) went-out)))
    (is (equal '(:out :in :out :out) (tms-labels (list a b c d))))
    (is (null (ames.tms:assumptions-of d)))
    ;; retracting again changes nothing
    (is (equal '(nil nil) (multiple-value-list (ames.tms:retract-assumption a))))))

(test retraction-keeps-what-has-other-support
  (let* ((jtms (ames.tms:make-jtms))
         (a (ames.tms:make-node jtms 'a :assumption t))
         (b (ames.tms:make-node jtms 'b :assumption t))
         (c (ames.tms:make-node jtms 'c))
         (d (ames.tms:make-node jtms 'd)))
    (ames.tms:justify-node 'from-a c (list a))
    (ames.tms:justify-node 'from-b c (list b))
    (ames.tms:justify-node 'from-c d (list c))
    (ames.tms:enable-assumption a)
    (ames.tms:enable-assumption b)
    (is (eq 'from-a (ames.tms:justification-informant (ames.tms:node-support c))))
    (multiple-value-bind (came-in went-out) (ames.tms:retract-assumption a)
      ;; C and D went out and came back: no net change for them
      (is (null came-in))
      (is (equal (list a) went-out)))
    (is (ames.tms:node-in-p c))
    (is (ames.tms:node-in-p d))
    (is (eq 'from-b (ames.tms:justification-informant (ames.tms:node-support c))))
    (is (equal (list b) (ames.tms:assumptions-of d)))))

(test circular-support-is-not-well-founded
  (let* ((jtms (ames.tms:make-jtms))
         (a (ames.tms:make-node jtms 'a :assumption t))
         (x (ames.tms:make-node jtms 'x))
         (y (ames.tms:make-node jtms 'y)))
    (ames.tms:justify-node 'loop x (list y))
    (ames.tms:justify-node 'loop y (list x))
    (is (ames.tms:node-out-p x))
    (ames.tms:justify-node 'seed x (list a))
    (ames.tms:enable-assumption a)
    (is (and (ames.tms:node-in-p x) (ames.tms:node-in-p y)))
    (ames.tms:retract-assumption a)
    (is (and (ames.tms:node-out-p x) (ames.tms:node-out-p y)))))

(test premises-and-enabled-assumptions-that-are-also-derived
  (let* ((jtms (ames.tms:make-jtms))
         (p (ames.tms:make-premise jtms 'p 'given))
         (a (ames.tms:make-node jtms 'a :assumption t))
         (q (ames.tms:make-node jtms 'q)))
    (is (ames.tms:node-premise-p p))
    (ames.tms:justify-node 'rule a (list p))
    (ames.tms:justify-node 'rule q (list a))
    (is (ames.tms:node-in-p q))
    (is (null (ames.tms:assumptions-of q)))
    (ames.tms:enable-assumption a)
    (is (equal (list a) (ames.tms:assumptions-of q)))
    (ames.tms:retract-assumption a)
    ;; A is still derived from the premise
    (is (ames.tms:node-in-p a))
    (is (not (ames.tms:node-enabled-p a)))
    (is (ames.tms:node-in-p q))))

(test operations-check-their-arguments
  (let* ((jtms (ames.tms:make-jtms))
         (other (ames.tms:make-jtms))
         (n (ames.tms:make-node jtms 'n))
         (m (ames.tms:make-node other 'm)))
    (signals ames.tms:not-an-assumption (ames.tms:enable-assumption n))
    (signals ames.tms:not-an-assumption (ames.tms:retract-assumption n))
    (signals ames.tms:foreign-node (ames.tms:justify-node 'mixed n (list m)))
    (signals ames.tms:foreign-node (ames.tms:justify-node 'junk n (list 'not-a-node)))
    (is (typep (handler-case (ames.tms:enable-assumption n) (ames-error (c) c))
               'ames.tms:tms-error))))

(defun contradictory-jtms ()
  "A JTMS where assumptions A and B together bring IN the contradiction C."
  (let* ((jtms (ames.tms:make-jtms))
         (a (ames.tms:make-node jtms 'a :assumption t))
         (b (ames.tms:make-node jtms 'b :assumption t))
         (c (ames.tms:make-node jtms 'clash :contradiction t)))
    (ames.tms:justify-node 'exclusive c (list a b))
    (ames.tms:enable-assumption a)
    (values jtms a b c)))

(test a-contradiction-signals-with-its-assumptions
  (multiple-value-bind (jtms a b c) (contradictory-jtms)
    (declare (ignore jtms))
    (signals ames.tms:contradiction (ames.tms:enable-assumption b))
    (let ((condition (handler-case (progn (ames.tms:retract-assumption b)
                                          (ames.tms:enable-assumption b))
                       (ames.tms:contradiction (c) c))))
      (is (eq c (ames.tms:contradiction-node condition)))
      (is (equal (list a b) (ames.tms:contradiction-assumptions condition)))
      (is (eq 'clash (ames-error-datum condition)))
      (is (search "CLASH" (princ-to-string condition))))))

(test the-retract-culprit-restart-retracts-the-chosen-assumption
  (multiple-value-bind (jtms a b c) (contradictory-jtms)
    (declare (ignore jtms))
    (let ((signalled 0))
      (multiple-value-bind (came-in went-out)
          (handler-bind ((ames.tms:contradiction
                           (lambda (condition)
                             (incf signalled)
                             (ames.tms:retract-culprit a condition))))
            (ames.tms:enable-assumption b))
        (is (= 1 signalled))
        (is (ames.tms:node-out-p c))
        (is (ames.tms:node-out-p a))
        (is (ames.tms:node-in-p b))
        ;; net effect of the whole operation: B in, A out, the clash never stayed
        (is (equal (list b) came-in))
        (is (equal (list a) went-out))))))

(test retract-culprit-refuses-an-unrelated-node
  (multiple-value-bind (jtms a b c) (contradictory-jtms)
    (declare (ignore a))
    (let ((bystander (ames.tms:make-node jtms 'bystander :assumption t)))
      (signals ames.tms:not-an-assumption
        (handler-bind ((ames.tms:contradiction
                         (lambda (condition) (ames.tms:retract-culprit bystander condition))))
          (ames.tms:enable-assumption b)))
      (is (ames.tms:node-in-p c)))))

(test the-continue-restart-leaves-the-contradiction-believed
  (multiple-value-bind (jtms a b c) (contradictory-jtms)
    (declare (ignore jtms))
    (handler-bind ((ames.tms:contradiction #'continue))
      (ames.tms:enable-assumption b))
    (is (ames.tms:node-in-p c))
    (is (equal (list a b) (ames.tms:assumptions-of c)))))

(test why-names-informants-and-assumptions
  (let* ((jtms (ames.tms:make-jtms
                :node-printer (lambda (datum stream) (format stream "<~(~A~)>" datum))))
         (g (ames.tms:make-premise jtms 'gravity 'scenario-file))
         (a (ames.tms:make-node jtms 'on-table :assumption t))
         (n (ames.tms:make-node jtms 'normal-force))
         (e (ames.tms:make-node jtms 'equilibrium)))
    (ames.tms:justify-node 'contact-law n (list a))
    (ames.tms:justify-node 'newton-second-law e (list g n a))
    (ames.tms:enable-assumption a 'initial-contact)
    (let ((text (with-output-to-string (s) (ames.tms:why e s))))
      (is (search "<equilibrium> is IN, by <newton-second-law>, from:" text))
      (is (search "<gravity> is a premise (<scenario-file>)." text))
      (is (search "<normal-force> is IN, by <contact-law>, from:" text))
      (is (search "<on-table> is an enabled assumption: <initial-contact>." text))
      (is (search "<on-table> (explained above)" text)))
    (is (equal '(:justified equilibrium newton-second-law
                 (:premise gravity scenario-file)
                 (:justified normal-force contact-law
                  (:assumption on-table initial-contact))
                 (:assumption on-table initial-contact))
               (ames.tms:explanation e)))
    (ames.tms:retract-assumption a)
    (is (equal '(:out equilibrium) (ames.tms:explanation e)))
    (is (search "<equilibrium> is OUT: none of its 1 justification holds."
                (with-output-to-string (s) (ames.tms:why-node e s))))))

;;; Random networks against propagation from scratch

(defun random-network (&key (max-nodes 30))
  "A generator of random network histories: a plist with :NODES (a count),
:ASSUMPTIONS (indices), :JUSTIFICATIONS ((consequence antecedent...) ...), some of
them present from the start, and :OPERATIONS, a random sequence of
(:enable i), (:retract i) and (:justify k) (add justification number k)."
  (lambda ()
    (let* ((n (+ 2 (random (1- max-nodes))))
           (assumptions (loop for i below n when (< (random 1.0) 0.35) collect i))
           (justifications
             (loop repeat (random (* 3 n))
                   collect (cons (random n)
                                 (loop repeat (random 4) collect (random n)))))
           (initial (random (1+ (length justifications))))
           (operations
             (append
              (loop for k from initial below (length justifications)
                    collect (list :justify k))
              (when assumptions
                (loop repeat (random (* 4 n))
                      collect (list (if (< (random 1.0) 0.55) :enable :retract)
                                    (nth (random (length assumptions)) assumptions)))))))
      (list :nodes n :assumptions assumptions :justifications justifications
            :initial initial
            ;; shuffle the late justifications in among the enables and retracts
            :operations (alexandria:shuffle operations)))))

(defun least-fixpoint (justifications enabled)
  "The set (a list of indices) of nodes derivable from the ENABLED node indices by
JUSTIFICATIONS, computed naively: the oracle for the JTMS's labels."
  (let ((in (make-hash-table)))
    (dolist (i enabled) (setf (gethash i in) t))
    (loop for changed = nil
          do (dolist (j justifications)
               (when (and (not (gethash (car j) in))
                          (every (lambda (a) (gethash a in)) (cdr j)))
                 (setf (gethash (car j) in) t changed t)))
          while changed)
    (sort (loop for i being the hash-keys of in collect i) #'<)))

(defun build-network (spec justification-count)
  "A JTMS with the nodes of SPEC and its first JUSTIFICATION-COUNT justifications."
  (let* ((jtms (ames.tms:make-jtms))
         (assumptions (getf spec :assumptions))
         (nodes (coerce (loop for i below (getf spec :nodes)
                              collect (ames.tms:make-node
                                       jtms i :assumption (member i assumptions)))
                        'vector)))
    (loop for j in (getf spec :justifications) repeat justification-count
          do (ames.tms:justify-node :random (aref nodes (car j))
                                    (mapcar (lambda (a) (aref nodes a)) (cdr j))))
    (values jtms nodes)))

(defun in-indices (nodes)
  "The indices of the IN nodes of the vector NODES."
  (loop for node across nodes for i from 0 when (ames.tms:node-in-p node) collect i))

(defun well-founded-p (nodes)
  "True when every IN node of NODES has support whose antecedents are IN and the
supports form no cycle, and every OUT node has no satisfied justification."
  (let ((state (make-hash-table :test #'eq)))
    (labels ((grounded-p (node)
               (case (gethash node state)
                 (:done t)
                 (:visiting nil)
                 (t (setf (gethash node state) :visiting)
                    (let* ((support (ames.tms:node-support node))
                           (ok (cond ((eq support :enabled-assumption)
                                      (ames.tms:node-assumption-p node))
                                     ((ames.tms:justification-p support)
                                      (and (eq node (ames.tms:justification-consequence support))
                                           (every (lambda (a) (and (ames.tms:node-in-p a)
                                                                   (grounded-p a)))
                                                  (ames.tms:justification-antecedents support))))
                                     (t nil))))
                      (setf (gethash node state) :done)
                      ok)))))
      (every (lambda (node)
               (if (ames.tms:node-in-p node)
                   (grounded-p node)
                   (and (null (ames.tms:node-support node))
                        (notany #'ames.tms:justification-satisfied-p
                                (ames.tms:node-justifications node)))))
             nodes))))

(test random-histories-end-where-propagation-from-scratch-ends
  (for-all ((spec (random-network)))
    (multiple-value-bind (jtms nodes) (build-network spec (getf spec :initial))
      (declare (ignore jtms))
      (let ((enabled '()) (justifications (subseq (getf spec :justifications)
                                                  0 (getf spec :initial)))
            (honest-changes t))
        (dolist (op (getf spec :operations))
          (let ((before (in-indices nodes)))
            (multiple-value-bind (came-in went-out)
                (ecase (first op)
                  (:enable (pushnew (second op) enabled)
                   (ames.tms:enable-assumption (aref nodes (second op))))
                  (:retract (setf enabled (remove (second op) enabled))
                   (ames.tms:retract-assumption (aref nodes (second op))))
                  (:justify
                   (let ((j (nth (second op) (getf spec :justifications))))
                     (setf justifications (append justifications (list j)))
                     (multiple-value-bind (justification came-in went-out)
                         (ames.tms:justify-node :random (aref nodes (car j))
                                                (mapcar (lambda (a) (aref nodes a)) (cdr j)))
                       (declare (ignore justification))
                       (values came-in went-out)))))
              ;; the reported changes are exactly the label differences
              (let ((after (in-indices nodes)))
                (unless (and (equal (sort (set-difference after before) #'<)
                                    (sort (mapcar #'ames.tms:node-datum came-in) #'<))
                             (equal (sort (set-difference before after) #'<)
                                    (sort (mapcar #'ames.tms:node-datum went-out) #'<)))
                  (setf honest-changes nil))))))
        (is-true honest-changes)
        (is (equal (least-fixpoint justifications enabled) (in-indices nodes)))
        (is-true (well-founded-p nodes))
        ;; a fresh TMS given the final network at once agrees
        (multiple-value-bind (fresh fresh-nodes) (build-network spec 0)
          (declare (ignore fresh))
          (dolist (i enabled) (ames.tms:enable-assumption (aref fresh-nodes i)))
          (dolist (j justifications)
            (ames.tms:justify-node :random (aref fresh-nodes (car j))
                                   (mapcar (lambda (a) (aref fresh-nodes a)) (cdr j))))
          (is (equal (in-indices nodes) (in-indices fresh-nodes))))
        ;; every IN node rests on enabled assumptions only
        (is-true (loop for node across nodes
                       always (every (lambda (a) (member (ames.tms:node-datum a) enabled))
                                     (ames.tms:assumptions-of node))))))))

(test assumptions-of-is-sufficient
  ;; Enabling only ASSUMPTIONS-OF a node, from scratch, still brings that node in.
  (for-all ((spec (random-network :max-nodes 20)))
    (multiple-value-bind (jtms nodes) (build-network spec (length (getf spec :justifications)))
      (declare (ignore jtms))
      (dolist (i (getf spec :assumptions))
        (when (< (random 1.0) 0.6) (ames.tms:enable-assumption (aref nodes i))))
      (is-true
       (loop for node across nodes
             for i from 0
             always (or (ames.tms:node-out-p node)
                        (member i (least-fixpoint
                                   (getf spec :justifications)
                                   (mapcar #'ames.tms:node-datum
                                           (ames.tms:assumptions-of node))))))))))
