;;;; src/simulator/check-model.lisp -- what a state's self-check needs from its model, recorded
;;;; apart from the closed forms.
;;;;
;;;; The self-check (src/check/) verifies a state's closed-form claims against a numeric
;;;; integration of the state's equations of motion and a numeric search over its
;;;; termination conditions. It must not share the closed-form path, so the state records
;;;; here, in its analysis (:CHECK-MODEL), the model as the knowledge base assembled it:
;;;;   :RATES       alist state term -> its rate, over the state terms, TAU and the
;;;;                parameters (the solved DERIVATIVE beliefs: accelerations as functions
;;;;                of the state, not of time);
;;;;   :INITIAL     alist state term -> its value at the start of the state;
;;;;   :EQUATIONS   the model's equations, each (LHS RHS) with the solved quantities put in:
;;;;                the check evaluates them along its integration (is the solve right?);
;;;;   :CONDITIONS  one plist per termination condition: :EVENT and :IMPACT (what the
;;;;                component names it), and either :GAP G :MARGINS (M...) for a contact's
;;;;                reaching (G the gap, each M >= 0 within the contact's extent) or
;;;;                :PARTS (F...) for a relation, which holds where some F < 0;
;;;;   :BODIES      alist moving body -> (:POSITION (X Y) :VELOCITY (VX VY) :ARC-LENGTH S)
;;;;                over the state terms, S the state term of its arc length along a curved
;;;;                contact (the variable of its motion reported :ON-PATH), or NIL;
;;;;   :UNCOMPARED  the moving bodies whose position is no state variable (their motion is
;;;;                not the model's to integrate): a state with one is not called checked.
;;;; Nothing here is solved in time: the check integrates it itself.

(in-package #:ames.simulator)

(defun check-condition (run solved condition)
  "The self-check's plist for the termination CONDITION (see the file header), or NIL
when its relation is none the check can search numerically."
  (let* ((relation (ames.engine:termination-condition-relation condition))
         (names (list :event (ames.engine:termination-condition-event condition)
                      :impact (ames.engine:termination-condition-impact condition)
                      :change (ames.engine:termination-condition-change condition))))
    (handler-case
        (let ((meeting (relation-meeting run solved relation)))   ; guarded-meetings.lisp
          (if meeting
              (append names
                      (list :gap (ames.geometry:meeting-gap meeting)
                            :margins (loop for r in (ames.geometry:meeting-extent meeting)
                                           unless (eq (first r) 'or) collect (extent-margin r))))
              (append names
                      (list :parts (loop for part in (if (eq (first relation) 'or) (rest relation) (list relation))
                                         collect (over-state-terms run solved (violation-function part)))))))
      ;; an equality or a relation the check cannot search: named, not searched
      (error () (append names (list :unsearchable relation))))))

(defun check-body-motion (run solved body)
  "BODY's position and velocity over SOLVED's state terms, as the self-check reads them,
and the state term of its arc length along a curved contact it moves on, if any."
  (list body (list :position (body-position-terms run solved body)
                   :velocity (body-velocity-terms run solved body)
                   :arc-length (find-if (lambda (term)
                                          (and (eq (first term) 'ames.kb:path-position)
                                               (eq body (first (contact-bodies run (second term))))))
                                        (solved-model-state solved)))))

(defun check-equations (run solved)
  "The model's equations as the solve took them (see SOLVE-MODEL), each as (LHS RHS)
with every quantity the solve determined replaced by its value (a state term's rate by
the rate the integration uses): over the state terms, TAU and the parameters, LHS = RHS
wherever the solution is right."
  (let ((values (append
                 ;; the rates as the integration takes them (simplified), then every value
                 (loop for (state-term . rate-term) in (model-derivatives (run-model run))
                       for rate = (cdr (assoc state-term (solved-model-rates solved) :test #'equal))
                       when (and rate (quantity-term-p rate-term))
                         collect (cons rate-term rate))
                 (solved-model-values solved))))
    ;; the values looked up in one table (the same as SUBSTITUTE-EXPRESSIONS over them)
    (let ((table (bindings-table values)))
      (loop for equation in (without-idle-path-terms
                             (mapcar (lambda (e) (with-initial-positions run e))
                                     (ames.engine:model-equations (run-model run)))
                             (solved-model-state solved))
            when (eq (first equation) '=)
              collect (list (substitute-from-table table (relation-lhs equation))
                            (substitute-from-table table (relation-rhs equation)))))))

(defun check-model (run solved)
  "The plist the self-check reads of the current state's model (see the file header)."
  (list :rates (copy-list (solved-model-rates solved))
        :equations (check-equations run solved)
        :initial (copy-list (solved-model-initial solved))
        :conditions (mapcar (lambda (condition) (check-condition run solved condition))
                            (ames.engine:model-termination-conditions (run-model run)))
        :bodies (loop for body in (free-body-names run)
                      when (state-variable-body-p solved body)
                        collect (check-body-motion run solved body))
        :uncompared (remove-if (lambda (body) (state-variable-body-p solved body))
                               (free-body-names run))))

(defun state-variable-body-p (solved body)
  "True when BODY's position is among SOLVED's state variables (its motion is integrated)."
  (and (member `(ames.kb:pos ,body :x) (solved-model-state solved) :test #'equal) t))
