;;;; src/maxima-bridge/maxima-server-functions.lisp -- the Maxima functions the bridge calls
;;;; ($AMES_POLYNOMIAL_COEFFICIENTS, $AMES_TRIGSIMP, the simplification and presentation
;;;; candidates, tex() of a form as it is), run INSIDE Debian's Maxima (GCL).
;;;;
;;;; GCL code, not part of the SBCL system (ames.asd lists it as a static file): the request
;;;; server, maxima-server.lisp, loads it after its whitelist of heads is made (the
;;;; presentation's functions add themselves to it) and before its loop.

(in-package :maxima)

;;; Helpers the bridge calls.

(defun $ames_pop_context (child parent)
  "Kill the context CHILD and make PARENT current again."
  ($killcontext child)
  (unless (eq $context parent)
    (mset '$context parent))
  '$done)

(defun $ames_polynomial_coefficients (expr var)
  "The list [c0, c1, ..., cd] when the numerator of EXPR is a polynomial in VAR with
coefficients free of VAR and its denominator is free of VAR; false otherwise."
  (let* ((e ($ratsimp expr))
         (numerator ($expand ($num e)))
         (denominator ($denom e)))
    (if (not ($freeof var denominator))
        nil
        (let* ((degree ($hipow numerator var))
               (coefficients (loop for k from 0 to degree
                                   collect ($ratsimp ($ratcoef numerator var k)))))
          (if (and (integerp degree) (>= degree 0)
                   (every #'(lambda (c) ($freeof var c)) coefficients)
                   (eql 0 ($ratsimp
                           (sub numerator
                                (addn (loop for c in coefficients for k from 0
                                            collect (mul c (power var k)))
                                      nil)))))
              (cons '(mlist simp) coefficients)
              nil)))))

(defun ames-monic-square-root (numerator var)
  "The polynomial q, monic in VAR, with NUMERATOR = c q^2 (c NUMERATOR's leading
coefficient in VAR), when NUMERATOR is of even degree 4 or more and such a square (a
point moving along a tangent of a circle: its gap is a square); NIL otherwise. The
coefficients of q follow from NUMERATOR's highest ones; the rest is checked by
ratsimp, then radcan (radicals that ratsimp keeps apart)."
  (let ((degree ($hipow numerator var)))
    (when (and (integerp degree) (>= degree 4) (evenp degree))
      (let* ((n (floor degree 2))
             (lead ($ratcoef numerator var degree))
             (q (make-array (1+ n) :initial-element 0)))
        (setf (aref q n) 1)
        (loop for j from 1 to n
              do (setf (aref q (- n j))
                       ($ratsimp
                        (div (sub (div ($ratcoef numerator var (- degree j)) lead)
                                  (addn (loop for i from 1 below j
                                              collect (mul (aref q (- n i)) (aref q (+ (- n j) i))))
                                        nil))
                             2))))
        (let* ((root (addn (loop for k from 0 to n collect (mul (aref q k) (power var k))) nil))
               (rest (sub numerator (mul lead (power root 2)))))
          (when (or (eql 0 ($ratsimp ($expand rest)))
                    (eql 0 ($ratsimp ($radcan rest))))
            ($ratsimp root)))))))

(defun $ames_square_free_part (expr var)
  "The numerator of EXPR, a polynomial in VAR, with each factor it repeats (a factor of
its gcd with its derivative in VAR, the part free of VAR left out) taken once, or with
its square root when it is a constant times a square (AMES-MONIC-SQUARE-ROOT: radicals
in its coefficients hide such a square from gcd()): the same roots in VAR at every
value of the other variables, fewer of them repeated."
  (let* ((numerator ($expand ($num ($ratsimp expr))))
         (common ($gcd numerator ($diff numerator var))))
    (cond ((not ($freeof var common))
           ($ratsimp (div numerator (third ($content common var)))))
          ((ames-monic-square-root numerator var))
          (t numerator))))

(defun $ames_expression_size (expr)
  "The number of atoms and operators in EXPR (to pick the simplest of several forms)."
  (if (atom expr) 1 (1+ (reduce #'+ (mapcar #'$ames_expression_size (cdr expr))))))

(defun ames-call (function argument)
  "FUNCTION(ARGUMENT) evaluated as meval evaluates it in a request, the result simplified
again; ARGUMENT (already a value) is quoted, so that it is not evaluated twice."
  (meval (list (list function) (list '(mquote) argument))))

(defun ames-call-or-nil (function argument)
  "AMES-CALL's FUNCTION(ARGUMENT), or NIL when Maxima fails on it (factor(r) divides by
zero when r is a zero written with nested radicals: `quotient' by `zero'), its
bindings undone as AMES-EVALUATE undoes a failed request's."
  (let ((saved (cons bindlist loclist)))
    (handler-case (rat-error-to-merror (ames-call function argument))
      (maxima-$error () (errlfun1 saved) nil))))

(defun ames-big-integer-p (form)
  "True when FORM holds an integer of more than 18 digits (factor() would factor it into
primes, which can take longer than a request may)."
  (if (atom form)
      (and (integerp form) (> (abs form) 1000000000000000000))
      (some #'ames-big-integer-p (cdr form))))

(defun ames-mentions-head-p (form heads)
  "True when the Maxima FORM contains an operator form whose head is one of HEADS."
  (and (consp form)
       (or (and (consp (car form)) (member (caar form) heads))
           (some #'(lambda (part) (ames-mentions-head-p part heads)) (cdr form)))))

(defun ames-trigonometric-power-p (form)
  "True when FORM contains a power of sin, cos, sinh or cosh whose exponent is an
integer of size 2 or more."
  (and (consp form)
       (or (and (consp (car form)) (eq (caar form) 'mexpt)
                (integerp (caddr form)) (>= (abs (caddr form)) 2)
                (consp (cadr form)) (consp (car (cadr form)))
                (member (caar (cadr form)) '(%sin %cos %sinh %cosh $sin $cos $sinh $cosh)))
           (some #'ames-trigonometric-power-p (cdr form)))))

(defun $ames_trigsimp (expr)
  "trigsimp(EXPR), computed without trigsimp where its code (share/trigonometry/trgsmp.mac)
is known to reduce to ratsimp(num(r)/denom(r)) with r = ratsimp(EXPR): when EXPR has no
tan, sec, csc, cot (or their hyperbolic kin), which are all its rules rewrite, and r has
no power (2 or more) of sin, cos, sinh or cosh, which are all its search works on."
  (if (ames-mentions-head-p expr '(%tan %sec %csc %cot %tanh %sech %csch %coth
                                   $tan $sec $csc $cot $tanh $sech $csch $coth))
      (ames-call '$trigsimp expr)
      (let ((ratsimped (ames-call '$ratsimp expr)))
        (if (ames-trigonometric-power-p ratsimped)
            (ames-call '$trigsimp expr)
            (meval (list '($ratsimp)
                         (list '(mquotient)
                               (list '($num) (list '(mquote) ratsimped))
                               (list '($denom) (list '(mquote) ratsimped)))))))))

(defun ames-linear-variable-p (x)
  "True when X is a name the bridge generated for a variable (AMES-MANGLED-NAME-P's
$AMESV... or $AMESX...): an indeterminate to rat() and factor(), unlike %pi or %e."
  (and (symbolp x)
       (let ((name (symbol-name x)))
         (and (> (length name) 6)
              (or (string= "$AMESV" name :end2 6) (string= "$AMESX" name :end2 6))))))

(defun ames-linear-integer-parts (r)
  "(VALUES TERMS CONSTANT) when R, a simplified form, is a linear form c0 + c1 x1 + ...
in distinct variables (AMES-LINEAR-VARIABLE-P) with integer coefficients: TERMS the
list of (ci . xi), CONSTANT the integer c0; NIL when R is of any other shape."
  (flet ((term (x)
           (cond ((ames-linear-variable-p x) (cons 1 x))
                 ((and (consp x) (consp (car x)) (eq (caar x) 'mtimes)
                       (= (length x) 3) (integerp (cadr x))
                       (ames-linear-variable-p (caddr x)))
                  (cons (cadr x) (caddr x))))))
    (cond ((and (consp r) (consp (car r)) (eq (caar r) 'mplus))
           (let ((terms nil) (constant 0))
             (dolist (x (cdr r))
               (cond ((integerp x) (unless (eql constant 0) (return-from ames-linear-integer-parts nil))
                                   (setq constant x))
                     ((term x) (push (term x) terms))
                     (t (return-from ames-linear-integer-parts nil))))
             (and terms
                  (= (length terms) (length (remove-duplicates (mapcar #'cdr terms))))
                  (values terms constant))))
          ((term r) (values (list (term r)) 0)))))

(defun ames-sum-term-variable (x)
  "The variable of X when X is a variable of the bridge (AMES-LINEAR-VARIABLE-P) or an
integer times one, as a request writes it; else NIL."
  (cond ((ames-linear-variable-p x) x)
        ((and (consp x) (consp (car x)) (eq (caar x) 'mtimes) (null (cdar x))
              (= (length x) 3) (integerp (cadr x)) (ames-linear-variable-p (caddr x)))
         (caddr x))))

(defun ames-presortable-sum-p (form)
  "True when FORM is a sum (no flags) of three or more arguments, at most one an integer,
the others distinct variables or integer multiples of them (AMES-SUM-TERM-VARIABLE):
one whose order AMES-PRESORT-SUMS chooses. Presorting inside FORM does not change
whether it is one (it only reorders arguments)."
  (and (consp form) (consp (car form)) (eq (caar form) 'mplus) (null (cdar form))
       (cdddr form)
       (<= (count-if #'integerp (cdr form)) 1)
       (every #'(lambda (x) (or (integerp x) (ames-sum-term-variable x))) (cdr form))
       (let ((variables (mapcar #'ames-sum-term-variable (remove-if #'integerp (cdr form)))))
         (= (length variables) (length (remove-duplicates variables :test #'eq))))))

(defun ames-variable-ranks (form)
  "An EQ hash table: each variable of the presortable sums within FORM
(AMES-PRESORTABLE-SUM-P) -> its rank in descending order of Maxima's GREAT (0 the
greatest); NIL when FORM has no such sum. One sort of the distinct variables, by GREAT,
instead of one per sum (GREAT of two symbols is slow: a sort of each of 48 sums of 64
widths took 0.2 s)."
  (let ((seen (make-hash-table :test #'eq))
        (variables '()))
    (labels ((walk (x)
               (when (and (consp x) (consp (car x)))
                 (if (ames-presortable-sum-p x)
                     (dolist (term (cdr x))
                       (let ((variable (and (not (integerp term)) (ames-sum-term-variable term))))
                         (when (and variable (not (gethash variable seen)))
                           (setf (gethash variable seen) t)
                           (push variable variables))))
                     (mapc #'walk (cdr x))))))
      (walk form))
    (when variables
      (let ((ranks (make-hash-table :test #'eq)))
        (loop for variable in (sort variables #'(lambda (a b) (great a b)))
              for rank from 0
              do (setf (gethash variable ranks) rank))
        ranks))))

(defun ames-presort-sums (form &optional (ranks (ames-variable-ranks form)))
  "FORM with the arguments of each sum of distinct variables (or integer multiples of
them: AMES-PRESORTABLE-SUM-P) put in descending order, their integer constant last:
the order in which Maxima's simplifier inserts them fastest (it inserts each term into
the sorted sum from its head: a sum given in ascending order takes time quadratic in
its length). Such a sum simplifies to the same form whatever the order of its terms;
other forms are left as they are. The order is GREAT's, read from RANKS
(AMES-VARIABLE-RANKS of the whole form)."
  (cond ((or (null ranks) (atom form) (atom (car form))) form)
        ((ames-presortable-sum-p form)
         (cons (car form)
               (append (sort (remove-if #'integerp (copy-list (cdr form)))
                             #'(lambda (a b) (< (gethash (ames-sum-term-variable a) ranks)
                                                (gethash (ames-sum-term-variable b) ranks))))
                       (remove-if-not #'integerp (cdr form)))))
        (t (cons (car form) (mapcar #'(lambda (x) (ames-presort-sums x ranks)) (cdr form))))))

(defun ames-linear-ratsimp (expr)
  "ratsimp(EXPR) as a request gets it (simplified again), computed without ratsimp()
when EXPR is a linear form in distinct variables with integer coefficients
(AMES-LINEAR-INTEGER-PARTS): the same terms, each product marked as ratsimp() marks
it; NIL for any other EXPR."
  (multiple-value-bind (terms constant) (ames-linear-integer-parts expr)
    (when terms
      (simplifya (cons (list 'mplus)
                       (cons constant
                             (mapcar #'(lambda (term)
                                         (if (eql (car term) 1)
                                             (cdr term)
                                             (list (list 'mtimes 'simp 'ratsimp) (car term) (cdr term))))
                                     terms)))
                 nil))))

(defun ames-linear-factor (r)
  "factor(R) computed without factor() when R is a linear form in distinct variables
with integer coefficients (AMES-LINEAR-INTEGER-PARTS): the content of R (the gcd of
its coefficients, with the sign of the coefficient of its main variable, the greatest
under Maxima's ordering) times the rest, which is irreducible, structured as factor()
structures it; NIL for any other R (then factor() is asked)."
  (multiple-value-bind (terms constant) (ames-linear-integer-parts r)
    (when terms
      (let* ((main (reduce #'(lambda (a b) (if (great (cdr a) (cdr b)) a b)) terms))
             (content (* (signum (car main))
                         (reduce #'gcd (mapcar #'car terms) :initial-value constant))))
        (if (and (null (cdr terms)) (eql constant 0))
            (if (eql (car main) 1)
                (cdr main)
                (list (list 'mtimes 'simp 'factored) (car main) (cdr main)))
            (let ((sum (simplifya
                        (cons (list 'mplus)
                              (cons (/ constant content)
                                    (mapcar #'(lambda (term)
                                                (let ((c (/ (car term) content)))
                                                  (if (eql c 1)
                                                      (cdr term)
                                                      (list (list 'mtimes 'simp 'ratsimp) c (cdr term)))))
                                            terms)))
                        nil)))
              (if (eql content 1)
                  (cons (list 'mplus 'simp 'irreducible 'factored) (cdr sum))
                  (list (list 'mtimes 'simp 'factored) content
                        (cons (list 'mplus 'simp 'irreducible) (cdr sum))))))))))

(defun $ames_simplification_candidates (expr trigonometric radicals)
  "The forms the bridge's simplest-form compares, each computed once (a request listing
them as separate calls computes ratsimp(EXPR) and trigsimp(EXPR) twice):
[ratsimp(EXPR), trigsimp(EXPR), ratsimp(trigsimp(EXPR)), factor(ratsimp(EXPR)), radcan(EXPR),
radcan(trigsimp(EXPR))],
trigsimp as $AMES_TRIGSIMP computes it. When TRIGONOMETRIC is false (EXPR has no sin,
cos or tan, so that trigsimp(EXPR) is ratsimp(EXPR) again), the two trigsimp forms are
left out; when RADICALS is false (EXPR has no radical, logarithm or power with a
symbolic or fractional exponent, where radcan(EXPR) is ratsimp(EXPR) again),
radcan(EXPR) is left out; radcan(trigsimp(EXPR)) needs both (a square root whose
argument is a square once sin^2 + cos^2 = 1 is used)."
  (let* ((ratsimped (or (ames-linear-ratsimp expr) (ames-call '$ratsimp expr)))
         (trigsimped (and trigonometric ($ames_trigsimp expr))))
    ;; factor and radcan, which only offer a smaller form, are left out where they fail
    (cons '(mlist simp)
          (remove nil
                  (append (list ratsimped)
                          (and trigonometric (list trigsimped (ames-call '$ratsimp trigsimped)))
                          (and (not (ames-big-integer-p ratsimped))
                               (list (or (ames-linear-factor ratsimped)
                                         (ames-call-or-nil '$factor ratsimped))))
                          (and radicals (list (ames-call-or-nil '$radcan expr)))
                          (and radicals trigonometric (list (ames-call-or-nil '$radcan trigsimped))))))))

;;; Presentation (src/maxima-bridge/presentation.lisp): the forms a textbook writes, and
;;; Maxima's tex() of a form exactly as the bridge structured it.

(defun ames-scanmap-factorsum (expr)
  "scanmap(factorsum, EXPR): every sum within EXPR grouped into factorable parts
((l2^2 - 2 l1 l2 + l1^2) mb + l3^2 ma becomes (l2 - l1)^2 mb + l3^2 ma)."
  (meval (list '($scanmap) '$factorsum (list '(mquote) expr))))

(defun $ames_presentation_candidates (expr trigonometric)
  "The forms of EXPR a presentation chooses from, each equal to EXPR by Maxima's own
algebra: [r, factor(r), scanmap(factorsum, factor(r)), multthru(r)] for r = ratsimp(EXPR)
(multthru: a quotient of a sum split into a sum of quotients) and, when
TRIGONOMETRIC is true, also for r = ratsimp(trigsimp(EXPR)) (sin^2 + cos^2 = 1, tan as
sin/cos), in that order. A base with a big integer (AMES-BIG-INTEGER-P) stands for
its factor(r) too."
  (let ((bases (cons (or (ames-linear-ratsimp expr) (ames-call '$ratsimp expr))
                     (and trigonometric
                          (list (ames-call '$ratsimp ($ames_trigsimp expr)))))))
    (cons '(mlist simp)
          (loop for base in bases
                for factored = (cond ((ames-big-integer-p base) base)
                                     ((ames-linear-factor base))
                                     (t (ames-call '$factor base)))
                append (list base factored (ames-scanmap-factorsum factored)
                             (ames-call '$multthru base))))))

(defun $ames_presentation_coefficients (expr var)
  "The list [c0, c1, ..., cd] with EXPR = c0 + c1 VAR + ... + cd VAR^d and every ci free
of VAR (each ratsimp'd), or false when EXPR is no such polynomial in VAR."
  (let ((coefficients ($ames_polynomial_coefficients expr var))
        (denominator ($denom ($ratsimp expr))))
    (and coefficients
         (cons '(mlist simp)
               (mapcar #'(lambda (c) (ames-call '$ratsimp (div c denominator)))
                       (cdr coefficients))))))

(defmspec $ames_tex_as_is (form)
  "tex(X, false) for the unevaluated argument X of FORM, printed exactly as it is
structured (simp:false): the order of terms and factors, quotients and negations are the
caller's. Returns the TeX string."
  (let (($simp nil))
    (meval (list '($tex) (list '(mquote) (cadr form)) nil))))

(defun ames-square-root-kernel (form)
  "Some subform sqrt(A) = ((MEXPT) A ((RAT) 1 2)) of FORM: the first met depth-first,
the form itself before its arguments, left to right; NIL when there is none."
  (cond ((atom form) nil)
        ((and (consp (car form)) (eq (caar form) 'mexpt)
              (consp (caddr form)) (consp (car (caddr form))) (eq (caar (caddr form)) 'rat)
              (eql (cadr (caddr form)) 1) (eql (caddr (caddr form)) 2))
         form)
        (t (some #'ames-square-root-kernel (cdr form)))))

(defun ames-apply (function &rest arguments)
  "FUNCTION(ARGUMENTS...) evaluated as meval evaluates it in a request (the arguments,
already values, quoted so that they are not evaluated twice)."
  (meval (cons (list function) (mapcar #'(lambda (a) (list '(mquote) a)) arguments))))

(defun $ames_square_root_parts (difference)
  "The list [n, d, k, a, b] for DIFFERENCE = n / d (num and denom of its ratsimp), k a
square root sqrt(A) in n (AMES-SQUARE-ROOT-KERNEL) and n = a + b k exactly: expand(n)
with k written as a fresh z (ratsubst(), which also reads sin(x)^(3/2) as z^3 and
2^(5/2) as z^5), its remainder by z^2 - A, whose coefficients of z^0 and z^1 are a and b;
[n, d] when n has no square root, or a or b still holds z. The requests the bridge's
SQUARE-ROOT-PART-SIGNS asked one after the other, in one. A numerator with a root that
AMES-VALIDATE refuses (%i) is an error, as the request that sent it back was refused."
  (let* ((simplified (ames-apply '$ratsimp difference))
         (numerator (ames-apply '$num simplified))
         (denominator (ames-apply '$denom simplified))
         (kernel (ames-square-root-kernel numerator))
         (expanded (and kernel
                        ;; the numerator went back to the server in a request of its
                        ;; own when there was a root: refused as that request was
                        (if (ames-validate numerator)
                            (merror "AMES server: the numerator is not allowed in a request")
                            (ames-apply '$expand numerator))))
         (z '$ames_root_z)
         (linear (and kernel
                      ;; hipow() and ratcoef() of expand(n) in k disagree on powers of
                      ;; k written as powers of A (sin(x)^(3/2), 2^(5/2)): reduce
                      ;; the polynomial in z modulo z^2 = A instead
                      (ames-apply '$ratdisrep
                                  (ames-apply '$remainder (ames-apply '$ratsubst z kernel expanded)
                                              (sub (power z 2) (second kernel)) z))))
         (a (and linear (ames-apply '$ratcoef linear z 0)))
         (b (and linear (ames-apply '$ratcoef linear z 1))))
    (if (and linear ($freeof z a) ($freeof z b))
        (list '(mlist simp) numerator denominator kernel a b)
        (list '(mlist simp) numerator denominator))))

(defmspec $ames_each (form)
  "The list of the answers to the unevaluated requests of FORM, each evaluated as
AMES-EVALUATE evaluates a request and given as [answer], or as [] when Maxima fails on
it (its bindings undone as AMES-EVALUATE undoes a failed request's): the bridge asks
several requests in one round trip, and one that fails does not lose the others."
  (cons '(mlist simp)
        (mapcar #'(lambda (request)
                    (let ((saved (cons bindlist loclist)))
                      (handler-case
                          (list '(mlist simp) (ames-disrep (rat-error-to-merror (meval request))))
                        (maxima-$error () (errlfun1 saved) (list '(mlist simp))))))
                (cdr form))))

(dolist (head '($ames_presentation_candidates $ames_presentation_coefficients $ames_tex_as_is
                $ames_each $ames_square_root_parts))
  (pushnew head *ames-allowed-heads*))
