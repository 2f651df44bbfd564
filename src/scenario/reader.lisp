;;;; src/scenario/reader.lisp -- reading scenario files as data: a restricted reader, one scenario at a time.
;;;;
;;;; A scenario file is data. It is never LOADed or EVALed: its text is read with
;;;; *READ-EVAL* nil, into the package AMES-SCENARIO (which uses no package), with a
;;;; restricted readtable that knows lists, symbols, keywords, numbers, strings and
;;;; comments (; and #| |#) and nothing else. Every other syntax is a
;;;; SCENARIO-READ-ERROR naming the file, line and column:
;;;;   - every # dispatch but #| (#. #S #P #+ #- #' #( #\ #: #x ...),
;;;;   - ' ` and , (a scenario file needs no quoting),
;;;;   - package-qualified symbols (pkg:sym, pkg::sym) and ::sym, so no symbol is
;;;;     ever looked up or interned in another package; only keywords (:name) go to
;;;;     KEYWORD, and every other symbol to AMES-SCENARIO,
;;;;   - dotted lists (a . b), lists nested deeper than +DEEPEST-LIST+, tokens longer
;;;;     than +LONGEST-TOKEN+ characters, files longer than +LARGEST-FILE+ characters.
;;;; Floats without an exponent marker are read as double-floats.
;;;;
;;;; A file may hold several scenarios. Before reading, the text is split into its
;;;; top-level forms by a scanner that knows strings, comments and escapes, and each is
;;;; read and validated on its own, so that one bad scenario, even one that does not
;;;; read, does not stop the others. Each failure is signalled as a SCENARIO-ERROR with
;;;; the restart SKIP-SCENARIO active; with :ON-ERROR :COLLECT the readers skip on
;;;; their own and return the conditions as a second value.

(in-package #:ames.scenario)

(defconstant +deepest-list+ 100
  "The deepest nesting of lists the reader accepts.")

(defconstant +longest-token+ 4096
  "The longest symbol or number token the reader accepts, in characters.")

(defconstant +largest-file+ (* 4 1024 1024)
  "The largest scenario text accepted, in characters.")

(define-condition forbidden-syntax (reader-error)
  ((detail :initarg :detail :reader forbidden-syntax-detail)
   (position :initarg :position :initform nil :reader forbidden-syntax-position))
  (:documentation "Internal: signalled by the restricted readtable's macro characters
on syntax the scenario language does not have; turned into a SCENARIO-READ-ERROR.")
  (:report (lambda (condition stream)
             (write-string (forbidden-syntax-detail condition) stream))))

;;; ------------------------------------------------------------------------------------
;;; Splitting a text into its top-level forms

(defstruct (span (:constructor make-span (start end &optional problem-position problem)))
  "A top-level form's text: [START, END) in the text; PROBLEM, a string, when the
scanner already knows the form cannot be read (at PROBLEM-POSITION)."
  start end problem-position problem)

(defun blank-char-p (char)
  "True for the characters the reader takes as whitespace."
  (member char '(#\Space #\Tab #\Newline #\Return #\Linefeed #\Page)))

(defun separator-char-p (char)
  "True for the characters that end a token (besides the forbidden prefixes)."
  (or (blank-char-p char) (member char '(#\( #\) #\" #\;))))

(defun top-level-spans (text)
  "The SPANs of the top-level forms of TEXT, in order. Signals nothing: a form that
is not closed runs to the end of TEXT, where reading it will fail."
  (let ((n (length text))
        (spans '())
        (problem nil) (problem-position nil))
    (labels ((note (position detail)
               (unless problem (setf problem detail problem-position position)))
             (at (i) (and (< i n) (char text i)))
             (block-comment-end (i)
               ;; I is just after "#|"; the index after the matching "|#", or NIL.
               (loop with depth = 1
                     while (< i n)
                     do (cond ((and (eql (at i) #\|) (eql (at (1+ i)) #\#))
                               (incf i 2)
                               (when (zerop (decf depth)) (return i)))
                              ((and (eql (at i) #\#) (eql (at (1+ i)) #\|))
                               (incf i 2) (incf depth))
                              (t (incf i)))
                     finally (return nil)))
             (skip-blank (i)
               ;; Past whitespace and comments; stops at an unclosed #| comment.
               (loop
                 (let ((c (at i)))
                   (cond ((null c) (return i))
                         ((blank-char-p c) (incf i))
                         ((eql c #\;)
                          (setf i (or (position #\Newline text :start i) n)))
                         ((and (eql c #\#) (eql (at (1+ i)) #\|))
                          (let ((end (block-comment-end (+ i 2))))
                            (if end (setf i end) (return i))))
                         (t (return i))))))
             (scan-string (i)
               ;; I is just after the opening quote.
               (loop (let ((c (at i)))
                       (cond ((null c) (return n))
                             ((eql c #\\) (incf i 2))
                             ((eql c #\") (return (1+ i)))
                             (t (incf i))))))
             (scan-token (i)
               (let ((start i))
                 (loop (let ((c (at i)))
                         (cond ((or (null c) (separator-char-p c) (member c '(#\' #\` #\,)))
                                (return))
                               ((eql c #\\) (incf i 2))
                               ((eql c #\|)
                                (incf i)
                                (loop (let ((d (at i)))
                                        (cond ((null d) (return))
                                              ((eql d #\\) (incf i 2))
                                              ((eql d #\|) (incf i) (return))
                                              (t (incf i))))))
                               (t (incf i)))))
                 (setf i (min i n))
                 (when (> (- i start) +longest-token+)
                   (note start (format nil "a token longer than ~D characters" +longest-token+)))
                 i))
             (scan-form (i)
               ;; I is at a non-blank character; the index after the form. Iterative,
               ;; so that no nesting depth can exhaust the stack.
               (let ((depth 0))
                 (loop
                   (setf i (skip-blank i))
                   (let ((c (at i)))
                     (flet ((done-if-top (j)
                              (setf i j)
                              (when (zerop depth) (return i))))
                       (case c
                         ((nil) (return n))
                         (#\( (incf depth) (incf i))
                         (#\) (incf i)
                          (when (or (zerop depth) (zerop (decf depth))) (return i)))
                         ((#\' #\` #\,)
                          ;; a prefix: the next form belongs to it
                          (setf i (if (and (eql c #\,) (eql (at (1+ i)) #\@)) (+ i 2) (1+ i))))
                         (#\" (done-if-top (scan-string (1+ i))))
                         (#\# (let ((j (1+ i)))
                                (loop while (and (at j) (digit-char-p (at j))) do (incf j))
                                (let ((d (at j)))
                                  (cond ((null d) (return n))
                                        ((eql d #\|) (return n)) ; an unclosed block comment
                                        ((eql d #\\) (done-if-top (scan-token (min n (+ j 2)))))
                                        ((eql d #\() (setf i j))
                                        ;; #. #S #P #+ ...: the next form belongs to it
                                        (t (setf i (1+ j)))))))
                         (t (done-if-top (scan-token i))))))))))
      (let ((i (skip-blank 0)))
        (loop while (< i n)
              do (setf problem nil problem-position nil)
                 (let ((end (max (scan-form i) (1+ i))))
                   (push (make-span i end problem-position problem) spans)
                   (setf i (skip-blank end))))))
    (nreverse spans)))

;;; ------------------------------------------------------------------------------------
;;; The restricted readtable

(defstruct (reading (:constructor make-reading (text)))
  "The state of the restricted reader over one text: the span being read (its start
in TEXT) and the current list depth."
  text (offset 0) (depth 0))

(defun forbid (stream position control &rest arguments)
  "Signal FORBIDDEN-SYNTAX on STREAM at the text POSITION."
  (error 'forbidden-syntax :stream stream :position position
                           :detail (apply #'format nil control arguments)))

(defun reading-position (reading stream)
  "The index in READING's text of STREAM's next character."
  (+ (reading-offset reading) (file-position stream)))

(defun read-scenario-list (reading stream)
  "The ( macro: a list, at most +DEEPEST-LIST+ deep, with no consing dot."
  (when (> (incf (reading-depth reading)) +deepest-list+)
    (forbid stream (1- (reading-position reading stream))
            "lists are nested more than ~D deep" +deepest-list+))
  (unwind-protect (read-delimited-list #\) stream t)
    (decf (reading-depth reading))))

(defun read-scenario-sharp (reading stream)
  "The # macro: a #| |# comment (nestable), or forbidden syntax."
  (let ((at (1- (reading-position reading stream)))
        (next (peek-char nil stream nil nil)))
    (unless (eql next #\|)
      (forbid stream at "#~@[~C~] syntax is not part of the scenario language (a scenario ~
                         file holds only lists, symbols, numbers, strings and comments)"
              next))
    (read-char stream)
    (let ((depth 1) (previous nil))
      (loop (let ((c (read-char stream nil nil)))
              (cond ((null c) (forbid stream at "the #| comment is not closed by |#"))
                    ((and (eql previous #\|) (eql c #\#))
                     (when (zerop (decf depth)) (return))
                     (setf c nil))
                    ((and (eql previous #\#) (eql c #\|))
                     (incf depth) (setf c nil)))
              (setf previous c))))
    (values)))

(defun read-scenario-colon (reading stream)
  "The : macro: a keyword :NAME at the start of a token; a colon inside a token
(a package prefix) or a double colon is forbidden syntax."
  (let* ((at (1- (reading-position reading stream)))
         (text (reading-text reading))
         (before (and (> at (reading-offset reading)) (char text (1- at))))
         (next (peek-char nil stream nil nil)))
    (when (and before (not (separator-char-p before)))
      (forbid stream at "a package prefix (pkg:symbol or pkg::symbol) is not allowed; ~
                         symbols are read into AMES-SCENARIO"))
    (when (eql next #\:)
      (forbid stream at "a double colon is not allowed"))
    (when (or (null next) (separator-char-p next) (member next '(#\' #\` #\,)))
      (forbid stream at "a colon must be followed by a keyword's name"))
    (let ((name (read stream t nil t)))
      (unless (symbolp name)
        (forbid stream at "a keyword's name must be a symbol, not ~A" (short-form-string name)))
      (intern (symbol-name name) '#:keyword))))

(defun make-scenario-readtable (reading)
  "A readtable for READING: the standard syntax of lists, symbols, numbers, strings
and ; comments, with # ' ` , : and ( replaced by the restricted macros above."
  (let ((readtable (copy-readtable nil)))
    (set-macro-character #\( (lambda (stream char)
                               (declare (ignore char))
                               (read-scenario-list reading stream))
                         nil readtable)
    (set-macro-character #\# (lambda (stream char)
                               (declare (ignore char))
                               (read-scenario-sharp reading stream))
                         t readtable)
    (set-macro-character #\: (lambda (stream char)
                               (declare (ignore char))
                               (read-scenario-colon reading stream))
                         nil readtable)
    (dolist (entry '((#\' "' (quote)") (#\` "` (backquote)") (#\, ", (comma)")))
      (destructuring-bind (character name) entry
        (set-macro-character character
                             (lambda (stream char)
                               (declare (ignore char))
                               (forbid stream (1- (reading-position reading stream))
                                       "~A is not part of the scenario language: a scenario ~
                                        file is data and needs no quoting" name))
                             nil readtable)))
    readtable))

;;; ------------------------------------------------------------------------------------
;;; Reading the spans

(defun line-and-column (text position)
  "The 1-based line and 0-based column of POSITION in TEXT."
  (let ((position (max 0 (min position (length text)))))
    (values (1+ (count #\Newline text :end position))
            (- position (1+ (or (position #\Newline text :end position :from-end t) -1))))))

(defun text-excerpt (text start)
  "Up to 40 characters of TEXT from START, for a condition's datum."
  (let* ((start (max 0 (min start (length text))))
         (end (min (length text) (+ start 40)))
         (excerpt (substitute #\Space #\Newline (subseq text start end))))
    (if (string= excerpt "") "end of text" excerpt)))

(defun span-read-error (text file position detail &optional (class 'scenario-read-error))
  "A SCENARIO-READ-ERROR (not yet signalled) at POSITION of TEXT."
  (multiple-value-bind (line column) (line-and-column text position)
    (make-condition class :file file :line line :column column :position position
                          :source (format nil "~@[~A, ~]line ~D" file line)
                          :datum (text-excerpt text position) :detail detail)))

(defun reader-error-detail (condition)
  "What the Lisp reader's CONDITION says, without its stream description."
  (typecase condition
    (forbidden-syntax (forbidden-syntax-detail condition))
    (end-of-file "the form is not closed: a ( or \" lacks its closing ) or \"")
    (simple-condition
     (handler-case (apply #'format nil (simple-condition-format-control condition)
                          (simple-condition-format-arguments condition))
       (error () (type-of condition))))
    (t (let ((message (princ-to-string condition)))
         (subseq message 0 (position #\Newline message))))))

(defun token-start (text start position)
  "The start of the token at or before POSITION in TEXT (not before START): where
the Lisp reader's complaint about the token it just read should point."
  (let ((p (max start (min position (1- (length text))))))
    (loop while (and (> p start) (blank-char-p (char text p))) do (decf p))
    (loop while (and (> p start) (not (separator-char-p (char text (1- p))))) do (decf p))
    p))

(defun read-span (reading readtable file span)
  "The form in SPAN of READING's text, read with READTABLE, or a SCENARIO-READ-ERROR
condition object (not signalled) saying why it cannot be read."
  (let* ((text (reading-text reading))
         (start (span-start span))
         (stream (make-string-input-stream text start (span-end span))))
    (setf (reading-offset reading) start
          (reading-depth reading) 0)
    (if (span-problem span)
        (span-read-error text file (span-problem-position span) (span-problem span))
        (handler-case
            (with-standard-io-syntax
              (let ((*readtable* readtable)
                    (*package* (find-package '#:ames-scenario))
                    (*read-eval* nil)
                    (*read-default-float-format* 'double-float))
                (let ((form (read stream t nil nil)))
                  (if (eq (read stream nil stream nil) stream)
                      form
                      (span-read-error text file start
                                       "more than one form where one was expected")))))
          (forbidden-syntax (condition)
            (span-read-error text file (or (forbidden-syntax-position condition)
                                           (reading-position reading stream))
                             (reader-error-detail condition)))
          (stream-error (condition)
            (span-read-error text file
                             (if (typep condition 'end-of-file)
                                 start
                                 (token-start text start (1- (reading-position reading stream))))
                             (reader-error-detail condition)))))))

(defun read-scenario-items (text file)
  "Each top-level form of TEXT as (:FORM FORM SOURCE) or (:ERROR CONDITION), in order."
  (let* ((reading (make-reading text))
         (readtable (make-scenario-readtable reading)))
    (loop for span in (top-level-spans text)
          collect (let ((form (read-span reading readtable file span)))
                    (if (typep form 'scenario-read-error)
                        (list :error form)
                        (list :form form
                              (format nil "~@[~A, ~]line ~D" file
                                      (line-and-column text (span-start span)))))))))

(defun call-with-skip-restart (on-error thunk)
  "Call THUNK with the restart SKIP-SCENARIO active. Returns THUNK's value, or, when
a SCENARIO-ERROR made someone invoke SKIP-SCENARIO, (values NIL CONDITION). ON-ERROR
:SIGNAL lets the condition go on to the caller's handlers (or the debugger); :COLLECT
invokes SKIP-SCENARIO at once."
  (check-type on-error (member :signal :collect))
  (let ((condition nil))
    (restart-case
        (handler-bind ((scenario-error
                         (lambda (c)
                           (setf condition c)
                           (when (eq on-error :collect) (skip-scenario c)))))
          (values (funcall thunk) nil))
      (skip-scenario ()
        :report "Skip this scenario and go on with the next one."
        (values nil condition)))))

(defun call-per-scenario (items on-error function)
  "Call FUNCTION on the form and source of each (:FORM FORM SOURCE) of ITEMS and
collect its values; signal the condition of each (:ERROR CONDITION). Each runs under
CALL-WITH-SKIP-RESTART with ON-ERROR. Returns (values RESULTS CONDITIONS)."
  (let ((results '()) (conditions '()))
    (dolist (item items)
      (multiple-value-bind (result condition)
          (call-with-skip-restart on-error
                                  (lambda ()
                                    (ecase (first item)
                                      (:error (error (second item)))
                                      (:form (funcall function (second item) (third item))))))
        (if condition
            (push condition conditions)
            (push result results))))
    (values (nreverse results) (nreverse conditions))))

(defun check-text-size (text file)
  "Signal SCENARIO-READ-ERROR when TEXT is longer than +LARGEST-FILE+."
  (when (> (length text) +largest-file+)
    (error (span-read-error "" file 0
                            (format nil "the text is longer than ~D characters"
                                    +largest-file+)))))

(defun read-scenario-forms (string &key file (on-error :signal))
  "The top-level forms of STRING, read as data by the restricted reader (see this
file's header), without validating them. FILE names the source in messages.
Returns (values FORMS CONDITIONS). Each form that cannot be read signals a
SCENARIO-READ-ERROR with the restart SKIP-SCENARIO; with ON-ERROR :COLLECT they are
skipped at once and returned as CONDITIONS."
  (check-text-size string file)
  (call-per-scenario (read-scenario-items string file) on-error
                     (lambda (form source) (declare (ignore source)) form)))

(defun read-scenarios-from-string (string &key file (on-error :signal))
  "The SCENARIOs of STRING, each read by the restricted reader and validated by
PARSE-SCENARIO. FILE names the source in messages. Returns (values SCENARIOS
CONDITIONS). Each scenario that cannot be read or is invalid signals its
SCENARIO-ERROR with the restart SKIP-SCENARIO active (invoke it with the function
SKIP-SCENARIO to go on with the next); with ON-ERROR :COLLECT, bad scenarios are
skipped at once and their conditions returned as CONDITIONS."
  (check-text-size string file)
  (call-per-scenario (read-scenario-items string file) on-error
                     (lambda (form source) (parse-scenario form :source source))))

(defun file-text (pathname)
  "The text of the file PATHNAME, decoded as UTF-8. Signals SCENARIO-FILE-ERROR when
it cannot be opened or decoded, or is longer than +LARGEST-FILE+ characters."
  (let ((name (enough-namestring pathname)))
    (flet ((fail (detail)
             (error 'scenario-file-error :file name :datum name :detail detail
                                         :source name)))
      (handler-case
          (with-open-file (stream pathname :external-format :utf-8 :element-type 'character)
            (when (> (file-length stream) (* 4 +largest-file+))
              (fail (format nil "the file is longer than ~D characters" +largest-file+)))
            (let* ((buffer (make-string (file-length stream)))
                   (end (read-sequence buffer stream)))
              (subseq buffer 0 end)))
        (file-error (condition)
          (fail (format nil "cannot open the file: ~A" (reader-error-detail condition))))
        (stream-error (condition)
          (fail (format nil "the file is not UTF-8 text: ~A"
                        (reader-error-detail condition))))))))

(defun read-scenario-file (pathname &key (on-error :signal))
  "The SCENARIOs of the scenario file PATHNAME, read as data (never loaded) and
validated, as READ-SCENARIOS-FROM-STRING does. Returns (values SCENARIOS CONDITIONS).
A file that cannot be read signals SCENARIO-FILE-ERROR (with SKIP-SCENARIO active;
with ON-ERROR :COLLECT it is returned among CONDITIONS)."
  (multiple-value-bind (text condition)
      (call-with-skip-restart on-error (lambda () (file-text pathname)))
    (if condition
        (values '() (list condition))
        (read-scenarios-from-string text :file (enough-namestring pathname)
                                         :on-error on-error))))
