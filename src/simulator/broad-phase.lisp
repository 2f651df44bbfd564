;;;; src/simulator/broad-phase.lisp -- the broad phase: contacts that cannot be met during a
;;;; state are set aside before the symbolic screening (termination.lisp) looks at them.
;;;;
;;;; Over a state of constant accelerations each coordinate of a body's position is a
;;;; polynomial c0 + c1 tau + c2 tau^2 (its start, velocity and half its acceleration).
;;;; A contact's locus in the configuration space lies within bounds along x and y (a
;;;; segment between its ends, an arc within its circle's box, an axis-parallel line on its
;;;; line). The observer cannot meet it while, along one axis, the relative coordinate
;;;; minus every bound of the locus stays strictly positive (or strictly negative) for
;;;; every tau > 0: every coefficient >= 0 (<= 0) and one of them > 0 (< 0). The signs come
;;;; from exact arithmetic, from the rules of signs over the parameters' declared signs
;;;; (their assumptions, such as m > 0), and, for each body's own acceleration, from the
;;;; bridge (once per body and axis, not per pair). Where none decides, the contact goes
;;;; to the symbolic screening as before: the broad phase only ever says "never", and only
;;;; when that is proven.

(in-package #:ames.simulator)

(defstruct (reach (:constructor %make-reach (run signs-of-parameters solved groups)))
  "What the broad phase knows of the current state: the RUN, solved as SOLVED and
integrated as GROUPS; the parameters' declared signs (SIGNS-OF-PARAMETERS, an alist);
memoized per-body coefficients (COEFFICIENTS: (body axis) -> (c0 c1 c2) or :UNKNOWN) and
the signs the bridge gave (SIGNS)."
  run signs-of-parameters solved groups
  (coefficients (make-hash-table :test #'equal)) (signs (make-hash-table :test #'equal)))

;;; Signs by a sign algebra over the parameters' declared signs (never by Maxima)

(defun parameter-signs (scenario)
  "An alist parameter -> its sign under SCENARIO's assumptions of the form (OP P N) or
(OP N P), N a number: its sign set (:POSITIVE), (:NEGATIVE), (:POSITIVE :ZERO) or
(:NEGATIVE :ZERO), the strongest one implied."
  (let ((signs '()))
    (dolist (relation (scenario-assumption-relations scenario) signs)
      (when (and (consp relation) (member (first relation) '(< <= > >=))
                 (= (length relation) 3))
        (destructuring-bind (op a b) relation
          (multiple-value-bind (parameter bound op)
              (cond ((and (symbolp a) (rationalp b)) (values a b op))
                    ((and (rationalp a) (symbolp b))
                     (values b a (ecase op (< '>) (<= '>=) (> '<) (>= '<=))))
                    (t (values nil nil nil)))
            (let ((sign (and parameter
                             (ecase op
                               (> (and (>= bound 0) (list :positive)))
                               (>= (cond ((> bound 0) (list :positive))
                                         ((= bound 0) (list :positive :zero))))
                               (< (and (<= bound 0) (list :negative)))
                               (<= (cond ((< bound 0) (list :negative))
                                         ((= bound 0) (list :negative :zero))))))))
              (when sign
                (let ((entry (assoc parameter signs)))
                  (cond ((null entry) (push (cons parameter sign) signs))
                        ((one-sign sign) (setf (cdr entry) sign))))))))))))

(defun sign-algebra (signs expression)
  "The sign of EXPRESSION for every admissible value of the parameters, whose signs
SIGNS gives (an alist), by the rules of signs (AMES.ALGEBRA:RULES-OF-SIGNS, the one sign
system): a sign set (all three signs when nothing is known)."
  (let ((table (signs-table signs)))
    (ames.algebra:rules-of-signs (lambda (parameter) (values (gethash parameter table)))
                                 expression)))

(defvar *signs-table* (cons nil nil)
  "(SIGNS . TABLE): the EQL hash table of the last alist SIGNS given to SIGNS-TABLE.")

(defun signs-table (signs)
  "The alist SIGNS (parameter -> sign, as PARAMETER-SIGNS makes it, never changed after)
as an EQL hash table, the first entry of a parameter winning as in ASSOC; the last one
made is reused for the same list."
  (let ((cache *signs-table*))
    (if (and (car cache) (eq (car cache) signs))
        (cdr cache)
        (let ((table (make-hash-table :test #'eql)))
          (dolist (entry (reverse signs))
            (setf (gethash (car entry) table) (cdr entry)))
          (setf *signs-table* (cons signs table))
          table))))

(defparameter *float-sign-margin* 1d-6
  "A constant expression evaluated in double precision (roots, pi) has its value's sign
taken when the value is farther than this from zero: the rounding error of the small
expressions the broad phase evaluates (positions and bounds) is below 1e-12.")

(defun cheap-sign (reach expression)
  "The sign of EXPRESSION for every admissible parameter value, by exact arithmetic (a
constant evaluated in floating point only beyond *FLOAT-SIGN-MARGIN*) or the rules of
signs, as written or after its like terms cancel (EXPANDED-SIGN): a sign set. Never
asks Maxima."
  (let ((constant (ames.algebra:constant-sign expression *float-sign-margin*)))
    (if constant
        (ames.algebra:number-signs constant)
        (let ((signs (sign-algebra (reach-signs-of-parameters reach) expression)))
          (if (one-sign signs)
              signs
              ;; like terms cancelled first (polynomial-signs.lisp)
              (let ((expanded (expanded-sign (reach-signs-of-parameters reach) expression)))
                (if (known-signs-p expanded) expanded signs)))))))

(defun known-signs-p (signs)
  "True when the sign set SIGNS says something: one sign, or one sign and zero (not
all three, nor a sign and its opposite)."
  (or (one-sign signs)
      (ames.algebra:only-signs-p signs :positive :zero)
      (ames.algebra:only-signs-p signs :negative :zero)))

;;; Each body's coordinates over the state

(defun make-reach (run solved groups)
  "The broad phase's knowledge of the current state of RUN, solved as SOLVED and
integrated as GROUPS."
  (%make-reach run (parameter-signs (run-scenario run)) solved groups))

(defun body-coefficients (reach body axis)
  "(c0 c1 c2) of BODY's coordinate AXIS over the state (position, velocity, half the
acceleration at the start), or :UNKNOWN when BODY does not move with constant
acceleration."
  (let ((key (list body axis)))
    (multiple-value-bind (known found) (gethash key (reach-coefficients reach))
      (if found
          known
          (setf (gethash key (reach-coefficients reach))
                (let* ((run (reach-run reach))
                       (position (axis-of (body-position run body) axis)))
                  (if (body-fixed-p run body)
                      (list position 0 0)
                      (let ((group (body-group (reach-groups reach) body)))
                        (if (and group (eq (group-kind group) :constant))
                            (let ((acceleration (quantity-value (reach-solved reach)
                                                                `(ames.kb:acc ,body ,axis))))
                              (if (mentions-state-p (reach-solved reach) acceleration)
                                  :unknown
                                  (list position (axis-of (body-velocity run body) axis)
                                        (if (eql acceleration 0) 0 `(/ ,acceleration 2)))))
                            :unknown)))))))))

(defun coefficient-sign (reach expression)
  "The sign of a body's own coefficient EXPRESSION: cheaply, else by the bridge (memoized,
so once per body and axis)."
  (let ((signs (cheap-sign reach expression)))
    (if (one-sign signs)
        signs
        (multiple-value-bind (known found) (gethash expression (reach-signs reach))
          (if found
              known
              (setf (gethash expression (reach-signs reach))
                    (sign-of (reach-run reach) expression)))))))

(defun difference-sign (reach a b)
  "The sign of A - B for every admissible parameter value (A and B coefficients of two
bodies), a sign set: equal forms give (:ZERO); else CHEAP-SIGN of the difference when it
gives one sign; else the two coefficients' signs when they are on opposite sides of
zero (or both zero)."
  (if (equal a b)
      (list :zero)
      (let ((signs (cheap-sign reach `(- ,a ,b))))
        (if (one-sign signs)
            signs
            (let ((sa (one-sign (coefficient-sign reach a)))
                  (sb (coefficient-sign reach b)))
              (cond ((and (eq sa :positive) (ames.algebra:only-signs-p sb :negative :zero))
                     (list :positive))
                    ((and (eq sa :zero) (eq (one-sign sb) :negative)) (list :positive))
                    ((and (eq sa :negative) (ames.algebra:only-signs-p sb :positive :zero))
                     (list :negative))
                    ((and (eq sa :zero) (eq (one-sign sb) :positive)) (list :negative))
                    ((and (eq sa :zero) (eq (one-sign sb) :zero)) (list :zero))
                    (t ames.algebra:+all-signs+)))))))

;;; The bounds of a contact's locus

(defun locus-bounds (geometry axis)
  "The values between which CONTACT GEOMETRY's locus lies along AXIS (:X or :Y): a list
of expressions whose least and greatest bound it, or NIL when it is unbounded there."
  (let ((index (if (eq axis :x) 0 1)))
    (ecase (ames.geometry:contact-kind geometry)
      (:segment (list (nth index (ames.geometry:contact-start geometry))
                      (nth index (ames.geometry:contact-end geometry))))
      ((:arc :circle)
       (let ((centre (nth index (ames.geometry:contact-center geometry)))
             (radius (ames.geometry:contact-radius geometry)))
         (list `(- ,centre ,radius) `(+ ,centre ,radius))))
      (:line
       ;; an infinite line parallel to the other axis lies at its start's coordinate
       (let ((tangent (ames.geometry:contact-unit-tangent geometry 0)))
         (and (eql 0 (nth index tangent))
              (list (nth index (ames.geometry:contact-start geometry)))))))))

(defun stays-beyond-p (reach offsets c1 c2 side)
  "True when, for each OFFSET (c0 of the relative coordinate minus a bound), OFFSET + C1
tau + C2 tau^2 keeps the strict SIDE (:POSITIVE above, :NEGATIVE below) for every
tau > 0: the signs of C1 and C2 (given as sign sets) allow it and each offset's with
them has one strict."
  (flet ((weak (signs) (ames.algebra:only-signs-p signs side :zero))
         (strict (signs) (eq (one-sign signs) side)))
    (and (weak c1) (weak c2)
         (every (lambda (offset)
                  (let ((sign (cheap-sign reach offset)))
                    (and (weak sign) (or (strict sign) (strict c1) (strict c2)))))
                offsets))))

(defun cannot-meet-p (reach contact)
  "True when the broad phase proves that the observer of CONTACT (a contact between two
bodies' shapes) cannot reach its locus at any tau > 0 of the state."
  (let ((run (reach-run reach)))
    (when (assoc contact (run-locus-kinds run))
      (return-from cannot-meet-p nil))
    (let ((geometry (contact-geometry run contact)))
      (destructuring-bind (observer obstacle) (contact-bodies run contact)
        (dolist (axis '(:x :y) nil)
          (let ((a (body-coefficients reach observer axis))
                (b (body-coefficients reach obstacle axis))
                (bounds (locus-bounds geometry axis)))
            (when (and bounds (listp a) (listp b))
              (let ((c1 (difference-sign reach (second a) (second b)))
                    (c2 (difference-sign reach (third a) (third b)))
                    (offsets (mapcar (lambda (bound) `(- (- ,(first a) ,(first b)) ,bound)) bounds)))
                (when (or (stays-beyond-p reach offsets c1 c2 :positive)
                          (stays-beyond-p reach offsets c1 c2 :negative))
                  (return t))))))))))
