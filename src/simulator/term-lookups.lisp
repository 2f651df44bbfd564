;;;; src/simulator/term-lookups.lisp -- terms looked up in tables, not searched for in lists.
;;;;
;;;; A state of N bodies has 4 N state terms and solves for thousands of quantities:
;;;; walking an expression once per state term (FREE-OF-P), or searching an alist of every
;;;; value at each node (SUBSTITUTE-EXPRESSIONS over all of them), costs N^2. These read an
;;;; expression's own terms once (EXPRESSION-VARIABLES: a quantity term occurs where
;;;; FREE-OF-P finds it exactly when it is among them) and look them up in a table. The
;;;; results are the same as the list searches'.

(in-package #:ames.simulator)

(defun state-terms-table (solved)
  "An EQUAL hash table of SOLVED's state terms, made once; under the key :EVERY-TERM,
true when each is a quantity term (as it is: positions, velocities, arc lengths...)."
  (or (solved-model-state-table solved)
      (let ((table (make-hash-table :test #'equal)))
        (dolist (state (solved-model-state solved))
          (setf (gethash state table) t))
        (setf (gethash :every-term table) (every #'quantity-term-p (solved-model-state solved)))
        (setf (solved-model-state-table solved) table))))

(defun mentioned-terms (expression)
  "The quantity terms of EXPRESSION (of its EXPRESSION-VARIABLES): a quantity term occurs
in EXPRESSION (as FREE-OF-P looks for it) exactly when it is among them."
  (remove-if-not #'consp (expression-variables expression)))

(defun mentioned-p (term mentioned expression)
  "True when TERM occurs in EXPRESSION, whose MENTIONED-TERMS are MENTIONED (a quantity
term is looked up there; anything else is looked for by FREE-OF-P)."
  (if (quantity-term-p term)
      (and (member term mentioned :test #'equal) t)
      (not (free-of-p term expression))))

(defun bindings-table (bindings)
  "The alist BINDINGS as an EQUAL hash table key -> value, the first entry of a key
winning as in ASSOC."
  (let ((table (make-hash-table :test #'equal)))
    (loop for (key . value) in bindings
          unless (nth-value 1 (gethash key table))
            do (setf (gethash key table) value))
    table))

(defun substitute-from-table (table expression)
  "SUBSTITUTE-EXPRESSIONS of EXPRESSION by the bindings TABLE holds (see BINDINGS-TABLE):
only EXPRESSION's own variables and terms are looked up (the same result as the whole
alist, without a list search per node)."
  (substitute-expressions (loop for term in (expression-variables expression)
                                for (value found) = (multiple-value-list (gethash term table))
                                when found collect (cons term value))
                          expression))
