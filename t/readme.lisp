;;;; t/readme.lisp -- the README tells the truth (issue 25).
;;;;
;;;; Its REPL transcript is run: every form after a CL-USER> prompt is read and evaluated
;;;; in CL-USER, and what it prints (PRIN1, as the REPL does) must be what the README shows,
;;;; whitespace aside. Its table of scenarios lists every file of scenarios/. The copy of the
;;;; scenario language page in doc/ is the shared one, where the shared one is at hand.

(in-package #:ames.tests)

(def-suite readme :in all-tests :description "The README and doc/ agree with AMES.")

(in-suite readme)

(defun readme-text ()
  "The README of the checkout."
  (uiop:read-file-string (asdf:system-relative-pathname "ames" "README.md")))

(defun readme-transcript ()
  "The README's REPL transcript: the ```lisp block of the section \"At the REPL\"."
  (let* ((text (readme-text))
         (section (search "## At the REPL" text))
         (start (and section (search "```lisp" text :start2 section)))
         (end (and start (search "```" text :start2 (+ start 7)))))
    (and end (subseq text (+ start 7) end))))

(defun transcript-exchanges (transcript)
  "The (FORM-TEXT EXPECTED-OUTPUT) of each CL-USER> prompt of TRANSCRIPT."
  (let ((prompt "CL-USER> "))
    (loop with start = (search prompt transcript)
          while start
          collect (let* ((form-start (+ start (length prompt)))
                         (form-end (nth-value 1 (let ((*read-eval* nil) (*package* (find-package '#:cl-user)))
                                                  (read-from-string transcript t nil :start form-start))))
                         (next (search prompt transcript :start2 form-end)))
                    (prog1 (list (subseq transcript form-start form-end)
                                 (string-trim '(#\Space #\Newline) (subseq transcript form-end next)))
                      (setf start next))))))

(defun squeezed (text)
  "TEXT with every run of whitespace one space, trimmed."
  (string-trim " " (cl-ppcre:regex-replace-all "\\s+" text " ")))

(test readme-transcript-is-what-ames-prints
  "Each form of the README's REPL transcript, evaluated, prints what the README shows."
  (with-fixture simulator-bridge ()
    (let ((exchanges (transcript-exchanges (or (readme-transcript) ""))))
      (is (<= 5 (length exchanges)) "the README has no REPL transcript")
      (let ((ames.simulator::*bridge* bridge)
            (*package* (find-package '#:cl-user))
            (*default-pathname-defaults* (asdf:system-source-directory "ames")))
        (loop for (form-text expected) in exchanges
              for form = (let ((*read-eval* nil)) (read-from-string form-text))
              for printed = (with-standard-io-syntax
                              (let ((*package* (find-package '#:cl-user)) (*print-readably* nil))
                                (format nil "~{~S~^~%~}" (multiple-value-list (eval form)))))
              do (is (string= (squeezed expected) (squeezed printed))
                     "The README shows~%~A~%for ~A, AMES prints~%~A" expected form-text printed))))))

(test readme-lists-every-scenario
  "The README's table of scenarios has a row for every file of scenarios/."
  (let ((text (readme-text)))
    (dolist (file (scenario-files))
      (let ((name (format nil "~A.~A" (pathname-name file) (pathname-type file))))
        (is (cl-ppcre:scan (format nil "(?m)^\\| `~A` \\|" (cl-ppcre:quote-meta-chars name)) text)
            "The README's table of scenarios lacks ~A" name)))))

(test readme-introduces-queries-explain-and-the-language
  "The README introduces queries, explain and the scenario language, and the language page
it points to is in the repository."
  (let ((text (readme-text)))
    (dolist (heading '("## Queries" "## Explain" "## The scenario language"))
      (is (search heading text) "The README has no section ~S" heading))
    (is (search "doc/scenario-language.md" text))
    (is (probe-file (asdf:system-relative-pathname "ames" "doc/scenario-language.md")))))

(test language-page-in-step-with-the-shared-one
  "doc/scenario-language.md is the shared design page (checked where ../shared is present)."
  (let* ((root (asdf:system-source-directory "ames"))
         (shared (find-if #'probe-file
                          (list (merge-pathnames "../shared/design/scenario-language.md" root)
                                (merge-pathnames "../../shared/design/scenario-language.md" root)))))
    (if (null shared)
        (skip "the shared design pages are not beside the checkout")
        (is (string= (uiop:read-file-string shared)
                     (uiop:read-file-string (asdf:system-relative-pathname "ames" "doc/scenario-language.md")))
            "doc/scenario-language.md differs from ~A: copy it again" (namestring shared)))))

(test system-description-is-current
  "ames.asd's description no longer says the bodies are frictionless."
  (is (not (search "frictionless" (asdf:system-description (asdf:find-system "ames"))))))
