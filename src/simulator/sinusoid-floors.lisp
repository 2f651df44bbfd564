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
;;;;   - either one stationary at the start (w C = p B: a spring released from rest) has its
;;;;     extremes at w tau = n pi, B (-1)^n exp(-p n pi / w): never below A - |B|;
;;;;   - G > 0 proven for every TAU > 0 by Maxima's signs (a sum of positive terms: a critically
;;;;     damped spring's length l0 + a (1 + c tau / 2m) exp(-c tau / 2m)).
;;;; Each is sound: it answers only what it proves.

(in-package #:ames.simulator)

(defparameter *largest-boundary-fact* 40
  "The boundary branch (X = 0, a parameter solved for and substituted) is tried only for
a missing fact of at most this many atoms and operators: solving a long polynomial for
each parameter costs much, and its boundary is no textbook case. Also the
largest floor fact of an oscillation a run branches on (SINUSOID-FLOOR-FACT); defined
here, before its first use, for branching.lisp too.")

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

(defun exponentials-as-powers (run decay u expression)
  "EXPRESSION with each exponential exp(X) whose argument X is a constant multiple q of
DECAY's argument written (expt U q): the exponentials of one rate as powers of the
symbol U."
  (let ((rate (second decay)))
    (labels ((walk (x)
               (cond ((and (consp x) (eq (first x) 'exp) (not (free-of-p 'tau (second x))))
                      (let ((q (tidy run `(/ ,(second x) ,rate))))
                        (if (free-of-p 'tau q) `(expt ,u ,q) x)))
                     ((consp x) (cons (first x) (mapcar #'walk (rest x))))
                     (t x))))
      (walk expression))))

(defun damped-sinusoid (run g &optional (expand t))
  "(A B C W P) with G = A + exp(-P tau) (B cos(W tau) + C sin(W tau)), P >= 0, checked by
simplification; or NIL. G is first expanded (trigexpand) unless EXPAND is NIL (which
keeps sin(3 u) whole where W is 3 times a radical)."
  (let* ((expanded (if expand (ignore-errors (tidy run g :expanded-trigexpand)) g))
         (decay (and expanded (decaying-exponential run expanded))))
    (when decay
      (let* ((u (gensym "DECAY"))
             (linear (tidy run (exponentials-as-powers run decay u expanded)))
             (a (tidy run (substitute-expressions (list (cons u 0)) linear)))
             (wave (tidy run `(- ,(substitute-expressions (list (cons u 1)) linear) ,a)))
             (parts (and (free-of-p 'tau a) (time-sinusoid run wave))))
        (when (and parts
                   (holds run `(= ,(first parts) 0))
                   (holds run `(= (- ,g (+ ,a (* ,decay ,wave))) 0)))
          (list a (second parts) (third parts) (fourth parts)
                (tidy run `(- (/ ,(second decay) tau)))))))))

(defun oscillation-floor-parts (run g)
  "(A R2) when G is an oscillation about A whose distance from A never exceeds
sqrt(R2) after the start (see the file header), else NIL."
  (let ((parts (and (trigonometric-in-time-p g)
                    (or (time-sinusoid run g) (damped-sinusoid run g)))))
    (when parts
      (destructuring-bind (a b c w &optional (p 0)) parts
        (list a (if (holds run `(= (- (* ,w ,c) (* ,p ,b)) 0))
                    ;; stationary at the start: the extremes are at w tau = n pi, B (-1)^n exp(-p n pi / w)
                    `(expt ,b 2)
                    `(+ (expt ,b 2) (expt ,c 2))))))))

(defun sinusoid-never-negative-p (run g)
  "True when G's least value after the start, A - sqrt(R2) by OSCILLATION-FLOOR-PARTS, is
proven not negative: G never turns negative."
  (let ((parts (oscillation-floor-parts run g)))
    (and parts
         (destructuring-bind (a r2) parts
           (and (holds run `(>= ,a 0))
                (holds run `(>= (- (expt ,a 2) ,r2) 0)))))))

(defun damped-oscillation-never-negative-p (run g)
  "True when G = A + exp(-p tau) (B cos(w tau) + C sin(w tau)), p > 0 and w > 0 (a damped
oscillation: DAMPED-SINUSOID), is proven positive at its first two extremes after the
start: G' = exp(-p tau) R cos(w tau - psi), psi = atan2(-(p C + w B), w C - p B), vanishes
at w tau = psi + pi/2 + k pi, where the oscillation alternates in sign and shrinks by
exp(-p pi / w) from one to the next; so every later minimum lies above the first, and G,
monotone between, never turns negative. Sharper than the envelope A - sqrt(B^2 + C^2)
(a spring pushed in through a viscous medium, whose first swing the drag shortens)."
  (let ((parts (and (trigonometric-in-time-p g)
                    (or (damped-sinusoid run g) (damped-sinusoid run g nil)))))
    (when parts
      (destructuring-bind (a b c w p) parts
        (declare (ignore a))
        (when (and (holds run `(> ,p 0)) (holds run `(> ,w 0)))
          (let ((psi `(atan ,(tidy run `(- (+ (* ,p ,c) (* ,w ,b)))) ,(tidy run `(- (* ,w ,c) (* ,p ,b))))))
            ;; psi in (-pi, pi]: the first two extremes after 0 are among k = -1 .. 2
            (loop for k from -1 to 2
                  for theta = `(+ ,psi (* ,(+ 1/2 k) pi))
                  always (case (decide run `(> ,theta 0))
                           (:false t)
                           (:true (holds run `(> ,(at-time g `(/ ,theta ,w)) 0)))
                           (t nil)))))))))

(defun sinusoid-floor-fact (run g)
  "For G an oscillation about A > 0 (OSCILLATION-FLOOR-PARTS), the relation A^2 - R2 > 0
that would prove G never negative: the missing fact to branch on, when it is no larger
than *LARGEST-BOUNDARY-FACT*. NIL for any other G."
  (let ((parts (oscillation-floor-parts run g)))
    (and parts
         (destructuring-bind (a r2) parts
           (let ((fact (and (holds run `(> ,a 0))
                            `(> ,(tidy run `(- (expt ,a 2) ,r2)) 0))))
             ;; a fact on the parameters a textbook would state; a swollen one (the state
             ;; starts where an earlier root left nested radicals) is no branch to offer
             (and fact (<= (ames.maxima:expression-size fact) *largest-boundary-fact*) fact))))))

(defun positive-after-start-p (run g)
  "True when G > 0 is proven for every TAU > 0 under the assumptions (Maxima's signs):
G has no root after the start. Asked only where the root search did not decide."
  (positive-after-p run g 0))

(defun exponential-in-time-p (g)
  "True when G is a function of TAU alone (every parameter a number) whose functions of
TAU are exponentials and logarithms only: a gap under drag, whose sign Maxima decides
quickly (with parameters left, or tan or atan of TAU, is() can take a minute)."
  (labels ((walk (x)
             (cond ((and (symbolp x) x (not (member x '(tau pi))))
                    (return-from exponential-in-time-p nil))
                   ((atom x) nil)
                   ((and (member (first x) '(exp log)) (not (free-of-p 'tau x))) t)
                   ((and (not (member (first x) '(+ - * / expt sqrt))) (not (free-of-p 'tau x)))
                    (return-from exponential-in-time-p nil))
                   (t (some #'walk (rest x))))))
    (walk g)))

(defun positive-after-p (run g after)
  "True when G > 0 is proven for every TAU > AFTER under the assumptions (Maxima's signs,
which know exp() > 0 and log(X) > 0 for X > 1): G has no root after AFTER. Asked only
where the root search did not decide (a gap closing as exp(-k tau) under linear drag, or
opening as log(1 + k tau) under quadratic drag, never vanishes)."
  (ames.maxima:with-assumptions ((run-bridge run) `((> tau ,after)))
    (holds run `(> ,g 0))))
