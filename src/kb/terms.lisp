;;;; src/kb/terms.lisp -- the kinds of terms the knowledge base reports in a state's energy
;;;; and momentum sections, declared with their words: the report and the queries iterate
;;;; what is declared here and name no kind.
;;;;
;;;; A component reports a term as (reported SECTION (KIND SUBJECT VALUE)): SECTION is
;;;; :ENERGY (scalar terms, added into the total energy) or :MOMENTUM (each kind totalled
;;;; on its own); SUBJECT is a body, or a list ending in the body or bodies the term is of,
;;;; such as (:gravity B), (:spring S) or (:rotation B); VALUE an expression, or (X Y) for a
;;;; vector kind. Each KIND is declared once with DEFINE-REPORTED-TERM:
;;;;   (define-reported-term :kinetic :section :energy :label "kinetic K" :symbol "K"
;;;;                         :query :kinetic-energy :shown :always)
;;;; :LABEL is what the report prints before the kind's total, :SYMBOL its letter in the
;;;; total's sum (energy), :VECTOR true for (X Y) values, :QUERY the scenario query
;;;; (QUERY BODY) it answers (the sum of the BODY's terms of the kind: a body's kinetic
;;;; energy adds its translation's (:kinetic B E) and any other of its motions'
;;;; (:kinetic (:rotation B) E)), and :SHOWN :ALWAYS a kind the report lists even where a
;;;; state reports none of it (as 0); other kinds are listed where a state reports one.
;;;; So a new kind of term (angular momentum, say) is one component reporting it and one
;;;; declaration here or beside that component; a new term of a declared kind (rotational
;;;; kinetic energy) needs no declaration at all.

(in-package #:ames.kb)

(defstruct (reported-term (:conc-name term-))
  "A kind of term of a reported section (see the file header)."
  (kind nil :type keyword :read-only t)
  (section nil :type keyword :read-only t)
  (label "" :type string :read-only t)
  (symbol nil :type (or null string) :read-only t)
  (vector nil :read-only t)
  (query nil :read-only t)
  (shown nil :read-only t))

(defvar *reported-terms* '()
  "The declared kinds of reported terms, in the order of their declarations (the order
the report lists them in).")

(defun declare-reported-term (term)
  "Add TERM (a REPORTED-TERM) to *REPORTED-TERMS*, replacing a declaration of the same
kind in its place (so that reloading a file keeps the order). Returns its kind."
  (let ((old (position (term-kind term) *reported-terms* :key #'term-kind)))
    (if old
        (setf (nth old *reported-terms*) term)
        (setf *reported-terms* (append *reported-terms* (list term))))
    (term-kind term)))

(defmacro define-reported-term (kind &key section label symbol vector query shown)
  "Declare KIND, a kind of term the components report in SECTION (:ENERGY or :MOMENTUM),
with the words the report gives it (LABEL, SYMBOL), whether its values are vectors
(VECTOR), the scenario query it answers for one body (QUERY) and whether the report
lists it where no term of it is reported (SHOWN :ALWAYS). See the file header."
  (check-type kind keyword)
  (check-type section (member :energy :momentum))
  (check-type label string)
  (check-type shown (member nil :always))
  `(declare-reported-term (make-reported-term :kind ,kind :section ,section :label ,label
                                              :symbol ,symbol :vector ,vector :query ,query
                                              :shown ,shown)))

(defun reported-terms (section)
  "The declared kinds of terms of SECTION (:ENERGY or :MOMENTUM), in declaration order."
  (remove section *reported-terms* :key #'term-section :test-not #'eq))

(defun query-reported-term (query)
  "The declared kind of term that answers the scenario query QUERY (a keyword such as
:KINETIC-ENERGY) for one body, or NIL."
  (find query *reported-terms* :key #'term-query))

(defun term-entries (term entries)
  "The ENTRIES ((KIND SUBJECT VALUE) ...) of a reported section that are of TERM's kind."
  (remove (term-kind term) entries :key #'first :test-not #'eq))

(defun term-subject-body (subject)
  "The body a term's SUBJECT is of: SUBJECT itself when it is a name, else the last
element of the list, as in (:rotation B)."
  (if (consp subject) (car (last subject)) subject))
