;;;; src/algebra/radicals.lisp -- real quantities written with real square roots.
;;;;
;;;; Maxima's algebra keeps a value in the complex numbers' principal branch, so a real
;;;; quantity can come back as a product of square roots of negative quantities: A's speed
;;;; when the blocks in the corner fall is l3 sqrt(-D) sqrt(E)/D with D > 0 and E < 0 (the
;;;; two factors of i make it -l3 sqrt(D) sqrt(-E)/D). Nobody reads the first form, and a
;;;; program evaluating it in the reals cannot. REAL-RADICALS writes such products with the
;;;; radicands negated and the sign the factors of i give: sqrt(x)^m = i^m sqrt(-x)^m for
;;;; x < 0, m odd, the powers i^m multiplying to +1 or -1 in a real product.

(in-package #:ames.algebra)

(defun radical-exponent (form)
  "The exponent of FORM when it is a power of a square root, (sqrt X) or (expt X K/2)
with K odd; else NIL."
  (cond ((and (consp form) (eq (first form) 'sqrt) (= 2 (length form))) 1/2)
        ((and (consp form) (eq (first form) 'expt) (= 3 (length form))
              (rationalp (third form)) (= 2 (denominator (third form))))
         (third form))))

(defun radical-form (base exponent)
  "BASE to the half-integer EXPONENT, written (sqrt BASE) when EXPONENT is 1/2."
  (if (eql exponent 1/2) (list 'sqrt base) (list 'expt base exponent)))

(defun product-form-p (form)
  "True when FORM is a product, a quotient or a negation: the factors REAL-RADICALS
looks through."
  (and (consp form)
       (or (member (first form) '(* /))
           (and (eq (first form) '-) (= 2 (length form))))))

(defun real-radicals (bridge expression)
  "EXPRESSION (arithmetic, prefix algebra) with every product or quotient of square
roots whose radicands are proven negative under the current assumptions rewritten with
those radicands negated, when the factors of i they carry multiply to +1 or -1 (see the
file header); a product whose factors of i do not cancel (its value is not real) is
left as it is. The value is the same (principal branches). DECIDE answers which
radicands are negative; nothing is simplified. Signals what DECIDE signals."
  (labels ((negative-p (base)
             (and (not (realp base))
                  (eq :true (decide bridge (list '< base 0)))))
           (group (form)
             ;; FORM is a product form: rebuild it, noting its negative radicals
             (let ((found '()))
               (labels ((inner (x sign)
                          (cond ((product-form-p x)
                                 (case (first x)
                                   (* (cons '* (mapcar (lambda (a) (inner a sign)) (rest x))))
                                   (/ (list* '/ (inner (second x) sign)
                                             (mapcar (lambda (a) (inner a (- sign))) (cddr x))))
                                   (t (list '- (inner (second x) sign)))))
                                ((radical-exponent x)
                                 (let* ((exponent (radical-exponent x))
                                        (node (radical-form (walk (second x)) exponent)))
                                   (when (negative-p (second node))
                                     (push (cons node (* sign 2 exponent)) found))
                                   node))
                                (t (walk x))))
                        (replaced (x)
                          (let ((entry (assoc x found :test #'eq)))
                            (cond (entry (radical-form (list '- (second x)) (radical-exponent x)))
                                  ((consp x) (cons (first x) (mapcar #'replaced (rest x))))
                                  (t x)))))
                 (let ((rebuilt (inner form 1))
                       (phase (reduce #'+ found :key #'cdr)))
                   (cond ((or (null found) (oddp phase)) rebuilt)
                         ((zerop (mod phase 4)) (replaced rebuilt))
                         (t (list '- (replaced rebuilt))))))))
           (walk (form)
             (cond ((atom form) form)
                   ((or (product-form-p form) (radical-exponent form)) (group form))
                   (t (cons (first form) (mapcar #'walk (rest form)))))))
    (walk expression)))

(defun has-radical-p (form)
  "True when FORM has a power of a square root of something other than a number."
  (and (consp form)
       (or (and (radical-exponent form) (not (realp (second form))))
           (some #'has-radical-p (rest form)))))

(defun simplify-real (bridge expression)
  "EXPRESSION simplified as SIMPLIFY's :FULL strategy does, with any product of square
roots of negative quantities written with real roots (REAL-RADICALS) and simplified
again; the rewritten form unsimplified when simplifying it brings such a product back.
Equal to EXPRESSION in value. Signals what SIMPLIFY and DECIDE signal."
  (let ((simplified (simplify bridge expression :strategy :full)))
    (if (not (has-radical-p simplified))
        simplified
        (let ((real (real-radicals bridge simplified)))
          (if (equal real simplified)
              simplified
              (let ((again (simplify bridge real :strategy :full)))
                (if (equal again (real-radicals bridge again)) again real)))))))

;;; Facts told to Maxima with real roots

(defun fact-as-told (bridge fact)
  "FACT as Maxima is to be told it when assumed: with its products of square roots of
negative radicands written with real roots (REALIFIED-RELATION, truth.lisp), else as given. The
bridge calls it through its hook *TOLD-FACT*."
  (if (product-root-radicands fact)
      (realified-relation bridge fact)
      fact))

(setf *told-fact* 'fact-as-told)
