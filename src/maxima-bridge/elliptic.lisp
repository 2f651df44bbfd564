;;;; src/maxima-bridge/elliptic.lisp -- motion under E = A + B cos(k s) + C sin(k s): travel times and positions through elliptic functions.
;;;;
;;;; A particle on a circle of radius r under a constant force (a pendulum, a bead on a
;;;; hoop, the thesis's particle on a sphere) has the energy integral
;;;; w^2 = E(s) = A + B cos(k s) + C sin(k s) = A + D cos(k s - phi). With y = k s - phi,
;;;; 1 + cos y = 2 - 2 sin^2(y/2) gives E = (A + D) (1 - m sin^2(y/2)), m = 2D / (A + D),
;;;; so the time is 2 / (k sqrt(A + D)) [F(y/2 | m)] between the ends. For m < 1 (A > D:
;;;; the particle goes round) that is the antiderivative everywhere. For m >= 1 (A <= D: it
;;;; swings in a well around y = 0 mod 2 pi, |sin(y/2)| <= 1/sqrt(m)) F(y/2 | m) is
;;;; complex beyond the first well; the reciprocal-parameter form
;;;; F(y/2 | m) = F(beta | 1/m) / sqrt(m), with sin(beta) = sqrt(m) sin(y/2), is real, and
;;;; is the antiderivative while cos(y/2) > 0, that is while y stays in (-pi, pi): phi is
;;;; shifted by 2 pi n to make it so. Inverting F gives the position as a function of
;;;; time through Jacobi's functions (POSITION-OVER-TIME).

(in-package #:ames.maxima)

(defun sinusoidal-antiderivative (travel)
  "E = A + B cos(k s) + C sin(k s) = A + D cos(k s - phi): with m = 2D/(A + D),
2 F((k s - phi)/2 | m) / (k sqrt(A + D)) when A > D (the motion goes round), else
2 F(asin(sqrt(m) sin((k s - phi)/2)) | 1/m) / (k sqrt(2D)) with phi shifted by a
multiple of 2 pi so that k s - phi stays in (-pi, pi) on the path (see the file header).
Never proven: the numeric check decides."
  (let* ((bridge (travel-bridge travel))
         (s (travel-position travel))
         (parts (sinusoid-coefficients bridge (travel-energy travel) s)))
    (when parts
      (destructuring-bind (a b c k) parts
        (let ((k-sign (decided-sign bridge k)))
          (when (eq k-sign :negative)
            ;; cos(k s) = cos(-k s), sin(k s) = -sin(-k s)
            (setf c (simplified bridge `(- ,c)) k (simplified bridge `(- ,k))))
          (when (member k-sign '(:positive :negative))
            (multiple-value-bind (d phase) (amplitude-and-phase bridge b c)
              (when d
                (let ((angle `(- (* ,k ,s) ,phase)))
                  (case (or (decided-sign bridge (simplified bridge `(- ,a ,d)))
                            (witnessed-sign bridge (simplified bridge `(- ,a ,d))))
                    (:positive
                     (values `(/ (* 2 (elliptic-f (/ ,angle 2) (/ (* 2 ,d) (+ ,a ,d))))
                                 (* ,k (sqrt (+ ,a ,d))))
                             nil))
                    ((:negative :zero)
                     (let* ((phase (well-phase travel k phase))
                            (angle `(- (* ,k ,s) ,phase))
                            (parameter `(/ (+ ,a ,d) (* 2 ,d)))
                            (scale `(/ 2 (* ,k (sqrt (* 2 ,d))))))
                       (values `(* ,scale (elliptic-f (asin (* (sqrt (/ (* 2 ,d) (+ ,a ,d)))
                                                              (sin (/ ,angle 2))))
                                                        ,parameter))
                               nil
                               (lambda (end)
                                 ;; at a turning point the amplitude is +-pi/2 exactly
                                 (turning-value travel end `(- (* ,k ,end) ,phase)
                                                `(* ,scale (elliptic-k ,parameter)))))))))))))))))

(defun turning-value (travel end angle quarter)
  "QUARTER or -QUARTER (the antiderivative's value at a turning point of the libration
form, where the amplitude is pi/2 or -pi/2) when E vanishes at END, by the sign of ANGLE
there; NIL when E does not vanish there, or the sign is not decided."
  (let ((bridge (travel-bridge travel)))
    (when (zero-expression-p bridge (substituted bridge (travel-energy travel)
                                                 (travel-position travel) end))
      (case (decided-sign bridge angle)
        (:positive quarter)
        (:negative `(- ,quarter))))))

(defun amplitude-and-phase (bridge b c)
  "D >= 0 and phi with B cos x + C sin x = D cos(x - phi), as two values: plain ones
when B or C is 0 and the other's sign is decided, else sqrt(B^2 + C^2) and atan2(C, B)."
  (flet ((negated (x) (simplified bridge `(- ,x))))
    (cond ((zero-expression-p bridge c)
           (case (decided-sign bridge b)
             (:positive (values b 0))
             (:negative (values (negated b) 'pi))
             (t nil)))
          ((zero-expression-p bridge b)
           (case (decided-sign bridge c)
             (:positive (values c '(/ pi 2)))
             (:negative (values (negated c) '(- (/ pi 2))))
             (t nil)))
          (t (values (simplified bridge `(sqrt (+ (expt ,b 2) (expt ,c 2))))
                     (simplified bridge `(atan ,c ,b)))))))

(defun well-phase (travel k phase)
  "PHASE + 2 pi n with k s - (PHASE + 2 pi n) in (-pi, pi) at both ends of the path:
for n = 0, 1, -1 the first the assumptions decide; else the n that the first admissible
point gives (to be checked numerically); else PHASE."
  (let* ((bridge (travel-bridge travel))
         (ends (list (travel-from travel) (travel-to travel))))
    (flet ((shifted (n) (if (zerop n) phase (simplified bridge `(+ ,phase (* 2 pi ,n))))))
      (or (loop for n in '(0 1 -1)
                for candidate = (shifted n)
                when (eq (decide bridge `(and ,@(loop for end in ends
                                                      collect `(> (- (* ,k ,end) ,candidate) (- pi))
                                                      collect `(< (- (* ,k ,end) ,candidate) pi))))
                         :true)
                  return candidate)
          (let ((n nil)
                (offset `(- (* ,k ,(travel-from travel)) ,phase)))
            (call-with-admissible-points
             bridge (list '> offset 0)
             (lambda (point)
               (let ((value (expression-value offset point)))
                 (when value (setf n (round value (* 2 pi)))))
               n))
            (shifted (or n 0)))))))

(defun witnessed-sign (bridge expression)
  "The sign EXPRESSION has at every admissible point where it has a value (:POSITIVE or
:NEGATIVE; at least *VERIFICATION-POINTS* such points), else NIL. Chooses between
formulas that are then checked; proves nothing."
  (let ((signs '()) (count 0))
    (call-with-admissible-points
     bridge (list '> expression 0)
     (lambda (point)
       (let ((value (expression-value expression point)))
         (when value
           (incf count)
           (pushnew (cond ((plusp value) :positive) ((minusp value) :negative) (t :zero)) signs)))
       (rest signs)))
    (and (>= count *verification-points*) (null (rest signs))
         (member (first signs) '(:positive :negative))
         (first signs))))
