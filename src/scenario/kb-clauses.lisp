;;;; src/scenario/kb-clauses.lisp -- clauses that the knowledge base reads as entities of its
;;;; own (the phenomena added by new files: see src/scenario/drag.lisp).
;;;;
;;;; A phenomenon added to the language registers its clause word here with a checker and
;;;; a facts function (DEFINE-KB-CLAUSE). The checker turns a clause into plain data,
;;;; (KIND NAME :KEY VALUE ...) with KIND a keyword, over the user's checked symbols and
;;;; expressions; the validated scenario keeps that data in its extensions under
;;;; :KB-CLAUSES (SCENARIO-KB-CLAUSES), and the knowledge base makes its entities of it
;;;; (ames.kb:CLAUSE-ENTITY). The facts function gives the physical ranges of the clause's
;;;; coefficients, in the form of COEFFICIENT-FACTS (src/scenario/ranges.lisp). Nothing
;;;; outside the phenomenon's own files names its clause.

(in-package #:ames.scenario)

(defvar *kb-clauses* '()
  "Alist clause word (a symbol of AMES-SCENARIO) -> plist (:CHECKER F :FACTS G): F of
(VALIDATION CLAUSE BODIES) returns the clause's data (KIND NAME . PLIST); G of (DATA)
returns its coefficient facts ((LOCATION RELATION WHAT CLASS . OPTIONS) ...).")

(defmacro define-kb-clause (word &key checker facts)
  "Register the clause WORD (a symbol of AMES-SCENARIO, also listed in +CLAUSE-WORDS+)
as one the knowledge base reads: CHECKER and FACTS are function designators (see
*KB-CLAUSES*)."
  `(setf *kb-clauses*
         (cons (list ',word :checker ,checker :facts ,facts)
               (remove ',word *kb-clauses* :key #'first))))

(defun checked-kb-clauses (validation sorted bodies)
  "The data of every registered knowledge-base clause among the SORTED clauses (an alist
WORD -> clauses), in the order of the registrations and of the clauses."
  (loop for (word . entry) in (reverse *kb-clauses*)
        append (mapcar (lambda (clause) (funcall (getf entry :checker) validation clause bodies))
                       (cdr (assoc word sorted)))))

(defun scenario-kb-clauses (scenario)
  "The data (KIND NAME :KEY VALUE ...) of SCENARIO's knowledge-base clauses."
  (scenario-extension scenario :kb-clauses))

(defun kb-clause-facts (scenario)
  "The coefficient facts of SCENARIO's knowledge-base clauses (see COEFFICIENT-FACTS):
each clause's data handed to the facts function its clause word registered (the data's
KIND is named like the word)."
  (loop for data in (scenario-kb-clauses scenario)
        for entry = (find (symbol-name (first data)) *kb-clauses*
                          :key (lambda (e) (symbol-name (first e))) :test #'string=)
        when (and entry (getf (rest entry) :facts))
          append (funcall (getf (rest entry) :facts) data)))
