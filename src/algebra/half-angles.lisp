;;;; src/algebra/half-angles.lisp -- the half-angle substitution: sin and cos of a plain
;;;; angle written rationally in t = tan(x/2).
;;;;
;;;; sin x = 2t/(1 + t^2), cos x = (1 - t^2)/(1 + t^2) and tan x = 2t/(1 - t^2) hold at
;;;; every x that is not an odd multiple of pi. A sum such as 1 + sin a - cos a, which
;;;; sign() and the signed parts cannot place (two terms of opposite signs), becomes
;;;; 2t (1 + t)/(1 + t^2), whose sign is read off its factors. The signs of sin x and
;;;; cos x that the range of x gives become facts about t: sin x > 0 is t > 0, sin x < 0
;;;; is t < 0, cos x > 0 is -1 < t < 1. The step applies only to an angle whose sine has
;;;; a strict sign (so x is no multiple of pi and t is defined), and is sound: the
;;;; relation rewritten is decided for every t those facts allow, the angle's own t
;;;; among them.

(in-package #:ames.algebra)

(defun half-angle-subjects (prover relation)
  "The plain angles X under SIN, COS or TAN in RELATION whose sine has a strict sign from
X's range, each once, with that sign and their cosine's: a list of (X SIN-SIGNS
COS-SIGNS)."
  (let ((found '()))
    (labels ((walk (x)
               (when (and (consp x) (not (quantity-term-p x)))
                 (mapc #'walk (expression-arguments x))
                 (when (and (member (expression-operator x) '(sin cos tan))
                            (subject-p (second x))
                            (not (assoc (second x) found :test #'equal)))
                   (let ((sin-signs (trigonometric-signs prover (list 'sin (second x)))))
                     (when (member sin-signs '((:positive) (:negative)) :test #'equal)
                       (push (list (second x) sin-signs
                                   (trigonometric-signs prover (list 'cos (second x))))
                             found)))))))
      (walk relation))
    (nreverse found)))

(defun half-angle-facts (variable sin-signs cos-signs)
  "The facts about VARIABLE, t = tan(x/2), that the signs of sin x and cos x give."
  (append (if (equal sin-signs '(:positive))
              (list (list '> variable 0))
              (list (list '< variable 0)))
          (cond ((equal cos-signs '(:positive)) (list (list '< variable 1) (list '> variable -1)))
                ((equal cos-signs '(:negative)) (list (list '> (list 'expt variable 2) 1))))))

(defun half-angle-bindings (angle variable)
  "The rational forms in VARIABLE (t = tan(ANGLE/2)) of sin, cos and tan of ANGLE."
  (let ((square (list 'expt variable 2)))
    (list (cons (list 'sin angle) `(/ (* 2 ,variable) (+ 1 ,square)))
          (cons (list 'cos angle) `(/ (- 1 ,square) (+ 1 ,square)))
          (cons (list 'tan angle) `(/ (* 2 ,variable) (- 1 ,square))))))

(defun decide-by-half-angles (prover relation)
  "Step 9: sin, cos and tan of each plain angle whose sine has a strict sign written in
t = tan(x/2) (see this file's header), and the relation, simplified, decided under the
facts about t. :UNKNOWN when no angle applies or nothing is proven."
  (let ((bridge (prover-bridge prover)) (bindings '()) (facts '()))
    (loop for (angle sin-signs cos-signs) in (half-angle-subjects prover relation)
          for variable = (keyed-auxiliary-variable bridge (list :half-angle angle)
                                                   (format nil "~A-HALF-TAN" angle))
          do (setf bindings (append (half-angle-bindings angle variable) bindings)
                   facts (append (half-angle-facts variable sin-signs cos-signs) facts)))
    (if (null bindings)
        :unknown
        (let* ((rewritten (substitute-subexpressions bindings relation))
               (difference (full-simplification bridge (relation-difference rewritten))))
          (if (null difference)
              :unknown
              (handler-case
                  (call-with-assumptions
                   bridge facts
                   (lambda () (decide bridge (list (expression-operator relation) difference 0))))
                (inconsistent-assumptions () :unknown)
                (maxima-error () :unknown)))))))
