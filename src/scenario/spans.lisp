;;;; src/scenario/spans.lisp -- splitting a scenario text into its top-level forms, and recovering after a fault.
;;;;
;;;; Before anything is read, a scanner that knows lists, strings, |escaped| names, \
;;;; escapes and comments (; and nestable #| |#) splits the text into SPANs, one per
;;;; top-level form, so that each scenario is read and validated on its own. The scanner
;;;; never fails; what it already knows to be wrong becomes the span's PROBLEM, at the
;;;; position of the fault:
;;;;   - a ( that is not closed (the innermost one open), a string or a #| comment that is
;;;;     not closed (its first character);
;;;;   - a byte that was not UTF-8, outside a comment (a bad byte in a comment is harmless);
;;;;   - a token longer than +LONGEST-TOKEN+, lists nested deeper than +DEEPEST-LIST+.
;;;; Recovery: a line whose first non-blank characters are "(scenario" followed by a
;;;; separator starts a scenario. A form (or string, or |name|) still open when the scan
;;;; reaches such a line is cut there, as not closed, and the next span starts on that line,
;;;; so that a missing ) or " spoils one scenario only. (A closed #| |# comment may hold
;;;; such lines: commenting out a scenario is fine. A string that holds one is taken as
;;;; not closed.)

(in-package #:ames.scenario)

(defconstant +longest-token+ 4096
  "The longest symbol or number token the reader accepts, in characters.")

(defconstant +deepest-list+ 100
  "The deepest nesting of lists the reader accepts.")

(defstruct (span (:constructor make-span (start end &optional problem-position problem
                                                  (problem-class 'scenario-read-error))))
  "A top-level form's text: [START, END) in the text; PROBLEM, a string, when the
scanner already knows the form cannot be read (at PROBLEM-POSITION; the condition to
signal is of PROBLEM-CLASS)."
  start end problem-position problem problem-class)

(defun blank-char-p (char)
  "True for the characters the reader takes as whitespace."
  (member char '(#\Space #\Tab #\Newline #\Return #\Linefeed #\Page)))

(defun separator-char-p (char)
  "True for the characters that end a token (besides the forbidden prefixes)."
  (or (blank-char-p char) (member char '(#\( #\) #\" #\;))))

(defun scenario-line-starts (text)
  "The positions, ascending in a vector, of each ( that begins a line of TEXT (after
blanks) as \"(scenario\" followed by a separator or the end of TEXT."
  (let ((n (length text)) (starts (make-array 8 :adjustable t :fill-pointer 0)))
    (loop with line-start = 0
          while (< line-start n)
          do (let ((i line-start))
               (loop while (and (< i n) (member (char text i) '(#\Space #\Tab #\Page #\Return)))
                     do (incf i))
               (let ((after (+ i (length "(scenario"))))
                 (when (and (<= after n)
                            (string-equal "(scenario" text :start2 i :end2 after)
                            (or (= after n) (separator-char-p (char text after))))
                   (vector-push-extend i starts)))
               (setf line-start (let ((newline (position #\Newline text :start i)))
                                  (if newline (1+ newline) n)))))
    starts))

(defun first-at-or-after (positions x)
  "The first element of the ascending vector POSITIONS that is >= X, or NIL."
  (let ((low 0) (high (length positions)))
    (loop while (< low high)
          do (let ((middle (floor (+ low high) 2)))
               (if (< (aref positions middle) x) (setf low (1+ middle)) (setf high middle))))
    (and (< low (length positions)) (aref positions low))))

(defun note-bad-bytes (spans comments bad-bytes source)
  "Make each byte of BAD-BYTES (a vector of (POSITION . BYTE), ascending) that lies
outside the COMMENTS (a list of (START . END), ascending) the problem of the span of
SPANS (ascending) that holds it, unless that span has an earlier problem. One walk
through the three sequences."
  (loop for (position . byte) across bad-bytes
        do (loop while (and comments (<= (cdr (first comments)) position)) do (pop comments))
           (loop while (and spans (<= (span-end (first spans)) position)) do (pop spans))
           (let ((span (first spans)))
             (unless (or (and comments (<= (car (first comments)) position))
                         (null span) (< position (span-start span))
                         (and (span-problem span) (< (span-problem-position span) position)))
               (multiple-value-bind (line column) (text-line-and-column source position)
                 (setf (span-problem span)
                       (format nil "the byte #x~2,'0X at line ~D, column ~D is not UTF-8 text"
                               byte line column)
                       (span-problem-position span) position
                       (span-problem-class span) 'scenario-file-error))))))

;;; The scanner's state: the text and what the scan has found so far. The functions
;;; below take it as their first argument; TOP-LEVEL-SPANS makes one per text.

(defstruct (span-scanner (:conc-name scanner-)
                         (:constructor make-span-scanner
                             (text source &aux (length (length text))
                                               (resyncs (scenario-line-starts text)))))
  "The state of one scan of TEXT (see this file's header): SOURCE, its SOURCE-TEXT or NIL;
LENGTH, TEXT's; RESYNCS, the positions where a scenario line starts (see
SCENARIO-LINE-STARTS); COMMENTS, the (START . END) of each comment met, latest first;
PROBLEM and PROBLEM-POSITION, the first fault found in the current form, or NIL."
  text source length resyncs (comments '()) (problem nil) (problem-position nil))

(defun scanner-note (scanner position detail)
  "Record DETAIL (a string) at POSITION as the current form's problem, unless it
already has one."
  (unless (scanner-problem scanner)
    (setf (scanner-problem scanner) detail (scanner-problem-position scanner) position)))

(defun scanner-line-of (scanner position)
  "The line number (from 1) of POSITION in the scanned text, from the source when there
is one."
  (let ((source (scanner-source scanner)))
    (if source
        (values (text-line-and-column source position))
        (1+ (count #\Newline (scanner-text scanner) :end position)))))

(defun scanner-char (scanner i)
  "The character at I of the scanned text, or NIL past its end."
  (and (< i (scanner-length scanner)) (char (scanner-text scanner) i)))

(defun block-comment-end (scanner i)
  "I is just after \"#|\"; the index after the matching \"|#\" (they nest), or NIL."
  (flet ((at (i) (scanner-char scanner i)))
    (loop with depth = 1
          while (< i (scanner-length scanner))
          do (cond ((and (eql (at i) #\|) (eql (at (1+ i)) #\#))
                    (incf i 2)
                    (when (zerop (decf depth)) (return i)))
                   ((and (eql (at i) #\#) (eql (at (1+ i)) #\|))
                    (incf i 2) (incf depth))
                   (t (incf i)))
          finally (return nil))))

(defun skip-blank (scanner i)
  "The index past the whitespace and comments from I, recording each comment in the
SCANNER; stops at an unclosed #| comment."
  (let ((text (scanner-text scanner)) (n (scanner-length scanner)))
    (loop
      (let ((c (scanner-char scanner i)))
        (cond ((null c) (return i))
              ((blank-char-p c) (incf i))
              ((eql c #\;)
               (let ((end (or (position #\Newline text :start i) n)))
                 (push (cons i end) (scanner-comments scanner))
                 (setf i end)))
              ((and (eql c #\#) (eql (scanner-char scanner (1+ i)) #\|))
               (let ((end (block-comment-end scanner (+ i 2))))
                 (if end
                     (progn (push (cons i end) (scanner-comments scanner)) (setf i end))
                     (return i))))
              (t (return i)))))))

(defun scan-string (scanner i)
  "I is just after a string's opening quote; the index after the closing one, or NIL
when the string is not closed."
  (loop (let ((c (scanner-char scanner i)))
          (cond ((null c) (return nil))
                ((eql c #\\) (incf i 2))
                ((eql c #\") (return (1+ i)))
                (t (incf i))))))

(defun scan-token (scanner i)
  "The index after the token (symbol or number, with its \\ escapes and |names|) that
starts at I, at most the text's length. A token longer than +LONGEST-TOKEN+ becomes the
form's problem."
  (flet ((at (i) (scanner-char scanner i)))
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
      (setf i (min i (scanner-length scanner)))
      (when (> (- i start) +longest-token+)
        (scanner-note scanner start
                      (format nil "a token longer than ~D characters" +longest-token+)))
      i)))

(defun note-not-closed (scanner position what end limit)
  "Record as the form's problem that WHAT (a phrase), at POSITION, is not closed; it
should have been closed by the last line with text before END. LIMIT is where the scan
of the form stopped: before the text's end, a scenario line."
  (let* ((text (scanner-text scanner)) (n (scanner-length scanner))
         (last (scanner-line-of scanner (or (position-if-not #'blank-char-p text
                                                             :end end :from-end t)
                                            position))))
    (scanner-note scanner position
                  (cond
                    ((< end limit)
                     (format nil "~A is not closed; it should have been closed by ~
                                  the end of line ~D (the lines after it, indented ~
                                  as it is, fall inside it)" what last))
                    ((< limit n)
                      (format nil "~A is not closed before the (scenario of line ~D, ~
                                   where reading goes on; it should have been ~
                                   closed by the end of line ~D"
                              what (scanner-line-of scanner limit) last))
                    (t
                      (format nil "~A is not closed; it should have been closed by ~
                                   the end of line ~D, the last of the text"
                              what last))))))

(defun unclosed-form-cut (scanner start opens limit)
  "For a form from START whose scan reached LIMIT with the lists at OPENS (innermost
first) still open: the position, the phrase and the end for NOTE-NOT-CLOSED, as three
values."
  (let* ((text (scanner-text scanner))
         (suspect (and opens (unclosed-form-position text start limit))))
    (cond (suspect
           ;; the indentation shows which clause lacks its )
           (values suspect "this (" (or (position #\Newline text :start suspect) limit)))
          (opens (values (first opens) "this (" limit))
          (t (values start "the form that starts here" limit)))))

(defun scan-sharp-sign (scanner i)
  "I is at a #. What follows it, as two values: :END (the text ends), :UNCLOSED-COMMENT
(a #| that is never closed), :TOKEN and the index after the #\\ character token, or
:PREFIX and the index where the form it prefixes is scanned on."
  (let ((j (1+ i)))
    (loop while (and (scanner-char scanner j) (digit-char-p (scanner-char scanner j)))
          do (incf j))
    (let ((d (scanner-char scanner j)))
      (cond ((null d) (values :end nil))
            ;; skip-blank stopped here: a #| never closed
            ((eql d #\|) (values :unclosed-comment nil))
            ((eql d #\\) (values :token (scan-token scanner
                                                    (min (scanner-length scanner) (+ j 2)))))
            ((eql d #\() (values :prefix j))
            ;; #. #S #P #+ ...: the next form belongs to it
            (t (values :prefix (1+ j)))))))

(defun scan-form (scanner start)
  "START is at a non-blank character; the index after the form, or where the form is cut
(its fault then the form's problem). Iterative, so that no nesting depth can exhaust the
stack."
  (let* ((n (scanner-length scanner)) (resyncs (scanner-resyncs scanner))
         (depth 0) (opens '()) (i start)
         (limit (or (first-at-or-after resyncs (1+ start)) n)))
    (flet ((cut (position what &optional (end limit))
             (note-not-closed scanner position what end limit)
             (return-from scan-form limit)))
      (loop
        (setf i (skip-blank scanner i))
        (when (> i limit)
          ;; a closed comment held the (scenario line: it does not count
          (setf limit (or (first-at-or-after resyncs i) n)))
        ;; past the start and not done: inside a list, or after a prefix
        (when (and (> i start) (>= i limit))
          (multiple-value-call #'cut (unclosed-form-cut scanner start opens limit)))
        (let ((c (scanner-char scanner i)))
          (flet ((done-if-top (j)
                   (setf i j)
                   (when (zerop depth) (return i))))
            (case c
              ((nil) (return n))
              (#\( (push i opens)
               (when (= (incf depth) (1+ +deepest-list+))
                 (scanner-note scanner i (format nil "lists are nested more than ~D deep"
                                                 +deepest-list+)))
               (incf i))
              (#\) (incf i)
               (when (zerop depth) (return i))
               (pop opens)
               (when (zerop (decf depth)) (return i)))
              ((#\' #\` #\,)
               ;; a prefix: the next form belongs to it
               (setf i (if (and (eql c #\,) (eql (scanner-char scanner (1+ i)) #\@))
                           (+ i 2)
                           (1+ i))))
              (#\" (let ((j (scan-string scanner (1+ i))))
                     (when (or (null j) (> j limit))
                       (cut i "the string that starts here"))
                     (done-if-top j)))
              (#\# (multiple-value-bind (what j) (scan-sharp-sign scanner i)
                     (ecase what
                       (:end (return n))
                       (:unclosed-comment (cut i "the #| comment that starts here"))
                       (:token (done-if-top j))
                       (:prefix (setf i j)))))
              (t (let ((j (scan-token scanner i)))
                   (when (> j limit)
                     (cut i "the | (a name between bars) that starts this token"))
                   (done-if-top j))))))))))

(defun top-level-spans (text &optional source)
  "The SPANs of the top-level forms of TEXT, in order (see this file's header). SOURCE,
the SOURCE-TEXT of TEXT when there is one, gives the lines for messages and the bytes
that were not UTF-8. Signals nothing."
  (let* ((scanner (make-span-scanner text source))
         (n (scanner-length scanner))
         (spans '()))
    (let ((i (skip-blank scanner 0)))
      (loop while (< i n)
            do (setf (scanner-problem scanner) nil (scanner-problem-position scanner) nil)
               (let ((end (max (scan-form scanner i) (1+ i))))
                 (push (make-span i end (scanner-problem-position scanner)
                                  (scanner-problem scanner))
                       spans)
                 (setf i (skip-blank scanner end)))))
    (setf spans (nreverse spans))
    (when (and source (plusp (length (source-text-bad-bytes source))))
      (note-bad-bytes spans (nreverse (scanner-comments scanner))
                      (source-text-bad-bytes source) source))
    spans))
