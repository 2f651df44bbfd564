;;;; src/simulator/elimination.lisp -- the definitions of a state's model eliminated in one
;;;; pass: each equation is rewritten once, however many definitions reach it.
;;;;
;;;; A definition is an equation (= TERM EXPR) with TERM an unknown free of EXPR; it is
;;;; eliminated by substituting EXPR for TERM wherever TERM occurs. Substituting each
;;;; definition into the equations that mention it as it is found walks an equation once
;;;; per definition that reaches it: a chain of N blocks has chains of N definitions
;;;; (acc b1 = rel-acc b1 b2 + acc b2, acc b2 = ...), and its elimination cost grew as N^3.
;;;; Here the elimination is decided on the equations' sets of unknowns alone (which
;;;; unknown a side is, which unknowns the other side holds, both kept up to date as
;;;; definitions are found), and each equation is written out once, at the end (a
;;;; definition's expression when it is found), by one walk that substitutes every
;;;; eliminated unknown by its value (composed with the later definitions). The order of
;;;; elimination, the definitions and the equations returned are those of substituting
;;;; one definition at a time (the sequential substitution composes to the same trees).

(in-package #:ames.simulator)

(defstruct (elimination (:constructor %make-elimination))
  "The state of an elimination. IDS: unknown term -> index (EQUAL table); TERMS: index ->
term; VALUE: index -> the expression of its definition when eliminated (as it was then),
else NIL; GONE-TERM: index -> 1 when eliminated; ARITY: equation index -> its number of
arguments (0 once it is a definition eliminated); HELD: the set of (equation, argument,
live unknown) such that the argument holds the unknown, as keys (see HELD-KEY) of an EQL
table; MENTIONS: term index -> the equations whose arguments hold it (or held it while it
was live); MARK and STAMP: a scratch array for collecting sets without duplicates."
  (ids (make-hash-table :test #'equal))
  (terms (make-array 0 :adjustable t :fill-pointer t))
  (value #() :type simple-vector)
  (gone-term #* :type simple-bit-vector)
  (arity #() :type simple-vector)
  (stride 1 :type fixnum)
  (held (make-hash-table :test #'eql))
  (mentions #() :type simple-vector)
  (mark #() :type simple-vector)
  (stamp 0 :type fixnum))

(defun held-key (state index argument id)
  "The key of HELD for argument number ARGUMENT of equation INDEX and the unknown ID."
  (+ id (* (length (elimination-value state))
           (+ argument (* (elimination-stride state) index)))))

(defun held-p (state index argument id)
  "True when argument ARGUMENT of equation INDEX holds the live unknown ID."
  (gethash (held-key state index argument id) (elimination-held state)))

(defun (setf held-p) (value state index argument id)
  "Record whether argument ARGUMENT of equation INDEX holds the unknown ID."
  (if value
      (setf (gethash (held-key state index argument id) (elimination-held state)) t)
      (remhash (held-key state index argument id) (elimination-held state))))

(defun equation-holds-p (state index id)
  "True when some argument of equation INDEX holds the live unknown ID."
  (loop for argument below (aref (elimination-arity state) index)
          thereis (held-p state index argument id)))

(defun make-elimination (equations unknowns)
  "The elimination of EQUATIONS (a vector) for UNKNOWNS, before any definition is found."
  (let ((state (%make-elimination)))
    (dolist (unknown unknowns)
      (when (and (quantity-term-p unknown)
                 (not (nth-value 1 (gethash unknown (elimination-ids state)))))
        (setf (gethash unknown (elimination-ids state)) (fill-pointer (elimination-terms state)))
        (vector-push-extend unknown (elimination-terms state))))
    (let ((n (fill-pointer (elimination-terms state))))
      (setf (elimination-value state) (make-array n :initial-element nil)
            (elimination-gone-term state) (make-array n :element-type 'bit :initial-element 0)
            (elimination-mentions state) (make-array n :initial-element '())
            (elimination-mark state) (make-array n :initial-element -1)
            (elimination-arity state) (map 'simple-vector (lambda (e) (length (rest e))) equations)
            (elimination-stride state) (reduce #'max (elimination-arity state) :initial-value 1)))
    (dotimes (index (length equations) state)
      (loop for argument in (rest (aref equations index))
            for k from 0
            do (dolist (id (live-unknowns state argument))
                 (unless (equation-holds-p state index id)
                   (push index (aref (elimination-mentions state) id)))
                 (setf (held-p state index k id) t))))))

(defun live-id (state x)
  "The index of X when X is one of STATE's unknowns not yet eliminated, else NIL."
  (let ((id (gethash x (elimination-ids state))))
    (and id (zerop (aref (elimination-gone-term state) id)) id)))

(defun live-unknowns (state expression)
  "The indexes of the live unknowns occurring in EXPRESSION (as FREE-OF-P finds them:
quantity terms are not looked into), each once."
  (let ((found '())
        (stamp (incf (elimination-stamp state)))
        (mark (elimination-mark state)))
    (labels ((walk (x)
               (cond ((quantity-term-p x)
                      (let ((id (live-id state x)))
                        (when (and id (/= (aref mark id) stamp))
                          (setf (aref mark id) stamp)
                          (push id found))))
                     ((consp x) (mapc #'walk (cdr x))))))
      (walk expression))
    found))

(defun current-form (state expression &optional memo)
  "EXPRESSION with every eliminated unknown replaced by its value, itself written in
current form (SUBSTITUTE-EXPRESSIONS of each definition in turn gives the same tree).
MEMO, an array by term index, keeps each value written once (only while no further
definition is found)."
  (labels ((walk (x)
             (cond ((quantity-term-p x)
                    (let ((id (gethash x (elimination-ids state))))
                      (cond ((or (null id) (zerop (aref (elimination-gone-term state) id))) x)
                            ((null memo) (walk (aref (elimination-value state) id)))
                            ((aref memo id))
                            (t (setf (aref memo id) (walk (aref (elimination-value state) id)))))))
                   ((consp x) (cons (car x) (mapcar #'walk (cdr x))))
                   (t x))))
    (walk expression)))

(defun current-term (state expression)
  "The quantity term EXPRESSION is in current form (an eliminated unknown followed to its
value while that is a term), or NIL when it is not a term."
  (loop (unless (quantity-term-p expression) (return nil))
        (let ((id (gethash expression (elimination-ids state))))
          (if (and id (= 1 (aref (elimination-gone-term state) id)))
              (setf expression (aref (elimination-value state) id))
              (return expression)))))

(defun found-definition (state equation index)
  "When EQUATION (number INDEX) is, in current form, (= TERM EXPR) or (= EXPR TERM) with
TERM a live unknown not occurring in EXPR: (values TERM's index and the argument of
EQUATION that is EXPR), the left-hand side tried first; else NIL."
  (flet ((try (side other other-argument)
           (let* ((term (current-term state side))
                  (id (and term (live-id state term))))
             (when (and id (not (held-p state index other-argument id)))
               (return-from found-definition (values id other))))))
    (try (relation-lhs equation) (relation-rhs equation) 1)
    (try (relation-rhs equation) (relation-lhs equation) 0)
    nil))

(defun eliminate-term (state id expression index pending)
  "Record that the unknown ID is eliminated with value EXPRESSION (in current form) by
equation INDEX: every other equation holding it now holds EXPRESSION's live unknowns
instead and becomes PENDING (a bit vector). Returns the earliest equation changed (or
INDEX)."
  (setf (aref (elimination-value state) id) expression
        (aref (elimination-gone-term state) id) 1
        ;; the defining equation is gone: none of its arguments is looked at again
        (aref (elimination-arity state) index) 0)
  (let ((added (live-unknowns state expression))
        (mentions (elimination-mentions state))
        (earliest index))
    (dolist (other (aref mentions id) earliest)
      (when (equation-holds-p state other id)
        (dolist (new added)
          (unless (equation-holds-p state other new)
            (push other (aref mentions new))))
        (dotimes (argument (aref (elimination-arity state) other))
          (when (held-p state other argument id)
            (setf (held-p state other argument id) nil)
            (dolist (new added)
              (setf (held-p state other argument new) t))))
        (setf (aref pending other) 1
              earliest (min earliest other))))))

(defun eliminate-definitions (equations unknowns)
  "Eliminate from EQUATIONS every unknown that one of them defines outright (an equation
(= TERM EXPR) or (= EXPR TERM), TERM one of UNKNOWNS not occurring in EXPR, as the
equation reads once the definitions found before it are substituted): returns the
remaining equations (with the definitions substituted, zero terms folded, those that
became X = X dropped) and the definitions, an alist term -> expression in the order they
were eliminated (an expression may mention terms eliminated later, never earlier). The
first equation (in order) that is a definition is eliminated first, then the earliest
one changed by it, and so on; each equation is written out once."
  (let* ((remaining (coerce equations 'vector))
         (count (length remaining))
         (state (make-elimination remaining unknowns))
         (gone (make-array count :element-type 'bit :initial-element 0))
         (pending (make-array count :element-type 'bit :initial-element 1))
         (definitions '())
         (next 0))
    ;; only an equation changed by a definition can become one: look at each pending
    ;; one in order, from the earliest
    (loop while (< next count)
          do (if (zerop (aref pending next))
                 (incf next)
                 (let ((equation (aref remaining next)))
                   (setf (aref pending next) 0)
                   (multiple-value-bind (id side) (found-definition state equation next)
                     (when id
                       (let ((expression (current-form state side)))
                         (setf (aref gone next) 1)
                         (push (cons (aref (elimination-terms state) id) expression) definitions)
                         (setf next (eliminate-term state id expression next pending))))))))
    (let ((memo (make-array (length (elimination-value state)) :initial-element nil)))
      (values (remove-if (lambda (equation)
                           (equal (relation-lhs equation) (relation-rhs equation)))
                         (loop for index below count
                               when (zerop (aref gone index))
                                 collect (fold-zeros (current-form state (aref remaining index) memo))))
              (nreverse definitions)))))
