;;;; src/scenario/drag.lisp -- the (drag ...) clause (the language's "Drag"):
;;;;
;;;;   (drag NAME :on BODY :linear B)        ; F = -B v  (viscous)
;;;;   (drag NAME :on BODY :quadratic C)     ; F = -C |v| v (air resistance)
;;;;
;;;; Choices where the language page is silent:
;;;; - A drag is named in the namespace that parameters, bodies and forces share.
;;;; - Exactly one of :linear and :quadratic; the coefficient is an expression, positive
;;;;   (a number must be; a symbolic one must follow from the assumptions, like a
;;;;   spring's stiffness). Several drags may act on one body (they add).
;;;; - The medium is at rest in the fixed frame: v is the body's velocity there.
;;;; - Drag on a fixed or driven body does nothing (neither moves of its own accord).
;;;; The clause becomes the data (:drag NAME :on BODY :law :linear-or-:quadratic
;;;; :coefficient EXPR), which the knowledge base reads (src/kb/drag.lisp).

(in-package #:ames.scenario)

(defun checked-drag (validation clause bodies)
  "The data (:drag NAME :on BODY :law LAW :coefficient EXPR) of a (drag NAME ...) clause."
  (declare (ignore bodies))
  (let* ((name (cdr (declared validation (second clause))))
         (what (format nil "drag ~A" (symbol-name name))))
    (enter validation what clause)
    (let ((arguments (checked-keywords validation (cddr clause) '(:on :linear :quadratic) what)))
      (required validation arguments clause '(:on) "the drag")
      (let ((laws (remove-if-not (lambda (key) (assoc key arguments)) '(:linear :quadratic))))
        (unless (= (length laws) 1)
          (reject validation 'scenario-syntax-error clause
                  "a drag is either :linear B (F = -B v) or :quadratic C (F = -C |v| v): give one"))
        (list :drag name
              :on (checked-body-name validation (keyword-value :on arguments) ":on")
              :law (first laws)
              :coefficient (checked-positive validation (keyword-value (first laws) arguments)
                                             "a drag coefficient"))))))

(defun drag-facts (data)
  "The facts of a drag clause's DATA: its coefficient is positive."
  (destructuring-bind (kind name &key coefficient &allow-other-keys) data
    (declare (ignore kind))
    (list (list (format nil "drag ~A" (symbol-name name)) `(> ,coefficient 0)
                "the drag coefficient is positive" 'scenario-expression-error))))

(define-kb-clause ames-scenario:drag :checker 'checked-drag :facts 'drag-facts)
