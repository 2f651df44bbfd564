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

(defun arc-of-turn (group radius x)
  "The arc length reached after turning the angle X along GROUP's circle of RADIUS."
  `(+ ,(group-s0 group) (* ,(group-direction group) ,radius ,x)))

(defun circle-crossing (run group function)
  "On GROUP's circle: the first arc length ahead where FUNCTION (of the arc length)
reaches zero going negative, over every turn: (values :AT S), (values :NEVER), (values
:UNKNOWN FACT), or NIL when FUNCTION is no sinusoid of the angle turned (one frequency)."
  (let* ((radius (group-radius run group))
         (f (and radius (tidy run (at-arc function (arc-of-turn group radius +turn-angle+)) :full)))
         (after 0))
    (when (or (null f) (free-of-p +turn-angle+ f))
      (return-from circle-crossing nil))
    (loop repeat 4
          do (multiple-value-bind (root status)
                 (handler-case (ames.maxima:earliest-trigonometric-root (run-bridge run) f +turn-angle+
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
  (let ((s (tidy run (arc-of-turn group radius angle)))
        (roots (roots-in-arc run function))
        (turn `(* 2 pi ,radius)))
    (unless (eq roots :failed)
      (dolist (root roots)
        (dolist (k '(0 1 -1 2 -2))
          (dolist (candidate (list `(+ ,root (* ,k ,turn))
                                   `(+ (- (* pi ,radius) ,root) (* ,k ,turn))
                                   `(+ (- ,root) (* ,k ,turn))))
            (let ((candidate (tidy run candidate)))
              (when (eq (decide run `(= ,candidate ,s)) :true)
                (return-from nicest-arc candidate)))))))
    s))

(defun inverse-of-own-function (run expression)
  "EXPRESSION with acos(cos u) written u where 0 <= u <= pi is proven, asin(sin u) and
atan(tan u) written u where -pi/2 <= u <= pi/2 is (the principal ranges), and acos(-cos
u) written pi - u: the roots of a sinusoid at a turning point come out so."
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
                           ((and (member operator '(asin atan))
                                 (eq (first argument) (if (eq operator 'asin) 'sin 'tan))
                                 (within (second argument) '(- (/ pi 2)) '(/ pi 2)))
                            (second argument))
                           (t x)))))))
    (walk expression)))
