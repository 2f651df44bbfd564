;;;; src/report/json.lisp -- the s-expression report as JSON (through Debian's cl-yason), for tools outside Lisp.
;;;;
;;;; The content is HISTORY-SEXP's, as solved, one JSON document per scenario on one line.
;;;; The mapping is one to one, so that JSON-TO-SEXP gives back the s-expression:
;;;;   a property list (keywords at the even places, each once)  -> an object {"index": 0, ...}
;;;;   any other list                                             -> an array [...]
;;;;   a keyword :forever                                         -> the string ":forever"
;;;;   any other symbol mp, +, pi                                 -> the string "mp", "+", "pi"
;;;;   an integer; a float                                        -> a JSON number (a float with
;;;;                                                                 a decimal point, read back
;;;;                                                                 as a double-float)
;;;;   a ratio 1/2                                                -> {"ratio": [1, 2]}
;;;;   a string                                                   -> {"text": "..."}
;;;;   a dotted list (a b . c)                                    -> {"dotted": [[a, b], c]}
;;;;   T                                                          -> true
;;;; So an expression (/ (* mp g) 2) is ["/", ["*", "mp", "g"], 2].

(in-package #:ames.report)

(define-condition report-error (ames-error) ()
  (:documentation "A report cannot be made or read back: DATUM is the datum at fault.")
  (:report (lambda (condition stream)
             (format stream "~A~@[: ~A~]" (ames-error-detail condition)
                     (let ((datum (ames-error-datum condition)))
                       (and datum (datum-text datum)))))))

(defstruct (json-object (:constructor json-object (&rest pairs)))
  "A JSON object whose members are the alist PAIRS (string . value), kept in order."
  pairs)

(defmethod yason:encode ((object json-object) &optional (stream *standard-output*))
  (yason:encode-alist (json-object-pairs object) stream))

(defun property-list-p (datum)
  "True when DATUM is a non-empty list of keyword-value pairs, each keyword once."
  (and (consp datum) (alexandria:proper-list-p datum) (evenp (length datum))
       (loop for (key) on datum by #'cddr always (keywordp key))
       (let ((keys (loop for (key) on datum by #'cddr collect key)))
         (= (length keys) (length (remove-duplicates keys))))))

(defun sexp-to-json (datum)
  "DATUM (the data of an s-expression report) as the objects yason encodes (see the file
header). Signals REPORT-ERROR for what has no JSON form (a circular list, an object)."
  (cond ((eq datum t) t)
        ((null datum) (vector))
        ((keywordp datum) (format nil ":~(~A~)" (symbol-name datum)))
        ((symbolp datum) (string-downcase (symbol-name datum)))
        ((integerp datum) datum)
        ((rationalp datum) (json-object (cons "ratio" (vector (numerator datum) (denominator datum)))))
        ((floatp datum) (coerce datum 'double-float))
        ((stringp datum) (json-object (cons "text" datum)))
        ((property-list-p datum)
         (apply #'json-object (loop for (key value) on datum by #'cddr
                                    collect (cons (string-downcase (symbol-name key)) (sexp-to-json value)))))
        ((and (consp datum) (alexandria:proper-list-p datum)) (map 'vector #'sexp-to-json datum))
        ((and (consp datum) (not (alexandria:circular-list-p datum)))
         (let ((tail (cdr (last datum))))
           (json-object (cons "dotted" (vector (map 'vector #'sexp-to-json (ldiff datum tail))
                                               (sexp-to-json tail))))))
        (t (error 'report-error :datum datum :detail "This datum has no JSON form"))))

(defun history-json (history)
  "HISTORY-SEXP of HISTORY as one line of JSON text (see the file header)."
  (with-output-to-string (out)
    (write-string (json-control-escapes
                   (with-output-to-string (json)
                     (yason:encode (sexp-to-json (history-sexp history)) json)))
                  out)))

(defun print-history-json (history stream)
  "Print HISTORY as one line of JSON on STREAM (see HISTORY-JSON)."
  (write-string (history-json history) stream)
  (terpri stream))

(defun json-symbol (text packages)
  "The symbol TEXT names: a keyword for \":name\", else the first found in PACKAGES.
Only existing symbols are found (nothing is interned); signals REPORT-ERROR otherwise."
  (if (and (plusp (length text)) (char= (char text 0) #\:))
      (or (find-symbol (string-upcase (subseq text 1)) '#:keyword)
          (error 'report-error :datum text :detail "No such keyword"))
      (or (loop for package in packages
                for symbol = (find-symbol (string-upcase text) package)
                when (or symbol (string-equal text "nil")) return symbol)
          (error 'report-error :datum text :detail "No such symbol"))))

(defun json-to-sexp (text &key (packages '(#:ames-scenario #:ames.simulator)))
  "The s-expression whose JSON form (see the file header) is TEXT, its names looked up
in PACKAGES. Signals REPORT-ERROR when TEXT is no such JSON."
  (labels ((back (x)
             (cond ((eq x t) t)
                   ((null x) nil)
                   ((stringp x) (json-symbol x packages))
                   ((realp x) x)
                   ((vectorp x) (map 'list #'back x))
                   ((and (consp x) (null (rest x)) (equal (car (first x)) "ratio"))
                    (let ((parts (cdr (first x))))
                      (/ (aref parts 0) (aref parts 1))))
                   ((and (consp x) (null (rest x)) (equal (car (first x)) "text"))
                    (cdr (first x)))
                   ((and (consp x) (null (rest x)) (equal (car (first x)) "dotted"))
                    (let ((parts (cdr (first x))))
                      (append (back (aref parts 0)) (back (aref parts 1)))))
                   ((consp x)
                    (loop for (key . value) in x
                          append (list (json-symbol (concatenate 'string ":" key) packages)
                                       (back value))))
                   (t (error 'report-error :datum x :detail "Not the JSON of a report")))))
    (back (handler-case (let ((yason:*parse-json-arrays-as-vectors* t)
                              (yason:*parse-object-as* :alist)
                              (yason:*parse-json-booleans-as-symbols* nil)
                              (*read-default-float-format* 'double-float)
                              (*read-eval* nil))
                          (let ((parsed (yason:parse text)))
                            (labels ((ordered (y)
                                       ;; yason gives an object's members last first
                                       (cond ((stringp y) y)
                                             ((vectorp y) (map 'vector #'ordered y))
                                             ((and (consp y) (consp (first y)))
                                              (reverse (mapcar (lambda (pair) (cons (car pair) (ordered (cdr pair)))) y)))
                                             (t y))))
                              (ordered parsed))))
            (error (condition)
              (error 'report-error :datum (subseq text 0 (min 60 (length text)))
                                   :detail (format nil "Not JSON (~A)" (type-of condition))))))))
