;;;; src/simulator/turns.lisp -- roots along a circle in the direction of motion, over every
;;;; turn, and turning points of a one-degree-of-freedom motion.
;;;;
;;;; On a circle of radius r a condition is a function of the arc length s through sin(s/r)
;;;; and cos(s/r): solve() lists its principal roots only, which may lie behind the body
;;;; (a ball moving toward -s) or miss the root of the other family (pi - asin c). With
;;;; the angle turned x >= 0, s = s0 + direction r x, the condition is A + B cos x + C sin x
;;;; and the bridge's EARLIEST-TRIGONOMETRIC-ROOT proves its earliest root x > 0 (half-angle
;;;; substitution, every turn considered: the function has period 2 pi). A root in the
;;;; form solve() wrote (or that form shifted by whole turns, or its mirror image) is
;;;; used when it is proven to be that same root.
;;;;
;;;; A turning point is where the energy integral E(s) = s'^2 reaches zero ahead of the
;;;; body with E'(s) against the motion: the speed vanishes and the tangential
;;;; acceleration brings the body back. A condition whose violation function is the
;;;; speed along the path itself (its sign changes only through zero) is found there.

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

(defun speed-function-p (run group function)
  "True when FUNCTION (of the arc length) is the speed along GROUP's path or its
negative: a quantity whose sign changes only through zero, where E(s) vanishes."
  (let ((speed (group-speed group)))
    (and speed (not (free-of-p +arc-length+ function))
         (or (eql 0 (tidy run `(- ,function ,speed)))
             (eql 0 (tidy run `(+ ,function ,speed)))))))

(defun turning-crossing (run group function)
  "Where FUNCTION, the speed along GROUP's path (see SPEED-FUNCTION-P), changes sign
ahead of the body: where E(s) = s'^2 reaches zero with E going negative beyond it (the
body stops and the push brings it back). (values :AT S), (values :NEVER) or (values
:UNKNOWN FACT). FUNCTION is the speed's negative when the condition is the speed
turning from negative: then it never fires while the body moves forward, and the other
way round."
  (let ((sign (if (eql 0 (tidy run `(- ,function ,(group-speed group)))) 1 -1)))
    ;; the speed is direction sqrt(E): the condition fires when it reaches zero from the
    ;; side of its sign
    (if (/= (* sign (group-direction group)) 1)
        (values :never)
        (crossing-ahead run group (group-speed-squared group)))))
