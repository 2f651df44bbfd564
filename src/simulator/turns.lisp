;;;; src/simulator/turns.lisp -- roots along a circle in the direction of motion, over every
;;;; turn, and the inverse functions of a root's own angle undone.
;;;;
;;;; On a circle of radius r a condition is a function of the arc length s through sin(s/r)
;;;; and cos(s/r): solve() lists its principal roots only, which may lie behind the body
;;;; (a ball moving toward -s) or miss the root of the other family (pi - asin c). With
;;;; the angle turned x >= 0, s = s0 + direction r x, the condition is A + B cos x + C sin x
;;;; and the bridge's EARLIEST-TRIGONOMETRIC-ROOT proves its earliest root x > 0 (half-angle
;;;; substitution, every turn considered: the function has period 2 pi). A root in the
;;;; form solve() wrote (or that form shifted by whole turns, or its mirror image) is
;;;; used when it is proven to be that same root.

(in-package #:ames.simulator)

(defconstant +turn-angle+ 'turn-angle
  "The variable standing for the angle turned along a circle from a state's start.")

(defun arc-of-turn (run group radius x)
  "The arc length reached after turning the angle X along GROUP's circle of RADIUS."
  `(+ ,(inverse-of-own-function run (group-s0 group)) (* ,(group-direction group) ,radius ,x)))

(defun circle-crossing (run group function)
  "On GROUP's circle: the first arc length ahead where FUNCTION (of the arc length)
reaches zero going negative, over every turn: (values :AT S), (values :NEVER), (values
:UNKNOWN FACT), or NIL when FUNCTION is no sinusoid of the angle turned (one frequency)."
  (let* ((radius (group-radius run group))
         (f (and radius (tidy run (at-arc function (arc-of-turn run group radius +turn-angle+)) :full)))
         (after 0))
    (when (or (null f) (free-of-p +turn-angle+ f))
      (return-from circle-crossing nil))
    (loop repeat 4
          do (multiple-value-bind (root status)
                 (handler-case (ames.algebra:earliest-trigonometric-root (run-bridge run) f +turn-angle+
                                                                        :after after :strictly t)
                   (ames.maxima:maxima-error () (values :unknown nil)))
               (unless (keywordp root)
                 (setf root (tidy run (inverse-of-own-function run root))))
               (cond ((eq root :none) (return-from circle-crossing (values :never)))
                     ((eq root :unknown)
                      (return-from circle-crossing (and status (values :unknown status))))
                     (t
                      (let ((slope (tidy run (substitute-expressions
                                              (list (cons +turn-angle+ root))
                                              (ames.geometry:differentiate f +turn-angle+)))))
                        (case (decide run `(<= ,slope 0))
                          (:true (return-from circle-crossing
                                   (values :at (nicest-arc run group radius root function))))
                          (:false (setf after root))
                          (t (return-from circle-crossing (values :unknown `(< ,slope 0))))))))))
    nil))

(defun nicest-arc (run group radius angle function)
  "The arc length after turning ANGLE (a proven root of FUNCTION's sinusoid): solve()'s
root of FUNCTION, shifted by whole turns or mirrored, when it is proven equal; else the
arc length in the bridge's form."
  (let ((s (tidy run (arc-of-turn run group radius angle)))
        (roots (roots-in-arc run function))
        (turn `(* 2 pi ,radius)))
    (unless (eq roots :failed)
      (dolist (root roots)
        (dolist (k '(0 1 -1 2 -2))
          (dolist (candidate (list `(+ ,root (* ,k ,turn))
                                   `(+ (- (* pi ,radius) ,root) (* ,k ,turn))
                                   `(+ (- ,root) (* ,k ,turn))))
            (let ((candidate (tidy run (inverse-of-own-function run (tidy run candidate)))))
              (when (eq (decide run `(= ,candidate ,s)) :true)
                (return-from nicest-arc candidate)))))))
    s))

(defun inverse-of-own-function (run expression)
  "EXPRESSION with acos(cos u) written u where 0 <= u <= pi is proven, asin(sin u) and
atan(tan u) (also atan(sin u/cos u)) written u where -pi/2 <= u <= pi/2 is (the
principal ranges), acos(-cos u) written pi - u, and atan(cos u/sin u) and asin(cos u)
pi/2 - u where 0 <= u <= pi is (acos(sin u) where -pi/2 <= u <= pi/2): the roots of a sinusoid, and the arc lengths of a body released on a
circle, come out so."
  (labels ((within (u low high)
             (and (holds run `(>= ,u ,low)) (holds run `(<= ,u ,high))))
           (walk (x)
             (if (or (atom x) (quantity-term-p x))
                 x
                 (let ((x (cons (first x) (mapcar #'walk (rest x)))))
                   (destructuring-bind (operator &optional argument &rest more) x
                     (cond ((or more (atom argument)) x)
                           ((and (eq operator 'acos) (eq (first argument) 'cos)
                                 (within (second argument) 0 'pi))
                            (second argument))
                           ((and (eq operator 'acos) (eq (first argument) '-) (null (cddr argument))
                                 (consp (second argument)) (eq (first (second argument)) 'cos)
                                 (within (second (second argument)) 0 'pi))
                            `(- pi ,(second (second argument))))
                           ((and (eq operator 'atan) (eq (first argument) '/) (= (length argument) 3)
                                 (consp (second argument)) (consp (third argument))
                                 (equal (second (second argument)) (second (third argument)))
                                 (member (list (first (second argument)) (first (third argument)))
                                         '((sin cos) (cos sin)) :test #'equal))
                            ;; atan(tan u) = u on (-pi/2, pi/2); atan(cot u) = pi/2 - u on (0, pi)
                            (let ((u (second (second argument))))
                              (if (eq (first (second argument)) 'sin)
                                  (if (within u '(- (/ pi 2)) '(/ pi 2)) u x)
                                  (if (within u 0 'pi) `(- (/ pi 2) ,u) x))))
                           ((and (eq operator 'asin) (eq (first argument) 'cos)
                                 (within (second argument) 0 'pi))
                            ;; asin(cos u) = pi/2 - u on [0, pi]
                            `(- (/ pi 2) ,(second argument)))
                           ((and (eq operator 'acos) (eq (first argument) 'sin)
                                 (within (second argument) '(- (/ pi 2)) '(/ pi 2)))
                            ;; acos(sin u) = pi/2 - u on [-pi/2, pi/2]
                            `(- (/ pi 2) ,(second argument)))
                           ((and (member operator '(asin atan))
                                 (eq (first argument) (if (eq operator 'asin) 'sin 'tan))
                                 (within (second argument) '(- (/ pi 2)) '(/ pi 2)))
                            (second argument))
                           (t x)))))))
    (walk expression)))

;;; Turning points
;;;
;;; A turning point is where the energy integral E(s) = s'^2 reaches zero ahead of the
;;; body and turns negative: the speed vanishes and the tangential force brings the body
;;; back. A condition whose violation function is the speed along the path itself (whose
;;; sign changes only through zero) fires there.

(defun speed-condition-function (relation over-arc)
  "RELATION's violation function over the arc length (see VIOLATION-FUNCTION), or NIL
for a compound relation."
  (and (not (member (first relation) '(or and not)))
       (funcall over-arc (violation-function relation))))

(defun speed-multiple (run group function)
  "The constant K with FUNCTION (of the arc length) = K times the speed along GROUP's path
(its line, for a :LINE group), K of proven sign (+1 or -1 exactly for a condition on the
speed along a curve, l0 for the rate of a distance times the starting distance l0); NIL
when FUNCTION is no such multiple."
  (let ((speed (group-speed group)))
    (when (and speed function (not (free-of-p +arc-length+ function)))
      (cond ((eql 0 (tidy run `(- ,function ,speed))) 1)
            ((eql 0 (tidy run `(+ ,function ,speed))) -1)
            (t (let ((k (tidy run `(/ ,function ,speed) :full)))
                 (and (free-of-p +arc-length+ k)
                      (sign-is run k :positive :negative)
                      k)))))))

(defun speed-function-p (run group function)
  "True when FUNCTION (of the arc length) is the speed along GROUP's path or line times
a constant of proven sign (SPEED-MULTIPLE)."
  (and (speed-multiple run group function) t))

(defun turning-crossing (run solved group function)
  "Where FUNCTION, plus or minus the speed along GROUP's path, reaches zero from the
side of its sign ahead of the body: where E(s) = s'^2 reaches zero going negative.
(values :AT S), (values :NEVER) or (values :UNKNOWN FACT). FUNCTION, the speed times
the direction of motion, is positive while the body moves: it vanishes at the turning
point; of the opposite sign, it never reaches zero from its side. Where E vanishes
with a zero slope (a double zero: an unstable equilibrium, such as a pendulum sent to
its top with just the energy to get there) the body approaches it in no finite time:
:NEVER."
  (let ((direction (sign-direction (sign-of run (speed-multiple run group function)))))
    (cond ((not (eql direction (group-direction group))) (values :never))
          ((turning-preceded-p run solved group) (values :never))
          (t (multiple-value-bind (status s) (zero-ahead run group (group-speed-squared group))
               (if (eq status :at)
                   (let ((slope (tidy run (at-arc (ames.geometry:differentiate (group-speed-squared group)
                                                                               +arc-length+)
                                                  s))))
                     ;; E falls to 0 there, its slope of the sign opposite to the
                     ;; motion's: proven strict, a simple zero (asked first: where E's
                     ;; zero is an atan of a root, = 0 costs DECIDE minutes, the strict
                     ;; sign seconds)
                     (if (eq :true (decide run `(< (* ,(group-direction group) ,slope) 0)))
                         (values :at s)
                         (case (decide run `(= ,slope 0))
                           ;; a double zero of E: the body creeps toward it for ever (an
                           ;; unstable equilibrium reached in no finite time), never turning
                           (:true (values :never))
                           (:false (values :at s))
                           (t (values :unknown `(/= ,slope 0))))))
                   (values status s)))))))

(defun creeping-end-p (run group s)
  "True when GROUP's energy integral vanishes at S to second order (its slope there is
proven 0): the body approaches S for ever and never reaches it."
  (eq :true (decide run `(= ,(tidy run (at-arc (ames.geometry:differentiate (group-speed-squared group)
                                                                             +arc-length+)
                                               s))
                            0))))

(defun zero-ahead (run group function)
  "Where FUNCTION (of GROUP's coordinate) first reaches zero going negative ahead of its
start: along a curve or line (CROSSING-AHEAD), or along a rotating body's angle
(ANGLE-ROOT-AHEAD, every turn considered)."
  (if (eq (group-kind group) :rotation-path)
      (angle-root-ahead run group function)
      (crossing-ahead run group function)))

(defun energy-affine-parts (run group function)
  "(values ALPHA BETA) with FUNCTION (of the arc length) = ALPHA + BETA E(s), E GROUP's
energy integral, ALPHA and BETA constants; NIL when FUNCTION is no such function."
  (let ((energy (group-speed-squared group)))
    (when (and function energy (not (free-of-p +arc-length+ function))
               (not (free-of-p +arc-length+ energy)))
      (let* ((beta (tidy run `(/ ,(ames.geometry:differentiate function +arc-length+)
                                 ,(ames.geometry:differentiate energy +arc-length+))
                         :full))
             (alpha (and (free-of-p +arc-length+ beta)
                         (tidy run `(- ,function (* ,beta ,energy)) :full))))
        (when (and alpha (free-of-p +arc-length+ alpha))
          (values alpha beta))))))

(defun turning-preceded-p (run solved group)
  "True when another termination condition of the model surely fires before GROUP's
body could turn: its violation function is ALPHA + BETA E(s) with ALPHA < 0 < BETA, so
it turns negative while E is still positive (the normal force of a ball above the
centre of a loop vanishes before its speed does). Then the turning point, whether it
exists or not, never ends the state."
  (let ((over-arc (lambda (x) (motion-value (list group) (over-state-terms run solved x)))))
    (some (lambda (condition)
            (let ((relation (ames.engine:termination-condition-relation condition)))
              (and (not (gap-relation-contact relation))
                   (multiple-value-bind (alpha beta)
                       (energy-affine-parts run group (speed-condition-function relation over-arc))
                     (and alpha (holds run `(< ,alpha 0)) (holds run `(> ,beta 0)))))))
          (ames.engine:model-termination-conditions (run-model run)))))

(defun turning-watched-p (run solved group)
  "True when a termination condition of the model fires where GROUP's speed along its
path changes sign (SPEED-FUNCTION-P): the knowledge base's turning point, whatever it
calls it."
  (let ((over-arc (lambda (x) (motion-value (list group) (over-state-terms run solved x)))))
    (some (lambda (condition)
            (let ((relation (ames.engine:termination-condition-relation condition)))
              (and (not (gap-relation-contact relation))
                   (speed-function-p run group (speed-condition-function relation over-arc)))))
          (ames.engine:model-termination-conditions (run-model run)))))

(defun positive-where-reached-p (run group function)
  "True when FUNCTION (of the arc length) is proven positive wherever GROUP's body can
be: it is alpha + beta E(s), E the energy integral (>= 0 wherever the body is), with
constants alpha > 0 and beta >= 0. On a circle under gravity the normal force is such a
function (the height is affine in the speed squared): a particle swinging in a bowl
never lifts off, whatever the roots of N = 0 beyond its turning points."
  (multiple-value-bind (alpha beta) (energy-affine-parts run group function)
    (and alpha (holds run `(> ,alpha 0)) (holds run `(>= ,beta 0)))))

;;; Periodic motion

(defun periodic-swing (run solved fired)
  "When the state ends with FIRED, a single turning point (see TURNING-CROSSING) of a
body on a curve that started at rest (its energy integral vanishes at the start: a
turning point too), or of a body along its angle, the motion between the two turning
points is periodic, nothing
else interrupting it on the way there (nor, by the energy integral, on the way back):
the plist (:PERIOD P :BETWEEN (S1 S2)), P the closed form of the bridge's
LIBRATION-PERIOD. NIL otherwise (another end, or no closed form of the period)."
  (let* ((candidate (and fired (null (rest fired)) (first fired)))
         (group (and candidate (candidate-group candidate)))
         (condition (and candidate (candidate-condition candidate))))
    (when (and group condition (member (group-kind group) '(:path :rotation-path))
               (candidate-at-arc candidate))
      (let* ((relation (ames.engine:termination-condition-relation condition))
             (over-arc (lambda (x) (motion-value (list group) (over-state-terms run solved x))))
             (energy (group-speed-squared group)))
        (when (and (not (gap-relation-contact relation))
                   (speed-function-p run group (speed-condition-function relation over-arc))
                   (holds run `(= ,(tidy run (at-arc energy (group-s0 group))) 0)))
          (let ((period (handler-case (ames.algebra:libration-period (run-bridge run) energy +arc-length+)
                          (ames.maxima:maxima-condition () nil))))
            (when period
              (list :period period
                    :between (list (tidy run (inverse-of-own-function run (group-s0 group)))
                                   (candidate-at-arc candidate))))))))))
