;;;; src/engine/patterns.lisp -- pattern variables, matching beliefs, and the canonical order.
;;;;
;;;; A belief is a list (HEAD POSITIONAL... [KEY VALUE]...): the elements before the
;;;; first keyword are positional, the rest a property list whose order does not
;;;; matter. A pattern has the same shape, with ?-variables anywhere; it matches a
;;;; belief when the heads and positional parts match element by element (nested
;;;; lists exactly, structurally) and every property the pattern names is present in
;;;; the belief with a matching value. The pattern (force ?f :on ?body) thus matches
;;;; (force (gravity wedge) :type gravity :from earth :on wedge).
;;;; ?_ is the anonymous variable: it matches anything and binds nothing.

(in-package #:ames.engine)

(defun pattern-variable-p (x)
  "True when X is a pattern variable: a non-keyword symbol named ?SOMETHING."
  (and (symbolp x) x (not (keywordp x))
       (let ((name (symbol-name x)))
         (and (> (length name) 1) (char= (char name 0) #\?)))))

(defun anonymous-variable-p (x)
  "True when X is the anonymous pattern variable ?_."
  (and (pattern-variable-p x) (string= (symbol-name x) "?_")))

(defun form-variables (form)
  "The named pattern variables occurring anywhere in FORM, each once, in order."
  (let ((found '()))
    (labels ((walk (x)
               (cond ((pattern-variable-p x)
                      (unless (anonymous-variable-p x) (pushnew x found)))
                     ((consp x) (walk (car x)) (walk (cdr x))))))
      (walk form))
    (nreverse found)))

(defun binding-value (variable bindings)
  "The value of VARIABLE in the alist BINDINGS; second value true when bound."
  (let ((entry (assoc variable bindings :test #'eq)))
    (values (cdr entry) (and entry t))))

(defun substitute-bindings (bindings form)
  "FORM with every bound pattern variable replaced by its value in BINDINGS."
  (cond ((pattern-variable-p form)
         (multiple-value-bind (value bound) (binding-value form bindings)
           (if bound value form)))
        ((consp form)
         (let ((car (substitute-bindings bindings (car form)))
               (cdr (substitute-bindings bindings (cdr form))))
           (if (and (eq car (car form)) (eq cdr (cdr form))) form (cons car cdr))))
        (t form)))

;;; Splitting a belief or pattern into its parts

(defun pattern-head (pattern)
  "The head symbol of a belief or pattern."
  (car pattern))

(defun positional-part (pattern)
  "The elements of PATTERN after the head and before the first keyword."
  (loop for x in (cdr pattern) until (keywordp x) collect x))

(defun property-part (pattern)
  "The property list of PATTERN: everything from its first keyword on."
  (member-if #'keywordp (cdr pattern)))

;;; Matching (variables on one side)

(defun match-structure (pattern datum bindings)
  "Match PATTERN against DATUM exactly (structurally), extending BINDINGS. Returns
the bindings and, as second value, true on success."
  (cond ((anonymous-variable-p pattern) (values bindings t))
        ((pattern-variable-p pattern)
         (multiple-value-bind (value bound) (binding-value pattern bindings)
           (cond ((not bound) (values (acons pattern datum bindings) t))
                 ((equal value datum) (values bindings t))
                 (t (values nil nil)))))
        ((and (consp pattern) (consp datum))
         (multiple-value-bind (bindings ok) (match-structure (car pattern) (car datum) bindings)
           (if ok
               (match-structure (cdr pattern) (cdr datum) bindings)
               (values nil nil))))
        ((equal pattern datum) (values bindings t))
        (t (values nil nil))))

(defun match-properties (pattern-plist lookup bindings)
  "Match each value of PATTERN-PLIST against (FUNCALL LOOKUP KEY), which returns
the datum's value and whether the key is present; an absent key fails."
  (loop for (key value) on pattern-plist by #'cddr
        do (multiple-value-bind (datum present) (funcall lookup key)
             (unless present (return (values nil nil)))
             (multiple-value-bind (extended ok) (match-structure value datum bindings)
               (unless ok (return (values nil nil)))
               (setf bindings extended)))
        finally (return (values bindings t))))

(defun plist-lookup (plist)
  "A lookup function over PLIST for MATCH-PROPERTIES: absent keys are absent."
  (lambda (key)
    (let ((tail (loop for cell on plist by #'cddr
                      when (eq (car cell) key) return cell)))
      (values (cadr tail) (and tail t)))))

(defun match-positionals (pattern belief bindings)
  "Match the positional parts of PATTERN and BELIEF (see POSITIONAL-PART) element by
element, without copying them, extending BINDINGS. Returns the bindings, true on success
(the parts of equal length and every element matching), and the two property parts."
  (let ((p (cdr pattern)) (b (cdr belief)))
    (loop
      (let ((p-end (or (atom p) (keywordp (car p))))
            (b-end (or (atom b) (keywordp (car b)))))
        (cond ((and p-end b-end) (return (values bindings t p b)))
              ((or p-end b-end) (return (values nil nil)))
              (t (multiple-value-bind (extended ok) (match-structure (car p) (car b) bindings)
                   (unless ok (return (values nil nil)))
                   (setf bindings extended p (cdr p) b (cdr b)))))))))

(defun match-pattern (pattern belief bindings)
  "Match the belief PATTERN against the belief BELIEF, extending BINDINGS (see the
file header for the rules). Returns the bindings and, as second value, true on
success."
  (if (and (consp belief)
           (eq (pattern-head pattern) (pattern-head belief)))
      (multiple-value-bind (bindings ok pattern-properties belief-properties)
          (match-positionals pattern belief bindings)
        (if ok
            (match-properties pattern-properties (plist-lookup belief-properties) bindings)
            (values nil nil)))
      (values nil nil)))

;;; Unification (variables on both sides), for the static dependency graph

(defun rename-variables (form prefix)
  "FORM with each pattern variable replaced by a fresh uninterned variable whose
name starts with PREFIX, so that two forms share no variable."
  (let ((renaming '()))
    (labels ((walk (x)
               (cond ((anonymous-variable-p x)
                      (make-symbol (format nil "?~A_" prefix)))
                     ((pattern-variable-p x)
                      (or (cdr (assoc x renaming))
                          (let ((fresh (make-symbol (format nil "?~A~A" prefix (symbol-name x)))))
                            (push (cons x fresh) renaming)
                            fresh)))
                     ((consp x) (cons (walk (car x)) (walk (cdr x))))
                     (t x))))
      (walk form))))

(defun unify-structure (x y bindings)
  "Unify X and Y exactly (structurally) under BINDINGS. Returns the bindings and
true on success."
  (labels ((resolve (v)
             (loop while (pattern-variable-p v)
                   do (multiple-value-bind (value bound) (binding-value v bindings)
                        (if bound (setf v value) (return))))
             v))
    (let ((x (resolve x)) (y (resolve y)))
      (cond ((eq x y) (values bindings t))
            ((pattern-variable-p x) (values (acons x y bindings) t))
            ((pattern-variable-p y) (values (acons y x bindings) t))
            ((and (consp x) (consp y))
             (multiple-value-bind (bindings ok) (unify-structure (car x) (car y) bindings)
               (if ok (unify-structure (cdr x) (cdr y) bindings) (values nil nil))))
            ((equal x y) (values bindings t))
            (t (values nil nil))))))

(defun patterns-may-match-p (assertion reader)
  "True when some belief asserted by the pattern ASSERTION could match the pattern
READER (their variables are independent). Used to order components."
  (let ((assertion (rename-variables assertion "A"))
        (reader (rename-variables reader "R")))
    (and (eq (pattern-head assertion) (pattern-head reader))
         (let ((asserted (positional-part assertion)) (read (positional-part reader)))
           (and (= (length asserted) (length read))
                (multiple-value-bind (bindings ok) (unify-structure asserted read '())
                  (and ok
                       (loop with lookup = (plist-lookup (property-part assertion))
                             for (key value) on (property-part reader) by #'cddr
                             do (multiple-value-bind (asserted-value present)
                                    (funcall lookup key)
                                  (unless present (return nil))
                                  (multiple-value-bind (extended ok)
                                      (unify-structure asserted-value value bindings)
                                    (unless ok (return nil))
                                    (setf bindings extended)))
                             finally (return t)))))))))

;;; A canonical total order on data, so that collections and reports do not depend
;;; on the order in which beliefs were made

(defun datum-rank (x)
  "The class of X in the canonical order."
  (typecase x
    (real 0) (character 1) (string 2) (null 3) (symbol 4) (cons 5) (t 6)))

(defun datum< (x y)
  "True when X precedes Y in the canonical order of data: numbers, characters,
strings, NIL, other symbols (by package, then name), conses (lexicographically)."
  (let ((rx (datum-rank x)) (ry (datum-rank y)))
    (cond ((/= rx ry) (< rx ry))
          ((realp x) (< x y))
          ((characterp x) (char< x y))
          ((stringp x) (and (string< x y) t))
          ((null x) nil)
          ((symbolp x)
           (let ((px (let ((p (symbol-package x))) (if p (package-name p) "")))
                 (py (let ((p (symbol-package y))) (if p (package-name p) ""))))
             (if (string= px py)
                 (and (string< (symbol-name x) (symbol-name y)) t)
                 (and (string< px py) t))))
          ((consp x)
           (cond ((datum< (car x) (car y)) t)
                 ((datum< (car y) (car x)) nil)
                 (t (datum< (cdr x) (cdr y)))))
          (t nil))))

(defun canonical-sort (data)
  "A fresh list of DATA in the canonical order."
  (sort (copy-list data) #'datum<))

;;; Hash tables of data: SXHASH looks only a few conses deep, so beliefs that differ
;;; deep inside ((derivative (path-speed contact-27) ...)) would share a hash; a model of
;;; thousands of beliefs then spends its time comparing them.

(defconstant +datum-hash-atoms+ 48
  "How many atoms of a datum, depth first, DATUM-HASH mixes.")

(defun datum-hash (datum)
  "A hash of DATUM consistent with EQUAL that mixes its first +DATUM-HASH-ATOMS+ atoms
depth first, however deep they are, and the shape around them."
  (let ((hash 17) (budget +datum-hash-atoms+))
    (labels ((mix (value)
               (setf hash (logand (+ (* hash 31) value) most-positive-fixnum)))
             (walk (x)
               (when (plusp budget)
                 (cond ((consp x) (mix 7) (walk (car x)) (mix 11) (walk (cdr x)))
                       (t (decf budget) (mix (sxhash x)))))))
      (walk datum))
    hash))

(defun make-datum-table ()
  "An EQUAL hash table keyed by data, hashed with DATUM-HASH."
  (make-hash-table :test 'equal :hash-function #'datum-hash))
