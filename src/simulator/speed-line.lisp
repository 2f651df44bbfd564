;;;; src/simulator/speed-line.lisp -- the :SPEED-LINE integrator: a group whose accelerations
;;;; depend on its velocities alone and keep it moving along a fixed line, integrated in closed
;;;; form as a Riccati equation in the speed along that line.
;;;;
;;;; A body under constant forces and a force that depends on its velocity (a quadratic drag
;;;; -C |v| v) has accelerations a(v), free of the positions and of time. Let e be the
;;;; velocity at the start (or, from rest, the acceleration there: the way it starts to
;;;; move). When a(p e) = f(p) e for every p >= 0 (the force keeps the motion on the line
;;;; through e), the velocity stays v = p e with p >= 0 and
;;;;   p' = f(p),   p(0) = 1 (or 0 from rest),
;;;; a first-order autonomous equation (|v| = p |e| is p times a constant along the line, so
;;;; |p| is p). When f is a polynomial of degree at most 2 in p with constant coefficients,
;;;; f = A + B p + C p^2, and the quadratic term opposes the motion (C < 0: drag, so p
;;;; stays bounded), the equation is a Riccati equation with constant coefficients, solved
;;;; in closed form by the sign of its discriminant D = B^2 - 4 A C (decided by the
;;;; assumptions, or a branch: open-questions.lisp):
;;;;   D > 0  roots r1, r2 = (-B +- sqrt D) / (2 C), E = exp(sqrt(D) tau):
;;;;          p = r2 + (r1 - r2) (p0 - r2) / ((p0 - r2) - (p0 - r1) E)        (tanh)
;;;;          P = r1 tau - ln(((p0 - r2) - (p0 - r1) E) / (r1 - r2)) / C
;;;;   D < 0  w = sqrt(-D) / (-2 C), u = p + B / (2 C), phi0 = atan(u0 / w):
;;;;          p = w tan(phi0 + C w tau) - B / (2 C)                           (tan)
;;;;          P = -B tau / (2 C) - ln(cos(phi0 + C w tau) / cos(phi0)) / C
;;;;   D = 0  r = -B / (2 C):  p = r + (p0 - r) / (1 - C (p0 - r) tau),
;;;;          P = r tau - ln(1 - C (p0 - r) tau) / C
;;;;   C = 0  (linear, with B /= 0): p = -A/B + (p0 + A/B) exp(B tau), P its integral
;;;; with P = integral of p from 0 to tau. Positions are q0 + e P and velocities e p. A
;;;; body thrown up against gravity and drag slows to rest (p reaches 0): the knowledge
;;;; base's turning event ends the state there (src/kb/drag.lisp), so the motion is used
;;;; while p >= 0 only, where the formulas are the solution: a motion that may reach p = 0
;;;; (p0 = 1 and A not proven >= 0) is integrated so only when a termination condition of the
;;;; model fires there (REVERSAL-WATCHED-P), else numerically. Each is checked by Maxima:
;;;; p' - f(p) and P' - p simplify to 0, p(0) = p0 and P(0) = 0; otherwise the group is
;;;; integrated numerically. Nothing here knows which force it integrates.
;;;;
;;;; When a condition ends the state: over such a motion a condition that depends on the
;;;; motion through the speed p alone, or through the distance P alone, is monotone in time
;;;; while the state lasts (p is the solution of an autonomous first-order equation, so
;;;; monotone; P' = p >= 0). Where Maxima's solve() finds its root but cannot prove it the
;;;; earliest (roots of tan, exp and log), a root checked to be one, positive and crossing
;;;; downward is then the condition's only one in the state (SPEED-LINE-CANDIDATE). The
;;;; formulas hold while p >= 0: the knowledge base must end the state where the velocity
;;;; reverses (src/kb/drag.lisp does, for quadratic drag).

(in-package #:ames.simulator)

(defconstant +speed-along-line+ 'speed-along-line
  "The variable standing for the speed p along the line of a :SPEED-LINE motion.")

(defun with-abs-speed-taken (expression &optional (variable +speed-along-line+))
  "EXPRESSION with |p| written p, p (VARIABLE, by default +SPEED-ALONG-LINE+) being >= 0
over the state."
  (cond ((and (consp expression) (eq (first expression) 'abs) (eq (second expression) variable))
         variable)
        ((consp expression)
         (cons (first expression) (mapcar (lambda (x) (with-abs-speed-taken x variable)) (rest expression))))
        (t expression)))

(defun speed-line-direction (run velocities accelerations v0)
  "The direction e of a :SPEED-LINE motion and the speed p0 along it at the start: the
starting velocity V0 with p0 = 1, or from rest the acceleration there with p0 = 0; NIL
when the group starts at rest in equilibrium (the values (NIL 0))."
  (flet ((zero-vector-p (vector) (every (lambda (x) (eql 0 (tidy run x))) vector)))
    (if (zero-vector-p v0)
        (let ((a0 (mapcar (lambda (a) (tidy run (substitute-expressions
                                                 (mapcar (lambda (v) (cons v 0)) velocities) a)))
                          accelerations)))
          (values (if (zero-vector-p a0) nil a0) 0))
        (values v0 1))))

(defun speed-line-law (run velocities accelerations direction)
  "The scalar law f(p) with a(p e) = f(p) e for the DIRECTION e (VELOCITIES the group's
velocity terms, ACCELERATIONS their rates), or NIL when the accelerations leave the line."
  (let* ((along (mapcar (lambda (v e) (cons v `(* ,+speed-along-line+ ,e))) velocities direction))
         (a (mapcar (lambda (x) (with-abs-speed-taken (tidy run (substitute-expressions along x) :full)))
                    accelerations))
         (pivot (position-if (lambda (e) (sign-is run e :positive :negative)) direction)))
    (when pivot
      (let ((f (tidy run `(/ ,(nth pivot a) ,(nth pivot direction)) :full)))
        (when (every (lambda (x e) (eql 0 (tidy run `(- ,x (* ,f ,e)) :full))) a direction)
          f)))))

(defun quadratic-coefficients (run f)
  "(A B C) with F = A + B p + C p^2 (p the speed along the line), each free of p, or NIL."
  (let* ((p +speed-along-line+)
         (d1 (ames.geometry:differentiate f p))
         (d2 (ames.geometry:differentiate d1 p))
         (a (tidy run (substitute-expressions (list (cons p 0)) f) :full))
         (b (tidy run (substitute-expressions (list (cons p 0)) d1) :full))
         (c (tidy run `(/ ,d2 2) :full)))
    (when (and (every (lambda (x) (free-of-p p x)) (list a b c))
               (eql 0 (tidy run `(- ,f (+ ,a (* ,b ,p) (* ,c (expt ,p 2)))) :full)))
      (list a b c))))

(defun riccati-solution (run a b c p0)
  "The speed p(tau) and its integral P(tau) from 0 of p' = A + B p + C p^2, p(0) = P0, as
two values (see the file header); NIL when C is not proven negative (nor zero with B not
zero). Signals AMBIGUOUS-TRANSITION when the discriminant's sign is open."
  (progn
    (cond
      ((eql c 0)
       (when (sign-is run b :positive :negative)
         (let ((k `(+ ,p0 (/ ,a ,b))))
           (values `(+ (- (/ ,a ,b)) (* ,k (exp (* ,b ,tau))))
                   `(+ (- (* (/ ,a ,b) ,tau)) (/ (* ,k (- (exp (* ,b ,tau)) 1)) ,b))))))
      ((not (sign-is run c :negative)) nil)
      (t
       (let* ((d (tidy run `(- (expt ,b 2) (* 4 ,a ,c)) :full))
              (sign (one-sign (sign-of run d))))
         (when (null sign)
           (open-sign-question run d "the sign that selects the closed form of a motion along a line"))
         (case sign
           (:positive (let* ((q `(sqrt ,d))
                     (r1 `(/ (+ (- ,b) ,q) (* 2 ,c)))
                     (r2 `(/ (- (- ,b) ,q) (* 2 ,c)))
                     (den `(- (- ,p0 ,r2) (* (- ,p0 ,r1) (exp (* ,q ,tau))))))
                (values `(+ ,r2 (/ (* (- ,r1 ,r2) (- ,p0 ,r2)) ,den))
                        `(- (* ,r1 ,tau) (/ (log (/ ,den (- ,r1 ,r2))) ,c)))))
           (:negative (let* ((w `(/ (sqrt (- ,d)) (* -2 ,c)))
                      (shift `(/ ,b (* 2 ,c)))
                      (phi0 `(atan (/ (+ ,p0 ,shift) ,w)))
                      (phi `(+ ,phi0 (* ,c ,w ,tau))))
                 (values `(- (* ,w (tan ,phi)) ,shift)
                         `(- (- (* ,shift ,tau)) (/ (log (/ (cos ,phi) (cos ,phi0))) ,c)))))
           (:zero (let ((r `(/ (- ,b) (* 2 ,c))))
                (values `(+ ,r (/ (- ,p0 ,r) (- 1 (* ,c (- ,p0 ,r) ,tau))))
                        `(- (* ,r ,tau) (/ (log (- 1 (* ,c (- ,p0 ,r) ,tau))) ,c)))))))))))

(defun riccati-verified-p (run f p0 speed distance)
  "True when Maxima simplifies SPEED' - F(SPEED), DISTANCE' - SPEED, SPEED(0) - P0 and
DISTANCE(0) to 0."
  (flet ((zero-p (x) (eql 0 (tidy run x :full)))
         (at-zero (x) (substitute-expressions '((tau . 0)) x)))
    (and (zero-p `(- ,(ames.geometry:differentiate speed 'tau)
                     ,(substitute-expressions (list (cons +speed-along-line+ speed)) f)))
         (zero-p `(- ,(ames.geometry:differentiate distance 'tau) ,speed))
         (zero-p `(- ,(at-zero speed) ,p0))
         (zero-p (at-zero distance)))))

(defun integrate-speed-line (run solved group)
  "Fill GROUP's motion when its accelerations depend on its velocities alone and keep it
on a fixed line (see the file header): kind :SPEED-LINE, or :CONSTANT for a group at
rest in equilibrium. Returns GROUP, or NIL (it is then integrated numerically)."
  (multiple-value-bind (positions velocities) (group-positions-and-velocities group)
    (let* ((state (solved-model-state solved))
           (rate (lambda (v) (cdr (assoc v (solved-model-rates solved) :test #'equal))))
           (accelerations (mapcar rate velocities))
           (initial (lambda (term) (cdr (assoc term (solved-model-initial solved) :test #'equal))))
           (q0 (mapcar initial positions))
           (v0 (mapcar initial velocities)))
      (unless (and (every #'identity accelerations)
                   (every (lambda (a) (free-of-all-p (set-difference state velocities :test #'equal) a))
                          accelerations))
        (return-from integrate-speed-line nil))
      (multiple-value-bind (direction p0) (speed-line-direction run velocities accelerations v0)
        (if (null direction)
            (setf (group-kind group) :constant
                  (group-motion group) (append (mapcar #'cons positions q0)
                                               (mapcar (lambda (v) (cons v 0)) velocities)))
            (let* ((f (speed-line-law run velocities accelerations direction))
                   (coefficients (and f (quadratic-coefficients run f))))
              (multiple-value-bind (speed distance)
                  (and coefficients (apply #'riccati-solution run (append coefficients (list p0))))
                (unless (and speed (riccati-verified-p run f p0 speed distance))
                  (return-from integrate-speed-line nil))
                (setf (group-line group) (list :direction direction :from q0
                                               :speed speed :distance distance))
                ;; a motion that may come to rest and reverse is used only where the
                ;; model ends the state there (the formulas hold while p >= 0)
                (unless (or (eql p0 0) (holds run `(>= ,(first coefficients) 0))
                            (reversal-watched-p run solved group))
                  (setf (group-line group) nil)
                  (return-from integrate-speed-line nil))
                (setf (group-kind group) :speed-line
                      (group-motion group)
                      (append (mapcar (lambda (q p e) (cons q (tidy run `(+ ,p (* ,e ,distance)) :full)))
                                      positions q0 direction)
                              (mapcar (lambda (v e) (cons v (tidy run `(* ,e ,speed) :full)))
                                      velocities direction))))))
        group))))

(defun along-speed-line (run group expression p x)
  "EXPRESSION (over state terms) with the :SPEED-LINE GROUP's velocities written e P and
its positions q0 + e X (P and X symbols for the speed and the distance along the line),
simplified, |P| and |X| taken as P and X (neither is negative while the state lasts)."
  (multiple-value-bind (positions velocities) (group-positions-and-velocities group)
    (destructuring-bind (&key direction from &allow-other-keys) (group-line group)
      (with-abs-speed-taken
          (with-abs-speed-taken
              (tidy run (substitute-expressions
                         (append (mapcar (lambda (v e) (cons v `(* ,p ,e))) velocities direction)
                                 (mapcar (lambda (q q0 e) (cons q `(+ ,q0 (* ,x ,e))))
                                         positions from direction))
                         expression)
                    :full)
            p)
        x))))

(defun speed-line-signs-taken (run groups expression)
  "EXPRESSION (over state terms) with the velocities and positions of each :SPEED-LINE
group among GROUPS written e p and q0 + e P, |p| and |P| taken as p and P (neither is
negative while the state lasts), then p and P put to their closed forms: so that a speed
|v| = sqrt(v.v) in a force comes out as p |e|, not as the absolute value of a formula
Maxima cannot sign. EXPRESSION itself when no such group moves in it."
  (dolist (group groups expression)
    (when (and (eq (group-kind group) :speed-line)
               (some (lambda (term) (not (free-of-p term expression))) (group-terms group)))
      (let ((p (make-symbol "P")) (x (make-symbol "X")))
        (setf expression
              (substitute-expressions (list (cons p (getf (group-line group) :speed))
                                            (cons x (getf (group-line group) :distance)))
                                      (along-speed-line run group expression p x)))))))
