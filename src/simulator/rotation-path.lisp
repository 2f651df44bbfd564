;;;; src/simulator/rotation-path.lisp -- the :ROTATION-PATH integrator: a rotating body whose
;;;; contacts leave it one degree of freedom, its angle, integrated by the energy integral.
;;;;
;;;; A ladder on its wall and floor, a block tipping about a corner, a rod on a hinge: the
;;;; solved model gives the body's accelerations as functions of its angle theta and angular
;;;; velocity omega alone. When the angular acceleration is a function A(theta) of the angle
;;;; alone (a constant generalized inertia: the ladder's m l^2/3, a pivot's I + m d^2) and the
;;;; centre's accelerations are those of a point X(theta), a = X'(theta) alpha + X''(theta)
;;;; omega^2 (checked: X' is the integral of the omega^2 part from the start's slope, and
;;;; X' A must be the omega-free part, proven with the trigonometric identities), the
;;;; motion is one degree of freedom along theta:
;;;;   X(theta) = X0 + integral of X' from theta0 to theta,   omega^2 = E(theta) from
;;;;   theta'' = A(theta) (the bridge's autonomous ODE solver, as for a curved contact),
;;;; the velocities X'(theta) omega with omega = direction sqrt(E). The group's variable is
;;;; +ARC-LENGTH+ standing for theta; the events are found along theta by the algebra's
;;;; COORDINATE-ROOT-AHEAD (each factor's earliest zero ahead, every turn considered: the
;;;; conditions are periodic in theta), and their times by the travel-time integral (an
;;;; elliptic form for the ladder). A root beyond the next turning point of E is not
;;;; reached; under parameter values a root with no closed form is searched with numbers
;;;; (numeric-angle-roots.lisp). Nothing here knows which force or contact holds the body.

(in-package #:ames.simulator)

(defun rotation-path-rates (run solved group)
  "For GROUP, one rotating body B alone: (values B ALPHA AX AY) its angular acceleration
and its centre's accelerations from SOLVED, each over (angle B) and (angvel B) only;
else NIL."
  (let ((bodies (group-bodies group)))
    (when (and (null (rest bodies)) (rotating-p run (first bodies)))
      (let* ((body (first bodies))
             (allowed (list `(ames.kb:angle ,body) `(ames.kb:angvel ,body)))
             (others (set-difference (solved-model-state solved) allowed :test #'equal))
             (rates (list (angular-rate solved body)
                          (cdr (assoc `(ames.kb:vel ,body :x) (solved-model-rates solved) :test #'equal))
                          (cdr (assoc `(ames.kb:vel ,body :y) (solved-model-rates solved) :test #'equal)))))
        (when (every (lambda (rate) (and rate (free-of-all-p others rate))) rates)
          (apply #'values body rates))))))

(defun omega-coefficients (run expression omega)
  "(C0 C2) with EXPRESSION = C0 + C2 OMEGA^2, C0 and C2 free of OMEGA; NIL otherwise."
  (let ((coefficients (handler-case (ames.maxima:polynomial-coefficients-in (run-bridge run) expression omega)
                        (ames.maxima:maxima-condition () nil))))
    (when (and coefficients (<= (length coefficients) 3)
               (or (< (length coefficients) 2) (eql 0 (tidy run (second coefficients)))))
      (list (first coefficients) (or (third coefficients) 0)))))

(defun identically-zero-p (run expression)
  "True when EXPRESSION is proven 0: its rational form is 0, or Maxima shows it equal to 0
with the trigonometric identities (sin^2 + cos^2 = 1: the omega^2 coefficient of a body
turning about a pinned corner vanishes only with them)."
  (or (eql 0 (tidy run expression))
      (ames.maxima:equivalent-p (run-bridge run) expression 0)))

(defun antiderivative-from (run expression theta theta0)
  "The integral of EXPRESSION over THETA from THETA0 (in the name THETA), checked by
differentiation; NIL when Maxima finds none."
  (let* ((bridge (run-bridge run))
         (antiderivative (ames.maxima:call-or-nil
                          (lambda () (ames.maxima:maxima-antiderivative bridge expression theta)))))
    (when (and antiderivative
               (ames.maxima:equivalent-p bridge (ames.maxima:maxima-derivative bridge antiderivative theta)
                                         expression))
      (tidy run `(- ,antiderivative ,(substitute-expressions (list (cons theta theta0)) antiderivative))
            :full))))

(defun slope-from-start (run theta free squared driving theta0)
  "X'(theta) as the integral of the omega^2 part SQUARED from the slope at the start,
FREE/DRIVING at THETA0 (see CENTRE-ALONG-ANGLE); NIL when DRIVING is 0 there or the
integral is not found."
  (let* ((at-start (lambda (x) (substitute-expressions (list (cons theta theta0)) x)))
         (start-driving (tidy run (funcall at-start driving)))
         (start-slope (and (not (eql 0 start-driving))
                           (tidy run `(/ ,(funcall at-start free) ,start-driving) :full)))
         (turned (and start-slope (antiderivative-from run squared theta theta0))))
    (and turned (tidy run `(+ ,start-slope ,turned) :full))))

(defun centre-along-angle (run theta acceleration omega driving theta0 x0)
  "The centre's coordinate X(theta) (in the name THETA) whose acceleration over the angle
and OMEGA is ACCELERATION, when the angular acceleration is DRIVING (over THETA):
ACCELERATION = X' DRIVING + X'' OMEGA^2. X'' is the omega^2 part C2, so X' is its
integral from the slope at the start, C0/DRIVING at THETA0 (C0 the omega-free part), and
must then satisfy X' DRIVING = C0 everywhere (proven; the quotient C0/DRIVING itself
often cancels only with sin^2 + cos^2 = 1, which rational simplification does not see,
and its integral is needlessly hard). Where DRIVING is 0 at the start (a hinged body set
turning from its equilibrium), X' is that quotient, its derivative proven to be C2. X is
X' integrated from X0. (values X X') or NIL."
  (let ((parts (omega-coefficients run acceleration omega)))
    (when (and parts (not (identically-zero-p run driving)) (free-of-p omega (second parts)))
      (destructuring-bind (free squared) parts
        (let ((slope (or (let ((slope (slope-from-start run theta free squared driving theta0)))
                           (and slope (identically-zero-p run `(- (* ,slope ,driving) ,free)) slope))
                         (let ((quotient (tidy run `(/ ,free ,driving) :full)))
                           (and (eql 0 (tidy run `(- ,(ames.maxima:maxima-derivative (run-bridge run) quotient theta)
                                                     ,squared)))
                                quotient)))))
          (when slope
            (let ((moved (antiderivative-from run slope theta theta0)))
              (when moved
                (values (tidy run `(+ ,x0 ,moved) :full) slope)))))))))

(defun integrate-rotation-path (run solved group)
  "Fill GROUP's motion along its body's angle (see the file header) and make it a
:ROTATION-PATH group; NIL (GROUP unchanged) when it is no such motion, the initial velocity is
not the one the angle gives, or the direction of motion is not decided."
  (multiple-value-bind (body alpha ax ay) (rotation-path-rates run solved group)
    (when body
      (let* ((theta-term `(ames.kb:angle ,body)) (omega-term `(ames.kb:angvel ,body))
             (s +arc-length+)
             (over-angle (lambda (x) (substitute-expressions (list (cons theta-term s)) x)))
             (driving-parts (omega-coefficients run (funcall over-angle alpha) omega-term))
             (theta0 (body-angle run body)) (omega0 (body-angular-velocity run body))
             (p0 (body-position run body)) (v0 (body-velocity run body)))
        (when (and driving-parts (identically-zero-p run (second driving-parts)))
          (let ((driving (first driving-parts)))
            (multiple-value-bind (x x-slope)
                (centre-along-angle run s (funcall over-angle ax) omega-term driving theta0 (first p0))
              (multiple-value-bind (y y-slope)
                  (and x (centre-along-angle run s (funcall over-angle ay) omega-term driving theta0 (second p0)))
                (when (and y
                           (holds run `(= ,(first v0) (* ,(at-arc x-slope theta0) ,omega0)))
                           (holds run `(= ,(second v0) (* ,(at-arc y-slope theta0) ,omega0))))
                  (fill-rotation-path run group body driving s theta0 omega0
                                      (list x y) (list x-slope y-slope)))))))))))

(defun fill-rotation-path (run group body driving s theta0 omega0 centre slopes)
  "Set GROUP's motion along the angle S of BODY (see INTEGRATE-ROTATION-PATH): the energy
integral of S'' = DRIVING from THETA0 at OMEGA0, CENTRE (X Y) and their SLOPES over S.
GROUP, or NIL when the ODE has no energy integral or the direction is not decided."
  (let* ((ode (handler-case (ames.maxima:solve-autonomous-ode (run-bridge run) driving s
                                                               :initial-position theta0
                                                               :initial-velocity omega0)
                ((or ames.maxima:solve-failed ames.maxima:maxima-question) () nil)))
         (direction (or (sign-direction (sign-of run omega0))
                        (sign-direction (sign-of run (at-arc driving theta0))))))
    (when (and ode (member direction '(1 -1)))
      (let* ((energy (tidy run (ames.maxima:ode-solution-speed-squared ode)))
             (speed (tidy run `(* ,direction (sqrt ,energy)))))
        (setf (group-variable group) s
              (group-s0 group) theta0
              (group-direction group) direction
              (group-speed-squared group) energy
              (group-speed group) speed
              (group-ode-kind group) (ames.maxima:ode-solution-kind ode)
              (group-line group) (list :coordinate `(= ,s (ames.kb:angle ,body)))
              (group-kind group) :rotation-path
              (group-motion group)
              (list (cons `(ames.kb:pos ,body :x) (first centre))
                    (cons `(ames.kb:pos ,body :y) (second centre))
                    (cons `(ames.kb:vel ,body :x) (tidy run `(* ,(first slopes) ,speed) :full))
                    (cons `(ames.kb:vel ,body :y) (tidy run `(* ,(second slopes) ,speed) :full))
                    (cons `(ames.kb:angle ,body) s)
                    (cons `(ames.kb:angvel ,body) speed)))
        group))))

;;; Where a condition fires along the angle

(defun decided-or-by-values-first (run relation)
  "RELATION's truth (:TRUE, :FALSE or :UNKNOWN) as AMES.ALGEBRA:DECIDED-OR-BY-VALUES gives
it, but, while the run's values decide first (AMES.ALGEBRA:VALUES-FIRST-P), after only a
cheap proof: the values settle the order of two angles along the path, as they settle
the order of two event times (recorded as assumed from them)."
  (let ((truth (ames.algebra:decide-first-cheaply (run-bridge run) relation)))
    (if (eq truth :unknown)
        (or (ames.algebra:decide-by-values relation) :unknown)
        truth)))

(defun angle-root-ahead (run group function)
  "Where FUNCTION (of the angle) first reaches zero going negative ahead of GROUP's start:
(values :AT S), (values :NEVER) or (values :UNKNOWN FACT)."
  (let ((function (tidy run function :full)))
    (when (free-of-p +arc-length+ function)
      (return-from angle-root-ahead (values :never)))
    (multiple-value-bind (root status)
        (handler-case (ames.algebra:coordinate-root-ahead (run-bridge run) function +arc-length+
                                                         (group-s0 group) (group-direction group))
          (ames.maxima:maxima-error () (values :unknown nil)))
      (when (eq root :unknown)
        ;; no proven root: under parameter values, searched with numbers; none found,
        ;; proven positive up to the turning point by intervals (angle-intervals.lisp)
        (let ((found (numeric-angle-root run group function)))
          (cond (found (setf root found))
                ((positive-before-turning-p run group function) (setf root :none)))))
      (case root
        (:none (values :never))
        (:unknown (values :unknown (or status `(:roots-of (= ,function 0)))))
        (t (let ((slope (tidy run `(* ,(group-direction group)
                                      ,(at-arc (ames.geometry:differentiate function +arc-length+) root)))))
             (case (decided-or-by-values-first run `(<= ,slope 0))
               (:true (values :at root))
               (t (values :unknown `(< ,slope 0))))))))))

(defun angle-relation-root (run group relation over-angle)
  "Where RELATION (an inequality or an OR of them, or a guarded conjunction:
guarded-meetings.lisp) first holds ahead along GROUP's angle."
  (when (guarded-relation-parts relation)
    (return-from angle-relation-root (guarded-angle-root run group relation over-angle)))
  (if (eq (first relation) 'or)
      (let ((best nil) (unknown nil))
        (dolist (part (rest relation))
          (multiple-value-bind (status s) (angle-relation-root run group part over-angle)
            (case status
              (:at (if (or (null best) (eq (nearer-p run group s best) :true))
                       (setf best s)
                       (unless (eq (nearer-p run group best s) :true) (setf unknown `(< ,s ,best)))))
              (:unknown (setf unknown s)))))
        (cond (unknown (values :unknown unknown)) (best (values :at best)) (t (values :never))))
      (angle-root-ahead run group (funcall over-angle (violation-function relation)))))

(defun reached-before-turning (run group s)
  "Whether GROUP's body reaches the angle S before its speed vanishes: :TRUE, :FALSE, or
(values :UNKNOWN FACT) (the parameter values decide the order when the run has some)."
  (multiple-value-bind (turn status)
      (handler-case (ames.algebra:coordinate-root-ahead (run-bridge run) (group-speed-squared group)
                                                       +arc-length+ (group-s0 group) (group-direction group))
        (ames.maxima:maxima-error () (values :unknown nil)))
    (case turn
      (:none :true)
      (:unknown (if (numeric-reached-p run group s)
                    ;; under parameter values: no turning point before S (numbers)
                    :true
                    (values :unknown (or status `(>= ,(at-arc (group-speed-squared group) s) 0)))))
      (t (let ((before `(< (* ,(group-direction group) (- ,s ,turn)) 0)))
           (case (decided-or-by-values-first run before)
             (:true :true)
             (:false :false)
             (t (values :unknown before))))))))

(defun turning-candidate (run solved group condition)
  "When CONDITION, over GROUP's motion along its angle, fires: a CANDIDATE (its TIME the
travel time, its AT-ARC the angle), :NEVER, or (values :UNKNOWN FACT). A condition on
the angular velocity itself (SPEED-FUNCTION-P) fires at the turning point ahead, where
the energy integral vanishes (TURNING-CROSSING). Another condition met only beyond that
turning point never fires when the knowledge base watches it (TURNING-WATCHED-P), and
is reported unsupported otherwise."
  (let* ((relation (ames.engine:termination-condition-relation condition))
         (over-angle (lambda (x) (motion-value (list group) (over-state-terms run solved x))))
         (turning (speed-function-p run group (speed-condition-function relation over-angle))))
    (multiple-value-bind (status s)
        (if turning
            ;; the angular velocity changes sign: a turning point (turns.lisp)
            (turning-crossing run solved group (speed-condition-function relation over-angle))
            (angle-relation-root run group relation over-angle))
      (case status
        (:at
         (multiple-value-bind (reached fact) (if turning :true (reached-before-turning run group s))
           (case reached
             (:true (angle-candidate run group condition relation over-angle s (not turning)))
             (:false (if (turning-watched-p run solved group)
                         ;; the knowledge base's turning point ends the state first
                         :never
                         (error 'unsupported-situation
                                :datum (group-bodies group)
                                :detail "The body would turn back before the event; a turning point of a rotation is not supported yet.")))
             (t (values :unknown fact)))))
        (:never :never)
        (t (values :unknown s))))))

(defun angle-candidate (run group condition relation over-angle s with-rate)
  "A pending CANDIDATE of CONDITION at the angle S of GROUP: its time and rate are worked
out (FIRING-AT-ANGLE) only when no other candidate on GROUP is proven nearer
(SETTLE-PENDING-CANDIDATES, pending-candidates.lisp): the travel time and the rate at a
far angle cost integrals and sign proofs that cannot change which event comes first."
  (make-pending-candidate
   condition s group
   (lambda () (firing-at-angle run group condition relation over-angle s with-rate))))

(defun firing-at-angle (run group condition relation over-angle s with-rate)
  "The CANDIDATE of CONDITION (its RELATION) firing at the angle S of GROUP; its rate in
time there WITH-RATE (none at a turning point, where the speed's slope is infinite). At
an angle found with numbers (a rational S under parameter values, numeric-angle-roots.lisp)
the rate's sign is the numbers' and the time the numeric travel time."
  (let* ((f (funcall over-angle (guarded-violation-function relation)))
         (numeric (and (rationalp s) (run-numbers-known-p run)))
         (rate (and with-rate (not (eq (first relation) 'or))
                    (tidy run `(* ,(at-arc (ames.geometry:differentiate f +arc-length+) s)
                                  ,(at-arc (group-speed group) s)))))
         (approaching (and rate
                           (if numeric
                               (let ((r (numeric-or-nil (run-bridge run) rate (run-values run))))
                                 (and r (< r (- (* 1d-9 (max 1d0 (abs r)))))))
                               ;; under values, as the slope's sign at the root
                               ;; (ANGLE-ROOT-AHEAD): a cheap proof, else the values
                               (eq :true (decided-or-by-values-first run `(< ,rate 0)))))))
    (make-candidate condition
                    (condition-event condition (and approaching rate))
                    (if numeric
                        (list :no-closed-form :from-arc-length (group-s0 group) :to-arc-length s
                                              :speed-squared (group-speed-squared group))
                        (arc-travel-time run group s))
                    :at-arc s :group group :rate rate)))

(defun check-rotation-paths-forever (run groups)
  "Signal UNSUPPORTED-SITUATION when a :ROTATION-PATH group of GROUPS (a state no event
ends) may reach a turning point ahead, where its angle would turn back: nothing watches
that turning point yet, and the motion over the angle holds only up to it."
  (dolist (group groups)
    (when (eq (group-kind group) :rotation-path)
      (let ((turn (handler-case (ames.algebra:coordinate-root-ahead
                                 (run-bridge run) (group-speed-squared group) +arc-length+
                                 (group-s0 group) (group-direction group))
                    (ames.maxima:maxima-error () :unknown))))
        (unless (or (eq turn :none) (and (not (keywordp turn)) (creeping-end-p run group turn)))
          (error 'unsupported-situation
                 :datum (group-bodies group)
                 :detail (format nil "The body turns back~:[~; at the angle ~S~] before any event ~
                                      ends the state; a turning point of a rotation is not ~
                                      supported yet." (not (keywordp turn)) turn)))))))
