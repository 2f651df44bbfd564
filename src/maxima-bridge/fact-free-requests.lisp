;;;; src/maxima-bridge/fact-free-requests.lisp -- requests whose answer no fact can
;;;; change, cached once for all facts.
;;;;
;;;; The bridge's cache keys an answer by the request and the facts in force
;;;; (ASSUMPTION-KEY): sign(), is() and a simplification of sqrt(x^2) or abs(x) depend on
;;;; them. A rational simplification of a rational form does not: ratsimp(), factor(),
;;;; expand() and the bridge's candidates of a form built of numbers, symbols, sums,
;;;; products and integer powers only compute with polynomials, and never ask Maxima's
;;;; facts. A branch of a run (a fork on a fact) asks much of what its parent or its
;;;; sibling asked before, under other facts: such a request is answered from the cache
;;;; whatever the facts, with the very answer Maxima gave (the same form, not merely an
;;;; equal one).

(in-package #:ames.maxima)

(defparameter *fact-free-heads*
  (mapcar #'wire '("$RATSIMP" "$FACTOR" "$EXPAND" "$NUM" "$DENOM"
                   "$AMES_SIMPLIFICATION_CANDIDATES" "$AMES_POLYNOMIAL_COEFFICIENTS"))
  "The heads of the requests whose answer for a rational form depends on no fact: they
compute with polynomials only (ratsimp, factor, expand, num, denom, and the server's
$AMES_SIMPLIFICATION_CANDIDATES and $AMES_POLYNOMIAL_COEFFICIENTS built of them, whose
radcan() and trigsimp() of a rational form are its ratsimp()).")

(defparameter *rational-heads* (mapcar #'wire '("MPLUS" "MTIMES" "RAT" "MMINUS" "MQUOTIENT"))
  "The heads of a rational form besides MEXPT: sums, products, rational numbers, negation
and quotients.")

(defun rational-form-p (form)
  "True when the Maxima FORM is built of numbers (not floats), symbols, sums, products,
quotients and integer powers only: its rational simplification asks no fact."
  (cond ((symbolp form) t)
        ((rationalp form) t)
        ((atom form) nil)
        ((not (consp (first form))) nil)
        ((member (first (first form)) *rational-heads*)
         (every #'rational-form-p (rest form)))
        ((eq (first (first form)) +mexpt+)
         (and (= (length form) 3) (integerp (third form)) (rational-form-p (second form))))
        (t nil)))

(defun fact-free-request-p (form)
  "True when the answer to the Maxima request FORM depends on no fact in force: a request
of *FACT-FREE-HEADS* whose arguments are rational forms (RATIONAL-FORM-P)."
  (and (consp form) (consp (first form))
       (member (first (first form)) *fact-free-heads*)
       (every #'rational-form-p (rest form))))

(defun request-key (bridge form)
  "The key of the request FORM's answer in BRIDGE's cache: FORM and the facts in force
(ASSUMPTION-KEY), or FORM and :ANY when no fact can change the answer
(FACT-FREE-REQUEST-P)."
  (cons form (if (fact-free-request-p form) :any (assumption-key bridge))))
