;;;; src/base/conditions.lisp -- the root of AMES's condition hierarchy, and how reports print data.

(in-package #:ames.base)

(defconstant +report-print-level+ 8
  "How deep a datum is printed in a condition report before its sub-forms show as #.")

(defconstant +report-print-length+ 16
  "How many elements of a list a condition report prints before ...")

(defun format-report (stream control &rest arguments)
  "FORMAT CONTROL with ARGUMENTS to STREAM, for a condition's :REPORT: *PRINT-LEVEL* and
*PRINT-LENGTH* are bound to +REPORT-PRINT-LEVEL+ and +REPORT-PRINT-LENGTH+ (and
*PRINT-READABLY* to NIL), so that a very deep, very long or circular datum prints cut
short (with # and ...) instead of exhausting the stack or never ending."
  (let ((*print-level* +report-print-level+)
        (*print-length* +report-print-length+)
        (*print-readably* nil))
    (apply #'format stream control arguments)))

(define-condition ames-error (error)
  ((datum :initarg :datum :initform nil :reader ames-error-datum
          :documentation "The form, body, equation or other datum at fault.")
   (detail :initarg :detail :initform nil :reader ames-error-detail
           :documentation "A sentence saying what is wrong with DATUM."))
  (:documentation "The root of every condition a user of AMES can meet. Every layer
defines its own subclasses; each names the datum at fault.")
  (:report (lambda (condition stream)
             (format-report stream "~@[~A~]~@[~%  at fault: ~S~]"
                            (ames-error-detail condition)
                            (ames-error-datum condition)))))

(define-condition malformed-expression (ames-error)
  ((expression :initarg :expression :initform nil
               :reader malformed-expression-expression
               :documentation "The whole expression in which the fault was found."))
  (:documentation "An expression that is not in AMES's prefix algebra. DATUM is the
offending sub-expression, EXPRESSION the whole.")
  (:report (lambda (condition stream)
             (format-report stream "Malformed expression: ~A~%  at fault: ~S~@[~%  in: ~S~]"
                            (ames-error-detail condition)
                            (ames-error-datum condition)
                            (let ((whole (malformed-expression-expression condition)))
                              (and (not (eq whole (ames-error-datum condition))) whole))))))
