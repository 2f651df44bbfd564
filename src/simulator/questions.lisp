;;;; src/simulator/questions.lisp -- the questions of the language page's "Queries, more
;;;; questions" (issue 26): when a body comes to rest for good, when a quantity first takes a
;;;; value, the distance a body travels (summed over a Zeno sequence of impacts), and the
;;;; extrema of a quantity over a state (over time, or over the arc length along a path).
;;;;
;;;; Each works on one path of the run (see HISTORY-PATHS) and signals UNANSWERABLE, saying
;;;; why, where the history does not give the answer in closed form.

(in-package #:ames.simulator)

(defun motion-states (states)
  "The STATES that are periods of motion (a fork only splits the run)."
  (remove-if #'state-branches states))

(defun zero-vector-p (bridge vector)
  "True when both components of VECTOR are proven identically 0."
  (and (consp vector) (not (keywordp (first vector)))
       (every (lambda (x) (or (eql x 0) (eql 0 (ames.maxima:simplify bridge x :strategy :full)))) vector)))

(defun at-rest-p (bridge scenario state body)
  "True when BODY's velocity in STATE is identically zero."
  (let ((velocity (ignore-errors (quantity-expression scenario state `(:velocity ,body)))))
    (and velocity (zero-vector-p bridge velocity))))

(defun rest-time (bridge scenario states outcome body)
  "The time from which BODY stays at rest for good: the start of the first of the last
STATES in which it is at rest, the last lasting forever (a Zeno sequence's accumulation
point when impacts bring it to rest)."
  (let* ((moving (motion-states states))
         (last (first (last moving))))
    (unless (and last (eq (state-duration last) :forever))
      (unanswerable "the run ~(~A~) before ~(~A~) could be seen at rest for good" outcome body))
    (let ((resting (loop for state in (reverse moving)
                         while (at-rest-p bridge scenario state body)
                         collect state)))
      (unless resting (unanswerable "~(~A~) never comes to rest for good in this run" body))
      (let ((start (state-start (first (last resting)))))
        (unless (closed-form-p start) (unanswerable "the time it comes to rest has no closed form"))
        (ames.algebra:simplify-real bridge start)))))

(defun reaches-time (bridge scenario states quantity value)
  "The first time QUANTITY takes VALUE on STATES: at a state's start, or at the earliest
root of their difference inside a state; (:NEVER REASON) when a complete run never
reaches it."
  (dolist (state (motion-states states) (list :never "it is never reached in this run"))
    (let* ((difference (quantity-in scenario state `(- ,quantity ,value)))
           (start (state-start state))
           (duration (state-duration state)))
      (unless (closed-form-p start) (unanswerable "state ~D's start has no closed form" (state-index state)))
      (unless (free-of-p +arc-length+ difference)
        (unanswerable "along a path the time a quantity takes a value has no closed form"))
      (let ((at-start (ames.algebra:decide bridge `(= ,(substitute-expressions '((tau . 0)) difference) 0))))
        (when (eq at-start :true) (return (ames.algebra:simplify-real bridge start)))
        (when (eq at-start :unknown)
          (unanswerable "whether it holds at the start of state ~D is not decided" (state-index state))))
      (unless (free-of-p 'tau difference)
        (let ((root (query-root bridge difference 'tau 0)))
          (when (eq root :unknown)
            (unanswerable "where it is reached in state ~D is not decided" (state-index state)))
          (unless (eq root :none)
            (case (if (eq duration :forever) :true
                      (progn (unless (closed-form-p duration)
                               (unanswerable "state ~D's end has no closed form" (state-index state)))
                             (ames.algebra:decide bridge `(<= ,root ,duration))))
              (:true (return (ames.algebra:simplify-real bridge `(+ ,start ,root))))
              (:unknown (unanswerable "whether it is reached before state ~D ends is not decided"
                                      (state-index state))))))))))

(defun absolute-value (bridge x)
  "|X| where the sign of X is decided, else signals UNANSWERABLE."
  (let ((x (ames.maxima:simplify bridge x :strategy :full)))
    (cond ((eql x 0) 0)
          ((eq :true (ames.algebra:decide bridge `(>= ,x 0))) x)
          ((eq :true (ames.algebra:decide bridge `(<= ,x 0))) `(- ,x))
          (t (unanswerable "the sign of the displacement ~S is not decided" x)))))

(defun turning-times (bridge component duration)
  "The times in (0, DURATION) at which the velocity COMPONENT (over TAU) vanishes, in order."
  (loop with times = '()
        for after = 0 then (first times)
        for root = (query-root bridge component 'tau after)
        repeat 8
        do (cond ((eq root :unknown) (unanswerable "where the body turns back is not decided"))
                 ((eq root :none) (return (reverse times)))
                 ((eq :true (ames.algebra:decide bridge `(< ,root ,duration))) (push root times))
                 ((eq :true (ames.algebra:decide bridge `(>= ,root ,duration))) (return (reverse times)))
                 (t (unanswerable "whether the body turns back before the state ends is not decided")))
        finally (unanswerable "the body turns back too many times")))

(defun state-distance (bridge scenario state body)
  "The path length BODY travels in STATE (a straight-line motion; a state lasting
forever only when the body is at rest in it)."
  (let ((duration (state-duration state)))
    (when (at-rest-p bridge scenario state body) (return-from state-distance 0))
    (when (eq duration :forever) (unanswerable "~(~A~) moves forever in state ~D" body (state-index state)))
    (unless (closed-form-p duration) (unanswerable "state ~D's end has no closed form" (state-index state)))
    (let* ((position (quantity-expression scenario state `(:position ,body)))
           (velocity (quantity-expression scenario state `(:velocity ,body)))
           (acceleration (quantity-expression scenario state `(:acceleration ,body))))
      (unless (and (free-of-p +arc-length+ position) (free-of-p +arc-length+ velocity))
        (unanswerable "the distance along a curved path is not worked out"))
      (unless (eql 0 (ames.maxima:simplify bridge `(- (* ,(first velocity) ,(second acceleration))
                                                      (* ,(second velocity) ,(first acceleration)))
                                           :strategy :full))
        (unanswerable "the distance along a curved path is not worked out"))
      (let* ((component (if (eql 0 (ames.maxima:simplify bridge (first velocity) :strategy :full))
                            (second velocity)
                            (first velocity)))
             (times (append '(0) (if (free-of-p 'tau component) '() (turning-times bridge component duration))
                            (list duration)))
             (pieces (loop for (a b) on times while b
                           collect (flet ((at (x time) (substitute-expressions (list (cons 'tau time)) x)))
                                     (let ((dx (absolute-value bridge `(- ,(at (first position) b) ,(at (first position) a))))
                                           (dy (absolute-value bridge `(- ,(at (second position) b) ,(at (second position) a)))))
                                       (cond ((eql dx 0) dy)
                                             ((eql dy 0) dx)
                                             (t `(sqrt (+ (expt ,dx 2) (expt ,dy 2))))))))))
        (if (rest pieces) (cons '+ pieces) (first pieces))))))

(defun repeated-distance (bridge state distance)
  "DISTANCE, travelled in STATE, with the repeats of a Zeno sequence added when STATE's
impacts accumulate (its :ACCUMULATION note): under constant accelerations each cycle is
the one before scaled by the factor F in time and F^2 in space, so the sum is
DISTANCE / (1 - F^2)."
  (let ((accumulation (state-accumulation state)))
    (cond ((null accumulation) distance)
          ((not (every (lambda (entry) (free-of-p 'tau (second entry))) (state-accelerations state)))
           (unanswerable "the repeated cycles of state ~D do not have constant accelerations" (state-index state)))
          ((not (eq :true (ames.algebra:decide bridge `(= ,(getf accumulation :cycle) ,(state-duration state)))))
           (unanswerable "the repeated cycle is not state ~D alone" (state-index state)))
          (t `(/ ,distance (- 1 (expt ,(getf accumulation :factor) 2)))))))

(defun distance-travelled (bridge scenario states outcome body during)
  "The path length BODY travels during the state DURING names, or over the whole path
(a Zeno sequence's cycles summed) when DURING is NIL."
  (if during
      (ames.algebra:simplify-real bridge (state-distance bridge scenario (resolve-when bridge states during) body))
      (let ((moving (motion-states states)))
        (unless (or (member outcome '(:complete)) (and moving (eq :forever (state-duration (first (last moving))))))
          (unanswerable "the run ~(~A~) before its end" outcome))
        (ames.algebra:simplify-real
         bridge (cons '+ (mapcar (lambda (state)
                                   (repeated-distance bridge state (state-distance bridge scenario state body)))
                                 moving))))))

(defun equality-over-state (bridge state difference)
  "Whether DIFFERENCE (over TAU) is 0 throughout STATE: :TRUE when it is identically 0;
:FALSE when it is proven non-zero at a point of the state (its end, or tau = 1 in a
state that lasts forever): a function of the motion that is not zero at one point is
not zero throughout; else :UNKNOWN. Returns the reason too."
  (if (ignore-errors (ames.maxima:equivalent-p bridge difference 0))
      (values :true (format nil "it holds identically in state ~D" (state-index state)))
      (let* ((duration (state-duration state))
             (point (cond ((eq duration :forever) 1)
                          ((closed-form-p duration) duration))))
        (if (and point
                 (eq :true (ignore-errors
                            (ames.algebra:decide bridge `(/= ,(substitute-expressions (list (cons 'tau point)) difference) 0)))))
            (values :false (format nil "it does not hold at tau = ~A in state ~D" point (state-index state)))
            (values :unknown (format nil "whether it holds throughout state ~D is not decided" (state-index state)))))))

(defun extremum-in (bridge scenario states quantity during maximum)
  "The largest (MAXIMUM) or smallest value of QUANTITY over the state DURING names: the
best of its values at the state's ends and at every zero of its derivative between them,
over time, or over the arc length for a state along a path (no time needed: a
compression's greatest value from the energy integral)."
  (let* ((state (resolve-when bridge states during))
         (q (quantity-in scenario state quantity)))
    (when (vector-p* q) (unanswerable "the extremum of a vector"))
    (multiple-value-bind (variable from to)
        (if (free-of-p +arc-length+ q)
            (let ((duration (state-duration state)))
              (cond ((eq duration :forever)
                     ;; no end: the extremum is inside, or there is none
                     (check-extremum-attained bridge state q maximum)
                     (values 'tau 0 nil))
                    ((not (closed-form-p duration)) (unanswerable "the state's end has no closed form"))
                    (t (values 'tau 0 duration))))
            (let ((from (arc-length-start state)) (to (arc-length-end state)))
              (unless (and from to) (unanswerable "the state's ends along its path are not known"))
              (if (eq :true (ames.algebra:decide bridge `(<= ,from ,to)))
                  (values +arc-length+ from to)
                  (if (eq :true (ames.algebra:decide bridge `(>= ,from ,to)))
                      (values +arc-length+ to from)
                      (unanswerable "which way the state runs along its path is not decided")))))
      (let* ((points (append (list from) (and to (list to)) (critical-points bridge (ames.geometry:differentiate
                                                                           ;; sqrt is increasing: its argument's extrema
                                                                           (if (and (consp q) (eq (first q) 'sqrt)) (second q) q)
                                                                           variable)
                                                                          variable from to)))
             (values (mapcar (lambda (p) (ames.algebra:simplify-real bridge (substitute-expressions (list (cons variable p)) q)))
                             points))
             (best (find-if (lambda (v)
                              (every (lambda (w) (or (eq v w)
                                                     (eq :true (ames.algebra:decide bridge (list (if maximum '>= '<=) v w)))))
                                     values))
                            values)))
        (or best (unanswerable "which of ~{~A~^, ~} is the ~:[smallest~;largest~] is not decided"
                               values maximum))))))

(defun check-extremum-attained (bridge state q maximum)
  "Signal UNANSWERABLE unless Q (over TAU, in STATE, which lasts forever) has a largest
(MAXIMUM) or smallest value over it: Q (or the argument of its square root, which is
increasing) is a polynomial in TAU, so that it tends to its leading term, whose
coefficient has the sign that bounds it (negative for a maximum, positive for a
minimum), or a constant. A disc rolled up an incline: its height's maximum is inside."
  (let ((base (if (and (consp q) (eq (first q) 'sqrt)) (second q) q)))
    (loop for derivative = base
            then (handler-case (ames.maxima:simplify bridge (ames.geometry:differentiate derivative 'tau)
                                                     :strategy :full)
                   (ames-error () (ames.geometry:differentiate derivative 'tau)))
          for order from 0 to 4
          when (free-of-p 'tau derivative)
            do (return
                 (when (plusp order)
                   (case (ames.algebra:decide bridge (list (if maximum '< '>) derivative 0))
                     (:true nil)
                     (:false (unanswerable "it has no ~:[smallest~;largest~] value: it grows without bound in state ~D"
                                           maximum (state-index state)))
                     (t (unanswerable "whether it has a ~:[smallest~;largest~] value in state ~D is not decided"
                                      maximum (state-index state))))))
          finally (unanswerable "whether it has a ~:[smallest~;largest~] value in state ~D, which never ends, is not decided"
                                maximum (state-index state)))))

(defun critical-points (bridge slope variable from to)
  "The zeros of SLOPE (over VARIABLE) strictly between FROM and TO (after FROM when TO
is NIL: a state that never ends): those of each of its
factors (a product vanishes where a factor does), so that v0^2 w cos(w t) sin(w t) has
the zeros of the cosine and of the sine, each found by the root finder of its kind."
  (let ((slope (handler-case (ames.maxima:simplify bridge slope :strategy :full)
                 (ames-error () slope))))
    (loop for factor in (product-factors slope)
          for base = (if (and (consp factor) (eq (first factor) 'expt) (integerp (third factor))
                              (plusp (third factor)))
                         (second factor)
                         factor)
          unless (free-of-p variable base)
            append (factor-zeros bridge base variable from to))))

(defun factor-zeros (bridge factor variable from to)
  "The zeros of FACTOR (over VARIABLE) strictly between FROM and TO, in order."
  (loop with points = '()
        for after = from then (first points)
        for root = (query-root bridge factor variable after)
        repeat 8
        do (cond ((eq root :unknown) (unanswerable "where its derivative vanishes is not decided"))
                 ((eq root :none) (return (reverse points)))
                 ((or (null to) (eq :true (ames.algebra:decide bridge `(< ,root ,to)))) (push root points))
                 ((eq :true (ames.algebra:decide bridge `(>= ,root ,to))) (return (reverse points)))
                 (t (unanswerable "whether its derivative vanishes before the state ends is not decided")))
        finally (unanswerable "its derivative vanishes too many times in the state")))

(defun query-root (bridge g variable after)
  "The earliest root of G in VARIABLE strictly after AFTER, :NONE or :UNKNOWN: through
ames.algebra:EARLIEST-TRIGONOMETRIC-ROOT for a sinusoid in time, else EARLIEST-ROOT."
  (if (and (eq variable 'tau) (trigonometric-in-time-p g))
      (let ((root (ames.algebra:earliest-trigonometric-root bridge g 'tau :after after :strictly t)))
        root)
      (values (ames.algebra:earliest-root bridge g variable :after after :strictly t :candidates nil))))
