;;;; src/tms/explain.lisp -- explanations: why a node is believed, and what it rests on.

(in-package #:ames.tms)

(defun assumptions-of (node)
  "The enabled assumptions in NODE's well-founded support, in node-index order:
what NODE's belief rests on. NIL for an OUT node and for a node that rests on
premises only; (NODE) for an enabled assumption."
  (let ((seen (make-hash-table :test #'eq)) (assumptions '()))
    (labels ((walk (node)
               (unless (gethash node seen)
                 (setf (gethash node seen) t)
                 (let ((support (node-support node)))
                   (cond ((eq support :enabled-assumption) (push node assumptions))
                         ((justification-p support)
                          (mapc #'walk (justification-antecedents support))))))))
      (when (node-in-p node) (walk node)))
    (sort assumptions #'< :key #'node-index)))

(defun explanation (node)
  "NODE's justification tree as data, following well-founded supports:
  (:assumption DATUM REASON)                    an enabled assumption,
  (:premise DATUM INFORMANT)                    justified with no antecedents,
  (:justified DATUM INFORMANT SUBTREE...)       justified by INFORMANT from the
                                                antecedents' subtrees,
  (:out DATUM)                                  not believed.
A node reached along several paths shares one subtree (the result is a DAG)."
  (let ((memo (make-hash-table :test #'eq)))
    (labels ((tree (node)
               (or (gethash node memo)
                   (setf (gethash node memo)
                         (let ((support (node-support node)))
                           (cond ((node-out-p node) (list :out (node-datum node)))
                                 ((eq support :enabled-assumption)
                                  (list :assumption (node-datum node)
                                        (node-enabling-reason node)))
                                 ((null (justification-antecedents support))
                                  (list :premise (node-datum node)
                                        (justification-informant support)))
                                 (t (list* :justified (node-datum node)
                                           (justification-informant support)
                                           (mapcar #'tree
                                                   (justification-antecedents support))))))))))
      (tree node))))

(defun datum-string (jtms datum)
  "DATUM (a node datum, an informant or a reason) as JTMS's node printer writes it."
  (with-output-to-string (stream)
    (funcall (jtms-node-printer jtms) datum stream)))

(defun print-node-status (node stream)
  "Write one line's worth on NODE: its datum, label and immediate support (the
informant and reasons written by the node printer). Return true when the support
has antecedents to explain further."
  (let ((support (node-support node)) (jtms (node-jtms node)))
    (write-string (node-string node) stream)
    (cond ((node-out-p node)
           (format stream " is OUT~[ (it has no justification)~:;: none of its ~:*~D ~
                           justification~:P holds~]."
                   (length (node-justifications node)))
           nil)
          ((eq support :enabled-assumption)
           (format stream " is an enabled assumption~@[: ~A~]."
                   (and (node-enabling-reason node)
                        (datum-string jtms (node-enabling-reason node))))
           nil)
          ((null (justification-antecedents support))
           (format stream " is a premise (~A)."
                   (datum-string jtms (justification-informant support)))
           nil)
          (t (format stream " is IN, by ~A, from:"
                     (datum-string jtms (justification-informant support)))
             t))))

(defun why-node (node &optional (stream *standard-output*))
  "Print one step of NODE's explanation on STREAM: its label, the informant of its
support and the antecedents. Returns NODE."
  (fresh-line stream)
  (when (print-node-status node stream)
    (format stream "~{~%  ~A~}"
            (mapcar #'node-string (justification-antecedents (node-support node)))))
  (terpri stream)
  node)

(defun why (node &optional (stream *standard-output*))
  "Print NODE's whole justification tree on STREAM, one node per line, indented by
depth, naming the informant of every justification and the reason of every enabled
assumption (both written, like the data, by the JTMS's node printer). A node already explained higher up is shown once more with
\"(explained above)\". Returns NODE."
  (let ((explained (make-hash-table :test #'eq)))
    (labels ((explain (node depth)
               (fresh-line stream)
               (loop repeat depth do (write-string "  " stream))
               (cond ((gethash node explained)
                      (format stream "~A (explained above)" (node-string node)))
                     (t (setf (gethash node explained) t)
                        (when (print-node-status node stream)
                          (dolist (antecedent (justification-antecedents
                                               (node-support node)))
                            (explain antecedent (1+ depth))))))))
      (explain node 0)
      (terpri stream))
    node))
