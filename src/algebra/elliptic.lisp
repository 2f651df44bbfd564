;;;; src/algebra/elliptic.lisp -- motion under E = A + B cos(k s) + C sin(k s): travel times and positions through elliptic functions.
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

(in-package #:ames.algebra)

(defstruct (sinusoid (:constructor make-sinusoid (a d phase k regime)))
  "E = A + D cos(K s - PHASE), with D >= 0 and K > 0 (prefix expressions), and its
REGIME: :ROTATION when A > D (E > 0 everywhere), :LIBRATION when A <= D."
  a d phase k regime)

(defun analyse-sinusoid (bridge energy position)
  "The SINUSOID that ENERGY is in POSITION, or NIL: not of that shape, the sign of k or
of B or C (when the other is 0) not decided, or the regime seen neither way. The regime
is decided from the assumptions, or else read off random admissible points (then only
the numeric checks that follow can accept the results)."
  (let ((parts (sinusoid-coefficients bridge energy position)))
    (when parts
      (destructuring-bind (a b c k) parts
        (let ((k-sign (decided-sign bridge k)))
          (when (eq k-sign :negative)
            ;; cos(k s) = cos(-k s), sin(k s) = -sin(-k s)
            (setf c (simplified bridge `(- ,c)) k (simplified bridge `(- ,k))))
          (when (member k-sign '(:positive :negative))
            (multiple-value-bind (d phase) (amplitude-and-phase bridge b c)
              (when d
                (let ((margin (simplified bridge `(- ,a ,d))))
                  ;; the regime only picks the formula, never proven (the numeric check
                  ;; decides): a cheap proof, else the admissible points, not DECIDE's
                  ;; full strategies (minutes on a tipping block's margin)
                  (case (or (cheaply-decided-sign bridge margin) (witnessed-sign bridge margin))
                    (:positive (make-sinusoid a d phase k :rotation))
                    ((:negative :zero) (make-sinusoid a d phase k :libration))))))))))))

(defun sinusoidal-antiderivative (travel)
  "E = A + B cos(k s) + C sin(k s) = A + D cos(k s - phi): with m = 2D/(A + D),
2 F((k s - phi)/2 | m) / (k sqrt(A + D)) when A > D (the motion goes round), else
2 F(asin(sqrt(m) sin((k s - phi)/2)) | 1/m) / (k sqrt(2D)) with phi shifted by a
multiple of 2 pi so that k s - phi stays in (-pi, pi) on the path (see the file header).
Never proven: the numeric check decides."
  (let* ((bridge (travel-bridge travel))
         (s (travel-position travel))
         (wave (analyse-sinusoid bridge (travel-energy travel) s)))
    (when wave
      (let ((a (sinusoid-a wave)) (d (sinusoid-d wave)) (k (sinusoid-k wave)))
        (ecase (sinusoid-regime wave)
          (:rotation
           (values `(/ (* 2 (elliptic-f (/ (- (* ,k ,s) ,(sinusoid-phase wave)) 2)
                                        (/ (* 2 ,d) (+ ,a ,d))))
                       (* ,k (sqrt (+ ,a ,d))))
                   nil))
          (:libration
           (let* ((phase (well-phase bridge k (sinusoid-phase wave)
                                     (list (travel-from travel) (travel-to travel))))
                  (parameter `(/ (+ ,a ,d) (* 2 ,d)))
                  (scale `(/ 2 (* ,k (sqrt (* 2 ,d))))))
             (values `(* ,scale (elliptic-f (asin (* (sqrt (/ (* 2 ,d) (+ ,a ,d)))
                                                    (sin (/ (- (* ,k ,s) ,phase) 2))))
                                              ,parameter))
                     nil
                     (lambda (end)
                       ;; at a turning point the amplitude is +-pi/2 exactly
                       (and (at-rest-p travel end)
                            (case (decided-sign bridge `(- (* ,k ,end) ,phase))
                              (:positive `(* ,scale (elliptic-k ,parameter)))
                              (:negative `(- (* ,scale (elliptic-k ,parameter)))))))))))))))

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

(defun well-phase (bridge k phase ends)
  "PHASE + 2 pi n with k s - (PHASE + 2 pi n) in (-pi, pi) at each of ENDS: for n = 0,
1, -1 the first the assumptions decide; else the n that the first admissible point
gives (to be checked numerically); else PHASE."
  (flet ((shifted (n) (if (zerop n) phase (simplified bridge `(+ ,phase (* 2 pi ,n))))))
    (or (loop for n in '(0 1 -1)
              for candidate = (shifted n)
              when (eq (decide bridge `(and ,@(loop for end in ends
                                                    collect `(> (- (* ,k ,end) ,candidate) (- pi))
                                                    collect `(< (- (* ,k ,end) ,candidate) pi))))
                       :true)
                return candidate)
        (let ((n nil)
              (offset `(- (* ,k ,(first ends)) ,phase)))
          (call-with-admissible-points
           bridge (list '> offset 0)
           (lambda (point)
             (let ((value (expression-value offset point)))
               (when value (setf n (round value (* 2 pi)))))
             n))
          (shifted (or n 0))))))

(defun cheaply-decided-sign (bridge expression)
  "The strict sign of EXPRESSION (:POSITIVE or :NEGATIVE) that CHEAP-PROOF proves under the
current assumptions, or NIL."
  (cond ((eq :true (cheap-proof bridge (list '> expression 0))) :positive)
        ((eq :true (cheap-proof bridge (list '< expression 0))) :negative)))

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

;;; The position as a function of time

(defun position-over-time (bridge speed-squared position initial-position
                           &key direction (time tau))
  "The motion s(TIME) with s(0) = INITIAL-POSITION when the squared speed is
SPEED-SQUARED = A + B cos(k s) + C sin(k s) in POSITION s (a particle on a circle under
a constant force), with D cos(k s - phi) = B cos(k s) + C sin(k s) and
u = u0 + DIRECTION * lambda * TIME:
  going round (A > D):  s = (phi + 2 am(u | m)) / k,       w = DIRECTION sqrt(A + D) dn(u | m),
      m = 2D / (A + D), lambda = k sqrt(A + D) / 2, u0 = F((k s0 - phi)/2 | m);
  swinging (A <= D):    s = (phi + 2 asin(sqrt(mu) sn(u | mu))) / k,  w = DIRECTION sqrt(A + D) cn(u | mu),
      mu = (A + D) / (2D), lambda = k sqrt(2D) / 2, u0 = F(beta0 | mu) with
      sin beta0 = sin((k s0 - phi)/2) / sqrt(mu) (+-K(mu) at rest), phi shifted by 2 pi n
      so that k s0 - phi lies in (-pi, pi).
The swing passes its turning points by itself (sn and cn are periodic): the formula
holds for all TIME. Returns (values POSITION VELOCITY :NUMERIC), both expressions of
TIME, checked at 5 or more random admissible points, each at several times, with
s(0) = s0, w^2 = E(s), w = ds/dTIME (by central differences) and the initial direction;
or (values NIL :NO-CLOSED-FORM) when SPEED-SQUARED has another shape or the check fails.
DIRECTION (1 or -1) is the sign of the initial velocity; it may be omitted when the
motion starts at rest.
Signals INVALID-BRIDGE-ARGUMENT (names that are not names, an initial position
depending on POSITION or TIME, a missing or malformed DIRECTION when not at rest),
UNTRANSLATABLE-EXPRESSION."
  (check-travel-arguments position (list speed-squared initial-position) (list initial-position))
  (unless (and (variable-symbol-p time) (free-of-p time speed-squared) (free-of-p time initial-position))
    (error 'invalid-bridge-argument :datum time
                                    :detail "the time must be a variable that the squared speed and start do not mention"))
  (let* ((wave (call-or-nil (lambda () (analyse-sinusoid bridge speed-squared position))))
         (at-rest (zero-expression-p bridge (substituted bridge speed-squared position initial-position))))
    (unless (or at-rest (member direction '(1 -1)))
      (error 'invalid-bridge-argument :datum direction
                                      :detail "the direction of the initial velocity (1 or -1) is needed"))
    (multiple-value-bind (motion velocity rate)
        (and wave (call-or-nil (lambda () (elliptic-motion bridge wave initial-position
                                                            (or direction 1) time at-rest))))
      (if (and motion
               (elliptic-motion-checked-p bridge speed-squared position initial-position motion velocity
                                          time rate (and (not at-rest) direction)))
          (flet ((tidy (expression)
                   ;; Maxima may rewrite a Jacobi quotient outside the algebra: then as built
                   (or (call-or-nil (lambda () (simplified bridge expression))) expression)))
            (values (tidy motion) (tidy velocity) :numeric))
          (values nil :no-closed-form)))))

(defun elliptic-motion (bridge wave s0 direction time at-rest)
  "The position and velocity expressions of POSITION-OVER-TIME for the SINUSOID WAVE.
The parameters are simplified one by one and the expressions assembled here: Maxima
would rewrite sn(K + x) as jacobi_cd(x), outside the algebra. At rest at a turning
point u0 = +-K, and sn(+-K + x) = +-cn(x)/dn(x), cn(+-K + x) = -+sqrt(1 - mu) sn(x)/dn(x)."
  (let* ((a (sinusoid-a wave)) (d (sinusoid-d wave)) (k (sinusoid-k wave))
         (speed (simplified bridge `(sqrt (+ ,a ,d)))))
    (ecase (sinusoid-regime wave)
      (:rotation
       (let* ((phase (sinusoid-phase wave))
              (m (simplified bridge `(/ (* 2 ,d) (+ ,a ,d))))
              (rate (simplified bridge `(* ,direction (/ (* ,k (sqrt (+ ,a ,d))) 2))))
              (u `(+ ,(simplified bridge `(elliptic-f (/ (- (* ,k ,s0) ,phase) 2) ,m))
                     (* ,rate ,time))))
         (unless at-rest
           (values `(/ (+ ,phase (* 2 (jacobi-am ,u ,m))) ,k)
                   `(* ,direction ,speed (jacobi-dn ,u ,m))
                   rate))))
      (:libration
       (let* ((phase (well-phase bridge k (sinusoid-phase wave) (list s0)))
              (mu (simplified bridge `(/ (+ ,a ,d) (* 2 ,d))))
              (root-mu (simplified bridge `(sqrt ,mu)))
              (rate (simplified bridge `(/ (* ,k (sqrt (* 2 ,d))) 2)))
              (side (and at-rest (decided-sign bridge `(- (* ,k ,s0) ,phase)))))
         (flet ((position-from (sine)
                  `(/ (+ ,phase (* 2 (asin (* ,root-mu ,sine)))) ,k)))
           (if (member side '(:positive :negative))
               (let ((x `(* ,rate ,time))
                     (sign (if (eq side :positive) 1 -1)))
                 (values (position-from `(* ,sign (/ (jacobi-cn ,x ,mu) (jacobi-dn ,x ,mu))))
                         `(* ,(- sign) ,speed ,(simplified bridge `(sqrt (- 1 ,mu)))
                             (/ (jacobi-sn ,x ,mu) (jacobi-dn ,x ,mu)))
                         rate))
               (let ((u `(+ ,(simplified bridge `(elliptic-f (asin (/ (sin (/ (- (* ,k ,s0) ,phase) 2))
                                                                      ,root-mu))
                                                              ,mu))
                            (* ,direction ,rate ,time))))
                 (values (position-from `(jacobi-sn ,u ,mu))
                         `(* ,direction ,speed (jacobi-cn ,u ,mu))
                         rate)))))))))

(defun elliptic-motion-checked-p (bridge energy position s0 motion velocity time rate direction)
  "True when, at *VERIFICATION-POINTS* or more admissible points and at none against it,
MOTION starts at S0 (within 1e-8), VELOCITY^2 = ENERGY(MOTION) (within 1e-7 of the
largest squared speed met) and VELOCITY = dMOTION/dTIME (central differences, within
1e-5) at 4 times in [0, 8 / RATE] (RATE: how fast the elliptic argument grows), and
VELOCITY(0) has the sign DIRECTION (when given). Proves nothing symbolically."
  (let ((random-state (sb-ext:seed-random-state 1994))
        (subjects (remove-duplicates
                   (remove-if (lambda (x) (or (equal x position) (equal x time)))
                              (mapcan #'expression-variables (list energy s0 motion velocity)))
                   :test #'equal))
        (checked 0) (failed nil))
    (labels ((at (expression point time-value)
               (let ((value (expression-value expression (acons time time-value point))))
                 (and value (float value 1d0))))
             (energy-at (point s)
               (let ((value (expression-value energy (acons position s point))))
                 (and value (float value 1d0))))
             (check (point)
               (let ((start (expression-value s0 point))
                     (s-zero (at motion point 0d0))
                     (w-zero (at velocity point 0d0)))
                 (cond ((null start) nil)
                       ((not (and s-zero w-zero)) :fail)
                       ((> (abs (- s-zero start)) (* 1d-8 (max 1 (abs start)))) :fail)
                       ((and direction (not (plusp (* direction w-zero)))) :fail)
                       (t (let* ((top (max 1d-300 (abs w-zero) (sqrt (max 0d0 (or (energy-at point start) 0d0)))))
                                 (speed-of-argument (expression-value rate point))
                                 (horizon (and speed-of-argument (/ 8 (abs speed-of-argument)))))
                            (unless horizon (return-from check :fail))
                            (loop repeat 4
                                  for tm = (random horizon random-state)
                                  for h = (* 1d-5 horizon)
                                  for s = (at motion point tm)
                                  for w = (at velocity point tm)
                                  for e = (and s (energy-at point s))
                                  for before = (at motion point (- tm h))
                                  for after = (at motion point (+ tm h))
                                  unless (and s w e before after
                                              (<= (abs (- (* w w) e)) (* 1d-7 (max (* w w) (abs e) (* top top))))
                                              (<= (abs (- (/ (- after before) (* 2 h)) w)) (* 1d-5 (max (abs w) top))))
                                    return :fail
                                  finally (return :ok))))))))
      (call-with-admissible-points
       bridge `(> (+ 0 ,@subjects) 0)
       (lambda (point)
         (case (check point)
           (:ok (incf checked))
           (:fail (setf failed t)))
         (or failed (>= checked (* 2 *verification-points*))))))
    (and (not failed) (>= checked *verification-points*))))
