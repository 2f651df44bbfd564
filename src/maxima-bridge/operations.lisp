;;;; src/maxima-bridge/operations.lisp -- what the rest of AMES asks of Maxima: simplify, solve, equivalence.
;;;;
;;;; Every operation takes and returns AMES's prefix algebra. Deciding relations is in
;;;; the algebra layer (src/algebra/: deciding.lisp, truth.lisp, witnesses.lisp; the earliest
;;;; root in roots.lisp), the autonomous ODE and numeric values in ode.lisp, TeX in
;;;; presentation.lisp.
;;;;
;;;; Speed: a round trip costs little next to Maxima's own work, so the work is cut, never
;;;; the answers: steps that give the ratsimp form again (trigsimp without sin, cos or
;;;; tan; radcan without radicals) are skipped.

(in-package #:ames.maxima)

(defun to-mx (bridge expression &optional (kind :arithmetic))
  "EXPRESSION translated for BRIDGE's Maxima (see TO-MAXIMA)."
  (to-maxima (bridge-names bridge) expression :kind kind))

(defun from-mx (bridge form)
  "Maxima's FORM translated back for BRIDGE (see FROM-MAXIMA)."
  (from-maxima (bridge-names bridge) form))

(defun mcall (name &rest arguments)
  "The Maxima call NAME(ARGUMENTS...), NAME a constant string such as \"$RATSIMP\"."
  (apply #'mform (wire name) arguments))

(defun mdifference (a b)
  "The Maxima form of A - B."
  (mform +mplus+ a (mform +mtimes+ -1 b)))

(defun expression-size (expression)
  "The number of atoms and operators in the prefix EXPRESSION."
  (if (atom expression) 1 (reduce #'+ (mapcar #'expression-size expression))))

;;; Simplification

(defparameter *simplification-strategies* '(:ratsimp :trigsimp :trigexpand :expanded-trigexpand
                                           :radcan :full)
  "The strategies SIMPLIFY knows.")

(defun simplification-form (strategy form)
  "The Maxima request simplifying FORM by STRATEGY (one of :RATSIMP :TRIGSIMP :RADCAN).
trigsimp is the server's ames_trigsimp: the same answer, without trigsimp's own slow
search where it is known to be ratsimp's."
  (ecase strategy
    (:ratsimp (mcall "$RATSIMP" form))
    (:trigsimp (mcall "$AMES_TRIGSIMP" form))
    (:trigexpand (mcall "$RATSIMP" (mcall "$TRIGEXPAND" form)))
    ;; sin((pi + 2 u)/2) is expanded only once its argument is a sum: pi/2 + u; the
    ;; second pass expands the multiples a sum left (sin(2 asin u))
    (:expanded-trigexpand (mcall "$RATSIMP" (mcall "$TRIGEXPAND" (mcall "$TRIGEXPAND" (mcall "$EXPAND" form)))))
    (:radcan (mcall "$RADCAN" form))))

(defun simplify (bridge expression &key (strategy :ratsimp))
  "EXPRESSION (an arithmetic expression or a relation) simplified by Maxima under the
current assumptions. STRATEGY is :RATSIMP (rational canonical form), :TRIGSIMP
(trigonometric identities), :TRIGEXPAND (sums and multiples of angles expanded, so that
sin(asin(u) - atan(v)) becomes algebraic in u and v), :EXPANDED-TRIGEXPAND (the same after
expand(), twice, so that sin((pi + 2 u)/2) becomes cos(u)), :RADCAN (radicals, logs, exponentials) or :FULL (the
smallest of ratsimp, trigsimp, ratsimp after trigsimp, factor after ratsimp, radcan).
Signals UNTRANSLATABLE-EXPRESSION, INVALID-BRIDGE-ARGUMENT for an unknown strategy,
UNTRANSLATABLE-RESULT, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (unless (member strategy *simplification-strategies*)
    (error 'invalid-bridge-argument :datum strategy
                                    :detail (format nil "the strategy must be one of ~{~S~^ ~}"
                                                    *simplification-strategies*)))
  (let ((form (to-mx bridge expression :any))
        (constant (and (member strategy '(:ratsimp :full)) (exact-constant-value expression))))
    (cond
      ;; Maxima's answer is that rational (exact-constants.lisp)
      (constant constant)
      ((eq strategy :full)
       (simplest-form bridge form expression))
      (t
       (let ((answer (maxima-request bridge (simplification-form strategy form) :datum expression)))
         (or (and (not (and (consp expression) (member (first expression) '(= /= < > <= >= and or not))))
                  (mentions-imaginary-unit-p answer)
                  (real-form bridge form expression))
             (from-mx bridge answer)))))))

(defun trigonometric-form-p (form)
  "True when the Maxima FORM contains sin, cos or tan. Without them trigsimp() is
ratsimp() again (its rules rewrite only tan, sec, csc, cot and squares of sin and cos,
then it ratsimps), and trigexpand() changes nothing, so those steps can be skipped."
  (and (consp form)
       (or (and (mform-p form) (member (mform-head form) (list +sin+ +cos+ +tan+)))
           (some #'trigonometric-form-p (cdr form)))))

(defun radical-form-p (form)
  "True when the Maxima FORM has a square root, a logarithm, or a power whose exponent
is not an integer (a radical, an exponential). Without them radcan() gives the form
ratsimp() gives (seen on every simplification of the test suite and the scenarios)."
  (and (consp form)
       (or (and (mform-p form) (member (mform-head form) (list +sqrt+ +log+)))
           (and (mform-p form +mexpt+) (not (integerp (third form))))
           (some #'radical-form-p (cdr form)))))

(defun simplest-form-request (form)
  "The one request SIMPLEST-FORM sends for the Maxima FORM: its candidates' list."
  (mcall "$AMES_SIMPLIFICATION_CANDIDATES" form
         (if (trigonometric-form-p form) +true+ +false+)
         (if (radical-form-p form) +true+ +false+)))

(defun simplest-form (bridge form expression)
  "The smallest translatable result of several simplifications of FORM: ratsimp,
trigsimp, ratsimp after trigsimp, factor after ratsimp and radcan (the first of equal
size wins), each computed once in one round trip; the trigsimp ones only when FORM has
sin, cos or tan, radcan only when it has radicals, logarithms or exponentials (otherwise
they equal the ratsimp one). A constant of numbers and radicals is compared with FORM
over exact intervals (EXACTLY-SAME-NUMBER-P), and is FORM itself when no simplification
keeps its value."
  (let* ((candidates (mlist-items
                      (maxima-request bridge (simplest-form-request form) :datum expression)))
         (original (exact-constant-original bridge form))
         (best nil)
         (reference :unset))
    (dolist (candidate candidates)
      (let ((translated (handler-case (from-mx bridge candidate)
                          (untranslatable-result () nil))))
        (when (eq reference :unset)
          (setf reference (and translated (constant-number translated))))
        (when (and translated
                   (if original
                       (exactly-same-number-p original translated)
                       (same-number-p reference translated))
                   (or (null best) (< (expression-size translated) (expression-size best))))
          (setf best translated))))
    (or best original (real-form bridge form expression) (from-mx bridge (first candidates)))))

(defun exact-constant-original (bridge form)
  "FORM, as sent, in prefix algebra when it is a constant of numbers and radicals whose
value exact interval arithmetic bounds (EXACT-CONSTANT-SIGN answers); else NIL."
  (let ((expression (handler-case (from-mx bridge form)
                      (untranslatable-result () nil))))
    (and expression (consp expression)
         (null (expression-variables expression))
         (exact-constant-sign expression :precisions '(64 256))
         expression)))

(defun exactly-same-number-p (original candidate)
  "True unless exact interval arithmetic tells CANDIDATE's value (a simplification of
the constant ORIGINAL) from ORIGINAL's, or cannot bound it (a square root of a negative,
a name): the guard of SAME-NUMBER-P, for constants of numbers and radicals whose terms
cancel beyond a double's digits, where a double tells nothing apart (radcan() wrote a
root of a quadratic, 0.2928, as a form worth 0.5298, with %i; Maxima's own bfloat() at
60 digits put the root and its ratsimp(), factor() and radcan() forms at 2.37, 2.37,
1.05 and 0.89)."
  (member (exact-constant-sign (list '- candidate original) :precisions '(64 1024))
          '(:zero :near-zero)))

(defun constant-number (expression)
  "EXPRESSION's value as a double when it is a real number written without names (only
numbers, PI and functions of them), else NIL."
  (and (null (expression-variables expression))
       (let ((value (ignore-errors (expression-value expression))))
         (and (realp value) (coerce value 'double-float)))))

(defun same-number-p (reference expression)
  "True unless REFERENCE (a double, the value of the first simplification of a number)
and EXPRESSION's value (another simplification's) are both known and differ beyond
rounding: radcan() takes sqrt(x^2) for x whatever the sign of x, so a number it rewrites
can change sign (a root of a quadratic whose leading coefficient is a negative number
written with sin and atan became the other root); such a simplification is dropped."
  (let ((value (and reference (constant-number expression))))
    (or (null value)
        (<= (abs (- value reference)) (* 1d-9 (max 1d0 (abs reference)))))))

(defun mentions-imaginary-unit-p (form)
  "True when the Maxima FORM contains %i."
  (if (atom form) (eq form +i+) (some #'mentions-imaginary-unit-p (cdr form))))

(defun real-form (bridge form expression)
  "When Maxima writes the real FORM (an AMES quantity) with %i under the assumptions
(sqrt(x)^-1 |x|^(1/2) with x < 0 is -%i, with -2 %i beside it: a real number written
as a product of imaginary ones), its real part, provided its imaginary part simplifies
to 0 (so the two are equal); else NIL."
  (let ((simplified (first (request-list bridge (list (mcall "$RATSIMP" form)) :datum expression))))
    (when (mentions-imaginary-unit-p simplified)
      (destructuring-bind (real imaginary)
          (request-list bridge (list (mcall "$RATSIMP" (mcall "$REALPART" form))
                                     (mcall "$RATSIMP" (mcall "$IMAGPART" form)))
                        :datum expression)
        (and (eql imaginary 0)
             (not (mentions-imaginary-unit-p real))
             (handler-case (from-mx bridge real)
               (untranslatable-result () nil)))))))

;;; Equivalence

(defun equivalent-p (bridge a b)
  "True when the arithmetic expressions A and B are equal: A - B simplifies to 0 by
ratsimp, by trigsimp (then ratsimp; also after trigexpand, for multiple angles) or by
radcan, under the current assumptions. NIL
means no proof was found, not that they differ.
Signals UNTRANSLATABLE-EXPRESSION, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (let* ((difference (mdifference (to-mx bridge a) (to-mx bridge b)))
         (trigonometric (trigonometric-form-p difference))
         (datum (list '- a b)))
    (flet ((zero-p (form) (eql 0 (maxima-request bridge form :datum datum))))
      ;; without sin, cos or tan the trigsimp and trigexpand steps are ratsimp again,
      ;; and so is radcan without radicals, logarithms or exponentials
      (and (or (zero-p (mcall "$RATSIMP" difference))
               (and trigonometric
                    (or (zero-p (mcall "$RATSIMP" (mcall "$AMES_TRIGSIMP" difference)))
                        (zero-p (mcall "$RATSIMP" (mcall "$AMES_TRIGSIMP" (mcall "$TRIGEXPAND" difference))))))
               (and (radical-form-p difference)
                    (zero-p (mcall "$RATSIMP" (mcall "$RADCAN" difference)))))
           t))))

;;; Solving equations

(defun equation-to-maxima (bridge equation)
  "The Maxima equation for EQUATION: a relation (= lhs rhs), or an expression meaning
expression = 0. Signals INVALID-BRIDGE-ARGUMENT for other relations and connectives."
  (cond ((and (consp equation) (eq (expression-operator equation) '=))
         (to-mx bridge equation :condition))
        ((and (consp equation) (or (relation-operator-p (expression-operator equation))
                                   (logical-operator-p (expression-operator equation))))
         (error 'invalid-bridge-argument :datum equation
                                         :detail "only equations (=) can be solved"))
        (t (mform +mequal+ (to-mx bridge equation :arithmetic) 0))))

(defun solve-equations (bridge equations unknowns)
  "Solve EQUATIONS (a list of relations (= lhs rhs), or expressions meaning = 0) for
UNKNOWNS (variables or quantity terms). Returns every solution Maxima finds, each an
alist ((unknown . expression) ...) in the order of UNKNOWNS; NIL when there is none.
Complex solutions are left out; for periodic functions of an unknown Maxima gives the
principal solution only.
Signals SOLVE-FAILED when Maxima gives up, answers implicitly, or leaves a solution
with free parameters (an underdetermined system); INVALID-BRIDGE-ARGUMENT when an
unknown is not a name; UNTRANSLATABLE-EXPRESSION, MAXIMA-ERROR, MAXIMA-QUESTION,
MAXIMA-TIMEOUT."
  (unless (and (consp equations) (alexandria:proper-list-p equations))
    (error 'invalid-bridge-argument :datum equations :detail "a non-empty list of equations is expected"))
  (unless (and (consp unknowns) (alexandria:proper-list-p unknowns) (every #'subject-p unknowns))
    (error 'invalid-bridge-argument :datum unknowns
                                    :detail "the unknowns must be a non-empty list of variables or quantity terms"))
  (let* ((equation-forms (mapcar (lambda (e) (equation-to-maxima bridge e)) equations))
         (unknown-forms (mapcar (lambda (u) (to-mx bridge u)) unknowns))
         (answer (maxima-request bridge (mcall "$SOLVE" (mlist equation-forms) (mlist unknown-forms))
                                 :datum equations)))
    (flet ((fail (detail) (error 'solve-failed :datum equations :detail detail)))
      (when (eq answer +all+)
        (fail "every value of the unknowns is a solution"))
      (let ((items (handler-case (mlist-items answer)
                     (untranslatable-result () (fail "Maxima's answer is not a list of solutions"))))
            (solutions '()))
        (dolist (item items (nreverse solutions))
          (let ((bindings (cond ((mform-p item +mequal+) (list item))
                                ((mform-p item +mlist+) (mform-arguments item))
                                (t (fail "Maxima's answer is not a list of solutions")))))
            (unless (and (= (length bindings) (length unknowns))
                         (every (lambda (b) (and (mform-p b +mequal+)
                                                 (member (second b) unknown-forms)))
                                bindings))
              (fail "Maxima answered implicitly (not every unknown is isolated)"))
            (let ((solution (solution-alist bridge bindings unknowns unknown-forms equations)))
              (when solution (push solution solutions)))))))))

(defun contains-symbol-p (symbol form)
  "True when the Maxima FORM mentions SYMBOL."
  (cond ((eq form symbol) t)
        ((consp form) (some (lambda (x) (contains-symbol-p symbol x)) (cdr form)))
        (t nil)))

(defun solution-alist (bridge bindings unknowns unknown-forms equations)
  "The alist for one solution, NIL when it is complex; signals SOLVE-FAILED when a value
has free parameters or is outside the algebra."
  (if (some (lambda (b) (contains-symbol-p +i+ (third b))) bindings)
      nil
      (loop for unknown in unknowns
            for unknown-form in unknown-forms
            for binding = (find unknown-form bindings :key #'second)
            collect (cons unknown
                          (handler-case (from-mx bridge (third binding))
                            (untranslatable-result (c)
                              (error 'solve-failed
                                     :datum equations
                                     :detail (format nil "the value of ~S is not in the algebra (~A~@[ ~A~])"
                                                     unknown (ames-error-detail c)
                                                     (let ((part (ames-error-datum c)))
                                                       (and (symbolp part) (string-downcase (symbol-name part))))))))))))

;;; A bare Maxima script (for benchmarks: what Maxima alone takes to solve a model)

(defparameter *infix-heads*
  `((,+mplus+ . "+") (,+mtimes+ . "*") (,+mexpt+ . "^") (,+mquotient+ . "/")
    (,+mequal+ . "=") (,+mnotequal+ . "#") (,+mlessp+ . "<") (,+mgreaterp+ . ">")
    (,+mleqp+ . "<=") (,+mgeqp+ . ">=") (,+mand+ . " and ") (,+mor+ . " or "))
  "Maxima operators written infix in Maxima's own syntax.")

(defun maxima-source (form)
  "The text of the Maxima FORM (as TO-MAXIMA makes it) in Maxima's input syntax, fully
parenthesised: ((MPLUS) $AMESVA 1) gives \"(amesva+1)\"."
  (labels ((name (symbol)
             (string-downcase (string-left-trim "$%" (symbol-name symbol))))
           (text (x)
             (cond ((integerp x) (if (minusp x) (format nil "(~D)" x) (format nil "~D" x)))
                   ((floatp x) (format nil "(~,,,,,,'eE)" (coerce x 'double-float)))
                   ((eq x +pi+) "%pi")
                   ((eq x +e+) "%e")
                   ((symbolp x) (name x))
                   ((mform-p x +rat+) (format nil "(~D/~D)" (second x) (third x)))
                   ((mform-p x +mminus+) (format nil "(-~A)" (text (second x))))
                   ((mform-p x +mnot+) (format nil "(not ~A)" (text (second x))))
                   ((mform-p x +mlist+) (format nil "[~{~A~^,~}]" (mapcar #'text (mform-arguments x))))
                   ((mform-p x)
                    (let ((infix (cdr (assoc (mform-head x) *infix-heads*)))
                          (arguments (mapcar #'text (mform-arguments x))))
                      (if infix
                          (format nil "(~{~A~})"
                                  (loop for (argument . more) on arguments
                                        collect argument when more collect infix))
                          (format nil "~A(~{~A~^,~})"
                                  (if (eq (mform-head x) +abs+) "abs" (name (mform-head x)))
                                  arguments))))
                   (t (error 'invalid-bridge-argument :datum x
                                                      :detail "not a Maxima form the bridge makes")))))
    (text form)))

(defun solve-script (equations unknowns &key facts)
  "The text of a batch script for a bare `maxima -b` that does what SOLVE-EQUATIONS asks
of Maxima for EQUATIONS and UNKNOWNS: in a context of its own, assume FACTS (relations
of the algebra), solve, print the solutions, and kill the context. Names are mangled
as a fresh bridge mangles them (no Maxima process is started). For benchmarks.
Signals UNTRANSLATABLE-EXPRESSION and INVALID-BRIDGE-ARGUMENT as SOLVE-EQUATIONS does."
  (let* ((scratch (make-bridge))
         (context (fresh-context-name (bridge-names scratch)))
         (equation-forms (mapcar (lambda (equation) (equation-to-maxima scratch equation))
                                 equations))
         (unknown-forms (mapcar (lambda (unknown) (to-mx scratch unknown)) unknowns))
         (fact-forms (mapcar (lambda (fact) (fact-to-maxima (bridge-names scratch) fact))
                             (flatten-facts facts))))
    (with-output-to-string (stream)
      (format stream "supcontext(~A)$~%" (maxima-source context))
      (when fact-forms
        (format stream "assume(~{~A~^, ~})$~%" (mapcar #'maxima-source fact-forms)))
      (format stream "solve(~A, ~A);~%" (maxima-source (mlist equation-forms))
              (maxima-source (mlist unknown-forms)))
      (format stream "killcontext(~A)$~%" (maxima-source context)))))
