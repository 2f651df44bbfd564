;;;; src/simulator/query-proofs.lisp -- proving a query's relation over a state and along
;;;; the path of states to an outcome (the questions of queries.lisp, split from it).

(in-package #:ames.simulator)

(defun relation-holds-over (bridge scenario state relation)
  "Whether RELATION (over query quantities) holds throughout STATE: :TRUE, :FALSE or
:UNKNOWN, and the reason."
  (let* ((lhs (quantity-in scenario state (second relation)))
         (rhs (quantity-in scenario state (third relation)))
         (difference (ames.maxima:simplify bridge `(- ,lhs ,rhs) :strategy :full))
         (duration (state-duration state)))
    (when (or (vector-p* lhs) (vector-p* rhs)) (unanswerable "a relation between vectors"))
    (when (not (free-of-p +arc-length+ difference))
      (return-from relation-holds-over
        (let ((verdict (ames.algebra:decide bridge (list (first relation) difference 0))))
          (values verdict "on the curve, decided for every arc length at once"))))
    (when (and (eq (first relation) '=) (not (free-of-p 'tau difference)))
      (return-from relation-holds-over (equality-over-state bridge state difference)))
    (flet ((at (time) (substitute-expressions (list (cons 'tau time)) difference)))
      (let ((start (ames.algebra:decide bridge (list (first relation) (at 0) 0))))
        (cond ((eq start :false) (values :false (format nil "it fails at the start of state ~D" (state-index state))))
              ((free-of-p 'tau difference)
               (values start (format nil "in state ~D it is a constant relation~:[, not decided~;~]"
                                     (state-index state) (not (eq start :unknown)))))
              ((eq start :unknown) (values :unknown (format nil "not decided at the start of state ~D" (state-index state))))
              (t (let ((root (ames.algebra:earliest-root bridge difference 'tau :after 0 :strictly t :candidates nil)))
                   (cond ((eq root :none) (values :true (format nil "it holds at the start of state ~D and never changes sign" (state-index state))))
                         ((eq root :unknown) (values :unknown (format nil "where it changes sign in state ~D is not decided" (state-index state))))
                         ((eq duration :forever) (values :false (format nil "it changes sign at tau = ~S in state ~D" root (state-index state))))
                         ((not (closed-form-p duration)) (values :unknown "the state's end has no closed form"))
                         (t (case (ames.algebra:decide bridge `(>= ,root ,duration))
                              (:true (values :true (format nil "it holds from the start of state ~D to its end" (state-index state))))
                              (:false (values :false (format nil "it changes sign inside state ~D" (state-index state))))
                              (t (values :unknown "whether it changes sign before the state ends is not decided"))))))))))))

(defun prove-on-path (bridge scenario states outcome condition during)
  "CONDITION's verdict on the path STATES whose run ended with OUTCOME: :TRUE, :FALSE or
:UNKNOWN, and the reason."
  (case (first condition)
    (:outcome (cond ((event-state states (second condition)) (values :true "it happens"))
                    ((member outcome '(:complete :time-limit :state-limit))
                     (values :false (format nil "it does not happen (the run ~(~A~))" outcome)))
                    (t (values :unknown (format nil "the run ~(~A~) before it could be told" outcome)))))
    (:not (multiple-value-bind (verdict reason) (prove-on-path bridge scenario states outcome (second condition) during)
            (values (case verdict (:true :false) (:false :true) (t :unknown)) reason)))
    (t (let ((chosen (if during
                         (list (resolve-when bridge states during))
                         (remove-if (lambda (s) (or (eql 0 (state-duration s)) (state-branches s))) states)))
             (reasons '()))
         (when (null chosen)
           (return-from prove-on-path
             (values :unknown (format nil "no period of motion on this path to tell (the run ~(~A~))" outcome))))
         (dolist (state chosen (if (or during (member outcome '(:complete :time-limit :state-limit)))
                                   (values :true (format nil "~{~A~^; ~}" (reverse reasons)))
                                   (values :unknown (format nil "it holds in the states found, but the run ~(~A~) before its end"
                                                            outcome))))
           (multiple-value-bind (verdict reason) (relation-holds-over bridge scenario state condition)
             (push reason reasons)
             (unless (eq verdict :true) (return (values verdict reason)))))))))
