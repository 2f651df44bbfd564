;;;; src/algebra/orders.lisp -- the last strategy of DECIDE: the orderings of the parameters substituted.
;;;;
;;;; Maxima's sign() uses a fact V > E only where V stands alone. A fact that orders a
;;;; variable V of the relation against an expression E (V > E, or any fact linear in V,
;;;; such as w < h - g d^2/(2 v0^2), which says h > w + g d^2/(2 v0^2)) lets DECIDE write V as
;;;; E + D with D > 0 fresh, after which sums show their signs term by term.

(in-package #:ames.algebra)

(defun coefficient-sign (bridge coefficient)
  "1 or -1 when COEFFICIENT is proven positive or negative under the facts in force (a
number, or DECIDE without the order substitution); else NIL."
  (if (realp coefficient)
      (cond ((plusp coefficient) 1) ((minusp coefficient) -1))
      (let ((*substituting-orders* t))
        (cond ((eq :true (decide bridge (list '> coefficient 0))) 1)
              ((eq :true (decide bridge (list '< coefficient 0))) -1)))))

(defun linear-parts (bridge difference variable)
  "(values C R) with DIFFERENCE = C VARIABLE + R, R free of VARIABLE: from the sum's
terms when VARIABLE stands alone in one with a rational coefficient, else from
Maxima's expansion in VARIABLE when DIFFERENCE is of degree 1 in it; NIL otherwise."
  (let* ((terms (linear-terms difference))
         (coefficient (cdr (assoc variable terms :test #'eq)))
         (rest (remove variable terms :key #'car :test #'eq)))
    (if (and (rationalp coefficient)
             (every (lambda (entry) (free-of-p variable (car entry))) rest))
        (values coefficient (linear-expression rest))
        (let ((coefficients (handler-case (polynomial-coefficients bridge difference variable)
                              (maxima-condition () nil))))
          (when (= 2 (length coefficients))
            (values (second coefficients) (first coefficients)))))))

(defun linear-order (bridge fact variable)
  "The ordering (VARIABLE E SIGN WEAK) the relation FACT gives when it is linear in
VARIABLE with a coefficient c of proven sign: c V + R > 0 gives V > -R/c for c > 0 and
V < -R/c for c < 0 (SIGN 1 or -1), c V + R = 0 gives V = -R/c (SIGN 0); E is free of
VARIABLE. NIL otherwise."
  (let ((operator (expression-operator fact)))
    (multiple-value-bind (coefficient remainder)
        (linear-parts bridge (list '- (relation-lhs fact) (relation-rhs fact)) variable)
      (let ((sign (and coefficient (coefficient-sign bridge coefficient))))
        (when sign
          (list variable
                (if (realp coefficient)
                    (linear-expression (mapcar (lambda (entry) (cons (car entry) (/ (cdr entry) (- coefficient))))
                                               (linear-terms remainder)))
                    (list '- (list '/ remainder coefficient)))
                (cond ((eq operator '=) 0)
                      ((eq (and (member operator '(> >=)) t) (plusp sign)) 1)
                      (t -1))
                (and (member operator '(>= <=)) t)))))))

(defparameter *largest-relation-for-solved-orders* 60
  "Facts solved for a variable (see LINEAR-ORDER) are substituted only into relations of
at most this many atoms and operators: solving costs Maxima requests, and a large
relation with rational expressions put for its variables grows past what Maxima
decides in time (the corner's cubics took minutes), where the small relations of a
textbook bound are decided at once.")

(defun order-facts (bridge relation &key solved)
  "The facts in force that order a variable V of RELATION against an expression E free of
V and not a number, as lists (V E SIGN WEAK): V is E + SIGN * D for some D > 0 (D >= 0
when WEAK; V is E when SIGN is 0, from an equation). These are the orderings Maxima's
sign() does not use inside sums. Without SOLVED, the facts with V alone on a side (V >
E, E < V ...); with SOLVED, the equations V = E and the facts with no variable of
RELATION alone on a side, each solved for the first variable of RELATION it is linear
in (see LINEAR-ORDER). A bound by a square root is read squared too (SQUARED-ROOT-FACTS)."
  (flet ((useful-p (order)
           (and order
                (free-of-p (first order) (second order))
                (not (numberp (second order)))
                (not (free-of-p (first order) relation)))))
    (loop for fact in (let ((facts (current-assumptions bridge)))
                        ;; a bound by a square root counts squared too (v0 < sqrt(2 g r) is
                        ;; v0^2 < 2 g r, linear in g and in r)
                        (append facts (squared-root-facts (flatten-facts facts))))
          for operator = (expression-operator fact)
          for lhs = (relation-lhs fact)
          for rhs = (relation-rhs fact)
          for weak = (and (member operator '(>= <=)) t)
          for sign = (case operator ((> >=) 1) ((< <=) -1) (= 0))  ; of lhs against rhs
          for alone = (cond ((null sign) nil)
                            ((variable-symbol-p lhs) (list lhs rhs sign weak))
                            ((variable-symbol-p rhs) (list rhs lhs (- sign) weak)))
          for order = (cond ((null sign) nil)
                            ((not solved) (and (/= sign 0) (useful-p alone) alone))
                            ((useful-p alone) (and (= sign 0) alone))
                            (t (loop for variable in (expression-variables relation)
                                     for solved = (and (not (free-of-p variable fact))
                                                       (linear-order bridge fact variable))
                                     when (useful-p solved) return solved)))
          when order
            collect order)))

(defun decide-by-order-substitution (bridge relation)
  "Decide RELATION once more after writing each ordered variable V (see ORDER-FACTS) as
E + D or E - D with D > 0 fresh: sums such as mb g (l1 - l2)^2 + f (l1 - l2) then show
their sign term by term. First the facts with V alone on a side, all at once and then
each alone (writing V = E - D forgets V > 0); then, for a small relation (see
*LARGEST-RELATION-FOR-SOLVED-ORDERS*), each other fact solved for one of its variables
(V = E exactly for an equation). Sound: every admissible V is some E +/- D (or E).
:UNKNOWN when no such fact decides it."
  (flet ((each-alone (orders)
           (loop for order in orders
                 for single = (decide-with-orders bridge relation (list order))
                 unless (eq single :unknown) return single
                 finally (return :unknown))))
    (if *substituting-orders*
        :unknown
        (let* ((orders (order-facts bridge relation))
               (verdict (cond ((null orders) :unknown)
                              ((null (rest orders)) (decide-with-orders bridge relation orders))
                              (t (let ((together (decide-with-orders bridge relation orders)))
                                   (if (eq together :unknown) (each-alone orders) together))))))
          (when (and (eq verdict :unknown)
                     (<= (expression-size relation) *largest-relation-for-solved-orders*))
            (setf verdict (each-alone (order-facts bridge relation :solved t))))
          (if (and (eq verdict :unknown)
                   (<= (expression-size relation) *largest-relation-for-solved-orders*))
              ;; bounds carried through x -> x^2 (square-orders.lisp), on small relations
              ;; only, like the solved orders
              (decide-by-square-orders bridge relation)
              verdict)))))

(defun order-excess-name (bridge variable)
  "The fresh variable D standing for the excess of VARIABLE over its bound (V = E + D or
E - D) in DECIDE-BY-ORDER-SUBSTITUTION: an uninterned symbol, so no user name can be
it, and the same one each time for a VARIABLE of BRIDGE, so that the rewritten requests
are answered from the cache when they come again."
  (keyed-auxiliary-variable bridge variable (format nil "~A-EXCESS" variable)))

(defun decide-with-orders (bridge relation orders)
  "DECIDE-BY-ORDER-SUBSTITUTION's work for the given ORDERS (see ORDER-FACTS)."
  (let* ((*substituting-orders* t)
         (deltas (loop for order in orders
                       collect (order-excess-name bridge (first order))))
         (bindings (loop for (variable base sign) in orders
                         for delta in deltas
                         collect (cons variable (if (zerop sign)
                                                    base
                                                    (list '+ base (list '* sign delta))))))
         (facts (loop for (nil nil sign weak) in orders
                      for delta in deltas
                      unless (zerop sign)
                        collect (list (if weak '>= '>) delta 0))))
    ;; substitute one ordering after another, and again, so that a bound written with
    ;; another ordered variable (f > mb g (l1 - l2) / l3 with l1 > l2) is rewritten too
    (let ((rewritten relation))
      (loop repeat 3
            do (dolist (binding bindings)
                 (setf rewritten (substitute-expressions (list binding) rewritten))))
      ;; a rewriting that leaves the reals (a square root of a negative quantity)
      ;; proves nothing: Maxima's complaint then means :UNKNOWN
      (handler-case (call-with-assumptions bridge facts
                                           (lambda () (decide bridge rewritten)))
        (maxima-error () :unknown)))))
