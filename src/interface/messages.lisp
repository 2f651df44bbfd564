;;;; src/interface/messages.lisp -- the one line AMES writes on the standard error per error.
;;;;
;;;; A message quotes the user's names and forms, which may hold control characters (a
;;;; |symbol| with ESC in it): they are written visibly (AMES.REPORT:VISIBLE-TEXT), so that
;;;; no message drives the terminal.

(in-package #:ames)

(defun print-error-message (condition &optional (stream *error-output*))
  "Write \"ames: \" and CONDITION's report on a fresh line of STREAM, its control
characters but line breaks and tabs written visibly, and finish the output."
  (let ((text (handler-case (princ-to-string condition)
                (error () (format nil "~A (a condition that cannot be printed)"
                                  (type-of condition))))))
    (format stream "~&ames: ~A~%" (visible-text text :keep '(#\Newline #\Tab)))
    (finish-output stream)))
