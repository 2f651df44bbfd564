;;;; src/report/escaping.lisp -- no control character of a user's text reaches an output raw.
;;;;
;;;; Names and descriptions come from the user; the reader lets a |symbol| or a string hold
;;;; any character. A control character (ESC, BEL, a carriage return) would drive the
;;;; terminal from the text report, make JSON invalid and SVG (XML 1.0) ill-formed, and
;;;; a line break would end a LaTeX comment early. So every format writes them visibly, in
;;;; caret notation (ESC as ^[, BEL as ^G, DEL as ^?, a C1 control as <U+0085>), each
;;;; format keeping the line breaks it can carry (see VISIBLE-TEXT's callers), and JSON as
;;;; \uXXXX escapes (JSON-CONTROL-ESCAPES).

(in-package #:ames.report)

(defun control-character-p (char)
  "True when CHAR is a C0 or C1 control character or DEL."
  (let ((code (char-code char)))
    (or (< code 32) (<= 127 code 159))))

(defun visible-text (text &key (keep '()))
  "TEXT with every control character but those in KEEP (a list of characters) written
visibly: a C0 control or DEL in caret notation (^[ for ESC), a C1 control as <U+XXXX>.
TEXT itself when it has none."
  (if (notany (lambda (c) (and (control-character-p c) (not (member c keep)))) text)
      text
      (with-output-to-string (out)
        (loop for c across text
              for code = (char-code c)
              do (cond ((or (not (control-character-p c)) (member c keep)) (write-char c out))
                       ((< code 32) (write-char #\^ out) (write-char (code-char (+ code 64)) out))
                       ((= code 127) (write-string "^?" out))
                       (t (format out "<U+~4,'0X>" code)))))))

(defun json-control-escapes (json)
  "The JSON text JSON with every raw control character (which can only stand inside its
strings) written as a \\uXXXX escape, as JSON requires."
  (if (notany #'control-character-p json)
      json
      (with-output-to-string (out)
        (loop for c across json
              do (if (control-character-p c)
                     (format out "\\u~4,'0X" (char-code c))
                     (write-char c out))))))
