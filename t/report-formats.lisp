;;;; t/report-formats.lisp -- every scenario in every format: presentation, text, LaTeX (pdflatex), JSON, SVG, HTML (Chromium).
;;;;
;;;; Each scenario of scenarios/ is simulated once; its presented forms are checked against the
;;;; solved ones (t/report-presentation.lisp), then each format: the text names no internal
;;;; symbol, the JSON parses and gives back the s-expression, the SVG is well-formed XML with
;;;; one trajectory path per moving body per state, the LaTeX fragments compile with pdflatex
;;;; (where texlive-latex-base is installed; skipped otherwise). The HTML page is rendered by
;;;; headless Chromium where it is installed: its formulas typeset and its pictures show.

(in-package #:ames.tests)

(in-suite report)

(defun program-path (name)
  "The pathname of the program NAME on the PATH, or NIL."
  (dolist (directory (cl-ppcre:split ":" (or (uiop:getenv "PATH") "")))
    ;; the path itself, not its truename: pdflatex is a link to pdftex, which reads its
    ;; format from the name it is called by
    (let ((path (format nil "~A/~A" directory name)))
      (when (and (probe-file path) (not (uiop:directory-pathname-p (probe-file path))))
        (return path)))))

(defun fresh-temporary-directory (prefix)
  "A new empty directory under the temporary directory, named PREFIX and random letters."
  (let ((state (make-random-state t)))
    (loop (let ((directory (uiop:ensure-directory-pathname
                            (merge-pathnames (format nil "~A-~36R" prefix (random (expt 36 8) state))
                                             (uiop:temporary-directory)))))
            (unless (probe-file directory)
              (ensure-directories-exist directory)
              (return directory))))))

(defun well-formed-xml-p (text)
  "True when TEXT is well-formed XML (one root element, tags nested and closed, attribute
values quoted, & only in entities, no < in text): a checker for what the SVG writer
writes. Returns as a second value what was wrong."
  (let ((stack '()) (roots 0) (i 0) (n (length text)))
    (flet ((malformed (why) (return-from well-formed-xml-p (values nil (format nil "~A at ~D" why i)))))
      (loop while (< i n)
            do (let ((c (char text i)))
                 (cond
                   ((char= c #\<)
                    (let ((end (position #\> text :start i)))
                      (unless end (malformed "unclosed tag"))
                      (let ((tag (subseq text (1+ i) end)))
                        (cond ((and (plusp (length tag)) (member (char tag 0) '(#\? #\!))))
                              ((and (plusp (length tag)) (char= (char tag 0) #\/))
                               (unless (equal (pop stack) (string-trim " " (subseq tag 1))) (malformed "mismatched end tag")))
                              (t (let* ((self-closing (and (plusp (length tag)) (char= (char tag (1- (length tag))) #\/)))
                                        (body (if self-closing (subseq tag 0 (1- (length tag))) tag))
                                        (name (first (cl-ppcre:split "\\s+" body))))
                                   (unless (cl-ppcre:scan "^[A-Za-z][A-Za-z0-9:-]*$" (or name "")) (malformed "bad tag name"))
                                   (unless (cl-ppcre:scan "^[A-Za-z][A-Za-z0-9:-]*(\\s+[A-Za-z][A-Za-z0-9:-]*=\"[^\"<]*\")*\\s*$" body)
                                     (malformed "bad attributes"))
                                   (when (null stack) (incf roots))
                                   (unless self-closing (push name stack))))))
                      (setf i (1+ end))))
                   ((char= c #\&)
                    (unless (cl-ppcre:scan "^&(amp|lt|gt|quot|apos|#[0-9]+);" text :start i) (malformed "bad entity"))
                    (incf i))
                   (t (when (and (null stack) (not (member c '(#\Space #\Newline #\Tab #\Return))))
                        (malformed "text outside the root"))
                      (incf i)))))
      (cond (stack (values nil "unclosed elements"))
            ((/= roots 1) (values nil "not one root element"))
            (t t)))))

(defun trajectory-paths (svg)
  "The (BODY STATE) of each trajectory path of the picture SVG."
  (let ((pattern "<path class=\"trajectory[^\"]*\" data-body=\"([^\"]*)\" data-state=\"([0-9]+)\""))
    (mapcar (lambda (match)
              (let ((groups (nth-value 1 (cl-ppcre:scan-to-strings pattern match))))
                (list (aref groups 0) (parse-integer (aref groups 1)))))
            (cl-ppcre:all-matches-as-strings pattern svg))))

(defun check-formats (bridge history latex)
  "Check HISTORY's text, JSON and SVG (see the file header); write its LaTeX on LATEX."
  (let* ((scenario (ames:history-scenario history))
         (name (ames:scenario-name scenario))
         (text (with-output-to-string (out) (ames:print-history-text history out :bridge bridge)))
         (json (ames.report:history-json history))
         (svg (with-output-to-string (out) (ames.report:print-history-svg history out))))
    (is (equal (ames:history-sexp history) (ames.report:json-to-sexp json)) "~A: JSON" name)
    (is (not (find #\Newline (string-right-trim '(#\Newline) json))))
    (multiple-value-bind (ok why) (well-formed-xml-p svg)
      (is-true ok "~A: the SVG is not well-formed XML: ~A" name why))
    (let ((moving (mapcar (lambda (b) (string-downcase (symbol-name (ames:scenario-body-name b))))
                          (ames:scenario-moving-bodies scenario)))
          (paths (trajectory-paths svg)))
      ;; the states drawn: the top-level ones, then a fork's branch (see PICTURE-PATH)
      (let ((drawn (remove-duplicates (mapcar #'second paths))))
        (dolist (state (ames:history-states history))
          (unless (ames.simulator:state-fork-p state) ; no period of motion: its branch is drawn
            (is (member (ames:state-index state) drawn) "~A: state ~D not drawn" name (ames:state-index state))))
        (dolist (index drawn)
          (dolist (body moving)
            (is (= 1 (count (list body index) paths :test #'equal))
                "~A: not one path for ~A in state ~D" name body index)))
        (is (= (length paths) (* (length moving) (length drawn))))))
    (let ((fragment (with-output-to-string (out) (ames.report:print-history-latex history out :bridge bridge))))
      (check-human-formats bridge history text fragment svg)
      (is (search "\\subsection*{Scenario" fragment))
      (is (= (count #\{ fragment) (count #\} fragment)) "~A: unbalanced braces in its LaTeX" name)
      (write-string fragment latex))))

(defun compiles-with-pdflatex-p (fragments)
  "Compile FRAGMENTS (LaTeX) in a plain article with pdflatex in a fresh directory;
true when it succeeds. Returns the log as a second value."
  (let ((directory (fresh-temporary-directory "ames-latex")))
    (unwind-protect
         (progn
           (with-open-file (out (merge-pathnames "report.tex" directory) :direction :output)
             ;; the standalone document's own preamble and end (--format latex --standalone)
             (ames.report:print-latex-document-start out)
             (write-string fragments out)
             (ames.report:print-latex-document-end out))
           (multiple-value-bind (output error-output code)
               (uiop:run-program (list (program-path "pdflatex") "-interaction=nonstopmode"
                                       "-halt-on-error" "report.tex")
                                 :directory directory :output :string :error-output :string
                                 :ignore-error-status t)
             (declare (ignore error-output))
             (values (and (eql code 0) (probe-file (merge-pathnames "report.pdf" directory)) t) output)))
      (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore))))

(defun check-scenario-file-in-every-format (file)
  "Presentation forms equal the solved ones, the text, JSON, SVG and LaTeX reports are
produced and valid, and the energy query equals the report's total energy, for every
scenario of FILE; their LaTeX compiles (skipped without pdflatex)."
  (with-fixture simulator-bridge ()
    (let ((latex (make-string-output-stream)))
      (dolist (scenario (ames:read-scenario-file file))
        (let ((history (simulate-stopping-when-ambiguous scenario bridge)))
          (check-presentation bridge history)
          (check-formats bridge history latex)
          ;; the energy query on this very run (t/phenomena.lisp)
          (check-energy-query-is-the-report-total bridge history)))
      (if (program-path "pdflatex")
          (multiple-value-bind (ok log) (compiles-with-pdflatex-p (get-output-stream-string latex))
            (is-true ok "pdflatex failed:~%~A" (subseq log (max 0 (- (length log) 3000)))))
          (skip "pdflatex is not installed (Debian's texlive-latex-base)")))))

(def-suite every-scenario-in-every-format :in report
  :description "One test per file of scenarios/, made when the tests are loaded (so that
`make test` can run them in parallel): see CHECK-SCENARIO-FILE-IN-EVERY-FORMAT.")

(defun define-every-format-tests ()
  "Define, in the suite EVERY-SCENARIO-IN-EVERY-FORMAT, the test
EVERY-FORMAT/NAME for each file NAME.lisp of scenarios/."
  (let ((*package* (find-package '#:ames.tests)))
    (dolist (file (scenario-files))
      (it.bese.fiveam::register-test
       (intern (string-upcase (format nil "every-format/~A" (pathname-name file))) '#:ames.tests)
       (format nil "Every report format for scenarios/~A.~A."
               (pathname-name file) (pathname-type file))
       `((check-scenario-file-in-every-format ,(namestring file)))
       (get-test 'every-scenario-in-every-format) nil :definition-time nil))))

(define-every-format-tests)

(test the-command-line-writes-every-format-and-the-pictures
  (with-fixture simulator-bridge ()
    (let* ((file (namestring (find "particle-under-plane" (scenario-files) :key #'pathname-name :test #'string=)))
           (directory (fresh-temporary-directory "ames-svg"))
           (picture (merge-pathnames "run.svg" directory)))
      (unwind-protect
           (progn
             (dolist (format ames.report:*report-formats*)
               (let ((output (make-string-output-stream)))
                 (is (eql 0 (ames:run-files (list file file) :format format :stream output :bridge bridge
                                                             :svg (and (eq format :json) picture))))
                 (is (plusp (length (get-output-stream-string output))))))
             ;; two scenarios of the same name: one picture each, named after it
             (is (probe-file (merge-pathnames "run-particle-under-plane.svg" directory)))
             (is (eql 0 (ames:run-files (list file) :format :sexp :stream (make-broadcast-stream)
                                                    :bridge bridge :svg picture)))
             (is (probe-file picture)))
        (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore)))
    (let ((options (ames::parse-command-line '("run" "a.lisp" "--format" "html" "--svg" "out.svg"))))
      (is (eq :html (getf options :format)))
      (is (equal "out.svg" (getf options :svg))))
    (signals ames:usage-error (ames::parse-command-line '("run" "a.lisp" "--svg")))
    (signals ames:usage-error (ames::parse-command-line '("run" "a.lisp" "--format" "pdf")))))

(test the-html-report-typesets-in-chromium
  "The page's formulas typeset with the inlined KaTeX and its picture shows (headless
Chromium; skipped where it is not installed)."
  (let ((chromium (or (program-path "chromium") (program-path "chromium-browser"))))
    (if (not chromium)
        (skip "Chromium is not installed (Debian's chromium)")
        (with-fixture simulator-bridge ()
          (let* ((histories (list (history-of "particle-on-wedge" bridge)
                                  (history-of "particle-on-sphere" bridge
                                              :parameter-values '(("g" . 981/100) ("r" . 1) ("theta0" . 1/10) ("m" . 1)))))
                 (page (uiop:tmpize-pathname (merge-pathnames "ames-report.html" (uiop:temporary-directory)))))
            (unwind-protect
                 (progn
                   (with-open-file (out page :direction :output :if-exists :supersede :external-format :utf-8)
                     (ames.report:print-history-html histories out :bridge bridge))
                   (let* ((dom (uiop:run-program (list chromium "--headless" "--no-sandbox" "--disable-gpu"
                                                       "--virtual-time-budget=10000" "--dump-dom"
                                                       (format nil "file://~A" (namestring page)))
                                                 :output :string :error-output nil :ignore-error-status t))
                          (spans (length (cl-ppcre:all-matches-as-strings "class=\"math" dom)))
                          (typeset (length (cl-ppcre:all-matches-as-strings "class=\"katex\"" dom))))
                     (is (search "data-typeset=\"done\"" dom) "KaTeX did not run")
                     (is (plusp spans))
                     (is (= spans typeset) "~D formulas, ~D typeset" spans typeset)
                     (is (not (search "class=\"katex-error" dom)))
                     (is (= 2 (length (cl-ppcre:all-matches-as-strings "<svg[^>]*class=\"ames-picture\"" dom))))
                     (is (search "class=\"trajectory" dom))))
              (when (probe-file page) (delete-file page))))))))

(test standalone-latex-is-a-whole-document
  "--format latex --standalone writes one whole document (one preamble, one end, whatever
the number of scenarios) that pdflatex compiles (where texlive-latex-base is installed)."
  (with-fixture simulator-bridge ()
    (let* ((file (namestring (find "particle-under-plane" (scenario-files) :key #'pathname-name :test #'string=)))
           (output (make-string-output-stream)))
      (let ((ames.report:*latex-standalone* t))
        (is (eql 0 (ames:run-files (list file file) :format :latex :stream output :bridge bridge))))
      (let ((document (get-output-stream-string output)))
        (is (eql 0 (search "\\documentclass" document)))
        (is (= 1 (count-matches "\\\\begin\\{document\\}" document)))
        (is (= 1 (count-matches "\\\\end\\{document\\}" document)))
        (is (= 2 (count-matches "\\\\subsection\\*\\{Scenario" document)))
        (is (string= "\\end{document}" (string-trim '(#\Space #\Newline) (subseq document (- (length document) 16)))))
        (if (program-path "pdflatex")
            (let ((directory (fresh-temporary-directory "ames-standalone")))
              (unwind-protect
                   (progn
                     (with-open-file (out (merge-pathnames "report.tex" directory) :direction :output)
                       (write-string document out))
                     (multiple-value-bind (log error-output code)
                         (uiop:run-program (list (program-path "pdflatex") "-interaction=nonstopmode"
                                                 "-halt-on-error" "report.tex")
                                           :directory directory :output :string :error-output :string
                                           :ignore-error-status t)
                       (declare (ignore error-output))
                       (is (eql 0 code) "pdflatex failed:~%~A" (subseq log (max 0 (- (length log) 2000))))
                       (is (probe-file (merge-pathnames "report.pdf" directory)))))
                (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore)))
            (skip "pdflatex is not installed (Debian's texlive-latex-base)"))))))

(defun count-matches (regex text)
  "How many times REGEX matches in TEXT."
  (length (cl-ppcre:all-matches-as-strings regex text)))
