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
;;;; top-level forms by a scanner that knows strings, comments and escapes (spans.lisp),
;;;; and each is read and validated on its own, so that one bad scenario, even one that
;;;; does not read or is never closed, does not stop the others. Each failure is
;;;; signalled as a SCENARIO-ERROR with the restart SKIP-SCENARIO active; with :ON-ERROR
;;;; :COLLECT the readers skip on their own and return the conditions as a second value.
;;;;
;;;; A file's bytes are decoded as UTF-8 with each bad byte standing for U+FFFD
;;;; (positions.lisp): only the scenario that holds one outside a comment fails, with a
;;;; SCENARIO-FILE-ERROR naming its line and column. The reader notes where it read every
;;;; list and element (a SOURCE-TEXT), so that the validator's messages name the line of
;;;; the clause at fault.

(in-package #:ames.scenario)


(define-condition forbidden-syntax (reader-error)
  ((detail :initarg :detail :reader forbidden-syntax-detail)
   (position :initarg :position :initform nil :reader forbidden-syntax-position))
  (:documentation "Internal: signalled by the restricted readtable's macro characters
on syntax the scenario language does not have; turned into a SCENARIO-READ-ERROR.")
  (:report (lambda (condition stream)
             (write-string (forbidden-syntax-detail condition) stream))))

;;; ------------------------------------------------------------------------------------
;;; The restricted readtable

(defstruct (reading (:constructor make-reading (source)))
  "The state of the restricted reader over one SOURCE-TEXT: the span being read (its
start in the text) and the current list depth."
  source (offset 0) (depth 0))

(defun reading-text (reading)
  "The text READING reads."
  (source-text-text (reading-source reading)))

(defun forbid (stream position control &rest arguments)
  "Signal FORBIDDEN-SYNTAX on STREAM at the text POSITION."
  (error 'forbidden-syntax :stream stream :position position
                           :detail (apply #'format nil control arguments)))

(defun reading-position (reading stream)
  "The index in READING's text of STREAM's next character."
  (+ (reading-offset reading) (file-position stream)))

(defun read-scenario-list (reading stream)
  "The ( macro: a list, at most +DEEPEST-LIST+ deep, with no consing dot. The position
of the list and of each of its elements is noted in READING's SOURCE-TEXT."
  (let ((open (1- (reading-position reading stream))))
    (when (> (incf (reading-depth reading)) +deepest-list+)
      (forbid stream open "lists are nested more than ~D deep" +deepest-list+))
    (unwind-protect
         (let ((items '()) (positions '()))
           (loop (let ((c (peek-char t stream t nil t)))
                   (when (char= c #\)) (read-char stream) (return))
                   (let* ((at (reading-position reading stream))
                          (macro (get-macro-character c))
                          ;; a macro character at the start of an element is called as
                          ;; READ would call it; a comment gives no value
                          (values (if macro
                                      (progn (read-char stream)
                                             (multiple-value-list (funcall macro stream c)))
                                      (list (read stream t nil t)))))
                     (when values
                       (push (first values) items)
                       (push at positions)))))
           (let ((list (nreverse items)) (source (reading-source reading)))
             (loop for cell on list
                   for at in (nreverse positions)
                   do (note-element-position source cell at))
             (note-list-position source list open)
             list))
      (decf (reading-depth reading)))))

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

(defun text-excerpt (text start)
  "Up to 40 characters of TEXT from START to the end of its line, for a condition's
datum."
  (let* ((start (max 0 (min start (length text))))
         (end (min (length text) (+ start 40)
                   (or (position #\Newline text :start start) (length text))))
         (excerpt (subseq text start end)))
    (cond ((string/= excerpt "") excerpt)
          ((< start (length text)) "end of line")
          (t "end of text"))))

(defun span-read-error (source position detail &optional (class 'scenario-read-error))
  "A SCENARIO-READ-ERROR of CLASS (not yet signalled) at POSITION of SOURCE's text."
  (multiple-value-bind (line column) (text-line-and-column source position)
    (let ((file (source-text-file source)))
      (make-condition class :file file :line line :column column :position position
                            :source (source-description source line)
                            :datum (text-excerpt (source-text-text source) position)
                            :detail detail))))

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

(defun read-span (reading readtable span)
  "The form in SPAN of READING's text, read with READTABLE, or a SCENARIO-READ-ERROR
condition object (not signalled) saying why it cannot be read."
  (let* ((source (reading-source reading))
         (text (source-text-text source))
         (start (span-start span))
         (stream (make-string-input-stream text start (span-end span))))
    (setf (reading-offset reading) start
          (reading-depth reading) 0)
    (if (span-problem span)
        (span-read-error source (span-problem-position span) (span-problem span)
                         (span-problem-class span))
        (handler-case
            (with-standard-io-syntax
              (let ((*readtable* readtable)
                    (*package* (find-package '#:ames-scenario))
                    (*read-eval* nil)
                    (*read-default-float-format* 'double-float))
                (let ((form (read stream t nil nil)))
                  (if (eq (read stream nil stream nil) stream)
                      form
                      (span-read-error source start
                                       "more than one form where one was expected")))))
          (forbidden-syntax (condition)
            (span-read-error source (or (forbidden-syntax-position condition)
                                        (reading-position reading stream))
                             (reader-error-detail condition)))
          (stream-error (condition)
            (span-read-error source
                             (if (typep condition 'end-of-file)
                                 start
                                 (token-start text start (1- (reading-position reading stream))))
                             (reader-error-detail condition)))))))

(defun read-scenario-items (source)
  "Each top-level form of the SOURCE-TEXT SOURCE as (:FORM FORM DESCRIPTION) or
(:ERROR CONDITION), in order; DESCRIPTION is \"FILE, line N\" of the form's start."
  (let* ((reading (make-reading source))
         (readtable (make-scenario-readtable reading)))
    (loop for span in (top-level-spans (source-text-text source) source)
          collect (let ((form (read-span reading readtable span)))
                    (if (typep form 'scenario-read-error)
                        (list :error form)
                        (list :form form
                              (source-description
                               source (text-line-and-column source (span-start span)))))))))

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

(defun check-text-size (source)
  "Signal SCENARIO-READ-ERROR when the text of SOURCE is longer than +LARGEST-FILE+."
  (when (> (length (source-text-text source)) +largest-file+)
    (error (span-read-error (make-source-text "" :file (source-text-file source)) 0
                            (format nil "the text is longer than ~D characters"
                                    +largest-file+)))))

(defun read-scenario-forms (string &key file (on-error :signal))
  "The top-level forms of STRING, read as data by the restricted reader (see this
file's header), without validating them. FILE names the source in messages.
Returns (values FORMS CONDITIONS). Each form that cannot be read signals a
SCENARIO-READ-ERROR with the restart SKIP-SCENARIO; with ON-ERROR :COLLECT they are
skipped at once and returned as CONDITIONS."
  (let ((source (make-source-text string :file file)))
    (check-text-size source)
    (call-per-scenario (read-scenario-items source) on-error
                       (lambda (form description) (declare (ignore description)) form))))

(defun read-scenarios-from-source (source on-error)
  "The SCENARIOs of the SOURCE-TEXT SOURCE, as READ-SCENARIOS-FROM-STRING returns them."
  (check-text-size source)
  (call-per-scenario (read-scenario-items source) on-error
                     (lambda (form description)
                       (parse-scenario form :source description :positions source))))

(defun read-scenarios-from-string (string &key file (on-error :signal))
  "The SCENARIOs of STRING, each read by the restricted reader and validated by
PARSE-SCENARIO. FILE names the source in messages. Returns (values SCENARIOS
CONDITIONS). Each scenario that cannot be read or is invalid signals its
SCENARIO-ERROR with the restart SKIP-SCENARIO active (invoke it with the function
SKIP-SCENARIO to go on with the next); with ON-ERROR :COLLECT, bad scenarios are
skipped at once and their conditions returned as CONDITIONS. Messages name the line
(and for reading faults the column) of the fault."
  (read-scenarios-from-source (make-source-text string :file file) on-error))

(defun file-source (pathname)
  "The SOURCE-TEXT of the file PATHNAME (\"-\": the standard input; a pipe or a device
too, see READ-INPUT-OCTETS): its bytes decoded as UTF-8, each byte that is not UTF-8
noted (see DECODE-UTF-8). Signals SCENARIO-FILE-ERROR when the file cannot be opened or
read, holds more bytes than 4 * +LARGEST-FILE+, holds nothing, or gives nothing within
the time left in the running budget."
  (let ((name (if (standard-input-name-p pathname) "standard input" (enough-namestring pathname))))
    (flet ((fail (detail)
             (error 'scenario-file-error :file name :datum name :detail detail
                                         :source name)))
      (let ((octets (handler-case (read-input-octets pathname)
                      (input-failure (condition) (fail (input-failure-detail condition))))))
        (when (every (lambda (octet) (member octet '(9 10 13 32))) octets)
          (fail (if (zerop (length octets)) "the input is empty" "the input holds only blanks")))
        (multiple-value-bind (text bad-bytes) (decode-utf-8 octets)
          (make-source-text text :file name :bad-bytes bad-bytes))))))

(defun read-scenario-file (pathname &key (on-error :signal))
  "The SCENARIOs of the scenario file PATHNAME, read as data (never loaded) and
validated, as READ-SCENARIOS-FROM-STRING does. Returns (values SCENARIOS CONDITIONS).
A byte that is not UTF-8 spoils only the scenario that holds it (outside a comment),
with a SCENARIO-FILE-ERROR. A file that cannot be read, or holds no scenario (empty,
blank, only comments), signals SCENARIO-FILE-ERROR
(with SKIP-SCENARIO active; with ON-ERROR :COLLECT it is returned among CONDITIONS)."
  (multiple-value-bind (source condition)
      (call-with-skip-restart on-error (lambda () (file-source pathname)))
    (if condition
        (values '() (list condition))
        (multiple-value-bind (scenarios conditions) (read-scenarios-from-source source on-error)
          (if (or scenarios conditions)
              (values scenarios conditions)
              ;; only comments: a file of no scenario is a mistake, as an empty one is
              (multiple-value-bind (nothing condition)
                  (call-with-skip-restart
                   on-error
                   (lambda ()
                     (error 'scenario-file-error
                            :file (source-text-file source) :datum (source-text-file source)
                            :source (source-text-file source)
                            :detail "the file holds no scenario, only comments")))
                (declare (ignore nothing))
                (values '() (list condition))))))))
