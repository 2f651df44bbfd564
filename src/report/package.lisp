;;;; src/report/package.lisp -- the package of the reports: a simulation history for people and
;;;; for programs, in text, LaTeX, HTML, SVG, JSON and s-expressions.

(defpackage #:ames.report
  (:use #:cl #:ames.base #:ames.scenario #:ames.simulator)
  (:import-from #:ames.geometry #:v+ #:v- #:vscale #:norm-squared)
  (:documentation "Reports of a simulation history. For programs: the readable
s-expression of the scenario language's output section, and the same content as JSON.
For people: the presentation step (each quantity written as a textbook would, through
Maxima), then the text report, a LaTeX fragment, an SVG picture and a self-contained
HTML page.")
  (:export
   ;; no control character of a user's text reaches an output raw (escaping.lisp)
   #:visible-text
   ;; s-expressions and JSON (sexp.lisp, json.lisp)
   #:history-sexp #:state-sexp #:state-forces-of #:print-history-sexp
   #:history-json #:print-history-json #:json-to-sexp #:sexp-to-json
   ;; the presentation step (presentation.lisp, forms.lisp, form-display.lisp, view.lisp)
   #:presenter #:make-presenter #:call-with-presenter #:present #:present-relation
   #:arrange #:make-arrangement #:history-view #:acceleration-symbol
   ;; reports for people
   #:infix #:text-form #:number-text
   #:print-history-text #:print-history-latex #:print-history-html
   #:history-svg #:print-history-svg
   ;; the command line's output (output.lisp)
   #:make-report-output #:report-history #:finish-report #:*report-formats* #:*latex-standalone*
   #:print-latex-document-start #:print-latex-document-end #:impulse-entry #:event-text #:keyword-words #:failure-phrase #:text-phrase
   #:report-error))
