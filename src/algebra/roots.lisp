;;;; src/algebra/roots.lisp -- the earliest root of an expression after a given value, proven earliest.
;;;;
;;;; A termination condition of a qualitative state is the earliest time at which some
;;;; expression reaches zero. With symbolic coefficients Maxima's sign() of a single root is
;;;; usually pnz, while the signs of the product and sum of the roots and of the
;;;; discriminant are decided. So after shifting the variable to start at AFTER, a
;;;; polynomial of degree 1 or 2 is handled through those signs (Vieta); higher degrees and
;;;; other expressions go through solve() and pairwise comparison. A root is returned only
;;;; when it is proven to be the earliest; otherwise the answer is :UNKNOWN with the
;;;; candidates.
;;;;
;;;; The Maxima forms of the search (the polynomial's coefficients, Vieta's forms, the
;;;; offsets of roots) are the bridge's root forms (src/maxima-bridge/root-forms.lisp):
;;;; this file holds them as opaque values and asks about them by name.

(in-package #:ames.algebra)

(defun root-verdict (signs strictly)
  "Whether a root offset with SIGNS lies after the start: :YES, :NO or :MAYBE."
  (flet ((only (&rest allowed) (and signs (subsetp signs allowed))))
    (cond ((null signs) :maybe)
          (strictly (cond ((only :positive) :yes)
                          ((not (member :positive signs)) :no)
                          (t :maybe)))
          (t (cond ((only :positive :zero) :yes)
                   ((only :negative) :no)
                   (t :maybe))))))

(defstruct (root-search (:conc-name search-))
  "What EARLIEST-ROOT knows while it works: the bridge, the original expression (for
conditions), the shift, whether the root must lie strictly after it, and whether the
candidates of an undecided answer are wanted."
  bridge expression after-form strictly (candidates t))

(defun root-expression (search offset)
  "The root AFTER + OFFSET (OFFSET a root form), simplified, in prefix algebra."
  (root-at-offset (search-bridge search) (search-after-form search) offset
                  (search-expression search)))

(defun root-candidates (search offsets)
  "The translatable roots AFTER + OFFSET for OFFSETS."
  (loop for offset in offsets
        for root = (and (not (complex-root-form-p offset)) ; a complex root is no time
                        (handler-case (root-expression search offset)
                          (untranslatable-result () nil)))
        when root collect root))

(defun found (search offset)
  (values (root-expression search offset) :found))

(defun unknown (search offsets)
  (values :unknown (and (search-candidates search) (root-candidates search offsets))))

(defun signs-of (search form)
  (root-form-signs (search-bridge search) form :datum (search-expression search)))

(defun mixed-signs-p (search form)
  "True when the root FORM is seen positive at one admissible point and negative at
another (see WITNESSED-BOTH-WAYS-P): its signs include :POSITIVE and :NEGATIVE."
  (let ((expression (handler-case (root-form-expression (search-bridge search) form)
                      (untranslatable-result () nil))))
    (and expression
         (witnessed-both-ways-p (search-bridge search) (list '> expression 0)))))

(defun sign-pattern-of (search form &optional tests)
  "The signs of FORM, for the tests that only ask whether they lie within a set that
lacks :POSITIVE or :NEGATIVE (ONLY, ROOT-VERDICT): all three, without asking Maxima,
when FORM is seen to take both signs, else SIGNS-OF, narrowed by DECIDE (which knows
more than Maxima's sign(): trigonometric bounds, orderings) when Maxima leaves several.
A constant FORM zero to round-off is decided exactly or left open (round-off.lisp):
Maxima's sign() would give its float's sign. TESTS, when given, are the sets the caller
asks the signs to lie within (SUBSETP), all it asks of them: DECIDED-SIGNS then leaves
out the proofs whose outcome could not change any test's answer."
  (cond ((constant-form-zero-signs search form))
        ((mixed-signs-p search form) (list :positive :negative :zero))
        (t (let ((signs (signs-of search form)))
             (if (rest signs) (decided-signs search form signs tests) signs)))))

(defun constant-form-zero-signs (search form)
  "CONSTANT-ZERO-SIGNS of the root FORM's expression, NIL when it has none or does not
translate."
  (let ((expression (handler-case (root-form-expression (search-bridge search) form)
                      (untranslatable-result () nil))))
    (and expression (constant-zero-signs (search-bridge search) expression))))

(defun decided-signs (search form signs &optional tests)
  "SIGNS (several) narrowed by DECIDE on FORM's translation: the sign it proves, or the
pair it proves with >= or <=; SIGNS when it proves nothing. The proofs are tried in that
order (>, <, then >= and <= when SIGNS hold :ZERO), the first proven giving the answer.
With TESTS (sets of signs; see SIGN-PATTERN-OF) only the proofs that can change what
the caller reads of the answer are asked (SETTLED-SIGNS)."
  (let* ((bridge (search-bridge search))
         (expression (handler-case (root-form-expression bridge form)
                       (untranslatable-result () (return-from decided-signs signs))))
         (steps (append (list (cons '> '(:positive)) (cons '< '(:negative)))
                        (and (member :zero signs)
                             (list (cons '>= '(:positive :zero)) (cons '<= '(:negative :zero))))))
         ;; only a proof counts: HOLDS-P leaves out one that fails at an admissible point
         (proven-p (lambda (step) (holds-p bridge (list (car step) expression 0)))))
    (if tests
        (settled-signs steps signs tests proven-p)
        (loop for step in steps
              when (funcall proven-p step) return (copy-list (cdr step))
              finally (return signs)))))

(defun settled-signs (steps signs tests proven-p)
  "The answer of STEPS ((OPERATOR . SIGNS-IF-PROVEN) ..., tried in order, the first that
PROVEN-P proves giving its signs, SIGNS when none does), or another answer that lies
within the same sets of TESTS (SUBSETP): the steps are tried in the same order, and the
search stops, with SIGNS, as soon as every answer still possible lies within the same
sets (SAME-ANSWERS-P). It asks PROVEN-P a part of what the search in order asks."
  (loop for (step . rest) on steps
        when (same-answers-p tests (cons signs (mapcar #'cdr (cons step rest))))
          return signs
        when (funcall proven-p step)
          return (copy-list (cdr step))
        finally (return signs)))

(defun same-answers-p (tests answers)
  "True when every set of signs in ANSWERS lies within the same sets of TESTS (SUBSETP)."
  (flet ((reading (signs) (mapcar (lambda (set) (subsetp signs set)) tests)))
    (let ((first (reading (first answers))))
      (every (lambda (signs) (equal (reading signs) first)) (rest answers)))))

(defun verdict-tests (strictly)
  "The sets of signs ROOT-VERDICT reads (see SIGN-PATTERN-OF's TESTS) when STRICTLY is
true or false."
  (if strictly
      '((:positive) (:negative :zero))
      '((:positive :zero) (:negative))))

(defun check-root-search-arguments (expression variable after)
  "Check the arguments of a search for the earliest root of EXPRESSION in VARIABLE after
AFTER: both expressions translatable arithmetic, VARIABLE a variable or a quantity term,
AFTER free of it. Signals UNTRANSLATABLE-EXPRESSION or INVALID-BRIDGE-ARGUMENT."
  (check-translatable expression :arithmetic)
  (check-translatable after :arithmetic)
  (unless (subject-p variable)
    (error 'invalid-bridge-argument :datum variable
                                    :detail "the variable must be a variable or a quantity term"))
  (unless (free-of-p variable after)
    (error 'invalid-bridge-argument :datum after
                                    :detail (format nil "the start may not depend on ~S" variable))))

(defun earliest-root (bridge expression variable &key (after 0) (strictly t) (candidates t))
  "The earliest real root of EXPRESSION = 0 in VARIABLE greater than AFTER (or equal to
it, when STRICTLY is false), proven earliest under the current assumptions. Returns
  (values ROOT :FOUND)          the proven earliest root (prefix algebra);
  (values :NONE NIL)            proven: no real root after AFTER;
  (values :UNKNOWN CANDIDATES)  not decided; CANDIDATES are the roots Maxima found that
                                could not be ruled out (possibly none), simplified;
                                NIL when CANDIDATES is false (they are costly).
Polynomials of degree at most 2 are decided through the signs of the product and sum
of their roots and of their discriminant; other polynomials through solve() and
pairwise comparison (numeric ones through Sturm sequences, realroots(), giving a
float); other expressions never yield :FOUND or :NONE, since solve() may miss roots.
Signals UNTRANSLATABLE-EXPRESSION, INVALID-BRIDGE-ARGUMENT (VARIABLE not a name, AFTER
depending on VARIABLE), MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (check-root-search-arguments expression variable after)
  (let ((shifted (if (eql after 0)
                     expression
                     (substitute-expressions (list (cons variable (list '+ variable after)))
                                             expression))))
    (multiple-value-bind (form offset-variable after-form coefficients)
        (offset-polynomial bridge shifted variable after :datum expression)
      (let ((search (make-root-search :bridge bridge :expression expression
                                      :after-form after-form :strictly strictly
                                      :candidates candidates)))
        (if (eq coefficients :not-polynomial)
            (solved-earliest-root search form offset-variable nil)
            (polynomial-earliest-root search form offset-variable coefficients))))))

(defun constant-earliest-root (search constant)
  "EXPRESSION does not depend on the variable: no root, or (identically zero) every value.
Its signs are SIGN-PATTERN-OF's (narrowed by DECIDE: mb g (5 l1 - l2)(l1 - l2) expanded
is not zero when l1 > l2 > 0, which Maxima's sign() does not see)."
  (let ((signs (sign-pattern-of search constant '((:positive :negative) (:zero)))))
    (cond ((not (member :zero signs)) (values :none nil))
          ((and (equal signs '(:zero)) (not (search-strictly search))) (found search 0))
          (t (values :unknown nil)))))

(defun linear-earliest-root (search coefficients)
  "c0 + c1 s = 0: the one root -c0/c1, when c1 cannot vanish."
  (destructuring-bind (c0 c1) coefficients
    (let ((offset (linear-root-offset c0 c1)))
      (if (member :zero (sign-pattern-of search c1 '((:positive :negative))))
          (unknown search (list offset))
          (ecase (root-verdict (sign-pattern-of search offset (verdict-tests (search-strictly search)))
                                (search-strictly search))
            (:yes (found search offset))
            (:no (values :none nil))
            (:maybe (unknown search (list offset))))))))

(defun real-square-root (search radicand)
  "The square root of the root form RADICAND, written so that Maxima's simplifier does
not turn it into the imaginary unit (see REAL-SQUARE-ROOT-FORM): RADICAND in rational
form, its numerator and denominator both negated when the numerator is proven negative.
A constant radicand (numbers and radicals) whose numerator or denominator a double
cannot sign is written sqrt(N D)/|D| instead (CONSTANT-SQUARE-ROOT)."
  (let ((bridge (search-bridge search))
        (datum (search-expression search)))
    (multiple-value-bind (rational numerator) (rational-radicand bridge radicand :datum datum)
      (or (constant-square-root search rational numerator)
          (real-square-root-form bridge rational numerator
                                 (equal (sign-pattern-of search numerator '((:negative))) '(:negative))
                                 :datum datum)))))

(defun constant-square-root (search rational numerator)
  "The square root of the constant root form RATIONAL (numerator NUMERATOR) written
sqrt(N D)/|D| (CLEARED-SQUARE-ROOT-FORM), when its denominator D is a constant of
numbers and radicals whose sign EXACT-CONSTANT-SIGN proves, and N or D is zero to a
double's round-off (ZERO-TO-ROUND-OFF-P); else NIL. Maxima decides
the sign of such a constant by a float, and where its terms cancel beyond a double's
digits it took both N and D of a positive radicand for positive when both were negative,
and wrote sqrt(N/D) with %i (terrain 2028 #70): a sum under the root gives its
simplifier no factor to split."
  (let* ((bridge (search-bridge search))
         (datum (search-expression search))
         (expression (handler-case (root-form-expression bridge numerator)
                       (untranslatable-result () nil))))
    (when (and expression (null (expression-variables expression)))
      (let* ((denominator (radicand-denominator bridge rational :datum datum))
             (bottom (handler-case (root-form-expression bridge denominator)
                       (untranslatable-result () nil)))
             (sign (and bottom (exact-constant-sign bottom))))
        ;; only where a double cannot tell a sign (elsewhere Maxima's is right, and the
        ;; usual form is kept)
        (when (and (member sign '(:positive :negative))
                   (or (zero-to-round-off-p expression) (zero-to-round-off-p bottom)))
          (cleared-square-root-form bridge numerator denominator (eq sign :negative)
                                    :datum datum))))))

(defun quadratic-earliest-root (search coefficients form offset-variable)
  "c0 + c1 s + c2 s^2 = 0, through the product P = c0/c2 and sum S = -c1/c2 of the roots
and the reduced discriminant S^2/4 - P: the roots are S/2 -+ sqrt(S^2/4 - P)."
  (destructuring-bind (c0 c1 c2) coefficients
    (when (member :zero (sign-pattern-of search c2 '((:positive :negative))))
      (return-from quadratic-earliest-root
        (solved-earliest-root search form offset-variable coefficients)))
    (multiple-value-bind (product sum half-sum discriminant) (vieta-forms c0 c1 c2)
     (let* ((product-signs (sign-pattern-of search product '((:negative) (:zero) (:positive))))
           (strictly (search-strictly search))
           (root-of-discriminant nil))
      (flet ((only (signs &rest allowed) (and signs (subsetp signs allowed)))
             (root-of-discriminant ()
               ;; made once, when a root is wanted (it costs round trips)
               (or root-of-discriminant
                   (setf root-of-discriminant (real-square-root search discriminant)))))
        (symbol-macrolet ((larger (root-form-sum half-sum (root-of-discriminant)))
                          (smaller (root-form-difference half-sum (root-of-discriminant))))
          (cond
            ;; Roots of opposite signs: the larger is the only one after the start.
            ((only product-signs :negative) (found search larger))
            ;; A root at the start itself; the other is S.
            ((equal product-signs '(:zero))
             (if (not strictly)
                 (found search 0)
                 (ecase (root-verdict (sign-pattern-of search sum (verdict-tests t)) t)
                   (:yes (found search sum))
                   (:no (values :none nil))
                   (:maybe (unknown search (list sum))))))
            ;; Roots of the same sign (or complex): both before the start when S <= 0.
            ((only product-signs :positive)
             (let ((sum-signs (sign-pattern-of search sum '((:negative :zero) (:positive)))))
               (cond ((only sum-signs :negative :zero) (values :none nil))
                     ((only sum-signs :positive)
                      (let ((discriminant-signs (sign-pattern-of search discriminant
                                                                  '((:negative) (:positive :zero)))))
                        (cond ((only discriminant-signs :negative) (values :none nil))
                              ((only discriminant-signs :positive :zero) (found search smaller))
                              (t (unknown search (list smaller larger))))))
                     (t (unknown search (list smaller larger))))))
            (t (unknown search (list smaller larger))))))))))

(defun non-real-p (search offset)
  "True when OFFSET, a root solve() gave, is decidedly not a real number: the imaginary
part is decidedly not zero (sqrt(h - top) under h < top). Such a root of
a polynomial in time is no time at which anything happens.
The imaginary part's signs are SIGN-PATTERN-OF's, and only whether they leave out
:ZERO counts: so of DECIDE's narrowing (DECIDED-SIGNS) only the proofs of > 0 and < 0
are asked (through HOLDS-P: only a proof counts), and none when Maxima's signs leave out :ZERO already (>= 0 and <= 0, which
DECIDED-SIGNS tries next, can only give signs with :ZERO: the same answer, the failing
proofs not paid for)."
  (let ((imaginary (root-form-imaginary-part (search-bridge search) offset
                                             :datum (search-expression search))))
    (and (not (eql imaginary 0))
         (not (mixed-signs-p search imaginary))
         (let ((signs (signs-of search imaginary)))
           (cond ((not (member :zero signs)) t) ; as SIGN-PATTERN-OF's, none included
                 ((null (rest signs)) nil)
                 (t (let ((expression (handler-case (root-form-expression (search-bridge search)
                                                                          imaginary)
                                        (untranslatable-result () nil))))
                      (and expression
                           (let ((bridge (search-bridge search)))
                             (or (holds-p bridge (list '> expression 0))
                                 (holds-p bridge (list '< expression 0))))))))))))

(defun solved-earliest-root (search form offset-variable coefficients)
  "The general case: the roots solve() finds, compared pairwise. COEFFICIENTS is the
list of polynomial coefficients, or NIL when FORM is no polynomial (then solve() may
miss roots and nothing is proven)."
  (let* ((bridge (search-bridge search))
         (strictly (search-strictly search))
         (explicit '()) (complete nil)
         (numeric (and coefficients (every #'numeric-root-form-p coefficients)))
         (proven '()) (undecided '()))
    (multiple-value-bind (offsets count)
        (solved-root-offsets bridge form offset-variable :datum (search-expression search))
      (setf explicit offsets
            complete (and coefficients (= (length offsets) count))))
    (flet ((undecided-anyway ()
             ;; the answer is :UNKNOWN whatever the other roots are: without candidates
             ;; wanted, their signs need not be asked
             (when (and (not numeric) (not (search-candidates search)))
               (return-from solved-earliest-root (values :unknown nil)))))
      (unless complete (undecided-anyway))
      (dolist (offset explicit)
        (if (complex-root-form-p offset)
            (progn (push offset undecided) (undecided-anyway))
            (ecase (root-verdict (sign-pattern-of search offset (verdict-tests strictly)) strictly)
              ;; a root of undecided realness (sqrt of a radicand of undecided sign,
              ;; which sign() takes for real) is no proven time (real-roots.lisp)
              (:yes (cond ((proven-real-root-p search offset) (push offset proven))
                          ((non-real-p search offset))
                          (t (push offset undecided) (undecided-anyway))))
              (:no)
              (:maybe (unless (non-real-p search offset)
                        (push offset undecided) (undecided-anyway)))))))
    (setf proven (nreverse proven) undecided (nreverse undecided))
    (cond
      ((and complete (null undecided))
       (if (null proven)
           (values :none nil)
           (let ((earliest (find-if (lambda (candidate)
                                      (every (lambda (other)
                                               (or (eq other candidate)
                                                   (subsetp (sign-pattern-of search (root-form-difference other candidate)
                                                                    '((:positive :zero)))
                                                            '(:positive :zero))))
                                             proven))
                                    proven)))
             (if earliest (found search earliest) (unknown search proven)))))
      (numeric
       (numeric-earliest-root search form offset-variable))
      (t (unknown search (append proven undecided))))))

(defun numeric-earliest-root (search form offset-variable)
  "A polynomial with numeric coefficients: Sturm sequences (realroots) isolate every real
root; the earliest after the start is returned as a float."
  (let ((bridge (search-bridge search))
        (offsets (real-root-offsets (search-bridge search) form offset-variable
                                    :datum (search-expression search))))
    (unless (every #'realp offsets)
      (return-from numeric-earliest-root (values :unknown nil)))
    (let ((after (remove-if-not (lambda (offset)
                                  (if (search-strictly search) (plusp offset) (>= offset 0)))
                                offsets)))
      (if (null after)
          (values :none nil)
          (let ((offset (coerce (reduce #'min after) 'double-float))
                (start (root-form-expression bridge (search-after-form search))))
            ;; Not through Maxima: ratsimp would turn the float back into a ratio.
            (values (if (realp start) (+ start offset) (list '+ start offset)) :found))))))
