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
short (with # and ...) instead of exhausting the stack or never ending; *PRINT-PRETTY*
is NIL, so that a datum stays on the message's line instead of being broken into a
staircase indented past the message's head."
  (let ((*print-level* +report-print-level+)
        (*print-length* +report-print-length+)
        (*print-readably* nil)
        (*print-pretty* nil))
    (apply #'format stream control arguments)))

(defstruct (error-context (:constructor make-error-context (&key file line scenario location)))
  "Where a condition arose in a run of scenarios: the FILE (a string, or NIL at the
REPL), the LINE in it (of the clause involved, else of the scenario), the SCENARIO's
name and the LOCATION in the scenario (a string such as \"body BALL\" or \"bodies BALL
and FLOOR\", or NIL)."
  file line scenario location)

(setf (documentation 'error-context-file 'function)
      "The file a condition arose in (a string), or NIL at the REPL."
      (documentation 'error-context-line 'function)
      "The line of that file: of the clause involved, else of the scenario; or NIL."
      (documentation 'error-context-scenario 'function)
      "The name of the scenario that was read or run, or NIL."
      (documentation 'error-context-location 'function)
      "Where in the scenario, a string such as \"body BALL\" or \"bodies BALL and
FLOOR\", or NIL.")

(defun write-error-context (context stream)
  "Write CONTEXT as the head of a report: Scenario NAME, LOCATION (FILE, line N): "
  (format stream "Scenario ~:[?~;~:*~A~]~@[, ~A~]~:[~2*~; (~@[~A, ~]line ~D)~]: "
          (let ((name (error-context-scenario context)))
            (and name (if (symbolp name) (symbol-name name) (princ-to-string name))))
          (error-context-location context)
          (error-context-line context)
          (error-context-file context)
          (error-context-line context)))

(define-condition ames-error (error)
  ((datum :initarg :datum :initform nil :reader ames-error-datum
          :documentation "The form, body, equation or other datum at fault.")
   (detail :initarg :detail :initform nil :reader ames-error-detail
           :documentation "A sentence saying what is wrong with DATUM.")
   (context :initarg :context :initform nil :accessor ames-error-context
            :documentation "An ERROR-CONTEXT saying in which file, scenario and clause
the condition arose, filled by whoever runs the scenario (the simulator knows no
files); NIL when unknown."))
  (:documentation "The root of every condition a user of AMES can meet. Every layer
defines its own subclasses; each names the datum at fault. Its report is headed by its
CONTEXT, when known, and cut to +REPORT-MAXIMUM-LINES+ lines and
+REPORT-MAXIMUM-CHARACTERS+ characters unless *FULL-REPORTS* is true (see
AMES-ERROR-FULL-REPORT).")
  (:report (lambda (condition stream)
             (format-report stream "~@[~A~]~@[~%  at fault: ~S~]"
                            (ames-error-detail condition)
                            (ames-error-datum condition)))))

(setf (documentation 'ames-error-context 'function)
      "The ERROR-CONTEXT of an AMES-ERROR (file, line, scenario, location), or NIL when
unknown; SETF-able: whoever runs the scenario fills it.")

(defconstant +report-maximum-lines+ 30
  "The most lines of an AMES-ERROR's report printed unless *FULL-REPORTS* is true.")

(defconstant +report-maximum-characters+ 3000
  "The most characters of an AMES-ERROR's report printed unless *FULL-REPORTS* is true.")

(defvar *full-reports* nil
  "When true, AMES-ERROR reports print in full (bin/ames --verbose binds it); when false,
a long report (a Maxima message of a megabyte, a dump of equations) is cut short.")

(defun ames-error-full-report (condition)
  "The whole report of the AMES-ERROR CONDITION, context included, never cut short."
  (let ((*full-reports* t))
    (princ-to-string condition)))

(defun cut-report (text)
  "TEXT, or its first +REPORT-MAXIMUM-LINES+ lines and +REPORT-MAXIMUM-CHARACTERS+
characters followed by a note saying how much was left out and how to see it."
  (let* ((line-end (loop with start = 0
                         repeat +report-maximum-lines+
                         do (let ((newline (position #\Newline text :start start)))
                              (if newline (setf start (1+ newline)) (return nil)))
                         finally (return (1- start))))
         (end (min (length text) +report-maximum-characters+ (or line-end (length text)))))
    (if (= end (length text))
        text
        (format nil "~A~%  [... ~:D more characters; bin/ames --verbose, or ~
                     AMES:AMES-ERROR-FULL-REPORT at the REPL, shows them all]"
                (subseq text 0 end) (- (length text) end)))))

(defmethod print-object :around ((condition ames-error) stream)
  "The report of an AMES-ERROR: its context first, then what its class reports, cut
short unless *FULL-REPORTS* is true. (Printed with escapes, it is #<CLASS ...> as usual.)"
  (if (or *print-escape* *print-readably*)
      (call-next-method)
      (let ((text (with-output-to-string (buffer)
                    (let ((context (ames-error-context condition)))
                      (when context (write-error-context context buffer)))
                    (call-next-method condition buffer))))
        (write-string (if *full-reports* text (cut-report text)) stream))))

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
