;;;; src/simulator/sinusoid-floors.lisp -- functions of time that never turn negative: the least
;;;; value of an oscillation, and positivity proven at once.
;;;;
;;;; A termination condition's function G of TAU whose root search does not decide can still be
;;;; settled without its roots (FIRST-TIME-NEGATIVE, termination.lisp):
;;;;   - G = A + B cos(w tau) + C sin(w tau) is never below A - sqrt(B^2 + C^2): with
;;;;     A >= 0 and A^2 >= B^2 + C^2 it never turns negative (it may touch zero once a period,
;;;;     where no search after the first touch can settle it); else A^2 - (B^2 + C^2) > 0 is
;;;;     the fact that would, the one to branch on;
;;;;   - G = A + exp(-p tau) (B cos(w tau) + C sin(w tau)), p >= 0 (a damped oscillation), is
;;;;     never below A - sqrt(B^2 + C^2) either: the same test and fact, sufficient only;
;;;;   - G > 0 proven for every TAU > 0 by Maxima's signs (a sum of positive terms: a critically
;;;;     damped spring's length l0 + a (1 + c tau / 2m) exp(-c tau / 2m)).
;;;; Each is sound: it answers only what it proves.

(in-package #:ames.simulator)

(defun time-sinusoid (run g)
  "(A B C W) with G = A + B cos(W tau) + C sin(W tau), or NIL."
  (and (trigonometric-in-time-p g)
       (handler-case (ames.algebra:sinusoid-coefficients (run-bridge run) g 'tau)
         (ames.maxima:maxima-condition () nil))))

(defun decaying-exponential (run g)
  "An exponential (exp E) in G whose argument E is -p tau with p >= 0 proven, or NIL."
  (labels ((walk (x)
             (when (consp x)
               (if (and (eq (first x) 'exp) (not (free-of-p 'tau (second x)))
                        (let ((slope (tidy run `(/ ,(second x) tau))))
                          (and (free-of-p 'tau slope) (holds run `(<= ,slope 0)))))
                   (return-from decaying-exponential x)
                   (mapc #'walk (rest x))))))
    (walk g)
    nil))

(defun replaced-subexpression (old new expression)
  "EXPRESSION with every subexpression EQUAL to OLD replaced by NEW."
  (cond ((equal expression old) new)
        ((consp expression) (cons (first expression)
                                  (mapcar (lambda (x) (replaced-subexpression old new x)) (rest expression))))
        (t expression)))

(defun damped-sinusoid (run g)
  "(A B C W) with G = A + exp(-p tau) (B cos(W tau) + C sin(W tau)), p >= 0, checked by
simplification; or NIL."
  (let* ((expanded (ignore-errors (tidy run g :expanded-trigexpand)))
         (decay (and expanded (decaying-exponential run expanded))))
    (when decay
      (let* ((u (gensym "DECAY"))
             (linear (replaced-subexpression decay u expanded))
             (a (tidy run (substitute-expressions (list (cons u 0)) linear)))
             (wave (tidy run `(- ,(substitute-expressions (list (cons u 1)) linear) ,a)))
             (parts (and (free-of-p 'tau a) (time-sinusoid run wave))))
        (when (and parts
                   (holds run `(= ,(first parts) 0))
                   (holds run `(= (- ,g (+ ,a (* ,decay ,wave))) 0)))
          (list a (second parts) (third parts) (fourth parts)))))))

(defun oscillation-floor-parts (run g)
  "(A B C W) when G is an oscillation about A of amplitude at most sqrt(B^2 + C^2) (see the
file header), else NIL."
  (and (or (trigonometric-in-time-p g) (not (free-of-p 'tau g)))
       (or (time-sinusoid run g) (damped-sinusoid run g))))

(defun sinusoid-never-negative-p (run g)
  "True when G's least value, A - sqrt(B^2 + C^2) by OSCILLATION-FLOOR-PARTS, is proven
not negative: G never turns negative."
  (and (trigonometric-in-time-p g)
       (let ((parts (oscillation-floor-parts run g)))
         (and parts
              (destructuring-bind (a b c w) parts
                (declare (ignore w))
                (and (holds run `(>= ,a 0))
                     (holds run `(>= (- (expt ,a 2) (+ (expt ,b 2) (expt ,c 2))) 0))))))))

(defun sinusoid-floor-fact (run g)
  "For G an oscillation about A > 0 (OSCILLATION-FLOOR-PARTS), the relation
A^2 - (B^2 + C^2) > 0 that would prove G never negative: the missing fact to branch on.
NIL for any other G."
  (and (trigonometric-in-time-p g)
       (let ((parts (oscillation-floor-parts run g)))
         (and parts
              (destructuring-bind (a b c w) parts
                (declare (ignore w))
                (and (holds run `(> ,a 0))
                     `(> ,(tidy run `(- (expt ,a 2) (+ (expt ,b 2) (expt ,c 2)))) 0)))))))

(defun positive-after-start-p (run g)
  "True when G > 0 is proven for every TAU > 0 under the assumptions (Maxima's signs):
G has no root after the start. Asked only where the root search did not decide."
  (ames.maxima:with-assumptions ((run-bridge run) '((> tau 0)))
    (holds run `(> ,g 0))))
