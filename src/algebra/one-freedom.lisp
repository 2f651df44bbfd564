;;;; src/algebra/one-freedom.lisp -- a conservative motion of one degree of freedom whose
;;;; inertia depends on the configuration: a rod on a hinge, a ladder on its wall and floor.
;;;;
;;;; A system whose configuration is fixed by one coordinate q (an angle, say) has the
;;;; kinetic energy (1/2) M(q) q'^2, with the generalized inertia
;;;;   M(q) = sum over bodies of m (x_q^2 + y_q^2) + I theta_q^2
;;;; (x, y the centre of mass, theta the angle, each a function of q; the subscript a
;;;; derivative), and a potential V(q). Energy conservation gives q' as a function of q:
;;;;   q'^2 = E(q) = (M(q0) q0'^2 + 2 (V(q0) - V(q))) / M(q),
;;;; and q'' = E'(q)/2 (differentiate q'^2 = E(q) in time and divide by 2 q'). Anything
;;;; that depends on q, q' and q'' (a constraint force: the wall's push on a ladder, a
;;;; hinge's pull) is then a function of q alone (ALONG-MOTION), and its earliest zero
;;;; ahead (EARLIEST-COORDINATE-ROOT) is where an event happens (the ladder leaving the
;;;; wall). The turning point is E's first zero ahead; the time to reach a coordinate is
;;;; the travel-time integral of dq / sqrt(E(q)) (integrals.lisp: elliptic forms when M
;;;; is constant and V a sinusoid, as for a pendulum; under parameter values a number,
;;;; marked :NUMERIC, when no closed form is found), and the period of a swing between
;;;; two turning points is periods.lisp's for a sinusoid, else twice the travel time
;;;; between them. A rod of length l hinged at its end: M = m l^2/3, V = m g (l/2) sin q;
;;;; a ladder of length l on a frictionless wall and floor: M = m l^2/3 as well.

(in-package #:ames.algebra)

(defvar *turned-variable* (make-symbol "TURNED")
  "The variable u >= 0 of EARLIEST-COORDINATE-ROOT: how far the coordinate has gone.")

(defstruct (one-freedom (:constructor %make-one-freedom))
  "A conservative motion of one degree of freedom (see the file header): the name
COORDINATE q, the generalized INERTIA M(q), the POTENTIAL V(q), the START q0 and the
initial RATE q0', the energy integral SPEED-SQUARED E(q) = q'^2, the ACCELERATION
q'' = E'(q)/2, and the DIRECTION of motion (1, -1, or NIL when not decided)."
  coordinate inertia potential start rate speed-squared acceleration direction)

(defun generalized-inertia (bridge parts coordinate)
  "M(q) for the name COORDINATE q: the sum over PARTS, each a list (MASS INERTIA X Y
THETA) of a body whose centre of mass is at (X, Y) and whose angle is THETA, all
functions of q, of MASS (X_q^2 + Y_q^2) + INERTIA THETA_q^2; simplified."
  (flet ((rate (expression) (maxima-derivative bridge expression coordinate)))
    (simplified bridge
                `(+ 0 ,@(loop for (mass inertia x y theta) in parts
                              collect `(+ (* ,mass (+ (expt ,(rate x) 2) (expt ,(rate y) 2)))
                                          (* ,inertia (expt ,(rate theta) 2))))))))

(defun make-one-freedom (bridge &key coordinate inertia potential start (rate 0))
  "The ONE-FREEDOM motion of the name COORDINATE with the generalized INERTIA M(q) > 0
and the POTENTIAL V(q), starting at START with the RATE q' (0: from rest): its energy
integral, acceleration and direction (the sign of RATE, or at rest the sign of the
acceleration at the start; NIL when the assumptions decide neither).
Signals INVALID-BRIDGE-ARGUMENT (COORDINATE no name, START or RATE depending on it),
UNTRANSLATABLE-EXPRESSION."
  (check-travel-arguments coordinate (list inertia potential start rate) (list start rate))
  (flet ((at-start (expression) (substitute-expressions (list (cons coordinate start)) expression)))
    (let* ((energy (simplified bridge `(/ (+ (* ,(at-start inertia) (expt ,rate 2))
                                              (* 2 (- ,(at-start potential) ,potential)))
                                           ,inertia)))
           (acceleration (simplified bridge `(/ ,(maxima-derivative bridge energy coordinate) 2)))
           (rate-sign (decided-sign bridge rate))
           (direction (case (if (eq rate-sign :zero)
                                (decided-sign bridge (substituted bridge acceleration coordinate start))
                                rate-sign)
                        (:positive 1) (:negative -1))))
      (%make-one-freedom :coordinate coordinate :inertia inertia :potential potential
                         :start start :rate rate :speed-squared energy
                         :acceleration acceleration :direction direction))))

(defun along-motion (bridge system expression &key rate acceleration)
  "EXPRESSION, a function of the coordinate q, of its rate q' (the name RATE) and of its
acceleration q'' (the name ACCELERATION), as a function of q alone along SYSTEM's motion:
q'' = E'(q)/2 and q'^2 = E(q); an odd power of q' becomes the DIRECTION times sqrt(E)
(NIL when EXPRESSION has one and the direction is not decided). Simplified."
  (let* ((energy (one-freedom-speed-squared system))
         (without-acceleration (if acceleration
                                   (substitute-expressions
                                    (list (cons acceleration (one-freedom-acceleration system)))
                                    expression)
                                   expression)))
    (if (or (null rate) (free-of-p rate without-acceleration))
        (simplified bridge without-acceleration)
        (let ((coefficients (polynomial-coefficients-in bridge without-acceleration rate))
              (direction (one-freedom-direction system)))
          (cond ((and coefficients
                      (loop for c in (rest coefficients) by #'cddr always (zero-expression-p bridge c)))
                 ;; even in q': powers of q'^2 = E
                 (simplified bridge `(+ 0 ,@(loop for c in coefficients by #'cddr for k from 0
                                                  collect `(* ,c (expt ,energy ,k))))))
                (direction
                 (substituted bridge without-acceleration rate `(* ,direction (sqrt ,energy))))
                (t nil))))))

(defun product-factors-of (expression)
  "The factors of EXPRESSION when it is a product or a quotient (the numerator's factors
and the denominator as one more), else the list of EXPRESSION itself; a power of a
factor counts as the factor."
  (flet ((base (x) (if (and (consp x) (eq (first x) 'expt) (realp (third x)) (plusp (third x)))
                       (second x) x)))
    (cond ((and (consp expression) (eq (first expression) '*))
           (mapcar #'base (rest expression)))
          ((and (consp expression) (eq (first expression) '/) (= (length expression) 3))
           (append (product-factors-of (second expression)) (list (third expression))))
          ((and (consp expression) (eq (first expression) '-) (= (length expression) 2))
           (product-factors-of (second expression)))
          (t (list (base expression))))))

(defun earliest-coordinate-root (bridge system expression)
  "The earliest coordinate q strictly ahead of SYSTEM's start, in its direction of
motion, where EXPRESSION (a function of the coordinate) is 0: COORDINATE-ROOT-AHEAD's
values for SYSTEM's coordinate, start and direction."
  (coordinate-root-ahead bridge expression (one-freedom-coordinate system)
                         (one-freedom-start system) (one-freedom-direction system)))

(defvar *trigonometric-variable* (make-symbol "TRIG")
  "The variable standing for sin q or cos q in ROOTLESS-TRIGONOMETRIC-POLYNOMIAL-P.")

(defun rootless-trigonometric-polynomial-p (bridge expression coordinate)
  "True when EXPRESSION is a polynomial P in sin q alone (or in cos q alone), q the
name COORDINATE, and P is proven to have no root v >= -1 (a quadratic: no real root, by its discriminant,
decided or, under parameter values, by them): EXPRESSION then never
vanishes (a ladder's push on the floor, 1 + 9 sin^2 q - 6 sin a sin q, of negative
discriminant). Several frequencies defeat EARLIEST-TRIGONOMETRIC-ROOT; this one form
does not."
  (let ((v (auxiliary-variable bridge *trigonometric-variable*)))
    (dolist (head '(sin cos) nil)
      (let ((polynomial (subst v (list head coordinate) expression :test #'equal)))
        (let ((coefficients (and (free-of-p coordinate polynomial)
                                 (call-or-nil (lambda () (polynomial-coefficients-in bridge polynomial v))))))
          (when (and coefficients
                     (if (= (length coefficients) 3)
                         ;; a quadratic: its discriminant, decided or (under values) by values
                         (destructuring-bind (c0 c1 c2) coefficients
                           (eq :true (decided-or-by-values
                                      bridge `(< (- (expt ,c1 2) (* 4 ,c2 ,c0)) 0))))
                         (eq :none (call-or-nil (lambda () (earliest-root bridge polynomial v :after -1
                                                                                       :strictly nil
                                                                                       :candidates nil))))))
            (return t)))))))


(defun coordinate-root-ahead (bridge expression coordinate start direction)
  "The earliest value of COORDINATE strictly ahead of START in DIRECTION (1 or -1) where
EXPRESSION (a function of COORDINATE) is 0, proven earliest: each of its factors
(Maxima's factored form) that is A + K sin q or A + K cos q through sine-roots.lisp (in
asin form), any other sinusoid through EARLIEST-TRIGONOMETRIC-ROOT (or EARLIEST-ROOT),
in the distance gone u > 0, COORDINATE = START + DIRECTION u. Returns
  (values Q :FOUND), (values :NONE NIL) or (values :UNKNOWN FACT)
as EARLIEST-TRIGONOMETRIC-ROOT does (:UNKNOWN NIL also when DIRECTION is NIL; :UNKNOWN
FACT when two factors' roots cannot be ordered: FACT is that order, which the run's
parameter values decide when there are some, recorded as DECIDE-BY-VALUES does). A
factor's zero is a root whether or not EXPRESSION changes sign there: the caller knows
its sign before."
  (let ((u (auxiliary-variable bridge *turned-variable*))
        (roots '()))
    (unless direction (return-from coordinate-root-ahead (values :unknown nil)))
    (dolist (factor (product-factors-of (simplified bridge expression)))
      (unless (or (free-of-p coordinate factor) (rootless-trigonometric-polynomial-p bridge factor coordinate))
        (multiple-value-bind (root status) (single-function-root-ahead bridge factor coordinate start direction)
          (case status
            (:found (push root roots))
            ((nil)
             ;; any sinusoid: the half-angle method, in the distance gone u
             (let ((shifted (simplified bridge (substitute-expressions
                                                (list (cons coordinate `(+ ,start (* ,direction ,u))))
                                                factor))))
               (multiple-value-bind (root status) (earliest-trigonometric-root bridge shifted u :after 0 :strictly t)
                 (case root
                   (:none)
                   (:unknown (return-from coordinate-root-ahead (values :unknown status)))
                   (t (push (simplified bridge `(+ ,start (* ,direction ,root))) roots))))))))))
    (if (null roots)
        (values :none nil)
        (let ((earliest (first roots)))
          (dolist (root (rest roots))
            (let ((earlier `(< (* ,direction (- ,root ,earliest)) 0)))
              (case (decided-or-by-values bridge earlier)
                (:true (setf earliest root))
                (:false)
                (t (return-from coordinate-root-ahead (values :unknown earlier))))))
          (values earliest :found)))))

(defun turning-point (bridge system)
  "SYSTEM's next turning point: the earliest coordinate ahead where E(q) = q'^2 is 0
(EARLIEST-COORDINATE-ROOT's values)."
  (earliest-coordinate-root bridge system (one-freedom-speed-squared system)))

(defun coordinate-travel-time (bridge system to &key values)
  "The time SYSTEM takes from its start to the coordinate TO, with no turning point
between (the caller's guarantee): the travel-time integral of dq / sqrt(E(q)).
  (values TIME :CLOSED-FORM VERIFICATION)  as TRAVEL-TIME answers;
  (values NUMBER :NUMERIC)                 no closed form, a double-float under VALUES
                                           (an alist name -> number), to about 1e-10;
  (values NIL :NO-CLOSED-FORM)             neither."
  (let ((q (one-freedom-coordinate system))
        (energy (one-freedom-speed-squared system))
        (from (one-freedom-start system)))
    (multiple-value-bind (time kind verification)
        (call-or-nil (lambda () (travel-time bridge energy q from to
                                             :direction (one-freedom-direction system))))
      (cond (time (values time kind verification))
            (values (let ((number (handler-case (numeric-travel-time bridge energy q from to values)
                                    (numeric-evaluation-failed () nil))))
                      (if number (values number :numeric) (values nil :no-closed-form))))
            (t (values nil :no-closed-form))))))

(defun reversed-motion (system)
  "SYSTEM going the other way from its start (its direction negated)."
  (let ((copy (copy-one-freedom system)))
    (setf (one-freedom-direction copy) (and (one-freedom-direction system)
                                            (- (one-freedom-direction system))))
    copy))

(defun swing-period (bridge system &key values)
  "The period of SYSTEM's swing between its two turning points, when it has them (the
turning point ahead, and the one behind or, from rest, the start):
  (values PERIOD :CLOSED-FORM (Q1 Q2))  periods.lisp's libration period when E(q) is a
                                         sinusoid, else twice the closed-form travel time;
  (values NUMBER :NUMERIC (Q1 Q2))       under VALUES, twice the numeric travel time;
  (values NIL :NO-CLOSED-FORM)           no turning points proven, or neither."
  (multiple-value-bind (ahead status) (turning-point bridge system)
    (unless (eq status :found) (return-from swing-period (values nil :no-closed-form)))
    (let* ((at-rest (zero-expression-p bridge (one-freedom-rate system)))
           (behind (if at-rest
                       (one-freedom-start system)
                       (multiple-value-bind (root found) (turning-point bridge (reversed-motion system))
                         (if (eq found :found)
                             root
                             (return-from swing-period (values nil :no-closed-form))))))
           (between (list behind ahead))
           (period (libration-period bridge (one-freedom-speed-squared system)
                                     (one-freedom-coordinate system))))
      (if period
          (values period :closed-form between)
          ;; from the turning point behind: E vanishes at both ends
          (let ((from-behind (copy-one-freedom system)))
            (setf (one-freedom-start from-behind) behind
                  (one-freedom-rate from-behind) 0)
            (multiple-value-bind (time kind) (coordinate-travel-time bridge from-behind ahead :values values)
              (case kind
                (:closed-form (values (simplified bridge `(* 2 ,time)) :closed-form between))
                (:numeric (values (* 2 time) :numeric between))
                (t (values nil :no-closed-form)))))))))
