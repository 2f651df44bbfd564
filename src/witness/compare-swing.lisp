;;;; src/witness/compare-swing.lisp -- AMES's own position along a swing at a given time.
;;;;
;;;; A periodic state along a path swings between two turning points (its :PERIODIC
;;;; :BETWEEN (S1 S2)); AMES gives the position X(s) and the velocity V(s) of the first
;;;; swing as functions of the arc length s, not of time. The comparator sets the
;;;; witness's velocity at a sample's time beside AMES's velocity at AMES's own position
;;;; at that time, found here from AMES's formulas alone: along the path ds/dt = V.X'/|X'|^2,
;;;; so the time from a turning point a to s is the integral of ds/|ds/dt|, whose integrand
;;;; goes as 1/sqrt(s - a) at a (the speed as the square root of the energy left); the
;;;; substitutions s = a + (s1 - a) u^2 (one singular end) and s = a + (b - a)(1 - cos th)/2
;;;; (both) make it smooth, integrated by composite Gauss-Legendre, then inverted by
;;;; bisection with Newton steps.
;;;;
;;;; Why not at the witness's position: a first-order witness (Moreau-Jean, step h) lags its
;;;; exact motion by O(h) in phase; near a turning point the speed at a position varies as
;;;; a/v, so AMES's exact velocity evaluated at the witness's lagging position differs from
;;;; the witness's by far more than the witness's own error in its velocity, a * (its lag in
;;;; time). At AMES's own time the difference is the witness's error only.

(in-package #:ames.witness)

(defun gauss-legendre-rule (n)
  "The N nodes and weights of Gauss-Legendre quadrature on [-1, 1]: (NODES WEIGHTS),
the nodes the roots of the Legendre polynomial P_N found by Newton's method."
  (let ((nodes '()) (weights '()))
    (dotimes (i n)
      (let ((x (cos (/ (* pi (+ i 3/4)) (+ n 1/2)))) (derivative 0d0))
        (loop repeat 100
              do (let ((p0 1d0) (p1 x))
                   (loop for k from 2 to n
                         do (psetf p0 p1 p1 (/ (- (* (- (* 2 k) 1) x p1) (* (- k 1) p0)) k)))
                   (setf derivative (/ (* n (- (* x p1) p0)) (- (* x x) 1)))
                   (let ((dx (/ p1 derivative)))
                     (decf x dx)
                     (when (< (abs dx) 1d-16) (return)))))
        (push x nodes)
        (push (/ 2 (* (- 1 (* x x)) derivative derivative)) weights)))
    (list nodes weights)))

(defparameter +gauss-legendre-16+ (gauss-legendre-rule 16)
  "The 16-point Gauss-Legendre rule on [-1, 1].")

(defun integral (f low high &optional (panels 4))
  "The integral of F (a function of a double to a double, or NIL) from LOW to HIGH by
composite 16-point Gauss-Legendre quadrature over PANELS equal panels; NIL when F has no
value at a node."
  (let ((width (/ (- high low) panels)) (sum 0d0))
    (dotimes (k panels sum)
      (let ((middle (+ low (* width (+ k 1/2)))))
        (loop for x in (first +gauss-legendre-16+)
              for w in (second +gauss-legendre-16+)
              for value = (funcall f (+ middle (* x width 1/2)))
              do (if (realp value)
                     (incf sum (* w width 1/2 value))
                     (return-from integral nil)))))))

(defstruct (swing (:constructor %make-swing))
  "AMES's swing along a path: from turning point A (where its first swing starts) to B,
the forms of the position and velocity (X Y) in *ARC-LENGTH*, the parameter VALUES, and
HALF, the time from A to B."
  a b position-form velocity-form values half)

(defun path-rate (swing s)
  "ds/dt at S on SWING's first swing, V(s).X'(s)/|X'(s)|^2 (X' by central differences),
or NIL where the forms have no value."
  (let* ((values (swing-values swing)) (h (* 1d-6 (max 1d0 (abs s))))
         (p+ (path-value (swing-position-form swing) (+ s h) values))
         (p- (path-value (swing-position-form swing) (- s h) values))
         (v (path-value (swing-velocity-form swing) s values)))
    (when (and p+ p- v)
      (let* ((tx (/ (- (first p+) (first p-)) (* 2 h))) (ty (/ (- (second p+) (second p-)) (* 2 h)))
             (norm (+ (* tx tx) (* ty ty))))
        (and (plusp norm) (/ (+ (* (first v) tx) (* (second v) ty)) norm))))))

(defun time-from-turn (swing turn s)
  "The time SWING takes between its turning point TURN and S (s = TURN + (S - TURN) u^2),
or NIL."
  (if (= s turn)
      0d0
      (integral (lambda (u)
                  (let ((rate (path-rate swing (+ turn (* (- s turn) u u)))))
                    (and rate (/= rate 0) (/ (* 2 (abs (- s turn)) u) (abs rate)))))
                0d0 1d0)))

(defun time-from-a (swing s)
  "The time from SWING's turning point A to S (between A and B): from A for S in A's
half, else the half period less the time from S to B; NIL when it has no value."
  (let ((a (swing-a swing)) (b (swing-b swing)))
    (if (<= (abs (- s a)) (/ (abs (- b a)) 2))
        (time-from-turn swing a s)
        (let ((rest (time-from-turn swing b s)))
          (and rest (- (swing-half swing) rest))))))

(defun swing-position (swing time)
  "The arc length where SWING is TIME after leaving A (0 <= TIME <= its half period):
bisection on [A, B] with Newton steps (dt/ds = 1/|ds/dt|) when they stay inside; NIL when
a time has no value."
  (let ((low 0d0) (high 1d0) (a (swing-a swing)) (span (- (swing-b swing) (swing-a swing))))
    (flet ((at (w) (+ a (* span w))))
      (loop with w = (max 0d0 (min 1d0 (/ time (swing-half swing))))
            repeat 200
            do (let ((tw (time-from-a swing (at w))))
                 (unless tw (return-from swing-position nil))
                 (if (< tw time) (setf low w) (setf high w))
                 (let* ((rate (path-rate swing (at w)))
                        (newton (and rate (/= rate 0) (- w (/ (* (- tw time) (abs rate)) (abs span))))))
                   (setf w (if (and newton (< low newton high)) newton (/ (+ low high) 2)))))
            until (< (- high low) 1d-14)
            finally (return (at w))))))

(defun make-swing (state entry ventry values)
  "The SWING of the body whose position and velocity entries are ENTRY and VENTRY in
STATE (a periodic state with :BETWEEN), under VALUES, or NIL: no two turning points, a
velocity that does not move the body along its path at their midpoint, or a half period
without a value."
  (let* ((between (getf (getf state :periodic) :between))
         (ends (and (= 2 (length between))
                    (mapcar (lambda (x) (expression-value (canonical-expression x) values)) between))))
    (when (and ends (every #'realp ends) (/= (first ends) (second ends)))
      (let* ((*arc-length* (or (path-symbol (second entry)) *arc-length*))
             (low (coerce (reduce #'min ends) 'double-float))
             (high (coerce (reduce #'max ends) 'double-float))
             (swing (%make-swing :a low :b high :position-form (second (second entry))
                                 :velocity-form (second (second ventry)) :values values))
             (rate (path-rate swing (/ (+ low high) 2))))
        (when (and rate (/= rate 0))
          (when (minusp rate) (setf (swing-a swing) high (swing-b swing) low))
          (let* ((a (swing-a swing)) (b (swing-b swing))
                 (half (integral (lambda (th)
                                   (let ((r (path-rate swing (+ a (* (- b a) (- 1 (cos th)) 1/2)))))
                                     (and r (/= r 0) (/ (* (abs (- b a)) (sin th) 1/2) (abs r)))))
                                 0d0 pi 8)))
            (when (and half (plusp half))
              (setf (swing-half swing) half)
              swing)))))))

(defun swing-phase-position (swing start-s elapsed)
  "AMES's arc length on SWING ELAPSED seconds after its state's start at START-S (NIL:
its turning point A) and the sign of its velocity there (+1 on a first swing, -1 on the
way back): (VALUES S SIGN), or NIL."
  (let ((offset (if start-s (time-from-a swing (coerce start-s 'double-float)) 0d0)))
    (when offset
      (let* ((period (* 2 (swing-half swing)))
             (phase (mod (+ elapsed offset) period))
             (back (> phase (swing-half swing)))
             (s (swing-position swing (if back (- period phase) phase))))
        (and s (values s (if back -1 1)))))))

(defun velocity-at-own-time (state entry ventry values start-s elapsed)
  "AMES's position and velocity, each (X Y), of the body with entries ENTRY and VENTRY on
the periodic STATE with two turning points, at AMES's own arc length ELAPSED seconds
after the state's start (at START-S, or NIL: at a turning point): (VALUES POSITION
VELOCITY), or NIL when the state has no such swing or a value is missing."
  (let ((swing (make-swing state entry ventry values)))
    (when swing
      (let ((*arc-length* (or (path-symbol (second entry)) *arc-length*)))
        (multiple-value-bind (s sign) (swing-phase-position swing start-s elapsed)
          (let ((p (and s (path-value (swing-position-form swing) s values)))
                (v (and s (path-value (swing-velocity-form swing) s values))))
            (and p v (values p (mapcar (lambda (x) (* sign x)) v)))))))))
