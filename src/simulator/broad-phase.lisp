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
(OP N P), N a number: 1, -1, :NONNEGATIVE or :NONPOSITIVE (the strongest one implied)."
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
                               (> (and (>= bound 0) 1))
                               (>= (cond ((> bound 0) 1) ((= bound 0) :nonnegative)))
                               (< (and (<= bound 0) -1))
                               (<= (cond ((< bound 0) -1) ((= bound 0) :nonpositive)))))))
              (when sign
                (let ((entry (assoc parameter signs)))
                  (cond ((null entry) (push (cons parameter sign) signs))
                        ((member sign '(1 -1)) (setf (cdr entry) sign))))))))))))

(defun sign-algebra (signs expression)
  "The sign of EXPRESSION for every admissible value of the parameters, whose signs
SIGNS gives (an alist), by the rules of signs (AMES.ALGEBRA:RULES-OF-SIGNS, the one sign
system): 1, -1, 0, :NONNEGATIVE, :NONPOSITIVE or :UNKNOWN."
  (let ((table (signs-table signs)))
    (ames.algebra:sign-set-signum
     (ames.algebra:rules-of-signs
      (lambda (parameter) (ames.algebra:signum-sign-set (values (gethash parameter table))))
      expression))))

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
signs, as written or after its like terms cancel (EXPANDED-SIGN): 1, -1, 0,
:NONNEGATIVE, :NONPOSITIVE or :UNKNOWN. Never asks Maxima."
  (or (ames.algebra:constant-sign expression *float-sign-margin*)
      (let ((sign (sign-algebra (reach-signs-of-parameters reach) expression)))
        (if (member sign '(1 -1 0))
            sign
            ;; like terms cancelled first (polynomial-signs.lisp)
            (let ((expanded (expanded-sign (reach-signs-of-parameters reach) expression)))
              (if (eq expanded :unknown) sign expanded))))))

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
  (let ((sign (cheap-sign reach expression)))
    (if (member sign '(1 -1 0))
        sign
        (multiple-value-bind (known found) (gethash expression (reach-signs reach))
          (if found
              known
              (setf (gethash expression (reach-signs reach))
                    (sign-of (reach-run reach) expression)))))))

(defun difference-sign (reach a b)
  "The sign of A - B for every admissible parameter value (A and B coefficients of two
bodies): equal forms give 0; else CHEAP-SIGN of the difference; else
the two signs when they are on opposite sides of zero."
  (if (equal a b)
      0
      (let ((sign (cheap-sign reach `(- ,a ,b))))
        (if (member sign '(1 -1 0))
            sign
            (let ((sa (coefficient-sign reach a)) (sb (coefficient-sign reach b)))
              (cond ((and (eql sa 1) (member sb '(0 -1 :nonpositive))) 1)
                    ((and (eql sa 0) (eql sb -1)) 1)
                    ((and (eql sa -1) (member sb '(0 1 :nonnegative))) -1)
                    ((and (eql sa 0) (eql sb 1)) -1)
                    ((and (eql sa 0) (eql sb 0)) 0)
                    (t :unknown)))))))

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
tau + C2 tau^2 keeps the strict SIDE (1 above, -1 below) for every tau > 0: the signs of
C1 and C2 (given as signs) allow it and each offset's with them has one strict."
  (flet ((weak (sign) (if (= side 1) (member sign '(1 0 :nonnegative)) (member sign '(-1 0 :nonpositive))))
         (strict (sign) (eql sign side)))
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
                (when (or (stays-beyond-p reach offsets c1 c2 1)
                          (stays-beyond-p reach offsets c1 c2 -1))
                  (return t))))))))))
