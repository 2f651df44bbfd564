;;;; src/interface/messages.lisp -- the one line AMES writes on the standard error per error.
;;;;
;;;; A message quotes the user's names and forms, which may hold control characters (a
;;;; |symbol| with ESC in it): they are written visibly (AMES.REPORT:VISIBLE-TEXT), so that
;;;; no message drives the terminal. Nor does a message show AMES's own packages: a symbol
;;;; of AMES's (AMES.KB::CONTACT, ames.simulator::contact-5) or an uninterned one (#:L1-EXCESS),
;;;; quoted in a condition's datum, is written by its name alone (WITHOUT-PACKAGE-PREFIXES).

(in-package #:ames)

(define-condition memory-exhausted (ames-error) ()
  (:documentation "A scenario run needed more memory than AMES's heap holds (SBCL's
STORAGE-CONDITION, DATUM). RUN-FILES reports it and goes on with the next scenario.")
  (:report (lambda (condition stream)
             (declare (ignore condition))
             (format-report stream "AMES ran out of memory (its heap holds ~:D MB) while running this scenario; ~
                                    ask for fewer states (simulate :states N) or use smaller numbers"
                            (floor (sb-ext:dynamic-space-size) (* 1024 1024))))))

(defun without-package-prefixes (text)
  "TEXT with the package prefixes of AMES's packages (AMES.KB::, ames-scenario:...) and
the #: of uninterned symbols taken off the symbols it quotes."
  (cl-ppcre:regex-replace-all
   "(?i)(?<![\\w.-])(?:#:|ames(?:[.-][a-z]+)*::?)(?=[^\\s:()\"])" text ""))

(defun print-error-message (condition &optional (stream *error-output*))
  "Write \"ames: \" and CONDITION's report on a fresh line of STREAM, its control
characters but line breaks and tabs written visibly, and finish the output."
  (let ((text (handler-case (princ-to-string condition)
                (error () (format nil "~A (a condition that cannot be printed)"
                                  (type-of condition))))))
    (format stream "~&ames: ~A~%" (visible-text (without-package-prefixes text)
                                               :keep '(#\Newline #\Tab)))
    (finish-output stream)))
