;;;; src/report/html.lisp -- the HTML report: one self-contained page with the picture, a timeline and typeset formulas.
;;;;
;;;; Each formula is the TeX of latex.lisp in a <span class="math" data-tex="...">, typeset in
;;;; the browser by KaTeX, which the page carries inline (Debian's libjs-katex: its script, its
;;;; style sheet, and its WOFF2 fonts as data: URLs), so the page needs no network and no file
;;;; beside it. Without KaTeX installed the page still opens and shows the TeX source.

(in-package #:ames.report)

(defparameter *katex-directory* #p"/usr/share/javascript/katex/"
  "Where Debian's libjs-katex installs KaTeX (katex.min.js, katex.min.css, fonts/).")

(defun html-escape (text)
  "TEXT escaped for HTML text and attribute values."
  (xml-escape text))

(defun file-octets (pathname)
  "The contents of the file PATHNAME as a vector of bytes."
  (with-open-file (in pathname :element-type '(unsigned-byte 8))
    (let ((octets (make-array (file-length in) :element-type '(unsigned-byte 8))))
      (read-sequence octets in)
      octets)))

(defun base64 (octets)
  "OCTETS (a vector of bytes) in base64 (RFC 4648, with padding)."
  (let ((alphabet "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/"))
    (with-output-to-string (out)
      (loop for i from 0 below (length octets) by 3
            do (let* ((n (min 3 (- (length octets) i)))
                      (word (logior (ash (aref octets i) 16)
                                    (if (> n 1) (ash (aref octets (+ i 1)) 8) 0)
                                    (if (> n 2) (aref octets (+ i 2)) 0))))
                 (loop for k from 0 below 4
                       do (write-char (if (<= k n) (char alphabet (ldb (byte 6 (- 18 (* 6 k))) word)) #\=)
                                      out)))))))

(defun katex-assets ()
  "KaTeX's script and its style sheet with the WOFF2 fonts inlined, as two strings; NIL
when libjs-katex is not installed."
  (let ((script (merge-pathnames "katex.min.js" *katex-directory*))
        (style (merge-pathnames "katex.min.css" *katex-directory*)))
    (when (and (probe-file script) (probe-file style))
      (values (uiop:read-file-string script)
              (cl-ppcre:regex-replace-all
               "url\\(fonts/([A-Za-z0-9_-]+)\\.woff2\\) format\\('woff2'\\)(?:,url\\([^)]*\\) format\\('[a-z]+'\\))*"
               (uiop:read-file-string style)
               (lambda (match name)
                 (let ((font (merge-pathnames (format nil "fonts/~A.woff2" name) *katex-directory*)))
                   (if (probe-file font)
                       (format nil "url(data:font/woff2;base64,~A) format('woff2')" (base64 (file-octets font)))
                       match)))
               :simple-calls t)))))

(defparameter *page-style*
  "body{font-family:Georgia,serif;max-width:60em;margin:2em auto;padding:0 1em;color:#222;line-height:1.45}
h1{font-size:1.5em}h2{border-bottom:1px solid #bbb;padding-bottom:.2em;margin-top:2em}
.timeline{display:flex;margin:1em 0;border:1px solid #999;border-radius:4px;overflow:hidden;font-size:.9em}
.timeline .segment{padding:.4em .6em;border-right:1px solid #999;background:#eef3fa;min-width:7em}
.timeline .segment:nth-child(even){background:#fbf1e6}
.timeline .event{display:block;font-weight:bold;margin-top:.2em}
.state{margin:1em 0;padding:.5em 1em;border-left:4px solid #1f5fa8;background:#fafafa}
.branch{margin:1em 0 1em 1.5em;padding:.3em .8em;border-left:4px solid #aaa}
.branch.selected{border-left-color:#2e8b57;background:#f3faf5}
.math.display{display:block;margin:.3em 0 .3em 1.5em}
.numbers{color:#555}
figure{margin:1em 0}figure svg{max-width:100%;height:auto;border:1px solid #ddd}
.tex-source{font-family:monospace;color:#555}"
  "The page's own style sheet.")

(defun tex-span (tex &key display)
  "A <span> that KaTeX typesets from TEX (showing TEX itself until it does)."
  (format nil "<span class=\"math~:[~; display~]\" data-tex=\"~A\"><span class=\"tex-source\">~:*~A</span></span>"
          display (html-escape tex)))

(defun math-html (presenter expression &key display)
  "A math span for the presented EXPRESSION."
  (tex-span (formula-latex presenter expression) :display display))

(defun phrase-html (presenter phrase)
  "PHRASE as HTML, its formulas as math spans."
  (with-output-to-string (out)
    (dolist (part phrase)
      (if (stringp part)
          (write-string (html-escape part) out)
          (write-string (math-html presenter (second part)) out)))))

(defun numbers-html (presenter numbers)
  "The TeX put beside a formula for NUMBERS (see NUMBERS-LATEX)."
  (let ((tex (numbers-latex presenter numbers)))
    (if (string= tex "") "" tex)))

(defun formula-line (presenter lhs value &optional numbers)
  "A display formula LHS = VALUE, with NUMBERS beside it."
  (tex-span (format nil "~@[~A = ~]~A~A" lhs (formula-latex presenter value) (numbers-html presenter numbers))
            :display t))

(defun selected-path-views (states)
  "STATES (views) and, at each fork, the states of the branch the given values select."
  (loop for state in states
        append (cons state (let ((branch (find-if (lambda (b) (getf b :selected)) (getf state :branches))))
                             (and branch (selected-path-views (getf branch :states)))))))

(defun timeline-html (presenter view stream)
  "Write the timeline of VIEW's states and events, along the selected branch at a fork:
one segment per state, as wide as its share of the known durations."
  (format stream "<div class=\"timeline\">~%")
  (let* ((states (selected-path-views (getf view :states)))
         (total (reduce #'+ (mapcar (lambda (s) (or (getf s :duration-number) 0)) states))))
    (dolist (state states)
      (let ((number (getf state :duration-number)))
        (format stream "<div class=\"segment\" style=\"flex:~,3F\">State ~D: ~A~@[ <span class=\"numbers\">(~A)</span>~]<span class=\"event\">~A</span></div>~%"
                (if (and number (plusp total)) (max 0.5 (* 4 (/ number total))) 1)
                (getf state :index) (phrase-html presenter (getf state :duration))
                (and number (number-text number)) (phrase-html presenter (getf state :end))))))
  (format stream "</div>~%"))

(defun state-html (presenter view stream)
  "Write one state's VIEW as HTML on STREAM."
  (format stream "<div class=\"state\"><h3>~:[State ~D~;Fork at the start of state ~D (no period of motion)~]~@[ (branch ~A)~], from ~A~@[ <span class=\"numbers\">(t = ~A)</span>~]</h3>~%"
          (getf view :fork) (getf view :index) (getf view :branch) (phrase-html presenter (cons "t = " (getf view :start)))
          (and (getf view :start-number) (number-text (getf view :start-number))))
  (format stream "<p><b>Contacts:</b> ~:[none~;~:*~{~A~^; ~}~].</p>~%"
          (mapcar (lambda (c) (phrase-html presenter c)) (getf view :contacts)))
  (format stream "<p><b>Forces:</b>~:[ none.~;~]</p><ul>~%" (getf view :forces))
  (dolist (force (getf view :forces))
    (let ((value (getf force :value)))
      (format stream "<li>~A~{ (~A)~}~@[: ~A~]</li>~%" (html-escape (getf force :label))
              (mapcar #'html-escape (getf force :options))
              (cond ((null value) nil)
                    ((getf force :vector-p)
                     (tex-span (format nil "~A~A" (vector-latex presenter value)
                                       (numbers-latex presenter (getf force :numbers)))
                               :display t))
                    (t (formula-line presenter (getf force :symbol) value (getf force :numbers)))))))
  (format stream "</ul>~%")
  (dolist (body (getf view :bodies))
    (format stream "<p><b>~A</b></p>~%" (html-escape (name-text (getf body :name))))
    (destructuring-bind (&optional ax ay) (getf body :acceleration)
      (destructuring-bind (&optional nx ny) (getf body :acceleration-numbers)
        (format stream "~A~A~%" (formula-line presenter "a_{x}" ax nx) (formula-line presenter "a_{y}" ay ny))))
    (let ((position (getf body :position)) (numbers (getf body :position-numbers)))
      (cond ((eq position :no-closed-form)
             (format stream "<p>Its position has no closed form in time (integrated numerically).</p>~%"))
            ((and (consp position) (eq (first position) :on-path))
             (format stream "<p>On the curve, at arc length s:</p>~A~A~%"
                     (formula-line presenter "x" (first (second position)) (first numbers))
                     (formula-line presenter "y" (second (second position)) (second numbers))))
            ((consp position)
             (format stream "~A~A~%" (formula-line presenter "x(\\tau)" (first position) (first numbers))
                     (formula-line presenter "y(\\tau)" (second position) (second numbers)))))))
  (loop for (label . phrases) in (getf view :notes)
        do (format stream "<p><b>~A:</b> ~{~A~^; ~}.</p>~%" (html-escape (string-capitalize label :end 1))
                   (mapcar (lambda (p) (phrase-html presenter p)) phrases)))
  (format stream "<p><b>Ends:</b> ~A~{; at the same instant ~A~}. <b>Duration:</b> ~A~@[ <span class=\"numbers\">(~A)</span>~].</p>~%"
          (phrase-html presenter (getf view :end))
          (mapcar (lambda (e) (phrase-html presenter e))
                  (remove (getf view :end) (getf view :events) :test #'equal))
          (phrase-html presenter (getf view :duration))
          (and (getf view :duration-number) (number-text (getf view :duration-number))))
  (when (getf view :final)
    (format stream "<p><b>At the end:</b></p><ul>~%")
    (dolist (final (getf view :final))
      (format stream "<li>~A at ~A, velocity ~A</li>~%"
              (html-escape (name-text (getf final :name)))
              (tex-span (vector-latex presenter (getf final :position)))
              (tex-span (vector-latex presenter (getf final :velocity)))))
    (format stream "</ul>~%"))
  (format stream "</div>~%")
  (dolist (branch (getf view :branches))
    (branch-html presenter branch stream)))

(defun branch-html (presenter branch stream)
  "Write a BRANCH view of a fork: a box, inside the box of the branch it forks from, with
its heading and fact, its states and how it ends; the selected branch marked."
  (format stream "<div class=\"branch~:[~; selected~]\" data-branch=\"~A\"><h3>~A</h3><p>Assuming ~A.</p>~%"
          (getf branch :selected) (html-escape (getf branch :label))
          (html-escape (branch-heading branch)) (phrase-html presenter (getf branch :assume)))
  (dolist (state (getf branch :states))
    (state-html presenter state stream))
  (format stream "<p><b>End of branch ~A:</b> ~A~@[ (~A)~].</p></div>~%" (html-escape (getf branch :label))
          (html-escape (branch-end-words branch))
          (and (getf branch :failure) (phrase-html presenter (getf branch :failure)))))

(defun scenario-html (history stream bridge)
  "Write one scenario's section of the page."
  (call-with-presenter
   history bridge
   (lambda (presenter)
     (let ((view (history-view presenter history)))
       (format stream "<section class=\"scenario\"><h2>Scenario ~A</h2>~%" (html-escape (name-text (getf view :name))))
       (when (getf view :description) (format stream "<p>~A</p>~%" (html-escape (getf view :description))))
       (format stream "<p><b>Parameters:</b> ~{~A~^, ~}.~@[ <b>Values:</b> ~{~A~^, ~}.~]~@[ <b>Fixed:</b> ~{~A~^, ~}.~]</p>~%"
               (mapcar (lambda (p) (phrase-html presenter p)) (getf view :parameters))
               (loop for (name . value) in (getf view :values)
                     collect (format nil "~A = ~A" (html-escape (name-text name)) (number-text value)))
               (mapcar (lambda (p) (phrase-html presenter p)) (getf view :fixed)))
       (format stream "<figure>~A</figure>~%" (history-svg history))
       (timeline-html presenter view stream)
       (dolist (state (getf view :states)) (state-html presenter state stream))
       (format stream "<p><b>Outcome:</b> ~A.</p>~%" (html-escape (keyword-words (getf view :outcome))))
       (dolist (line (getf view :self-check))
         (format stream "<p>~A</p>~%" (html-escape line)))
       (dolist (assumed (getf view :assumed))
         (format stream "<p>Assumed from the given values ~A.</p>~%" (phrase-html presenter assumed)))
       (let ((ambiguity (getf view :ambiguity)))
         (when ambiguity
           (format stream "<p>Which event ends the last state is not decided by the assumptions; the missing fact is ~A.</p><ul>~{<li>~A</li>~}</ul>~%"
                   (phrase-html presenter (getf ambiguity :missing-fact))
                   (mapcar (lambda (c) (phrase-html presenter c)) (getf ambiguity :candidates)))))
       (format stream "</section>~%")))))

(defun print-history-html (histories stream &key (bridge (current-bridge)))
  "Write one self-contained HTML page for HISTORIES (a simulation history or a list of
them) on STREAM: per scenario its picture, a timeline of its states and events, and
each state's formulas typeset by KaTeX (inlined from libjs-katex; without it the TeX
source shows)."
  (let ((histories (if (listp histories) histories (list histories)))
        (failures '()))
    (multiple-value-bind (script style) (katex-assets)
      (format stream "<!DOCTYPE html>~%<html lang=\"en\"><head><meta charset=\"utf-8\">~%<title>AMES: ~{~A~^, ~}</title>~%"
              (mapcar (lambda (h) (html-escape (name-text (scenario-name (history-scenario h))))) histories))
      (format stream "<style>~A~%~@[~A~]</style>~%" *page-style* style)
      (when script (format stream "<script>~A</script>~%" script))
      (format stream "</head><body>~%<h1>AMES report</h1>~%")
      (setf failures (remove nil (mapcar (lambda (history)
                                           (scenario-html-or-failure history stream bridge))
                                         histories)))
      (when script
        (format stream "<script>document.querySelectorAll('.math').forEach(function(e){katex.render(e.getAttribute('data-tex'),e,{throwOnError:false,displayMode:e.classList.contains('display')});});document.body.setAttribute('data-typeset','done');</script>~%"))
      (format stream "</body></html>~%"))
    (when failures
      (error 'report-error :datum (mapcar #'car failures)
                           :detail (format nil "The HTML section of ~{~A~^, ~} could not be written (~{~A~^; ~})"
                                           (mapcar (lambda (f) (name-text (car f))) failures)
                                           (mapcar #'cdr failures))))))

(defun scenario-html-or-failure (history stream bridge)
  "Write HISTORY's section of the page (SCENARIO-HTML). When presenting it fails (a
defect of AMES), write a section saying so instead, so that the page keeps every other
scenario, and return (SCENARIO-NAME . MESSAGE); else NIL."
  (let* ((failure nil)
         (section (handler-case (with-output-to-string (out) (scenario-html history out bridge))
                    ;; out of time: the caller makes the page again without Maxima
                    (budget-exceeded (condition) (error condition))
                    (error (condition)
                      (setf failure (handler-case (princ-to-string condition)
                                      (error () (string (type-of condition)))))
                      "")))
         (name (scenario-name (history-scenario history))))
    (if failure
        (progn
          (format stream "<section class=\"scenario\"><h2>Scenario ~A</h2>~%<p>This scenario's report could not be written: ~A</p></section>~%"
                  (html-escape (name-text name)) (html-escape failure))
          (cons name failure))
        (progn (write-string section stream) nil))))
