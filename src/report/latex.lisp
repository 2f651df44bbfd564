;;;; src/report/latex.lisp -- the LaTeX report: a fragment per scenario, its formulas through Maxima's tex().
;;;;
;;;; The fragment needs nothing beyond LaTeX itself (\subsection*, description lists, display
;;;; math); paste it into any article. Each formula is presented first (see PRESENT), then
;;;; written by Maxima's tex() exactly as presented (ames.maxima:presentation-latex), its names
;;;; written as a physicist does: mp as m_{p}, theta0 as \theta_{0}, tau as \tau, the arc length
;;;; as s, the acceleration terms as a_{x}. The HTML report uses the same TeX.

(in-package #:ames.report)

(defparameter *greek-names*
  '("alpha" "beta" "gamma" "delta" "epsilon" "zeta" "eta" "theta" "iota" "kappa" "lambda"
    "mu" "nu" "xi" "rho" "sigma" "tau" "upsilon" "phi" "chi" "psi" "omega")
  "Names written as Greek letters.")

(defun latex-escape (text)
  "TEXT with LaTeX's special characters escaped, for running text and comments: a line
break is a space (a blank line would end a paragraph, a line break a comment), other
control characters are written visibly (VISIBLE-TEXT), and ^ and \\ are escaped (so no
^^M can end a line)."
  (with-output-to-string (out)
    (loop for c across (visible-text (substitute #\Space #\Newline text))
          do (case c
               ((#\# #\$ #\% #\& #\_ #\{ #\}) (format out "\\~C" c))
               ((#\< #\>) (format out "$~C$" c))
               (#\~ (write-string "\\textasciitilde{}" out))
               (#\^ (write-string "\\textasciicircum{}" out))
               (#\\ (write-string "\\textbackslash{}" out))
               (t (write-char c out))))))

(defun latex-word (word)
  "A name's letters as LaTeX math: a Greek letter, a letter with a one-letter or numeric
subscript (mp -> m_{p}, v0 -> v_{0}, theta0 -> \\theta_{0}), or \\mathit{word}."
  (let* ((clean (map 'string (lambda (c) (if (alphanumericp c) (char-downcase c) #\-)) word))
         (digits (position-if-not #'digit-char-p clean :from-end t))
         (stem (subseq clean 0 (if digits (1+ digits) 0)))
         (index (subseq clean (if digits (1+ digits) 0))))
    (flet ((stem-latex (stem)
             (cond ((member stem *greek-names* :test #'string=) (format nil "\\~A" stem))
                   ((= (length stem) 1) stem)
                   ((and (= (length stem) 2) (string= index "") (every #'alpha-char-p stem))
                    (format nil "~C_{~C}" (char stem 0) (char stem 1)))
                   (t (format nil "\\mathit{~A}" (cl-ppcre:regex-replace-all "-" stem "\\\\mbox{-}"))))))
      (cond ((string= stem "") index)
            ((string= index "") (stem-latex stem))
            (t (format nil "{~A}_{~A}" (stem-latex stem) index))))))

(defun latex-name (name)
  "The LaTeX of a variable or quantity term NAME in a presented formula."
  (cond ((and (consp name) (eq (first name) 'acceleration)) (format nil "a_{~(~A~)}" (second name)))
        ((and (symbolp name) (null (symbol-package name)) (find #\' (symbol-name name)))
         (format nil "\\~:[ddot~;dot~]{~A}" (= 1 (count #\' (symbol-name name)))
                 (latex-word (remove #\' (symbol-name name)))))
        ((symbolp name) (latex-word (symbol-name name)))
        (t (format nil "\\mathrm{~(~A~)}_{~{~(~A~)~^,~}}" (symbol-name (first name))
                   (mapcar (lambda (a) (if (symbolp a) (symbol-name a) a)) (rest name))))))

(defun number-latex (number)
  "NUMBER as NUMBER-TEXT writes it, in TeX (1.5e-7 as 1.5\\times 10^{-7})."
  (let ((text (number-text number)))
    (if (find #\e text)
        (cl-ppcre:regex-replace "e(-?\\d+)$" text "\\\\times 10^{\\1}")
        text)))

(defun contains-float-p (expression)
  "True when EXPRESSION contains a float (a numeric form under parameter values)."
  (if (consp expression) (some #'contains-float-p expression) (floatp expression)))

(defun numeric-form-latex (expression)
  "The TeX of a numeric form (numbers, names, + - * and integer powers), its numbers
written by NUMBER-TEXT: 0.7483 + 1.692\\,\\tau - 4.905\\,\\tau^{2}."
  (labels ((render (x)
             (cond ((realp x) (number-latex x))
                   ((atom x) (latex-name x))
                   (t (case (first x)
                        (+ (with-output-to-string (out)
                             (loop for (term . more) on (rest x) for first = t then nil
                                   do (if (and (consp term) (eq (first term) '-) (null (cddr term)))
                                          (format out "~:[-~;-~]~A" first (render (second term)))
                                          (format out "~:[+~;~]~A" first (render term))))))
                        (- (if (cddr x)
                               (format nil "~A~{-~A~}" (render (second x)) (mapcar #'render (cddr x)))
                               (format nil "-~A" (render (second x)))))
                        (* (format nil "~{~A~^\\,~}" (mapcar #'render (rest x))))
                        (expt (format nil "~A^{~A}" (render (second x)) (render (third x))))
                        (t (princ-to-string x)))))))
    (render expression)))

(defun formula-latex (presenter expression)
  "The TeX of the presented EXPRESSION (arithmetic or a relation), from Maxima's tex().
Numbers, and numeric forms such as 0.7483 + 1.692 tau, are written by NUMBER-TEXT."
  (cond ((realp expression) (number-latex expression))
        ((contains-float-p expression) (numeric-form-latex expression))
        (t (handler-case (ames.maxima:presentation-latex (presenter-bridge presenter) expression
                                                         :name-function #'latex-name)
             ;; no time left (or Maxima failed): the form as solved, in typewriter type
             (ames.maxima:maxima-condition ()
               (format nil "\\mbox{\\texttt{~A}}" (latex-escape (text-form expression))))))))

(defun phrase-latex (presenter phrase)
  "PHRASE as LaTeX running text, its formulas as inline math."
  (with-output-to-string (out)
    (dolist (part phrase)
      (if (stringp part)
          (write-string (latex-escape part) out)
          (format out "$~A$" (formula-latex presenter (second part)))))))

(defun numbers-latex (presenter numbers)
  "The LaTeX put beside a formula for NUMBERS (see NUMBERS-TEXT)."
  (cond ((null numbers) "")
        ((and (consp numbers) (eq (first numbers) :from))
         (format nil "\\quad(~A\\ \\mathrm{at\\ the\\ start}~@[,\\ ~A\\ \\mathrm{at\\ the\\ end}~])"
                 (formula-latex presenter (getf numbers :from))
                 (and (getf numbers :to) (formula-latex presenter (getf numbers :to)))))
        ((and (consp numbers) (not (valid-expression-p numbers)))
         (if (and (every #'realp numbers) (= 2 (length numbers)))
             (format nil "\\quad(=(~{~A~^, ~}))" (mapcar (lambda (n) (formula-latex presenter n)) numbers))
             ""))
        (t (format nil "\\quad(=~A)" (formula-latex presenter numbers)))))

(defun display-math (stream lhs presenter value &optional numbers)
  "Write \\[ LHS = VALUE \\] (VALUE presented) with NUMBERS beside it."
  (format stream "\\[ ~@[~A = ~]~A~A \\]~%" lhs (formula-latex presenter value)
          (numbers-latex presenter numbers)))

(defun vector-latex (presenter pair)
  "The TeX of the presented vector PAIR, (x, y)."
  (format nil "\\left(~A,\\ ~A\\right)" (formula-latex presenter (first pair))
          (formula-latex presenter (second pair))))

(defun body-mass (presenter body)
  "The mass of the scenario body named BODY, or NIL."
  (let ((object (find-scenario-body body (presenter-scenario presenter))))
    (and object (scenario-body-mass object))))

(defun print-state-heading-latex (presenter view stream)
  "Write the subsection heading of one state's VIEW on STREAM: its number (or the fork
at its start), its branch, and when it starts."
  (let ((start (getf view :start)))
    (format stream "~%\\subsubsection*{~:[State ~D~;Fork at the start of state ~D (no period of motion)~]~@[ (branch ~A)~], from ~A}~%"
            (getf view :fork) (getf view :index) (getf view :branch)
            (if (and (= 1 (length start)) (consp (first start)))
                (format nil "$t = ~A$" (formula-latex presenter (second (first start))))
                (phrase-latex presenter start)))))

(defun print-forces-latex (presenter view stream)
  "Write the Forces item of one state's VIEW on STREAM: each force's label and options,
then its value as a vector or a displayed formula."
  (format stream "\\item[Forces]~:[ none.~;~]~%" (getf view :forces))
  (dolist (force (getf view :forces))
    (format stream "~A~{ (~A)~}:~%" (latex-escape (getf force :label))
            (mapcar #'latex-escape (getf force :options)))
    (let ((value (getf force :value)))
      (cond ((null value) (format stream "\\par~%"))
            ((getf force :vector-p)
             (format stream "\\[ ~A~A \\]~%" (vector-latex presenter value)
                     (numbers-latex presenter (getf force :numbers))))
            (t (display-math stream (getf force :symbol) presenter value (getf force :numbers)))))))

(defun print-equations-of-motion-latex (presenter view stream)
  "Write the Equations of motion item of one state's VIEW on STREAM, when it has bodies:
mass times each component of the acceleration, for each body whose mass and
acceleration are known expressions."
  (when (getf view :bodies)
    (format stream "\\item[Equations of motion] (net force $=$ mass $\\times$ acceleration)~%")
    (dolist (body (getf view :bodies))
      (let ((mass (body-mass presenter (getf body :name)))
            (acceleration (getf body :acceleration)))
        (when (and mass acceleration
                   (every (lambda (a) (valid-expression-p a :kind :arithmetic)) acceleration))
          (format stream "~A:~%\\[ ~A\\,\\ddot{x} = ~A, \\qquad ~A\\,\\ddot{y} = ~A \\]~%"
                  (latex-escape (name-text (getf body :name)))
                  (formula-latex presenter (present presenter mass))
                  (formula-latex presenter (present presenter `(* ,mass ,(first acceleration))))
                  (formula-latex presenter (present presenter mass))
                  (formula-latex presenter (present presenter `(* ,mass ,(second acceleration))))))))))

(defun print-body-motion-latex (presenter body stream)
  "Write the Motion item of one BODY view on STREAM: its acceleration, then its position
in time, along a curve, or the note that it has no closed form."
  (format stream "\\item[Motion of ~A]~%" (latex-escape (name-text (getf body :name))))
  (destructuring-bind (&optional ax ay) (getf body :acceleration)
    (destructuring-bind (&optional nx ny) (getf body :acceleration-numbers)
      (display-math stream "a_{x}" presenter ax nx)
      (display-math stream "a_{y}" presenter ay ny)))
  (let ((position (getf body :position)) (numbers (getf body :position-numbers)))
    (cond ((eq position :no-closed-form)
           (format stream "Its position has no closed form in time (integrated numerically).~%"))
          ((and (consp position) (eq (first position) :on-path))
           (format stream "On the curve, at arc length $s$:~%")
           (display-math stream "x" presenter (first (second position)) (first numbers))
           (display-math stream "y" presenter (second (second position)) (second numbers)))
          ((consp position)
           (display-math stream "x(\\tau)" presenter (first position) (first numbers))
           (display-math stream "y(\\tau)" presenter (second position) (second numbers))))))

(defun print-state-end-latex (presenter view stream)
  "Write the End, Duration and At the end items of one state's VIEW on STREAM: the
events that end it, how long it lasts, and each body's final position and velocity."
  (format stream "\\item[End] ~A~{; at the same instant ~A~}.~%"
          (phrase-latex presenter (getf view :end))
          (mapcar (lambda (e) (phrase-latex presenter e))
                  (remove (getf view :end) (getf view :events) :test #'equal)))
  (format stream "\\item[Duration] ~A~@[ ($\\approx ~A$)~].~%" (phrase-latex presenter (getf view :duration))
          (and (getf view :duration-number) (formula-latex presenter (getf view :duration-number))))
  (when (getf view :final)
    (format stream "\\item[At the end]~%")
    (dolist (final (getf view :final))
      (format stream "~A at $~A$, velocity $~A$.~%" (latex-escape (name-text (getf final :name)))
              (vector-latex presenter (getf final :position))
              (vector-latex presenter (getf final :velocity))))))

(defun print-state-latex (presenter view stream)
  "Write one state's VIEW as LaTeX on STREAM."
  (print-state-heading-latex presenter view stream)
  (format stream "\\begin{description}~%\\item[Contacts] ~:[none~;~:*~{~A~^; ~}~].~%"
          (mapcar (lambda (c) (phrase-latex presenter c)) (getf view :contacts)))
  (print-forces-latex presenter view stream)
  (print-equations-of-motion-latex presenter view stream)
  (dolist (body (getf view :bodies))
    (print-body-motion-latex presenter body stream))
  (loop for (label . phrases) in (getf view :notes)
        do (format stream "\\item[~A] ~{~A~^; ~}.~%" (latex-escape (string-capitalize label :end 1))
                   (mapcar (lambda (p) (phrase-latex presenter p)) phrases)))
  (print-state-end-latex presenter view stream)
  (format stream "\\end{description}~%")
  (dolist (branch (getf view :branches))
    (print-branch-latex presenter branch stream)))

(defun print-branch-latex (presenter branch stream)
  "Write a BRANCH view of a fork: its heading and fact, its states inside a quote (so a
fork within a branch is indented once more), and how it ends."
  (format stream "~%\\paragraph{~A} Assuming ~A.~%\\begin{quote}~%"
          (latex-escape (branch-heading branch)) (phrase-latex presenter (getf branch :assume)))
  (dolist (state (getf branch :states))
    (print-state-latex presenter state stream))
  (format stream "\\end{quote}~%End of branch ~A: ~A~@[ (~A)~].~%" (latex-escape (getf branch :label))
          (latex-escape (branch-end-words branch))
          (and (getf branch :failure) (phrase-latex presenter (getf branch :failure)))))

(defun print-view-latex (presenter view stream)
  "Write a HISTORY-VIEW as a LaTeX fragment on STREAM."
  (format stream "% AMES report: scenario ~A (a LaTeX fragment; needs no package)~%"
          (latex-escape (name-text (getf view :name))))
  (format stream "\\subsection*{Scenario ~A}~%" (latex-escape (name-text (getf view :name))))
  (when (getf view :description)
    (format stream "~A~%~%" (latex-escape (getf view :description))))
  (format stream "\\noindent Parameters: ~{~A~^, ~}.~%"
          (mapcar (lambda (p) (phrase-latex presenter p)) (getf view :parameters)))
  (when (getf view :values)
    (format stream "Values: ~{$~A$~^, ~}.~%"
            (loop for (name . value) in (getf view :values)
                  collect (format nil "~A = ~A" (latex-name name) (formula-latex presenter value)))))
  (when (getf view :fixed)
    (format stream "Fixed: ~{~A~^, ~}.~%" (mapcar (lambda (p) (phrase-latex presenter p)) (getf view :fixed))))
  (when (getf view :states)
    (format stream "~{~A.~%~}" (mapcar (lambda (p) (string-capitalize-first (phrase-latex presenter p)))
                                       (getf view :definitions))))
  (dolist (state (getf view :states))
    (print-state-latex presenter state stream))
  (format stream "~%\\paragraph{Outcome} ~A.~%" (latex-escape (keyword-words (getf view :outcome))))
  (dolist (line (getf view :self-check))
    (format stream "~A~%~%" (latex-escape line)))
  (dolist (assumed (getf view :assumed))
    (format stream "Assumed from the given values ~A.~%" (phrase-latex presenter assumed)))
  (let ((ambiguity (getf view :ambiguity)))
    (when ambiguity
      (format stream "Which event ends the last state is not decided by the assumptions; the missing fact is ~A. Candidates:~%\\begin{itemize}~%~{\\item ~A~%~}\\end{itemize}~%"
              (phrase-latex presenter (getf ambiguity :missing-fact))
              (mapcar (lambda (c) (phrase-latex presenter c)) (getf ambiguity :candidates)))))
  (when (getf view :stopped)
    (format stream "~A~%" (phrase-latex presenter (getf view :stopped)))))

(defun string-capitalize-first (text)
  "TEXT with its first character in upper case (a sentence's start); a formula's TeX first
(a $) is left as it is."
  (if (and (plusp (length text)) (alpha-char-p (char text 0)))
      (concatenate 'string (string (char-upcase (char text 0))) (subseq text 1))
      text))

(defparameter *latex-preamble*
  "\\documentclass{article}
\\usepackage[utf8]{inputenc}
\\title{AMES report}
\\date{}
\\begin{document}
\\maketitle
"
  "The start of a standalone LaTeX document: packages every TeX Live has.")

(defun print-latex-document-start (stream)
  "Write the preamble of a standalone LaTeX document (see PRINT-LATEX-DOCUMENT-END)."
  (write-string *latex-preamble* stream))

(defun print-latex-document-end (stream)
  "Close the document PRINT-LATEX-DOCUMENT-START opened."
  (format stream "~%\\end{document}~%"))

(defun print-history-latex (history stream &key (bridge (current-bridge)))
  "Print HISTORY on STREAM as a LaTeX fragment: the scenario's parameters, then per state
its contacts, forces, equations of motion, each moving body's acceleration and
trajectory, its end event, duration and end values, formulas typeset by Maxima's tex()
as presented (see PRESENT), numbers beside them under parameter values."
  (call-with-presenter history bridge
                       (lambda (presenter)
                         (print-view-latex presenter (history-view presenter history) stream))))
