;;;; src/maxima-bridge/weaker-assumptions.lisp -- the scopes whose facts the facts in force
;;;; include: what was proven under them still holds.
;;;;
;;;; A branch of a run (a fork on a fact the assumptions leave open) asks again, under its
;;;; own fact, much of what its parent asked before the fork: the same questions, under
;;;; more facts, so that the cache (keyed by the facts in force, see ASSUMPTION-KEY)
;;;; answers none of them. A relation proven true (or false) under some facts stays so
;;;; under any facts that include them. WEAKER-ASSUMPTION-KEYS names the scopes seen so far
;;;; whose facts are a strict part of the facts in force, so that a caller can take such
;;;; a proof over (DECIDE does: src/algebra/deciding.lisp). Only proofs are taken over:
;;;; an answer that did not decide is asked again, since more facts may decide it.

(in-package #:ames.maxima)

(defvar *assumption-fact-sets* (make-hash-table)
  "Assumption number (see ASSUMPTION-KEY) -> the list of its facts, every frame's Maxima
facts in one list without repetitions.")

(defvar *weaker-keys* (make-hash-table)
  "Assumption number -> (NUMBERS-CHECKED . WEAKER): the numbers below NUMBERS-CHECKED
were compared with it, and WEAKER are those whose facts are a strict part of its own.")

(defun assumption-fact-set (id)
  "The facts of the assumption number ID (see *ASSUMPTION-FACT-SETS*), or NIL when
*ASSUMPTION-IDS* has no such number."
  (or (gethash id *assumption-fact-sets*)
      (progn
        (maphash (lambda (frames number)
                   (unless (gethash number *assumption-fact-sets*)
                     (setf (gethash number *assumption-fact-sets*)
                           (remove-duplicates (apply #'append frames) :test #'equal))))
                 *assumption-ids*)
        (gethash id *assumption-fact-sets*))))

(defun weaker-assumption-keys (bridge)
  "The assumption numbers (see ASSUMPTION-KEY) of the scopes seen so far whose facts are
a strict part of BRIDGE's facts in force: whatever was proven under one of them holds
now. Oldest first."
  (let* ((id (assumption-key bridge))
         (known (hash-table-count *assumption-ids*))
         (entry (or (gethash id *weaker-keys*) (setf (gethash id *weaker-keys*) (cons 0 '())))))
    (when (< (car entry) known)
      (let* ((facts (assumption-fact-set id))
             (table (let ((table (make-hash-table :test #'equal)))
                      (dolist (fact facts table) (setf (gethash fact table) t))))
             (size (length facts)))
        (loop for other from (car entry) below known
              for other-facts = (and (/= other id) (assumption-fact-set other))
              when (and other-facts
                        (< (length other-facts) size)
                        (every (lambda (fact) (gethash fact table)) other-facts))
                do (setf (cdr entry) (append (cdr entry) (list other))))
        (setf (car entry) known)))
    (cdr entry)))

;;; Definite answers of sign() and is() taken over

(defparameter *sign-head* (wire "$SIGN") "The head of a sign() request.")
(defparameter *is-head* (wire "$IS") "The head of an is() request.")

(defun definite-answer-p (form answer)
  "True when ANSWER, Maxima's answer to the request FORM, is one that more facts cannot
change: sign() of pos, neg or zero, is() true or false. Any other request or answer
(pz, pnz, unknown, a simplified form) is NIL: more facts may narrow a sign or make a
simpler form."
  (let ((head (and (consp form) (consp (first form)) (first (first form)))))
    (cond ((eq head *sign-head*)
           (and (symbolp answer) (member (symbol-name answer) '("$POS" "$NEG" "$ZERO")
                                         :test #'string=)
                t))
          ((eq head *is-head*) (or (eq answer +true+) (eq answer +false+)))
          (t nil))))

(defun sign-or-is-request-p (form)
  "True when the Maxima request FORM is a sign() or an is() question."
  (and (consp form) (consp (first form))
       (or (eq (first (first form)) *sign-head*) (eq (first (first form)) *is-head*))))

(defun inherited-answer (bridge form)
  "The answer to the sign() or is() request FORM that BRIDGE's cache holds under facts
that are a strict part of the facts in force (see WEAKER-ASSUMPTION-KEYS), when it is
definite (DEFINITE-ANSWER-P): (values ANSWER T), the answer then also cached under the
facts in force; else (values NIL NIL). Sound as INHERITED-VERDICT is: what sign() or
is() showed from fewer facts holds under more (in a branch, the fork's own questions
asked again under the branch's fact)."
  (when (and (sign-or-is-request-p form) (bridge-frames bridge))
    (let ((cache (bridge-cache bridge)))
      (dolist (id (weaker-assumption-keys bridge) (values nil nil))
        (multiple-value-bind (answer found) (gethash (cons form id) cache)
          (when (and found (definite-answer-p form answer))
            (when (>= (hash-table-count cache) *cache-limit*) (clrhash cache))
            (setf (gethash (cons form (assumption-key bridge)) cache) answer)
            (return (values answer t))))))))

(defun known-answer (bridge form key)
  "(values ANSWER T) when FORM's answer is known without a round trip: cached under KEY,
or a definite sign() or is() answer found under fewer facts (INHERITED-ANSWER);
else (values NIL NIL)."
  (multiple-value-bind (answer found) (gethash key (bridge-cache bridge))
    (if found (values answer t) (inherited-answer bridge form))))
