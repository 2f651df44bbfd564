;;;; src/algebra/linear-ode.lisp -- systems of linear second-order ODEs with constant coefficients, solved by Laplace transform.
;;;;
;;;; Springs make the accelerations linear in the positions (and, with dampers, in the
;;;; velocities): x_i'' = c_i + sum_j K_ij x_j + sum_j D_ij x_j'. With x_i(0) = p_i and
;;;; x_i'(0) = w_i the Laplace transform turns them into linear equations for the
;;;; transforms X_i(s):
;;;;   s^2 X_i - s p_i - w_i = c_i / s + sum_j K_ij X_j + sum_j D_ij (s X_j - p_j),
;;;; which solve() solves; Maxima's ilt() (partial fractions) gives back x_i(t). This is
;;;; what desolve() does, without its function notation and atvalue(), which would leave
;;;; properties behind in Maxima. Every answer is substituted back into the equations and
;;;; the initial values before it is returned.

(in-package #:ames.algebra)

(defvar *transform-variables* '()
  "Uninterned symbols standing for the Laplace transforms X_1, X_2 ... (made as needed,
the same ones each time so that requests repeat and are answered from the cache).")

(defun transform-variable (bridge index)
  "The INDEXth (from 0) Laplace-transform unknown, registered in BRIDGE as an auxiliary name."
  (loop while (<= (length *transform-variables*) index)
        do (setf *transform-variables*
                 (append *transform-variables*
                         (list (make-symbol (format nil "TRANSFORM-~D" (length *transform-variables*)))))))
  (auxiliary-variable bridge (nth index *transform-variables*)))

(defun solve-linear-odes (bridge accelerations positions velocities
                          initial-positions initial-velocities &key (time tau))
  "Solve the system POSITION_i'' = ACCELERATION_i (i over the POSITIONS), where each
ACCELERATION_i is affine in the POSITIONS and VELOCITIES (the names standing for the
positions' derivatives) with coefficients free of them and of TIME (parameters), with
POSITION_i = INITIAL-POSITION_i and its velocity INITIAL-VELOCITY_i at TIME = 0.
Returns three values:
  POSITIONS   an alist ((position . expression of TIME) ...), in the order given;
  VELOCITIES  an alist ((velocity . expression of TIME) ...);
  VERIFICATION :SYMBOLIC (substituted back, every equation and initial value simplified
              to an identity) or :NUMERIC (where Maxima could not simplify a residual to
              0, it vanished at 5 or more admissible points and times, within 1e-9).
Sign questions Maxima asks (\"Is k*m positive?\", or the sign of a damped system's
discriminant) are answered from the current assumptions; one they leave open ends the
call with MAXIMA-QUESTION (its restart ASSUME-AND-RETRY retries under given facts).
Signals INVALID-BRIDGE-ARGUMENT for lists of different lengths, names that are not
distinct names, an initial value depending on the state or TIME, or an acceleration
that depends on TIME or is not affine in the state with constant coefficients (checked
by Maxima: it must equal its constant term plus its first derivatives times the state);
LINEAR-ODE-FAILED (a SOLVE-FAILED) when no closed form is found or it fails the check;
MAXIMA-QUESTION, UNTRANSLATABLE-EXPRESSION, MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (check-linear-system accelerations positions velocities initial-positions initial-velocities time)
  (let* ((state (append positions velocities))
         (datum (loop for a in accelerations for x in positions
                      collect `(= (second-derivative ,x ,time) ,a)))
         (coefficients (mapcar (lambda (a) (affine-coefficients bridge a state)) accelerations))
         (transforms (laplace-transforms bridge coefficients initial-positions initial-velocities datum))
         (solutions (mapcar (lambda (transform) (inverse-laplace bridge transform time datum))
                            transforms))
         (rates (mapcar (lambda (x) (simplified bridge (maxima-derivative bridge x time))) solutions)))
    (let ((verification (verify-linear-solution bridge accelerations state time solutions rates
                                                initial-positions initial-velocities)))
      (unless verification
        (error 'linear-ode-failed :datum datum
                                  :detail "the solution found does not satisfy the equations when substituted back"))
      (values (mapcar #'cons positions solutions)
              (mapcar #'cons velocities rates)
              verification))))

(defun check-linear-system (accelerations positions velocities initial-positions initial-velocities time)
  "Signal INVALID-BRIDGE-ARGUMENT unless the arguments of SOLVE-LINEAR-ODES are well formed."
  (flet ((invalid (datum detail) (error 'invalid-bridge-argument :datum datum :detail detail)))
    (let ((lists (list accelerations positions velocities initial-positions initial-velocities)))
      (unless (and (every #'alexandria:proper-list-p lists) (consp positions)
                   (every (lambda (list) (= (length list) (length positions))) lists))
        (invalid lists "accelerations, positions, velocities and initial values must be lists of one length")))
    (unless (variable-symbol-p time) (invalid time "the time must be a variable"))
    (let ((names (append positions velocities)))
      (unless (every #'subject-p names)
        (invalid names "the positions and velocities must be variables or quantity terms"))
      (unless (= (length names) (length (remove-duplicates names :test #'equal)))
        (invalid names "the positions and velocities must be distinct"))
      (when (member time names :test #'equal)
        (invalid time "the time may not be a position or velocity"))
      (dolist (expression (append accelerations initial-positions initial-velocities))
        (check-translatable expression :arithmetic))
      (dolist (a accelerations)
        (unless (free-of-p time a)
          (invalid a (format nil "the acceleration depends on the time ~S" time))))
      (dolist (value (append initial-positions initial-velocities))
        (unless (every (lambda (name) (free-of-p name value)) (cons time names))
          (invalid value "an initial value depends on the state or the time"))))))

(defun affine-coefficients (bridge acceleration state)
  "The list (c0 c1 ... c2n): ACCELERATION = c0 + sum c_j q_j over the STATE names q_j,
each c free of the state, checked by Maxima. Signals INVALID-BRIDGE-ARGUMENT otherwise."
  (let* ((zero-state (mapcar (lambda (q) (cons q 0)) state))
         (constant (simplified bridge (substitute-expressions zero-state acceleration) :ratsimp))
         (slopes (mapcar (lambda (q) (simplified bridge (maxima-derivative bridge acceleration q) :full))
                         state)))
    (flet ((invalid (detail)
             (error 'invalid-bridge-argument :datum acceleration :detail detail)))
      (unless (every (lambda (c) (every (lambda (q) (free-of-p q c)) state)) slopes)
        (invalid "the acceleration is not linear in the positions and velocities"))
      (unless (equivalent-p bridge acceleration
                            `(+ ,constant ,@(loop for c in slopes for q in state collect `(* ,c ,q))))
        (invalid "the acceleration is not affine in the positions and velocities")))
    (cons constant slopes)))

(defun laplace-transforms (bridge coefficients initial-positions initial-velocities datum)
  "The Laplace transforms X_i(s) of the positions, solved from the transformed equations."
  (let* ((n (length initial-positions))
         (s (auxiliary-variable bridge *laplace-variable*))
         (unknowns (loop for i below n collect (transform-variable bridge i)))
         (equations
           (loop for (constant . slopes) in coefficients
                 for x in unknowns for p in initial-positions for w in initial-velocities
                 collect `(= (- (* (expt ,s 2) ,x) (* ,s ,p) ,w)
                             (+ (/ ,constant ,s)
                                ,@(loop for k in (subseq slopes 0 n) for y in unknowns
                                        collect `(* ,k ,y))
                                ,@(loop for d in (subseq slopes n) for y in unknowns
                                        for q in initial-positions
                                        collect `(* ,d (- (* ,s ,y) ,q)))))))
         (solutions (handler-case (solve-equations bridge equations unknowns)
                      (solve-failed (c)
                        (error 'linear-ode-failed :datum datum
                                                  :detail (format nil "the transformed equations: ~A"
                                                                  (ames-error-detail c)))))))
    (unless (= (length solutions) 1)
      (error 'linear-ode-failed :datum datum
                                :detail "the transformed equations have no single solution"))
    (mapcar (lambda (x) (cdr (assoc x (first solutions)))) unknowns)))

(defun inverse-laplace (bridge transform time datum)
  "ilt(TRANSFORM, s, TIME), simplified, in prefix algebra."
  (handler-case (inverse-laplace-transform bridge transform *laplace-variable* time datum)
    (untranslatable-result (c)
      (error 'linear-ode-failed :datum datum
                                :detail (format nil "the inverse Laplace transform is outside the algebra (~A)"
                                                (ames-error-detail c))))))

(defun verify-linear-solution (bridge accelerations state time positions velocities
                               initial-positions initial-velocities)
  ":SYMBOLIC when POSITIONS and VELOCITIES (expressions of TIME) satisfy the equations
and initial values by simplification, :NUMERIC when the residuals Maxima cannot
simplify vanish at admissible points and times, else NIL."
  (let* ((bindings (mapcar #'cons state (append positions velocities)))
         (residuals
           (append (loop for a in accelerations for v in velocities
                         collect `(- ,(maxima-derivative bridge v time) ,(substitute-expressions bindings a)))
                   (loop for x in positions for p in initial-positions
                         collect `(- ,(substitute-expressions (list (cons time 0)) x) ,p))
                   (loop for v in velocities for w in initial-velocities
                         collect `(- ,(substitute-expressions (list (cons time 0)) v) ,w))))
         (open (remove-if (lambda (r) (zero-expression-p bridge r)) residuals)))
    (cond ((null open) :symbolic)
          ((every (lambda (r) (residual-vanishes-numerically-p bridge r time)) open) :numeric)
          (t nil))))

(defun residual-vanishes-numerically-p (bridge residual time)
  "True when RESIDUAL, a difference (- LEFT RIGHT) of expressions of TIME and
parameters, is 0 within 1e-9 relative to the larger of |LEFT| and |RIGHT| at
*VERIFICATION-POINTS* or more admissible points, each at a random time in [0, 10], and
is not larger at any."
  (let ((random-state (sb-ext:seed-random-state 1994))
        (sides (rest residual))
        (checked 0) (failed nil))
    (call-with-admissible-points
     bridge (list '> (list* '+ 0 (remove time (expression-variables residual) :test #'equal)) 0)
     (lambda (point)
       (let* ((point (acons time (random 10d0 random-state) point))
              (values (mapcar (lambda (side) (expression-value side point)) sides)))
         (if (and (every #'identity values)
                  (<= (abs (- (first values) (second values)))
                      (* 1d-9 (max (abs (first values)) (abs (second values))))))
             (incf checked)
             (setf failed t)))
       (or failed (>= checked (* 2 *verification-points*)))))
    (and (not failed) (>= checked *verification-points*))))
