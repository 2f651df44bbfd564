;;;; src/maxima-bridge/operations.lisp -- what the rest of AMES asks of Maxima: simplify, solve, decide, equivalence.
;;;;
;;;; Every operation takes and returns AMES's prefix algebra. The earliest root, the
;;;; autonomous ODE, numeric values and LaTeX are in roots.lisp and ode.lisp.
;;;;
;;;; Speed: a round trip costs little next to Maxima's own work, so the work is cut, never
;;;; the answers: sign() requests are asked one at a time until the relation is decided,
;;;; DECIDE caches its verdicts, steps that give the ratsimp form again (trigsimp without
;;;; sin, cos or tan; radcan without radicals) are skipped, and numeric witnesses (see
;;;; their section) answer at once the questions no strategy could decide.

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

(defparameter *simplification-strategies* '(:ratsimp :trigsimp :trigexpand :radcan :full)
  "The strategies SIMPLIFY knows.")

(defun simplification-form (strategy form)
  "The Maxima request simplifying FORM by STRATEGY (one of :RATSIMP :TRIGSIMP :RADCAN).
trigsimp is the server's ames_trigsimp: the same answer, without trigsimp's own slow
search where it is known to be ratsimp's."
  (ecase strategy
    (:ratsimp (mcall "$RATSIMP" form))
    (:trigsimp (mcall "$AMES_TRIGSIMP" form))
    (:trigexpand (mcall "$RATSIMP" (mcall "$TRIGEXPAND" form)))
    (:radcan (mcall "$RADCAN" form))))

(defun simplify (bridge expression &key (strategy :ratsimp))
  "EXPRESSION (an arithmetic expression or a relation) simplified by Maxima under the
current assumptions. STRATEGY is :RATSIMP (rational canonical form), :TRIGSIMP
(trigonometric identities), :TRIGEXPAND (sums and multiples of angles expanded, so that
sin(asin(u) - atan(v)) becomes algebraic in u and v), :RADCAN (radicals, logs, exponentials) or :FULL (the
smallest of ratsimp, trigsimp, ratsimp after trigsimp, factor after ratsimp, radcan).
Signals UNTRANSLATABLE-EXPRESSION, INVALID-BRIDGE-ARGUMENT for an unknown strategy,
UNTRANSLATABLE-RESULT, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (unless (member strategy *simplification-strategies*)
    (error 'invalid-bridge-argument :datum strategy
                                    :detail (format nil "the strategy must be one of ~{~S~^ ~}"
                                                    *simplification-strategies*)))
  (let ((form (to-mx bridge expression :any)))
    (if (eq strategy :full)
        (simplest-form bridge form expression)
        (from-mx bridge (maxima-request bridge (simplification-form strategy form)
                                        :datum expression)))))

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

(defun simplest-form (bridge form expression)
  "The smallest translatable result of several simplifications of FORM: ratsimp,
trigsimp, ratsimp after trigsimp, factor after ratsimp and radcan (the first of equal
size wins), each computed once in one round trip; the trigsimp ones only when FORM has
sin, cos or tan, radcan only when it has radicals, logarithms or exponentials (otherwise
they equal the ratsimp one)."
  (let* ((candidates (mlist-items
                      (maxima-request bridge (mcall "$AMES_SIMPLIFICATION_CANDIDATES" form
                                                    (if (trigonometric-form-p form) +true+ +false+)
                                                    (if (radical-form-p form) +true+ +false+))
                                      :datum expression)))
         (best nil))
    (dolist (candidate candidates)
      (let ((translated (handler-case (from-mx bridge candidate)
                          (untranslatable-result () nil))))
        (when (and translated
                   (or (null best) (< (expression-size translated) (expression-size best))))
          (setf best translated))))
    (or best (from-mx bridge (first candidates)))))

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

;;; Numeric witnesses: quick proofs that a relation is not decided, or not true
;;;
;;; A relation that fails at an admissible point (one that satisfies every fact in force)
;;; has no sound proof; one that also holds at another admissible point is decided neither
;;; way, and so is an equation whose sides differ both ways at two admissible points
;;; joined by a segment of admissible points on which both sides are continuous (they are
;;; equal somewhere between, by the intermediate value theorem, and not everywhere). DECIDE
;;; then answers :UNKNOWN at once instead of trying every strategy (the costliest case:
;;; each strategy fails), and HOLDS-P answers NIL. Points are drawn at random (from a
;;; fixed seed) within the numeric bounds of each variable; values are computed in double
;;; floats as balls (center and radius) that enclose the exact value, rounding included,
;;; and a sign, of the relation or of a fact, counts only when the whole ball has it. A
;;; point where anything is undefined or not real (a square root or logarithm of a ball
;;; reaching zero or below, a division by a ball holding zero, a pole of tan, an
;;; overflow) is left out. Finding no witness proves nothing, and the strategies run as
;;; before: no answer changes, only its cost (given that every strategy is sound).

(defparameter *witness-draws* 80
  "How many random points CALL-WITH-ADMISSIBLE-POINTS draws at most.")

(defparameter *witness-admissible-points* 16
  "How many admissible points CALL-WITH-ADMISSIBLE-POINTS offers at most.")

(defstruct (ball (:constructor make-ball (center radius)))
  "A real number known to lie within RADIUS of CENTER (double floats)."
  center radius)

(defun rounded-ball (center radius)
  "The ball CENTER +/- RADIUS widened by the rounding of computing CENTER."
  (make-ball center (+ radius (* 8 double-float-epsilon (abs center)) least-positive-normalized-double-float)))

(defun ball-sign (ball)
  ":POSITIVE or :NEGATIVE when every number of BALL has that sign, else NIL."
  (cond ((> (- (ball-center ball) (ball-radius ball)) 0) :positive)
        ((< (+ (ball-center ball) (ball-radius ball)) 0) :negative)
        (t nil)))

(defun ball+ (a b)
  (rounded-ball (+ (ball-center a) (ball-center b)) (+ (ball-radius a) (ball-radius b))))

(defun ball-negation (a)
  (make-ball (- (ball-center a)) (ball-radius a)))

(defun ball* (a b)
  (let ((x (ball-center a)) (rx (ball-radius a)) (y (ball-center b)) (ry (ball-radius b)))
    (rounded-ball (* x y) (+ (* (abs x) ry) (* (abs y) rx) (* rx ry)))))

(defun ball-reciprocal (a)
  "1/A, or NIL when A may hold zero."
  (let ((x (ball-center a)) (rx (ball-radius a)))
    (when (> (abs x) rx)
      (rounded-ball (/ 1 x) (/ rx (* (abs x) (- (abs x) rx)))))))

(defun ball-integer-power (a n)
  "A^N for an integer N (NIL when N <= 0 and A may hold zero: 0^0 is undefined too)."
  (cond ((and (zerop n) (<= (abs (ball-center a)) (ball-radius a))) nil)
        ((minusp n) (let ((power (ball-integer-power a (- n))))
                      (and power (ball-reciprocal power))))
        (t (let ((result (make-ball 1d0 0d0)))
             (dotimes (i n result) (setf result (ball* result a)))))))

(defun positive-ball-p (a)
  (> (- (ball-center a) (ball-radius a)) 0))

(defun ball-function (operator a)
  "OPERATOR (sqrt exp log sin cos tan asin acos atan) of the ball A, or NIL where it is
undefined or not real somewhere in A, and for the operators it does not know."
  (let ((x (ball-center a)) (rx (ball-radius a)))
    (case operator
      (sqrt (cond ((and (zerop x) (zerop rx)) (make-ball 0d0 0d0))
                  ((>= (- x rx) 0)
                   (rounded-ball (sqrt x) (- (sqrt x) (sqrt (max 0d0 (- x rx))))))))
      (exp (rounded-ball (exp x) (* (exp x) (- (exp rx) 1))))
      (log (when (positive-ball-p a)
             (rounded-ball (log x) (- (log x) (log (- x rx))))))
      (sin (rounded-ball (sin x) (min rx 2d0)))
      (cos (rounded-ball (cos x) (min rx 2d0)))
      (tan (let ((c (cos x)))
             (when (> (abs c) (+ rx 1d-12))
               (rounded-ball (tan x) (/ rx (expt (- (abs c) rx) 2))))))
      ((asin acos) (when (< (+ (abs x) rx) 1)
                     (rounded-ball (if (eq operator 'asin) (asin x) (acos x))
                                   (/ rx (sqrt (- 1 (expt (+ (abs x) rx) 2)))))))
      (atan (rounded-ball (atan x) (min rx pi))))))

(defun ball-atan2 (y x)
  "The angle of (X, Y) in (-pi, pi], or NIL when the balls reach the origin or the
negative x axis, where it is not continuous."
  (let ((cy (ball-center y)) (ry (ball-radius y)) (cx (ball-center x)) (rx (ball-radius x)))
    (let ((distance (- (sqrt (+ (* cx cx) (* cy cy))) rx ry)))
      (when (and (> distance 0) (or (> (- cx rx) 0) (> (abs cy) ry)))
        (rounded-ball (atan cy cx) (/ (+ rx ry) distance))))))

(defun expression-ball (expression point)
  "The ball enclosing the value of the arithmetic EXPRESSION at POINT (an alist subject ->
double float, or -> ball for a whole box of points), or NIL where it is undefined or not
real somewhere."
  (labels ((fail () (return-from expression-ball nil))
           (value (x)
             (cond ((rationalp x) (let ((d (coerce x 'double-float)))
                                    (rounded-ball d 0d0)))
                   ((floatp x) (make-ball (coerce x 'double-float) 0d0))
                   ((constant-symbol-p x) (rounded-ball pi 0d0))
                   ((or (variable-symbol-p x) (quantity-term-p x))
                    (let ((entry (assoc x point :test #'equal)))
                      (cond ((null entry) (fail))
                            ((ball-p (cdr entry)) (cdr entry))
                            (t (make-ball (cdr entry) 0d0)))))
                   (t (let ((arguments (mapcar #'value (expression-arguments x))))
                        (or (case (expression-operator x)
                              (+ (reduce #'ball+ arguments))
                              (- (if (rest arguments)
                                     (reduce #'ball+ (mapcar #'ball-negation (rest arguments))
                                             :initial-value (first arguments))
                                     (ball-negation (first arguments))))
                              (* (reduce #'ball* arguments))
                              (/ (if (rest arguments)
                                     (reduce (lambda (a b) (let ((r (ball-reciprocal b)))
                                                             (if r (ball* a r) (fail))))
                                             (rest arguments) :initial-value (first arguments))
                                     (ball-reciprocal (first arguments))))
                              (expt (let ((exponent (third x)))
                                      (if (and (integerp exponent) (<= (abs exponent) 64))
                                          (ball-integer-power (first arguments) exponent)
                                          ;; a^b = exp(b log a), for a > 0 only
                                          (let ((logarithm (ball-function 'log (first arguments))))
                                            (and logarithm
                                                 (ball-function 'exp (ball* (second arguments) logarithm)))))))
                              (atan (if (rest arguments)
                                        (ball-atan2 (first arguments) (second arguments))
                                        (ball-function 'atan (first arguments))))
                              (t (ball-function (expression-operator x) (first arguments))))
                            (fail)))))))
    (handler-case (value expression)
      (arithmetic-error () nil))))

(defun condition-truth (condition point)
  "Whether the relation or logical CONDITION surely holds at POINT: :TRUE, :FALSE, or NIL
when that is not sure (= is never sure)."
  (case (expression-operator condition)
    (not (case (condition-truth (second condition) point) (:true :false) (:false :true)))
    (and (let ((truths (mapcar (lambda (c) (condition-truth c point)) (expression-arguments condition))))
           (cond ((member :false truths) :false) ((every (lambda (x) (eq x :true)) truths) :true))))
    (or (let ((truths (mapcar (lambda (c) (condition-truth c point)) (expression-arguments condition))))
          (cond ((member :true truths) :true) ((every (lambda (x) (eq x :false)) truths) :false))))
    (t (let* ((difference (expression-ball (list '- (relation-lhs condition) (relation-rhs condition)) point))
              (sign (and difference (ball-sign difference))))
         (when sign
           (ecase (expression-operator condition)
             ((> >=) (if (eq sign :positive) :true :false))
             ((< <=) (if (eq sign :negative) :true :false))
             (/= :true)
             (= :false)))))))

(defun random-value (interval random-state)
  "A random double float within INTERVAL ((LOWER . UPPER) of BOUNDs, either NIL), away
from its ends; log-uniform in size over four decades where a side is open-ended."
  (let ((lower (and (car interval) (bound-value (car interval))))
        (upper (and (cdr interval) (bound-value (cdr interval))))
        (size (expt 10d0 (- (random 4d0 random-state) 2))))
    (cond ((and lower upper) (+ lower (* (- upper lower) (+ 0.02d0 (random 0.96d0 random-state)))))
          (lower (+ lower size))
          (upper (- upper size))
          ((zerop (random 2 random-state)) size)
          (t (- size)))))

(defun call-with-admissible-points (bridge relation function &optional assuming)
  "Call FUNCTION on random points (alists subject -> double float, over the subjects of
RELATION and of the facts in force) that surely satisfy the facts in force and the
facts ASSUMING, until it returns true or the limits (*WITNESS-DRAWS*,
*WITNESS-ADMISSIBLE-POINTS*) are reached. Returns the flattened facts."
  (let* ((facts (flatten-facts (append (current-assumptions bridge) assuming)))
         (intervals (subject-intervals facts))
         (subjects (remove-duplicates (append (expression-variables relation)
                                              (mapcan #'expression-variables facts))
                                      :test #'equal))
         (random-state (sb-ext:seed-random-state 1994))
         (admissible 0))
    (loop repeat *witness-draws*
          while (< admissible *witness-admissible-points*)
          do (let ((point (mapcar (lambda (subject)
                                    (cons subject (random-value (cdr (assoc subject intervals :test #'equal))
                                                                random-state)))
                                  subjects)))
               (when (every (lambda (fact) (eq (condition-truth fact point) :true)) facts)
                 (incf admissible)
                 (when (funcall function point) (return)))))
    facts))

(defun relation-witnesses (bridge relation)
  "Two points that surely satisfy the facts in force, RELATION (an inequality) surely
holding at the first and surely failing at the second, as (values HOLDS FAILS FACTS):
alists subject -> double float, and the facts (flattened). NIL when none are found."
  (let ((holds nil) (fails nil))
    (let ((facts (call-with-admissible-points
                  bridge relation
                  (lambda (point)
                    (case (condition-truth relation point)
                      (:true (unless holds (setf holds point)))
                      (:false (unless fails (setf fails point))))
                    (and holds fails)))))
      (and holds fails (values holds fails facts)))))

(defun relation-refuted-p (bridge relation &optional assuming)
  "True when the condition RELATION surely fails at a point that surely satisfies the
facts in force and the facts ASSUMING: then no sound strategy proves it under them."
  (let ((refuted nil))
    (call-with-admissible-points bridge relation
                                 (lambda (point)
                                   (setf refuted (eq (condition-truth relation point) :false)))
                                 assuming)
    refuted))

(defun witnessed-both-ways-p (bridge relation)
  "True when the inequality RELATION (< > <= >=) surely holds at one point that surely
satisfies the facts in force, and surely fails at another: then it is not decided."
  (and (relation-witnesses bridge relation) t))

(defparameter *segment-pieces* 256
  "How many pieces of a segment CONTINUOUS-AND-ADMISSIBLE-BETWEEN-P may evaluate at most.")

(defun segment-piece (from to start end)
  "The point whose subjects are balls enclosing the points FROM + s (TO - FROM) for s in
[START, END] (FROM and TO alists subject -> double float)."
  (mapcar (lambda (entry)
            (let* ((a (cdr entry))
                   (b (cdr (assoc (car entry) to :test #'equal)))
                   (middle (/ (+ start end) 2)))
              (cons (car entry) (rounded-ball (+ a (* (- b a) middle))
                                              (* (abs (- b a)) (/ (- end start) 2))))))
          from))

(defun continuous-and-admissible-between-p (expression facts from to)
  "True when, on the whole segment between the points FROM and TO, every fact of FACTS
surely holds and the arithmetic EXPRESSION is surely defined and real, hence
continuous: checked on pieces of the segment, as balls, halving a piece that is not
sure. With EXPRESSION positive at one end and negative at the other, it then vanishes
at an admissible point in between."
  (let ((pending (list (cons 0d0 1d0))) (budget *segment-pieces*))
    (loop while pending
          do (destructuring-bind (start . end) (pop pending)
               (when (minusp (decf budget)) (return-from continuous-and-admissible-between-p nil))
               (let ((piece (segment-piece from to start end)))
                 (unless (and (expression-ball expression piece)
                              (every (lambda (fact) (eq (condition-truth fact piece) :true)) facts))
                   (let ((middle (/ (+ start end) 2)))
                     (push (cons start middle) pending)
                     (push (cons middle end) pending))))))
    t))

(defun holds-p (bridge relation)
  "True when DECIDE answers :TRUE for RELATION (a relation or a logical form), found
faster where it does not: a point that surely satisfies the facts in force and surely
violates RELATION settles it without asking Maxima, since no sound strategy proves a
relation that fails somewhere (see RELATION-REFUTED-P). For callers that act only on
:TRUE. Signals what DECIDE signals."
  (check-translatable relation :condition)
  (multiple-value-bind (verdict found) (gethash (verdict-key bridge relation) (bridge-cache bridge))
    (cond (found (eq verdict :true))
          ((relation-refuted-p bridge relation) nil)
          (t (eq (decide bridge relation) :true)))))

(defun refuted-p (bridge relation &key assuming)
  "True when RELATION (a relation or a logical form of the algebra) is seen to fail at a
point that satisfies the facts in force and the facts ASSUMING (e.g. ((> tau 0))): then
it does not follow from them, and no sound proof of it exists. NIL proves nothing. Asks
Maxima nothing. Signals UNTRANSLATABLE-EXPRESSION for a RELATION or fact outside the
algebra."
  (check-translatable relation :condition)
  (dolist (fact assuming) (check-translatable fact :condition))
  (relation-refuted-p bridge relation assuming))

(defun sign-varies-p (bridge expression)
  "True when the arithmetic EXPRESSION is seen to be positive at one point that satisfies
the facts in force and negative at another: then no relation of EXPRESSION with 0 is
decided, and EXPRESSION is not identically 0. NIL proves nothing. Asks Maxima nothing.
Signals UNTRANSLATABLE-EXPRESSION for an EXPRESSION outside the algebra."
  (check-translatable expression :arithmetic)
  (witnessed-both-ways-p bridge (list '> expression 0)))

;;; Deciding relations

(defvar *substituting-orders* nil
  "True while DECIDE-BY-ORDER-SUBSTITUTION works, so that it does not recurse.")

(defvar *sides-differ* nil
  "True while DECIDE-RELATION works on an equation (or, in DECIDE-BY-ORDER-SUBSTITUTION,
on its rewriting) whose sides were seen to differ both ways at admissible points.")

(defparameter *sign-sets*
  '(("$POS" :positive) ("$NEG" :negative) ("$ZERO" :zero) ("$PZ" :positive :zero)
    ("$NZ" :negative :zero) ("$PN" :positive :negative) ("$PNZ" :positive :negative :zero))
  "Maxima's sign answers and the signs each allows.")

(defun sign-set (answer)
  "The list of signs (:POSITIVE :NEGATIVE :ZERO) Maxima's sign ANSWER allows."
  (or (rest (assoc (symbol-name answer) *sign-sets* :test #'string=))
      (list :positive :negative :zero)))

(defun sign-requests (form)
  "The sign() requests whose answers together bound the sign of the Maxima FORM,
cheapest first: FORM itself, factor(ratsimp(FORM)), factorsum(FORM) (which groups
terms, e.g. 2 acc l - 2 acc x0 into 2 acc (l - x0)) and trigsimp(FORM) (ratsimp(FORM)
when FORM has no sin, cos or tan, for which trigsimp gives the same form, slower)."
  (list (mcall "$SIGN" form)
        (mcall "$SIGN" (mcall "$FACTOR" (mcall "$RATSIMP" form)))
        (mcall "$SIGN" (mcall "$FACTORSUM" form))
        (mcall "$SIGN" (if (trigonometric-form-p form)
                           (mcall "$AMES_TRIGSIMP" form)
                           (mcall "$RATSIMP" form)))))

(defun narrowed-signs (signs answer)
  "SIGNS (a list of :POSITIVE :NEGATIVE :ZERO) narrowed by Maxima's sign ANSWER."
  (if (symbolp answer) (intersection signs (sign-set answer)) signs))

(defun forms-signs (bridge forms &key datum)
  "For each of the real Maxima FORMS, the signs (:POSITIVE :NEGATIVE :ZERO) it may have
under the current assumptions: the intersection of what sign() says of its forms (see
SIGN-REQUESTS). One round trip."
  (let* ((count (length (sign-requests 0)))
         (answers (request-list bridge (mapcan #'sign-requests forms) :datum datum)))
    (loop for rest on answers by (lambda (list) (nthcdr count list))
          collect (reduce #'narrowed-signs (subseq rest 0 count)
                          :initial-value (list :positive :negative :zero)))))

(defun form-signs (bridge form &key datum (enough (constantly nil)))
  "The signs the real Maxima FORM may have under the current assumptions: what the
answers to SIGN-REQUESTS allow together. They are asked one at a time, cheapest first
(each answer cached on its own), and the asking stops once at most one sign is left or
ENOUGH, a predicate on the signs found so far, is true; further answers could only
narrow the signs (an empty intersection would mean contradictory answers)."
  (let ((signs (list :positive :negative :zero)))
    (dolist (request (sign-requests form) signs)
      (setf signs (narrowed-signs signs (maxima-request bridge request :datum datum)))
      (when (or (null (rest signs)) (funcall enough signs))
        (return signs)))))

(defun square-root-kernel (form)
  "Some subform sqrt(A) = ((MEXPT) A 1/2) of the Maxima FORM, or NIL."
  (cond ((atom form) nil)
        ((and (mform-p form +mexpt+) (mform-p (third form) +rat+)
              (eql (second (third form)) 1) (eql (third (third form)) 2))
         form)
        (t (some #'square-root-kernel (cdr form)))))

(defun sign-product (a b)
  "The signs a product may have when its factors may have the signs A and B."
  (remove-duplicates
   (loop for x in a
         append (loop for y in b
                      collect (cond ((or (eq x :zero) (eq y :zero)) :zero)
                                    ((eq x y) :positive)
                                    (t :negative))))))

(defun radical-signs (bridge difference &key datum)
  "The signs of DIFFERENCE (a Maxima form) found by clearing one square root: written
as (a + b sqrt(A)) / c, its numerator has the sign of a when b = 0 and, when a and b
have opposite signs, the sign of b^2 A - a^2 times that of b. NIL when no square root
is there or the form is not linear in it."
  (destructuring-bind (numerator denominator)
      (request-list bridge (list (mcall "$NUM" (mcall "$RATSIMP" difference))
                                 (mcall "$DENOM" (mcall "$RATSIMP" difference)))
                    :datum datum)
    (let ((kernel (square-root-kernel numerator)))
      (when (and kernel (eql 1 (maxima-request bridge (mcall "$HIPOW" (mcall "$EXPAND" numerator) kernel)
                                              :datum datum)))
        (destructuring-bind (a b)
            (request-list bridge (list (mcall "$RATCOEF" (mcall "$EXPAND" numerator) kernel 0)
                                       (mcall "$RATCOEF" (mcall "$EXPAND" numerator) kernel 1))
                          :datum datum)
          (let* ((radicand (second kernel))
                 (gap (mdifference (mform +mtimes+ (mform +mexpt+ b 2) radicand)
                                   (mform +mexpt+ a 2))))
            (destructuring-bind (a-signs b-signs gap-signs radicand-signs denominator-signs)
                (forms-signs bridge (list a b gap radicand denominator) :datum datum)
              (flet ((only (signs &rest allowed) (and signs (subsetp signs allowed))))
                (let* ((real (only radicand-signs :positive :zero))
                       (numerator-signs
                        (cond ((or (null a-signs) (null b-signs)) nil)
                              ;; b sqrt(A) against a: the larger in size wins. When
                              ;; b^2 A > a^2 >= 0, A > 0 follows, so sqrt(A) is real.
                              ((and (only a-signs :negative :zero) (only b-signs :positive))
                               (cond ((only gap-signs :positive) '(:positive))
                                     (real gap-signs)))
                              ((and (only a-signs :positive :zero) (only b-signs :negative))
                               (cond ((only gap-signs :positive) '(:negative))
                                     (real (sign-product gap-signs '(:negative)))))
                              ((not real) nil)
                              ;; a and b sqrt(A) of one sign
                              ((and (only a-signs :positive :zero) (only b-signs :positive :zero))
                               (if (or (only a-signs :positive)
                                       (and (only b-signs :positive) (only radicand-signs :positive)))
                                   '(:positive) '(:positive :zero)))
                              ((and (only a-signs :negative :zero) (only b-signs :negative :zero))
                               (if (or (only a-signs :negative)
                                       (and (only b-signs :negative) (only radicand-signs :positive)))
                                   '(:negative) '(:negative :zero)))
                              (t nil))))
                  (and numerator-signs (only denominator-signs :positive :negative)
                       (sign-product numerator-signs denominator-signs)))))))))))

(defun relation-verdict (operator signs)
  "The truth of (OPERATOR d 0) when d may have only SIGNS."
  (flet ((only (&rest allowed) (and signs (subsetp signs allowed)))
         (none (&rest excluded) (and signs (null (intersection signs excluded)))))
    (cond ((null signs) :unknown)
          (t (ecase operator
               (> (cond ((only :positive) :true) ((none :positive) :false) (t :unknown)))
               (>= (cond ((only :positive :zero) :true) ((only :negative) :false) (t :unknown)))
               (< (cond ((only :negative) :true) ((none :negative) :false) (t :unknown)))
               (<= (cond ((only :negative :zero) :true) ((only :positive) :false) (t :unknown)))
               (= (cond ((only :zero) :true) ((none :zero) :false) (t :unknown)))
               (/= (cond ((none :zero) :true) ((only :zero) :false) (t :unknown))))))))

(defun decide-relation (bridge relation)
  "The truth of one RELATION (= /= < > <= >=) under the current assumptions: is(), then
numeric witnesses that no strategy can decide it (see RELATION-WITNESSES), then the
signs of the difference of its sides, after clearing a square root, equivalence (for =
and /=), and the order substitution."
  (let* ((operator (expression-operator relation))
         (equation (member operator '(= /=)))
         (lhs (to-mx bridge (relation-lhs relation)))
         (rhs (to-mx bridge (relation-rhs relation)))
         (question (case operator
                     (= (mform +equal+ lhs rhs))
                     (/= (mform +notequal+ lhs rhs))
                     (t (mform (cdr (assoc operator *relation-heads*)) lhs rhs))))
         (verdict (maxima-truth (maxima-request bridge (mcall "$IS" question) :datum relation))))
    (unless (eq verdict :unknown)
      (return-from decide-relation verdict))
    ;; an inequality seen to hold at one admissible point and to fail at another, or an
    ;; equation whose sides cross between two such points, is decided by no strategy
    (multiple-value-bind (holds fails facts)
        (and (not *substituting-orders*)
             (relation-witnesses bridge (if equation
                                            (list '> (relation-lhs relation) (relation-rhs relation))
                                            relation)))
      (when (and holds
                 (or (not equation)
                     (continuous-and-admissible-between-p
                      (list '- (relation-lhs relation) (relation-rhs relation)) facts holds fails)))
        (return-from decide-relation :unknown))
      ;; the signs are asked for only until they decide the relation
      (setf verdict (relation-verdict operator
                                      (form-signs bridge (mdifference lhs rhs)
                                                  :datum relation
                                                  :enough (lambda (signs)
                                                            (not (eq (relation-verdict operator signs)
                                                                     :unknown))))))
      (when (eq verdict :unknown)
        (let ((signs (radical-signs bridge (mdifference lhs rhs) :datum relation)))
          (when signs (setf verdict (relation-verdict operator signs)))))
      ;; sides seen to differ both ways are not equal: equivalence cannot be proven,
      ;; here nor after the order substitution
      (let ((*sides-differ* (or *sides-differ* (and equation holds t))))
        (when (and (eq verdict :unknown) equation (not *sides-differ*)
                   (equivalent-p bridge (relation-lhs relation) (relation-rhs relation)))
          (setf verdict (if (eq operator '=) :true :false)))
        (when (eq verdict :unknown)
          (setf verdict (decide-by-order-substitution bridge relation))))
      verdict)))

(defun order-facts (bridge relation)
  "The facts in force that order a variable V of RELATION against an expression E free of
V and not a number (V > E, V < E, E > V ...), as lists (V E SIGN WEAK): V is E + SIGN * D
for some D > 0 (D >= 0 when WEAK). These are the orderings Maxima's sign() does not use
inside sums."
  (loop for fact in (current-assumptions bridge)
        for operator = (expression-operator fact)
        for lhs = (relation-lhs fact)
        for rhs = (relation-rhs fact)
        for weak = (and (member operator '(>= <=)) t)
        for above = (member operator '(> >=))          ; lhs above rhs
        for order = (cond ((not (member operator '(> >= < <=))) nil)
                          ((variable-symbol-p lhs) (list lhs rhs (if above 1 -1) weak))
                          ((variable-symbol-p rhs) (list rhs lhs (if above -1 1) weak)))
        when (and order
                  (free-of-p (first order) (second order))
                  (not (numberp (second order)))
                  (not (free-of-p (first order) relation)))
          collect order))

(defun decide-by-order-substitution (bridge relation)
  "Decide RELATION once more after writing each ordered variable V (a fact V > E or V < E
in force, E not a number) as E + D or E - D with D > 0 fresh: sums such as
mb g (l1 - l2)^2 + f (l1 - l2) then show their sign term by term. Sound: every admissible
V is some E +/- D. :UNKNOWN when there is no such fact."
  (let ((orders (and (not *substituting-orders*) (order-facts bridge relation))))
    (cond ((null orders) :unknown)
          ((null (rest orders)) (decide-with-orders bridge relation orders))
          ;; all the orderings at once, else each alone (writing V = E - D forgets V > 0)
          (t (let ((verdict (decide-with-orders bridge relation orders)))
               (if (eq verdict :unknown)
                   (loop for order in orders
                         for single = (decide-with-orders bridge relation (list order))
                         unless (eq single :unknown) return single
                         finally (return :unknown))
                   verdict))))))

(defun order-excess-name (bridge variable)
  "The fresh variable D standing for the excess of VARIABLE over its bound (V = E + D or
E - D) in DECIDE-BY-ORDER-SUBSTITUTION: an uninterned symbol, so no user name can be
it, and the same one each time for a VARIABLE of BRIDGE, so that the rewritten requests
are answered from the cache when they come again."
  (let ((table (bridge-excess-names bridge)))
    (or (gethash variable table)
        (let ((excess (make-symbol (format nil "~A-EXCESS" variable))))
          ;; named apart from the algebra's variables ($AMESX...), so that it takes none
          ;; of their letters
          (maxima-name (bridge-names bridge) excess "$AMESX")
          (setf (gethash (copy-tree variable) table) excess)))))

(defun decide-with-orders (bridge relation orders)
  "DECIDE-BY-ORDER-SUBSTITUTION's work for the given ORDERS (see ORDER-FACTS)."
  (let* ((*substituting-orders* t)
         (deltas (loop for order in orders
                       collect (order-excess-name bridge (first order))))
         (bindings (loop for (variable base sign) in orders
                         for delta in deltas
                         collect (cons variable (list '+ base (list '* sign delta)))))
         (facts (loop for (nil nil nil weak) in orders
                      for delta in deltas
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

(defun decide (bridge relation)
  "Decide RELATION (a relation of the algebra, or AND / OR / NOT of relations) under the
current assumptions: :TRUE, :FALSE or :UNKNOWN. Uses Maxima's is(), then the sign of the
difference of the two sides in several simplified forms, then the same after clearing a
square root (so that roots of quadratics can be compared); connectives are combined in
three-valued logic. Verdicts are cached under the facts in force, like requests.
Signals UNTRANSLATABLE-EXPRESSION, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (check-translatable relation :condition)
  (let* ((cache (bridge-cache bridge))
         (key (verdict-key bridge relation))
         (record (bridge-statistics-record bridge)))
    (multiple-value-bind (verdict found) (gethash key cache)
      (incf (statistics-calls record))
      (if found
          (progn (incf (statistics-cache-hits record)) verdict)
          (let ((verdict (decide-uncached bridge relation)))
            (when (>= (hash-table-count cache) *cache-limit*) (clrhash cache))
            (setf (gethash (copy-tree key) cache) verdict))))))

(defun verdict-key (bridge relation)
  "The key of DECIDE's verdict on RELATION in BRIDGE's cache, under the facts in force."
  (list* :decide *substituting-orders* relation (assumption-key bridge)))

(defun decide-uncached (bridge relation)
  "DECIDE's work, without its cache of verdicts."
  (labels ((verdict (condition)
             (case (expression-operator condition)
               (not (ecase (verdict (second condition))
                      (:true :false) (:false :true) (:unknown :unknown)))
               (and (let ((result :true))
                      (dolist (part (expression-arguments condition) result)
                        (ecase (verdict part)
                          (:false (return :false))
                          (:unknown (setf result :unknown))
                          (:true)))))
               (or (let ((result :false))
                     (dolist (part (expression-arguments condition) result)
                       (ecase (verdict part)
                         (:true (return :true))
                         (:unknown (setf result :unknown))
                         (:false)))))
               (t (decide-relation bridge condition)))))
    (verdict relation)))

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
