;;;; t/api.lisp -- AMES's public API (src/interface/api.lisp): one export list, every export documented.

(in-package #:ames.tests)

(def-suite api :in all-tests
  :description "The package AMES: its exports listed once, in api.lisp, each documented.")

(in-suite api)

(defun api-file-exports ()
  "The symbols of every DEFINE-API section of src/interface/api.lisp, in order, read as
data (*READ-EVAL* NIL) in the package AMES."
  (let ((path (asdf:system-relative-pathname "ames" "src/interface/api.lisp")))
    (with-open-file (stream path)
      (with-standard-io-syntax
        (let ((*package* (find-package '#:ames))
              (*read-eval* nil))
          (loop for form = (read stream nil stream)
                until (eq form stream)
                when (and (consp form) (symbolp (first form))
                          (string= (symbol-name (first form)) "DEFINE-API"))
                  append (rest form)))))))

(defun symbol-documentation-missing (symbol)
  "The kinds of definition SYMBOL names without a docstring: :FUNCTION (a function or
macro), :TYPE (a class or condition), :VARIABLE (a special variable or constant)."
  (append (and (fboundp symbol) (null (documentation symbol 'function)) (list :function))
          (and (find-class symbol nil) (null (documentation symbol 'type)) (list :type))
          (and (boundp symbol) (null (documentation symbol 'variable)) (list :variable))))

(test the-export-list-lives-in-api-lisp
  "Every symbol AMES exports is listed in api.lisp, once, and nothing else is exported."
  (let* ((listed (api-file-exports))
         (external (let ((symbols '()))
                     (do-external-symbols (symbol '#:ames symbols) (push symbol symbols)))))
    (is (< 100 (length listed)))
    (is (null (loop for (symbol . later) on listed when (member symbol later) collect symbol))
        "listed twice in api.lisp")
    (is (null (set-difference external listed)) "exported but not listed in api.lisp")
    (is (null (set-difference listed external)) "listed in api.lisp but not exported")))

(test every-export-is-documented
  "Every external symbol of AMES that names a function, macro, class, condition or
variable has a docstring for it."
  (let ((missing '()))
    (do-external-symbols (symbol '#:ames)
      (let ((kinds (symbol-documentation-missing symbol)))
        (when kinds (push (cons symbol kinds) missing))))
    (is (null missing) "undocumented exports of AMES: ~S" missing)))

(test every-export-names-something
  "Every external symbol of AMES is defined: a function, macro, class, condition,
variable or constant (no stale name in the export list)."
  (let ((undefined '()))
    (do-external-symbols (symbol '#:ames)
      (unless (or (fboundp symbol) (find-class symbol nil) (boundp symbol))
        (push symbol undefined)))
    (is (null undefined) "exported names of nothing: ~S" undefined)))
