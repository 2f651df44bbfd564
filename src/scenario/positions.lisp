;;;; src/scenario/positions.lisp -- where things are in a scenario text: bytes decoded, lines and columns, the position of every form read.
;;;;
;;;; A SOURCE-TEXT is a scenario text with what the messages need to point into it: its
;;;; file, where each line starts, where bytes that were not UTF-8 stood (each decoded as
;;;; U+FFFD, so that one bad byte spoils only the scenario that holds it), and, filled by
;;;; the reader, the position of every list it read (its open parenthesis) and of every
;;;; element of a list (by the cons cell that holds it). The validator asks FORM-POSITION
;;;; for the datum at fault, so that its message names the line of the clause, or of the
;;;; very atom, rather than the scenario's first line; a run asks it for the clause of a
;;;; body. Forms typed at the REPL have no SOURCE-TEXT: their messages name no line.

(in-package #:ames.scenario)

(defstruct (source-text (:constructor %make-source-text (text file line-starts bad-bytes)))
  "A scenario TEXT, the FILE it came from (a string, or NIL), the positions where its
lines start (a vector), the positions of the bytes that were not UTF-8 (a vector of
(POSITION . BYTE), ascending), and the positions of the forms read from it."
  (text "" :type string)
  (file nil)
  (line-starts #() :type vector)
  (bad-bytes #() :type vector)
  (lists (make-hash-table :test 'eq))
  (elements (make-hash-table :test 'eq)))

(defun make-source-text (text &key file bad-bytes)
  "A SOURCE-TEXT for the string TEXT from FILE (a string or NIL). BAD-BYTES is a list
of (POSITION . BYTE) for bytes that were not UTF-8, as DECODE-UTF-8 returns them."
  (let ((starts (make-array 64 :adjustable t :fill-pointer 0)))
    (vector-push-extend 0 starts)
    (loop for i from 0 below (length text)
          when (char= (char text i) #\Newline)
            do (vector-push-extend (1+ i) starts))
    (%make-source-text text file starts (coerce bad-bytes 'vector))))

(defun text-line-and-column (source position)
  "The 1-based line and 0-based column of POSITION in SOURCE's text (binary search)."
  (let* ((starts (source-text-line-starts source))
         (position (max 0 (min position (length (source-text-text source)))))
         (low 0) (high (length starts)))
    ;; the last line start <= POSITION
    (loop while (> (- high low) 1)
          do (let ((middle (floor (+ low high) 2)))
               (if (<= (aref starts middle) position) (setf low middle) (setf high middle))))
    (values (1+ low) (- position (aref starts low)))))

;;; ------------------------------------------------------------------------------------
;;; Decoding bytes

(defun decode-utf-8 (octets &key (start 0) (end (length octets)))
  "The string that the OCTETS (unsigned bytes) from START to END encode in UTF-8, and a
list of (POSITION . BYTE), ascending, for each byte that is not part of a well-formed
UTF-8 sequence (overlong forms, surrogates and code points above #x10FFFF included);
each such byte becomes the character U+FFFD at POSITION in the string. A byte order
mark at START is skipped."
  (let ((string (make-array (- end start) :element-type 'character :fill-pointer 0))
        (bad '())
        (i start))
    (when (and (<= (+ i 3) end) (= (aref octets i) #xEF) (= (aref octets (+ i 1)) #xBB)
               (= (aref octets (+ i 2)) #xBF))
      (incf i 3))
    (flet ((continuation-p (k) (and (< k end) (= (logand (aref octets k) #xC0) #x80))))
      (loop while (< i end)
            do (let* ((b (aref octets i))
                      (length (cond ((< b #x80) 1) ((<= #xC2 b #xDF) 2) ((<= #xE0 b #xEF) 3)
                                    ((<= #xF0 b #xF4) 4) (t 0)))
                      (code (and (plusp length)
                                 (loop for k from (1+ i) below (+ i length)
                                       always (continuation-p k))
                                 (let ((c (if (= length 1) b (logand b (ash #x7F (- length))))))
                                   (loop for k from (1+ i) below (+ i length)
                                         do (setf c (logior (ash c 6) (logand (aref octets k) #x3F))))
                                   c))))
                 (if (and code
                          (>= code (aref #(0 0 #x80 #x800 #x10000) length)) ; not overlong
                          (not (<= #xD800 code #xDFFF))
                          (<= code #x10FFFF))
                     (progn (vector-push (code-char code) string) (incf i length))
                     (progn (push (cons (fill-pointer string) b) bad)
                            (vector-push (code-char #xFFFD) string)
                            (incf i))))))
    (values (coerce string 'simple-string) (nreverse bad))))

;;; ------------------------------------------------------------------------------------
;;; Where the forms read from a text are

(defun note-list-position (source list position)
  "Record that LIST (a cons) was read from the ( at POSITION of SOURCE."
  (when (consp list)
    (setf (gethash list (source-text-lists source)) position)))

(defun note-element-position (source cell position)
  "Record that the element in the car of the cons CELL was read at POSITION of SOURCE."
  (setf (gethash cell (source-text-elements source)) position))

(defconstant +largest-position-search+ 100000
  "FORM-POSITION looks at no more than this many conses of the form it searches.")

(defun form-position (source object &optional within)
  "The position in SOURCE's text where OBJECT was read: a list by its open parenthesis;
any object (an atom too) by its first occurrence as an element of a list in the tree
WITHIN (searched depth first, up to +LARGEST-POSITION-SEARCH+ conses). NIL when unknown."
  (when source
    (or (and (consp object) (gethash object (source-text-lists source)))
        (let ((elements (source-text-elements source)) (budget +largest-position-search+))
          (labels ((search-in (tree)
                     (loop while (and (consp tree) (plusp (decf budget)))
                           do (when (eql (car tree) object)
                                (let ((position (gethash tree elements)))
                                  (when position (return-from form-position position))))
                              (search-in (car tree))
                              (setf tree (cdr tree)))))
            (search-in within)
            nil)))))

(defun form-line (source object &optional within)
  "The 1-based line of SOURCE where OBJECT was read (see FORM-POSITION), or NIL."
  (let ((position (form-position source object within)))
    (and position (values (text-line-and-column source position)))))

(defun source-description (source line)
  "\"FILE, line LINE\" (or \"line LINE\" without a file) for messages."
  (format nil "~@[~A, ~]line ~D" (source-text-file source) line))
