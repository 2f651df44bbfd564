;;;; src/maxima-bridge/ode.lisp -- autonomous second-order ODEs and numeric values.
;;;;
;;;; A state variable's equation of motion x'' = f(x, x') is handed to ode2 and ic2. When
;;;; Maxima gives x(t) explicitly, that is the closed form; when it answers implicitly (an
;;;; unevaluated integral, as for the pendulum theta'' = (g/r) sin theta), the bridge falls
;;;; back on the energy integral v dv/dx = f(x), i.e. v^2 = v0^2 + 2 (F(x) - F(x0)) with F
;;;; an antiderivative of f, clearly marked as having no closed form. When f has x inside a
;;;; trigonometric function (and no velocity), ode2 can only answer implicitly, and is not
;;;; asked (see NONLINEAR-IN-P).

(in-package #:ames.maxima)

(defclass ode-solution ()
  ((kind :initarg :kind :reader ode-solution-kind
         :documentation ":CLOSED-FORM or :ENERGY-INTEGRAL.")
   (position :initarg :position :initform nil :reader ode-solution-position
             :documentation "The position as a function of time (closed form only).")
   (velocity :initarg :velocity :initform nil :reader ode-solution-velocity
             :documentation "The velocity as a function of time (closed form only).")
   (speed-squared :initarg :speed-squared :initform nil :reader ode-solution-speed-squared
                  :documentation "The velocity squared as a function of the position,
when the acceleration does not depend on the velocity."))
  (:documentation "The solution of an autonomous second-order ODE: in closed form, or
only its energy integral."))

(defmethod print-object ((solution ode-solution) stream)
  (print-unreadable-object (solution stream :type t)
    (format stream "~S~@[ position ~S~]~@[ speed^2 ~S~]" (ode-solution-kind solution)
            (ode-solution-position solution) (ode-solution-speed-squared solution))))

(defun substitute-form (new old form)
  "The Maxima FORM with the symbol OLD replaced by the form NEW."
  (cond ((eq form old) new)
        ((consp form) (cons (car form) (mapcar (lambda (x) (substitute-form new old x)) (cdr form))))
        (t form)))

(defun solve-autonomous-ode (bridge acceleration position
                             &key velocity (time tau) initial-position initial-velocity)
  "Solve POSITION'' = ACCELERATION, where ACCELERATION is an expression in POSITION
(and in VELOCITY, the name standing for POSITION', when given) but not in TIME, with
POSITION = INITIAL-POSITION and POSITION' = INITIAL-VELOCITY at TIME = 0. Returns an
ODE-SOLUTION: of kind :CLOSED-FORM, with the position and velocity as functions of TIME,
when Maxima's ode2 gives one; otherwise of kind :ENERGY-INTEGRAL, marked as having no
closed form, with the velocity squared as a function of POSITION. The velocity squared
is given in both cases when ACCELERATION does not depend on VELOCITY.
Signals INVALID-BRIDGE-ARGUMENT (a name that is not one, a missing initial value, an
acceleration depending on TIME), SOLVE-FAILED when neither a closed form nor an energy
integral can be had, MAXIMA-QUESTION when Maxima needs a sign (e.g. of k in
s'' = -k s; assume it first), UNTRANSLATABLE-EXPRESSION, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (flet ((invalid (datum detail) (error 'invalid-bridge-argument :datum datum :detail detail)))
    (unless (subject-p position) (invalid position "the position must be a variable or a quantity term"))
    (unless (variable-symbol-p time) (invalid time "the time must be a variable"))
    (when (and velocity (not (subject-p velocity)))
      (invalid velocity "the velocity must be a variable or a quantity term"))
    (when (or (null initial-position) (null initial-velocity))
      (invalid (list initial-position initial-velocity)
               "both the initial position and the initial velocity are needed"))
    (check-translatable acceleration :arithmetic)
    (unless (free-of-p time acceleration)
      (invalid acceleration (format nil "the acceleration depends on the time ~S: not autonomous" time))))
  (let* ((x (to-mx bridge position))
         (tm (to-mx bridge time))
         (x0 (to-mx bridge initial-position))
         (v0 (to-mx bridge initial-velocity))
         (derivative (mform +derivative+ x tm 1))
         (uses-velocity (and velocity (not (free-of-p velocity acceleration))))
         (f (let ((form (to-mx bridge acceleration)))
              (if uses-velocity (substitute-form derivative (to-mx bridge velocity) form) form)))
         (datum (list '= (list 'second-derivative position time) acceleration))
         (speed-squared (and (not uses-velocity)
                             (energy-integral bridge f x x0 v0 datum)))
         (closed (and (not (and (not uses-velocity)
                                (nonlinear-in-p x (maxima-request bridge f :datum datum))))
                      (block closed
                        (handler-bind ((maxima-question
                                         (lambda (condition)
                                           ;; with the energy integral in hand, a question ode2
                                           ;; asks about its own constant %k1 (for f = k/x^2:
                                           ;; nothing the caller could assume) only means that
                                           ;; there is no closed form to be had
                                           (when (and speed-squared
                                                      (null (maxima-question-expressions condition)))
                                             (return-from closed nil)))))
                          (closed-form bridge f x tm x0 v0 derivative datum))))))
    (cond (closed
           (make-instance 'ode-solution :kind :closed-form
                                        :position (first closed) :velocity (second closed)
                                        :speed-squared speed-squared))
          (speed-squared
           (make-instance 'ode-solution :kind :energy-integral :speed-squared speed-squared))
          (t (error 'solve-failed :datum datum
                                  :detail "no closed form, and no energy integral (the acceleration depends on the velocity)")))))

(defun closed-form (bridge f x tm x0 v0 derivative datum)
  "The list (position velocity) as functions of time when ode2 and ic2 give them
explicitly, else NIL."
  (let* ((ode2 (mcall "$ODE2" (mform +mequal+ (mform +derivative+ x tm 2) f) x tm))
         (general (maxima-request bridge ode2 :datum datum)))
    (when (and (mform-p general +mequal+) (eq (second general) x)
               (not (contains-head-p +integrate-noun+ general)))
      ;; ic2 gets ode2's call, not its answer: the answer holds Maxima's constants %k1 and
      ;; %k2, which no request may carry. The cache answers the inner call.
      (let ((particular (maxima-request bridge (mcall "$IC2" ode2 (mform +mequal+ tm 0)
                                                      (mform +mequal+ x x0)
                                                      (mform +mequal+ derivative v0))
                                        :datum datum)))
        (when (and (mform-p particular +mequal+) (eq (second particular) x))
          (let ((forms (request-list bridge
                                     (list (mcall "$RATSIMP" (third particular))
                                           (mcall "$RATSIMP" (mcall "$DIFF" (third particular) tm)))
                                     :datum datum)))
            (handler-case (mapcar (lambda (form) (from-mx bridge form)) forms)
              (untranslatable-result () nil))))))))

(defun nonlinear-in-p (x form)
  "True when the simplified Maxima FORM has X inside a trigonometric function (sin, cos,
tan, asin, acos, atan, atan2). For such an acceleration f(x), with no velocity in it,
ode2 never gives x(t) explicitly: f is not affine in x, so its linear methods do not
apply, and its reduction of an equation free of time yields [integral = t + %k2, ...]
only. Calling it (a third of a second for sin or cos) is then skipped."
  (labels ((mentions-p (part) (or (eq part x) (and (consp part) (some #'mentions-p (cdr part)))))
           (walk (part)
             (and (mform-p part)
                  (or (and (member (mform-head part)
                                   (list +sin+ +cos+ +tan+ +asin+ +acos+ +atan+ +atan2+))
                           (mentions-p part))
                      (some #'walk (cdr part))))))
    (walk form)))

(defun contains-head-p (head form)
  "True when the Maxima FORM contains an operator form with HEAD."
  (and (consp form)
       (or (mform-p form head)
           (some (lambda (x) (contains-head-p head x)) (cdr form)))))

(defun energy-integral (bridge f x x0 v0 datum)
  "v^2 = v0^2 + 2 (F(x) - F(x0)) with F an antiderivative of F in X, or NIL when Maxima
finds none."
  (let ((antiderivative (maxima-request bridge (mcall "$INTEGRATE" f x) :datum datum)))
    (unless (contains-head-p +integrate-noun+ antiderivative)
      (let ((speed-squared
              (maxima-request bridge
                              (mcall "$RATSIMP"
                                     (mform +mplus+ (mform +mexpt+ v0 2)
                                            (mform +mtimes+ 2 (mdifference
                                                               antiderivative
                                                               (mcall "$SUBSTITUTE" x0 x antiderivative)))))
                              :datum datum)))
        (handler-case (simplify-result bridge speed-squared datum)
          (untranslatable-result () nil))))))

(defun simplify-result (bridge form datum)
  "The simplest translation of the Maxima FORM (see SIMPLEST-FORM)."
  (simplest-form bridge form datum))

;;; Numeric values

(defparameter *lisp-evaluated-operators*
  '(elliptic-f elliptic-k elliptic-e jacobi-sn jacobi-cn jacobi-dn jacobi-am)
  "Operators whose numeric values NUMERIC-VALUE takes from AMES.BASE:EXPRESSION-VALUE
rather than Maxima's float(): Maxima 5.46 gives jacobi_am(u, m) beyond the first
quarter period as asin(sn(u, m)) (wrong), and complex rounding residues (or complex
values) for jacobi_dn and elliptic_e with m > 1.")

(defun mentions-operator-p (expression operators)
  "True when EXPRESSION has an operator form whose operator is one of OPERATORS."
  (and (consp expression) (not (quantity-term-p expression))
       (or (member (first expression) operators)
           (some (lambda (x) (mentions-operator-p x operators)) (rest expression)))))

(defun numeric-value (bridge expression bindings)
  "The value of the arithmetic EXPRESSION, as a double-float, when each name in the
alist BINDINGS ((name . real) ...) is replaced by its number. An expression with an
elliptic or Jacobi function is evaluated in Lisp where it has a real value there (see
*LISP-EVALUATED-OPERATORS*), else like any other by Maxima's float().
Signals NUMERIC-EVALUATION-FAILED naming what is left when the result is no real
number (a name without value, a complex value, a division by zero);
INVALID-BRIDGE-ARGUMENT for malformed BINDINGS; UNTRANSLATABLE-EXPRESSION;
MAXIMA-TIMEOUT."
  (check-translatable expression :arithmetic)
  (unless (and (alexandria:proper-list-p bindings)
               (every (lambda (b) (and (consp b) (subject-p (car b)) (realp (cdr b)))) bindings))
    (error 'invalid-bridge-argument :datum bindings
                                    :detail "bindings must be an alist (name . real number)"))
  (let* ((substituted (substitute-expressions bindings expression))
         (unbound (expression-variables substituted)))
    (when unbound
      (error 'numeric-evaluation-failed :datum expression
                                        :detail (format nil "no value for ~{~S~^, ~}" unbound)))
    (when (mentions-operator-p substituted *lisp-evaluated-operators*)
      (let ((value (expression-value substituted)))
        (when value (return-from numeric-value (float value 1d0)))))
    (let ((answer (handler-case (maxima-request bridge (mcall "$FLOAT" (to-mx bridge substituted))
                                                :datum expression)
                    (maxima-error (c)
                      (error 'numeric-evaluation-failed
                             :datum expression
                             :detail (format nil "Maxima: ~A" (maxima-error-message c)))))))
      (if (realp answer)
          (coerce answer 'double-float)
          (error 'numeric-evaluation-failed :datum expression
                                            :detail "the value is not a real number")))))
