;;;; src/simulator/simplest-conditions.lisp -- a condition (a disjunction of conjunctions of sign
;;;; conditions, as a parameter selection answers) in its plainest equivalent form under the
;;;; assumptions in force (issue 26): the angle of repose is tan a <= mu, not the facts of
;;;; three branches.
;;;;
;;;; Each relation is brought to (OP E 0); factors of E whose sign is proven are cancelled
;;;; (a negative one flips OP; for = any factor proven non-zero goes); where cos x > 0 is
;;;; proven, E/cos x is taken when that removes sin x and cos x (the tan form); relations
;;;; the assumptions (and the other conditions of the same conjunction) prove are dropped,
;;;; conjunctions with one proven false are dropped; two conjunctions that differ in one
;;;; relation on the same E are merged (< or = gives <=; < or = or > gives nothing left
;;;; to ask). The result is checked against the original at sample points that satisfy the
;;;; assumptions; where they differ, or too few points are found, the original is kept.

(in-package #:ames.simulator)

(defun flipped (operator)
  "OPERATOR with the sides exchanged (the relation of -E)."
  (ecase operator (< '>) (> '<) (<= '>=) (>= '<=) (= '=)))

(defun proven (bridge relation)
  "DECIDE's verdict on RELATION, :UNKNOWN where it signals."
  (handler-case (ames.algebra:decide bridge relation)
    (ames-error () :unknown)))

(defun product-factors (e)
  "The multiplicative factors of E (a quotient's denominator's too; a negation gives -1)."
  (cond ((and (consp e) (eq (first e) '-) (= 2 (length e))) (cons -1 (product-factors (second e))))
        ((and (consp e) (eq (first e) '*)) (mapcan #'product-factors (copy-list (rest e))))
        ((and (consp e) (eq (first e) '/)) (append (product-factors (second e)) (mapcan #'product-factors (copy-list (cddr e)))))
        (t (list e))))

(defun cancel-signed-factors (bridge operator e)
  "(OP E') with the factors of E of proven sign cancelled."
  (let ((kept '()) (op operator))
    (dolist (f (product-factors e))
      (cond ((numberp f) (when (minusp f) (setf op (flipped op))))
            ((eq :true (proven bridge `(> ,f 0))))
            ((eq :true (proven bridge `(< ,f 0))) (setf op (flipped op)))
            ((and (eq op '=) (eq :true (proven bridge `(/= ,f 0)))))
            (t (push f kept))))
    (list op (cond ((null kept) 1) ((rest kept) (cons '* (reverse kept))) (t (first kept))))))

(defun tan-form (bridge e)
  "E / cos x with sin x written tan x cos x, when that removes sin x and cos x and cos x > 0
is proven; else E."
  (let ((angle (let ((found nil))
                 (labels ((walk (x) (cond ((and (consp x) (eq (first x) 'cos)) (setf found (second x)))
                                          ((consp x) (mapc #'walk (rest x))))))
                   (walk e))
                 found)))
    (if (and angle (eq :true (proven bridge `(> (cos ,angle) 0))))
        (let ((tangent (handler-case
                           (ames.maxima:simplify
                            bridge `(/ ,(subst `(* (tan ,angle) (cos ,angle)) `(sin ,angle) e :test #'equal)
                                       (cos ,angle)))
                         (ames-error () nil))))
          (if (and tangent (free-of-p `(sin ,angle) tangent) (free-of-p `(cos ,angle) tangent))
              tangent
              e))
        e)))

(defun plain-relation (bridge relation)
  "RELATION as (OP E 0) in its plainest form, or :TRUE or :FALSE when proven."
  (let ((verdict (proven bridge relation)))
    (if (member verdict '(:true :false))
        verdict
        (let* ((e (handler-case (ames.maxima:simplify bridge `(- ,(relation-lhs relation) ,(relation-rhs relation))
                                                      :strategy :full)
                    (ames-error () `(- ,(relation-lhs relation) ,(relation-rhs relation)))))
               (cancelled (cancel-signed-factors bridge (first relation) e))
               (plain (list (first cancelled) (tan-form bridge (second cancelled)) 0))
               (verdict (proven bridge plain)))
          (if (member verdict '(:true :false)) verdict plain)))))

(defun plain-conjunction (bridge conjunction)
  "CONJUNCTION's relations in their plainest forms, each under the others too; :TRUE
when all are proven, :FALSE when one is proven false."
  (let ((plain (loop for r in conjunction
                     for p = (plain-relation bridge r)
                     when (eq p :false) do (return-from plain-conjunction :false)
                     unless (eq p :true) collect p)))
    (let ((again (loop for r in plain
                       for others = (remove r plain :test #'eq)
                       for p = (handler-case (ames.maxima:with-assumptions (bridge others) (plain-relation bridge r))
                                 (ames-error () r))
                       when (eq p :false) do (return-from plain-conjunction :false)
                       unless (eq p :true) collect p)))
      (or again :true))))

(defun merged-pair (bridge a b)
  "The conjunction that is A or B when they differ in one relation on the same E, or NIL;
:TRUE when that relation is then always met and nothing else is asked."
  (when (= (length a) (length b))
    (let ((only-a (set-difference a b :test #'equal))
          (only-b (set-difference b a :test #'equal)))
      (when (and (= 1 (length only-a)) (= 1 (length only-b)))
        (destructuring-bind ((op-a e-a zero-a)) only-a
          (declare (ignore zero-a))
          (destructuring-bind ((op-b e-b zero-b)) only-b
            (declare (ignore zero-b))
            (let ((op-b (cond ((or (equal e-a e-b) (ignore-errors (ames.maxima:equivalent-p bridge e-a e-b))) op-b)
                              ((ignore-errors (ames.maxima:equivalent-p bridge e-a `(- ,e-b))) (flipped op-b)))))
              (when op-b
                (let ((op (ames.algebra:signs-relation (union (ames.algebra:relation-signs op-a)
                                                              (ames.algebra:relation-signs op-b)))))
                  (cond ((eq op :all) (or (remove (first only-a) a :test #'equal) :true))
                        (op (substitute (list op e-a 0) (first only-a) a :test #'equal))))))))))))

(defun merged-conjunctions (bridge conjunctions)
  "CONJUNCTIONS with pairs merged (see MERGED-PAIR) until none merge; :TRUE when one
becomes always true."
  (loop
    (let ((merge (loop for (a . more) on conjunctions
                       thereis (loop for b in more
                                     for m = (merged-pair bridge a b)
                                     when m return (list a b m)))))
      (unless merge (return conjunctions))
      (destructuring-bind (a b m) merge
        (when (eq m :true) (return :true))
        (setf conjunctions (cons m (remove b (remove a conjunctions :test #'eq) :test #'eq)))))))

(defun disjunction-holds-p (disjunction bindings)
  "Whether the DISJUNCTION of conjunctions holds at BINDINGS: T, NIL, or :UNSURE where a
relation is too near its boundary or has no real value there."
  (flet ((relation-holds (r)
           (let ((v (ignore-errors (expression-value `(- ,(relation-lhs r) ,(relation-rhs r)) bindings))))
             (cond ((not (realp v)) (return-from disjunction-holds-p :unsure))
                   ((< (abs v) 1d-7) (return-from disjunction-holds-p :unsure))
                   (t (ecase (first r) ((< <=) (< v 0)) ((> >=) (> v 0)) (= nil)))))))
    (some (lambda (conjunction) (every #'relation-holds conjunction)) disjunction)))

(defun sample-points (assumptions variables &key (wanted 24) (tries 4000))
  "Up to WANTED bindings of VARIABLES satisfying every relation of ASSUMPTIONS (found by
a fixed pseudo-random search)."
  (let ((state (sb-ext:seed-random-state 20261125)) (points '()))
    (loop repeat tries
          while (< (length points) wanted)
          do (let ((bindings (mapcar (lambda (v)
                                       (cons v (let ((x (* (expt 10 (- (random 2.5d0 state) 1.25d0)) 1d0)))
                                                 (if (< (random 1d0 state) 0.1d0) (- x) x))))
                                     variables)))
               (when (every (lambda (r) (eq t (disjunction-holds-p (list (list r)) bindings))) assumptions)
                 (push bindings points))))
    points))

(defun same-condition-p (original simplified assumptions)
  "True when the disjunctions ORIGINAL and SIMPLIFIED (or :TRUE) agree at enough sample
points satisfying ASSUMPTIONS."
  (let* ((variables (remove-duplicates (append (expression-variables (cons '+ (mapcar #'relation-lhs assumptions)))
                                               (expression-variables (cons '+ (mapcar #'relation-rhs assumptions)))
                                               (expression-variables (list* '+ (mapcan (lambda (r) (list (relation-lhs r) (relation-rhs r)))
                                                                                        (apply #'append original)))))
                                       :test #'equal))
         (agreed 0))
    (dolist (bindings (sample-points assumptions variables) (>= agreed 8))
      (let ((a (disjunction-holds-p original bindings))
            (b (if (eq simplified :true) t (disjunction-holds-p simplified bindings))))
        (unless (or (eq a :unsure) (eq b :unsure))
          (unless (eq (and a t) (and b t)) (return nil))
          (incf agreed))))))

(defun simplest-condition (bridge disjunction assumptions)
  "DISJUNCTION (a list of conjunctions of relations) in its plainest equivalent form under
ASSUMPTIONS (in force in BRIDGE): a list of conjunctions, or :TRUE (always) or :FALSE
(never). The original when the simplified one is not confirmed at sample points."
  (let* ((plain (remove :false (mapcar (lambda (c) (plain-conjunction bridge c)) disjunction)))
         (result (cond ((null plain) :false)
                       ((member :true plain) :true)
                       (t (merged-conjunctions bridge (remove-duplicates plain :test #'equal))))))
    (cond ((eq result :false) (if (same-condition-p disjunction '() assumptions) :false disjunction))
          ((same-condition-p disjunction result assumptions) result)
          (t disjunction))))
