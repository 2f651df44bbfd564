;;;; src/report/output.lisp -- where the command line's reports go: a REPORT-OUTPUT per run.
;;;;
;;;; Text, s-expressions, LaTeX and JSON are written as each scenario is simulated; the HTML
;;;; page (one for the whole run) and the SVG pictures (one per scenario) when the run ends,
;;;; since what they look like depends on how many scenarios there are.

(in-package #:ames.report)

(defparameter *report-formats* '(:text :sexp :latex :json :html)
  "The formats REPORT-HISTORY writes.")

(defvar *latex-standalone* nil
  "True when the LaTeX report is a whole document (preamble, \\begin{document} ... \\end{document})
rather than fragments, for the REPORT-OUTPUTs made while it is bound.")

(defclass report-output ()
  ((format :initarg :format :reader output-format)
   (stream :initarg :stream :reader output-stream)
   (svg :initarg :svg :initform nil :reader output-svg
        :documentation "The pathname the pictures go to, or NIL for none.")
   (bridge :initarg :bridge :reader output-bridge)
   (standalone :initform *latex-standalone* :reader output-standalone
               :documentation "True for a whole LaTeX document (see *LATEX-STANDALONE*).")
   (started :initform nil :accessor output-started
            :documentation "True once the document's preamble is written.")
   (histories :initform '() :accessor output-histories
              :documentation "The histories kept for the end of the run, last first."))
  (:documentation "One run's reports: FORMAT on STREAM, pictures to SVG."))

(defun make-report-output (format stream &key svg (bridge (current-bridge)))
  "The REPORT-OUTPUT writing FORMAT (one of *REPORT-FORMATS*) on STREAM, and an SVG
picture per scenario to SVG (a pathname designator) when given. Signals REPORT-ERROR
for an unknown format."
  (unless (member format *report-formats*)
    (error 'report-error :datum format :detail (format nil "The format must be one of ~{~(~A~)~^, ~}"
                                                        *report-formats*)))
  (make-instance 'report-output :format format :stream stream :bridge bridge
                                :svg (and svg (pathname svg))))

(defun report-history (output history)
  "Write HISTORY's report to OUTPUT now, or keep it for FINISH-REPORT (HTML, pictures)."
  (let ((stream (output-stream output)) (bridge (output-bridge output)))
    (when (and (eq (output-format output) :latex) (output-standalone output)
               (not (output-started output)))
      (print-latex-document-start stream)
      (setf (output-started output) t))
    ;; made whole first: a report that fails half-way writes nothing
    (write-string (with-output-to-string (stream)
                    (ecase (output-format output)
                      (:text (print-history-text history stream :bridge bridge))
                      (:sexp (print-history-sexp history stream))
                      (:latex (print-history-latex history stream :bridge bridge))
                      (:json (print-history-json history stream))
                      (:html nil)))
                  stream)
    (when (or (eq (output-format output) :html) (output-svg output))
      (push history (output-histories output)))
    history))

(defun picture-pathname (pathname name several)
  "Where the picture of the scenario NAME goes: PATHNAME itself, or, when the run has
SEVERAL scenarios, PATHNAME with -NAME added to its name (out.svg -> out-wedge.svg)."
  (if several
      (make-pathname :name (format nil "~A-~A" (pathname-name pathname) (name-text name))
                     :defaults pathname)
      pathname))

(defun finish-report (output)
  "End the run's reports: write the HTML page on the stream and each picture to its
file (see PICTURE-PATHNAME). Returns the pathnames written. Signals REPORT-ERROR when a
picture cannot be written."
  (let ((histories (reverse (output-histories output))))
    (when (and (eq (output-format output) :latex) (output-standalone output))
      (unless (output-started output)
        (print-latex-document-start (output-stream output)))
      (print-latex-document-end (output-stream output)))
    (when (and (eq (output-format output) :html) histories)
      ;; made whole first: a page that fails half-way writes nothing
      (write-string (with-output-to-string (stream)
                      (print-history-html histories stream :bridge (output-bridge output)))
                    (output-stream output)))
    (when (output-svg output)
      (loop for history in histories
            for name = (scenario-name (history-scenario history))
            for pathname = (picture-pathname (output-svg output) name (rest histories))
            collect (handler-case
                        (with-open-file (out pathname :direction :output :if-exists :supersede
                                                      :external-format :utf-8)
                          (print-history-svg history out)
                          pathname)
                      (file-error (condition)
                        (error 'report-error :datum (namestring pathname)
                                             :detail (format nil "Cannot write the picture (~A)"
                                                             (type-of condition)))))))))
