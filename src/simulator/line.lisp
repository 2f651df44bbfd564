;;;; src/simulator/line.lisp -- the :LINE integrator: a group whose motion is one degree of
;;;; freedom along a fixed line of its configuration space, integrated by its energy integral.
;;;;
;;;; Two bodies released from rest under their mutual gravitation fall toward each other
;;;; along the line of their centres: their accelerations depend on the positions only
;;;; through one linear combination s = c.q (their distance), and point along one fixed
;;;; vector. Generally: a group's accelerations a(q) (free of the velocities and of time)
;;;; are a = b + lambda f(q) with constant vectors b and lambda and a scalar f whose
;;;; gradient is a constant vector c times a scalar (so f depends on q only through
;;;; s = c.q), b = mu lambda and the initial velocity v0 = nu lambda. Then
;;;;   q(t) = q0 + lambda (s(t) - s0) / gamma,   gamma = c.lambda (not zero),
;;;; and s'' = gamma (mu + f(q0 + lambda (s - s0)/gamma)) is autonomous: its energy integral
;;;; (s')^2 = E(s) gives the velocities over s, and the bridge's travel-time integral the
;;;; times (closed form where it has one: E = A + B/s for gravitation). This is the :PATH
;;;; integrator's machinery (events found along s, path.lisp) on a straight path in the
;;;; configuration space; nothing in it knows which force it is.

(in-package #:ames.simulator)

(defun group-positions-and-velocities (group)
  "GROUP's position terms and velocity terms, body by body, :x then :y."
  (loop for body in (group-bodies group)
        append (list `(ames.kb:pos ,body :x) `(ames.kb:pos ,body :y)) into positions
        append (list `(ames.kb:vel ,body :x) `(ames.kb:vel ,body :y)) into velocities
        finally (return (values positions velocities))))

(defun partial (expression term)
  "d EXPRESSION / d TERM, TERM a quantity term."
  (let ((symbol (state-symbol term)))
    (substitute-expressions (list (cons symbol term))
                            (ames.geometry:differentiate
                             (substitute-expressions (list (cons term symbol)) expression)
                             symbol))))

(defun free-of-all-p (terms expression)
  "True when EXPRESSION mentions none of TERMS (nor TAU)."
  (and (free-of-p 'tau expression)
       (every (lambda (term) (free-of-p term expression)) terms)))

(defun common-factor (run xs ys)
  "The constant K with XS = K YS component by component, or NIL: 0 when every X is 0."
  (let ((k nil))
    (loop for x in xs for y in ys
          do (let ((x (tidy run x)) (y (tidy run y)))
               (cond ((and (eql x 0) (eql y 0)))
                     ((eql y 0) (return-from common-factor nil))
                     ((null k) (setf k (tidy run `(/ ,x ,y))))
                     ((not (eql 0 (tidy run `(- ,x (* ,k ,y))))) (return-from common-factor nil)))))
    (or k 0)))

(defun line-reduction (run solved group)
  "When GROUP's motion is one degree of freedom along a fixed line (see the file header),
the plist (:C c :LAMBDA lambda :MU mu :NU nu :GAMMA gamma :REFERENCE ak) over GROUP's
positions and velocities (in GROUP-POSITIONS-AND-VELOCITIES's order); else NIL."
  (multiple-value-bind (positions velocities) (group-positions-and-velocities group)
    (let* ((state (solved-model-state solved))
           (accelerations (mapcar (lambda (v) (cdr (assoc v (solved-model-rates solved) :test #'equal)))
                                  velocities))
           (others (set-difference state positions :test #'equal)))
      (unless (every (lambda (a) (and a (free-of-all-p others a))) accelerations)
        (return-from line-reduction nil))
      (let* ((k (position-if-not (lambda (a) (free-of-all-p positions a)) accelerations))
             (reference (and k (nth k accelerations)))
             (gradient (and k (mapcar (lambda (q) (tidy run (partial reference q))) positions)))
             (m (and k (position-if-not (lambda (g) (eql g 0)) gradient))))
        (unless m (return-from line-reduction nil))
        (let* ((pivot (nth m gradient))
               (c (let* ((c (mapcar (lambda (g) (tidy run `(/ ,g ,pivot))) gradient))
                         (s0 (cons '+ (mapcar (lambda (x q) `(* ,x ,(cdr (assoc q (solved-model-initial solved)
                                                                                  :test #'equal))))
                                              c positions))))
                    ;; oriented so that the coordinate starts positive where that is decided
                    ;; (a distance rather than its negative)
                    (if (sign-is run (tidy run s0) :negative)
                        (mapcar (lambda (x) (tidy run `(- ,x))) c)
                        c)))
               (lambdas (mapcar (lambda (a)
                                  (if (free-of-all-p positions a)
                                      0
                                      (tidy run `(/ ,(partial a (nth m positions)) ,pivot))))
                                accelerations)))
          (unless (every (lambda (x) (free-of-all-p state x)) (append c lambdas))
            (return-from line-reduction nil))
          (let ((constants (loop for a in accelerations for l in lambdas
                                 collect (tidy run `(- ,a (* ,l ,reference))))))
            (unless (every (lambda (x) (free-of-all-p state x)) constants)
              (return-from line-reduction nil))
            (let* ((mu (common-factor run constants lambdas))
                   (v0 (mapcar (lambda (v) (cdr (assoc v (solved-model-initial solved) :test #'equal)))
                               velocities))
                   (nu (common-factor run v0 lambdas))
                   (gamma (tidy run (cons '+ (mapcar (lambda (x y) `(* ,x ,y)) c lambdas)))))
              (when (and mu nu (sign-is run gamma :positive :negative))
                (list :c c :lambda lambdas :mu mu :nu nu :gamma gamma :reference reference)))))))))

(defun integrate-line (run solved group)
  "Fill GROUP's motion along its line (see the file header): every position and velocity
as a function of s (+ARC-LENGTH+), s = c.q, with the energy integral E(s) = (s')^2.
Returns GROUP, or NIL when the group is not such a motion or the direction of motion is
not decided."
  (let ((reduction (line-reduction run solved group)))
    (when reduction
      (multiple-value-bind (positions velocities) (group-positions-and-velocities group)
        (destructuring-bind (&key c ((:lambda weights)) mu nu gamma reference) reduction
          (let* ((q0 (mapcar (lambda (q) (cdr (assoc q (solved-model-initial solved) :test #'equal)))
                             positions))
                 (s0 (tidy run (cons '+ (mapcar (lambda (x y) `(* ,x ,y)) c q0))))
                 (along (mapcar (lambda (q l p0)
                                  (cons q `(+ ,p0 (/ (* ,l (- ,+arc-length+ ,s0)) ,gamma))))
                                positions weights q0))
                 (force (tidy run `(* ,gamma (+ ,mu ,(substitute-expressions along reference)))))
                 (w0 (tidy run `(* ,gamma ,nu)))
                 (ode (handler-case (ames.maxima:solve-autonomous-ode
                                     (run-bridge run) force +arc-length+
                                     :initial-position s0 :initial-velocity w0)
                        ((or ames.maxima:solve-failed ames.maxima:maxima-question) () nil)))
                 (direction (or (sign-direction (sign-of run w0))
                                (sign-direction (sign-of run (at-arc force s0))))))
            (when (and ode (member direction '(1 -1)))
              (let* ((energy (tidy run (ames.maxima:ode-solution-speed-squared ode)))
                     (speed (tidy run `(* ,direction (sqrt ,energy)))))
                (setf (group-variable group) +arc-length+
                      (group-s0 group) s0
                      (group-direction group) direction
                      (group-speed-squared group) energy
                      (group-speed group) speed
                      (group-ode-kind group) (ames.maxima:ode-solution-kind ode)
                      (group-line group) (list :coordinate
                                               `(= ,+arc-length+
                                                   ,(tidy run (cons '+ (mapcar (lambda (x q) `(* ,x ,q))
                                                                               c positions)))))
                      (group-motion group)
                      (append (mapcar (lambda (entry) (cons (car entry) (tidy run (cdr entry) :full))) along)
                              (mapcar (lambda (v l) (cons v (tidy run `(/ (* ,l ,speed) ,gamma) :full)))
                                      velocities weights)))
                group))))))))
