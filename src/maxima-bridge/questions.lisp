;;;; src/maxima-bridge/questions.lisp -- the questions the deciding algebra asks of Maxima: is(), sign(), the signs behind a square root, and the cache of verdicts.
;;;;
;;;; Each operation takes AMES's prefix algebra and answers in AMES's terms: a truth
;;;; value (:TRUE :FALSE :UNKNOWN) or the list of signs (:POSITIVE :NEGATIVE :ZERO) an
;;;; expression may have under the facts in force. What to conclude from the answers (the
;;;; rules of signs, the strategies of DECIDE) is the algebra layer's (src/algebra/).
;;;; Every request goes through MAXIMA-REQUEST, so it is cached like any other.

(in-package #:ames.maxima)

;;; Maxima's sign()

(defparameter *sign-sets*
  '(("$POS" :positive) ("$NEG" :negative) ("$ZERO" :zero) ("$PZ" :positive :zero)
    ("$NZ" :negative :zero) ("$PN" :positive :negative) ("$PNZ" :positive :negative :zero))
  "Maxima's sign answers and the signs each allows.")

(defun sign-set (answer)
  "The list of signs (:POSITIVE :NEGATIVE :ZERO) Maxima's sign ANSWER allows."
  (or (rest (assoc (symbol-name answer) *sign-sets* :test #'string=))
      (list :positive :negative :zero)))

(defun sign-requests (form)
  "The sign() requests whose answers together bound the sign of the Maxima FORM,
cheapest first: FORM itself, factor(ratsimp(FORM)), factorsum(FORM) (which groups
terms, e.g. 2 acc l - 2 acc x0 into 2 acc (l - x0)) and trigsimp(FORM) (ratsimp(FORM)
when FORM has no sin, cos or tan, for which trigsimp gives the same form, slower)."
  (list (mcall "$SIGN" form)
        (mcall "$SIGN" (mcall "$FACTOR" (mcall "$RATSIMP" form)))
        (mcall "$SIGN" (mcall "$FACTORSUM" form))
        (mcall "$SIGN" (if (trigonometric-form-p form)
                           (mcall "$AMES_TRIGSIMP" form)
                           (mcall "$RATSIMP" form)))))

(defun narrowed-signs (signs answer)
  "SIGNS (a list of :POSITIVE :NEGATIVE :ZERO) narrowed by Maxima's sign ANSWER."
  (if (symbolp answer) (intersection signs (sign-set answer)) signs))

(defun exact-form-signs (bridge form)
  "The signs of the Maxima FORM when it is a constant of numbers and radicals, proven
without Maxima (EXACT-CONSTANT-SIGN, over exact rationals): (:POSITIVE), (:NEGATIVE) or
(:ZERO); :NEAR-ZERO when no precision tells it from 0; NIL when FORM is no such constant
(names, functions, %pi, %i), which sign() decides. Maxima's sign() of such a constant is
a float's sign, noise where its terms cancel (see src/base/exact-intervals.lisp)."
  (let ((expression (handler-case (from-mx bridge form)
                      (untranslatable-result () nil))))
    (when (and expression (consp expression) (null (expression-variables expression)))
      (let ((sign (exact-constant-sign expression)))
        (if (member sign '(:positive :negative :zero)) (list sign) sign)))))

(defun guarded-signs (exact signs)
  "SIGNS (Maxima's sign() of a constant) in the light of EXACT, its EXACT-FORM-SIGNS:
the proven sign when there is one; for a constant too near 0 to tell, (:ZERO) when
sign() says so, else any sign (sign()'s float is no proof); SIGNS when EXACT is NIL."
  (cond ((listp exact) (or exact signs))
        ((equal signs '(:zero)) signs)
        (t (list :positive :negative :zero))))

(defun forms-signs (bridge forms &key datum)
  "For each of the real Maxima FORMS, the signs (:POSITIVE :NEGATIVE :ZERO) it may have
under the current assumptions: the intersection of what sign() says of its forms (see
SIGN-REQUESTS). One round trip."
  (let ((exact (mapcar (lambda (form) (exact-form-signs bridge form)) forms)))
    (if (every #'consp exact)
        exact
        (mapcar #'guarded-signs exact (forms-signs-in-maxima bridge forms :datum datum)))))

(defun forms-signs-in-maxima (bridge forms &key datum)
  "FORMS-SIGNS by Maxima's sign() alone. One round trip."
  (let* ((count (length (sign-requests 0)))
         (requests (mapcan #'sign-requests forms))
         (answers (let ((answers (imaginary-as-unknown
                                  (lambda () (request-list bridge requests :datum datum)))))
                    ;; one form refused as imaginary: none of them decided
                    (if (listp answers) answers (mapcar (constantly answers) requests)))))
    (loop for rest on answers by (lambda (list) (nthcdr count list))
          collect (reduce #'narrowed-signs (subseq rest 0 count)
                          :initial-value (list :positive :negative :zero)))))

(defun imaginary-as-unknown (function)
  "FUNCTION's answer to a sign request, or Maxima's $PNZ (any sign) when Maxima's sign()
refuses the form as imaginary (\"sign: argument cannot be imaginary\": a root written
with the cube root of a complex number, Cardano's form of real roots): undecided, not
an error."
  (handler-case (funcall function)
    (maxima-error (condition)
      (if (search "imaginary" (or (maxima-error-message condition) ""))
          '$pnz
          (error condition)))))

(defvar *prefetch-signs* t
  "True when DECIDE's questions are asked in batches (see PREFETCH-REQUESTS): FORM-SIGNS
asks the sign() requests after the first together, PREFETCH-OPPOSITE-AND-SIGNS is() of
the opposite with the first sign(). NIL asks each alone (the answers are the same).")

(defun form-signs (bridge form &key datum (enough (constantly nil)) also)
  "The signs the real Maxima FORM may have under the current assumptions: what the
answers to SIGN-REQUESTS allow together. They are asked one at a time, cheapest first
(each answer cached on its own), and the asking stops once at most one sign is left or
ENOUGH, a predicate on the signs found so far, is true; further answers could only
narrow the signs (an empty intersection would mean contradictory answers). When the
first answer does not settle it, the other requests missing from the cache are sent in
one round trip (see PREFETCH-REQUESTS), with the requests ALSO (Maxima forms the caller
will likely ask next)."
  (let ((exact (exact-form-signs bridge form)))
    (if (consp exact)
        exact
        (guarded-signs exact (form-signs-in-maxima bridge form :datum datum :enough enough
                                                                :also also)))))

(defun form-signs-in-maxima (bridge form &key datum (enough (constantly nil)) also)
  "FORM-SIGNS by Maxima's sign() alone."
  (let ((signs (list :positive :negative :zero))
        (requests (sign-requests form)))
    (dolist (request requests signs)
      (setf signs (narrowed-signs signs (imaginary-as-unknown
                                         (lambda () (maxima-request bridge request :datum datum)))))
      (when (or (null (rest signs)) (funcall enough signs))
        (return signs))
      ;; the first form did not settle it: the others are asked together (most forms
      ;; that sign() does not settle at once need every form), with ALSO
      (when (and *prefetch-signs* (eq request (first requests)))
        (prefetch-requests bridge (append (rest requests) also))))))

(defun maxima-signs (bridge expression &key (datum expression) (enough (constantly nil)) also)
  "The signs (a list of :POSITIVE :NEGATIVE :ZERO) the real prefix EXPRESSION may have
under the facts in force, by Maxima's sign() of EXPRESSION in several simplified forms
(see FORM-SIGNS), asked one at a time until at most one sign is left or ENOUGH (a
predicate on the signs found so far) is true. DATUM names the question in conditions.
Signals UNTRANSLATABLE-EXPRESSION, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (form-signs bridge (to-mx bridge expression) :datum datum :enough enough :also also))

(defun maxima-difference-signs (bridge lhs rhs &key datum (enough (constantly nil)))
  "The signs of LHS - RHS (prefix) by Maxima's sign(), like MAXIMA-SIGNS; the
difference is formed of the two sides' translations."
  (form-signs bridge (mdifference (to-mx bridge lhs) (to-mx bridge rhs))
              :datum datum :enough enough))

;;; Maxima's is()

(defun is-question (bridge relation)
  "The Maxima form of the prefix RELATION (= /= < > <= >=) as is() is asked it: = as
equal() and /= as notequal(), which is() decides by simplification."
  (let ((lhs (to-mx bridge (relation-lhs relation)))
        (rhs (to-mx bridge (relation-rhs relation))))
    (case (expression-operator relation)
      (= (mform +equal+ lhs rhs))
      (/= (mform +notequal+ lhs rhs))
      (t (mform (cdr (assoc (expression-operator relation) *relation-heads*)) lhs rhs)))))

(defun maxima-is (bridge relation &key (datum relation))
  "What Maxima's is() says of the prefix RELATION (= /= < > <= >=) under the facts in
force: :TRUE, :FALSE or :UNKNOWN. = and /= are asked as equal() and notequal().
Signals UNTRANSLATABLE-EXPRESSION, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (maxima-truth (maxima-request bridge (mcall "$IS" (is-question bridge relation)) :datum datum)))

(defparameter *opposite-relations*
  '((= . /=) (/= . =) (< . >=) (> . <=) (<= . >) (>= . <))
  "Each relation of the algebra and the one saying the opposite.")

(defun maxima-is-opposite (bridge relation &key (datum relation))
  "What Maxima's is() says of the opposite of the prefix RELATION (X <= 0 for X > 0,
equal() for notequal() ...): :TRUE when it proves the opposite (RELATION fails),
:FALSE when it refutes it, else :UNKNOWN. is() proves X <= 0 from the fact X <= 0 but
does not see that X > 0 fails."
  (maxima-is bridge (list* (cdr (assoc (expression-operator relation) *opposite-relations*))
                           (expression-arguments relation))
             :datum datum))

(defun prefetch-opposite-and-signs (bridge relation)
  "Ask, in one round trip, the questions DECIDE asks of RELATION (= /= < > <= >=) after
is(): is() of its opposite (MAXIMA-IS-OPPOSITE) and the first sign() request of the
difference of its sides (MAXIMA-DIFFERENCE-SIGNS; FORM-SIGNS asks the others together
when it needs them); their answers are cached as theirs (see PREFETCH-REQUESTS). A
relation that does not translate is left to them."
  (let ((requests (handler-case
                      (list (mcall "$IS" (is-question bridge (list* (cdr (assoc (expression-operator relation)
                                                                                 *opposite-relations*))
                                                                    (expression-arguments relation))))
                            (first (sign-requests (mdifference (to-mx bridge (relation-lhs relation))
                                                               (to-mx bridge (relation-rhs relation))))))
                    (maxima-condition () nil))))
    (when (and requests *prefetch-signs*)
      (prefetch-requests bridge requests))))

(defparameter *fact-sign-relations*
  `((,+mgreaterp+ :negative :zero) (,+mlessp+ :positive :zero) (,+mgeqp+ :negative) (,+mleqp+ :positive))
  "The relations of X with 0 that MAXIMA-FACT-SIGNS asks is() about, each with the signs
its truth excludes.")

(defun fact-sign-requests (bridge x)
  "The is() requests MAXIMA-FACT-SIGNS asks about the prefix X: X > 0, X < 0, X >= 0,
X <= 0."
  (let ((form (to-mx bridge x)))
    (loop for (head) in *fact-sign-relations*
          collect (mcall "$IS" (mform head form 0)))))

(defun maxima-fact-signs (bridge x &key (datum x))
  "The signs of the prefix X that is() shows from the facts in force (X >= 0, X < 0
...), in one round trip: is() uses a fact about a compound X that sign() ignores."
  (let ((requests (fact-sign-requests bridge x))
        (signs (list :positive :zero :negative)))
    (prefetch-requests bridge requests)
    (loop for (nil . excluded) in *fact-sign-relations*
          for request in requests
          when (eq (maxima-truth (maxima-request bridge request :datum datum)) :true)
            do (setf signs (set-difference signs excluded)))
    signs))

;;; One square root cleared

(defun square-root-part-signs (bridge lhs rhs &key datum)
  "LHS - RHS (prefix) written as (a + b sqrt(A)) / c, for one square root sqrt(A) in its
numerator in which the numerator is linear: the signs (see MAXIMA-SIGNS) of a, b,
b^2 A - a^2, A and c, as a list of five sign lists. NIL when no square root is there
or the numerator is not linear in it. Two round trips: the parts (ames_square_root_parts
in maxima-server-functions.lisp), then their signs."
  (let ((parts (mlist-items (maxima-request bridge (mcall "$AMES_SQUARE_ROOT_PARTS"
                                                          (mdifference (to-mx bridge lhs)
                                                                       (to-mx bridge rhs)))
                                            :datum datum))))
    (when (= (length parts) 5)
      (destructuring-bind (numerator denominator kernel a b) parts
        (declare (ignore numerator))
        (let* ((radicand (second kernel))
               (gap (mdifference (mform +mtimes+ (mform +mexpt+ b 2) radicand)
                                 (mform +mexpt+ a 2))))
          (forms-signs bridge (list a b gap radicand denominator) :datum datum))))))

(defun square-root-parts (bridge lhs rhs &key datum)
  "LHS - RHS (prefix) written as (a + b sqrt(A)) / c, as SQUARE-ROOT-PART-SIGNS finds it
(one square root in the numerator, which is linear in it): (values a b A c), prefix. NIL
when no square root is there or the numerator is not linear in it, or a part leaves the
algebra. One round trip."
  (let ((parts (mlist-items (maxima-request bridge (mcall "$AMES_SQUARE_ROOT_PARTS"
                                                          (mdifference (to-mx bridge lhs)
                                                                       (to-mx bridge rhs)))
                                            :datum datum))))
    (when (= (length parts) 5)
      (destructuring-bind (numerator denominator kernel a b) parts
        (declare (ignore numerator))
        (handler-case (values (from-mx bridge a) (from-mx bridge b)
                              (from-mx bridge (second kernel)) (from-mx bridge denominator))
          (untranslatable-result () nil))))))

;;; The cache of verdicts

(defun cached-answer (bridge key &key (count t))
  "The answer BRIDGE's cache holds under KEY (a tree compared with EQUAL; include
ASSUMPTION-KEY when the answer depends on the facts in force), and whether one is held:
(values ANSWER FOUND). When COUNT, the look-up counts as a call in BRIDGE's statistics
(and as a cache hit when found)."
  (multiple-value-bind (answer found) (gethash key (bridge-cache bridge))
    (when count
      (let ((record (bridge-statistics-record bridge)))
        (incf (statistics-calls record))
        (when found (incf (statistics-cache-hits record)))))
    (values answer found)))

(defun cache-answer (bridge key answer)
  "Keep ANSWER under KEY (copied) in BRIDGE's cache, which is emptied first when it holds
*CACHE-LIMIT* entries, like the cache of requests. Returns ANSWER."
  (let ((cache (bridge-cache bridge)))
    (when (>= (hash-table-count cache) *cache-limit*) (clrhash cache))
    (setf (gethash (copy-tree key) cache) answer)))

;;; sin^2 + cos^2 = 1

(defun ratsimp-with-sines (bridge expression angles &key (datum expression))
  "EXPRESSION (prefix) ratsimp()ed by Maxima with each cos(K)^2, for K in ANGLES,
written 1 - sin(K)^2 (ratsubst), so that sin and cos of one angle are no independent
atoms; prefix. Signals what MAXIMA-REQUEST and FROM-MX signal."
  (from-mx bridge
           (maxima-request
            bridge
            (mcall "$RATSIMP"
                   (reduce (lambda (form k)
                             (mcall "$RATSUBST" (to-mx bridge `(- 1 (expt (sin ,k) 2)))
                                    (to-mx bridge `(expt (cos ,k) 2)) form))
                           angles
                           :initial-value (to-mx bridge expression)))
            :datum datum)))
