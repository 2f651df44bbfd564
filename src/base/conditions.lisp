;;;; src/base/conditions.lisp -- the root of AMES's condition hierarchy.

(in-package #:ames.base)

(define-condition ames-error (error)
  ((datum :initarg :datum :initform nil :reader ames-error-datum
          :documentation "The form, body, equation or other datum at fault.")
   (detail :initarg :detail :initform nil :reader ames-error-detail
           :documentation "A sentence saying what is wrong with DATUM."))
  (:documentation "The root of every condition a user of AMES can meet. Every layer
defines its own subclasses; each names the datum at fault.")
  (:report (lambda (condition stream)
             (format stream "~@[~A~]~@[~%  at fault: ~S~]"
                     (ames-error-detail condition)
                     (ames-error-datum condition)))))

(define-condition malformed-expression (ames-error)
  ((expression :initarg :expression :initform nil
               :reader malformed-expression-expression
               :documentation "The whole expression in which the fault was found."))
  (:documentation "An expression that is not in AMES's prefix algebra. DATUM is the
offending sub-expression, EXPRESSION the whole.")
  (:report (lambda (condition stream)
             (format stream "Malformed expression: ~A~%  at fault: ~S~@[~%  in: ~S~]"
                     (ames-error-detail condition)
                     (ames-error-datum condition)
                     (let ((whole (malformed-expression-expression condition)))
                       (and (not (eq whole (ames-error-datum condition))) whole))))))
