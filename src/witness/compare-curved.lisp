;;;; src/witness/compare-curved.lisp -- comparing the states that last forever along a
;;;; path: a particle looping round a loop, swinging in a bowl, a probe escaping.
;;;;
;;;; AMES gives such a state's positions and velocities along its path, as functions of
;;;; the arc length s, (:ON-PATH (X(s) Y(s)) :ARC-LENGTH s), not of time; a periodic state
;;;; adds :PERIODIC (:PERIOD P :BETWEEN (S1 S2)), its velocity formula being that of the
;;;; first swing (the way back is its mirror). The witness reports its state at a few times
;;;; (samples) and its turning points (:TURNS BODY BODY). Compared here:
;;;; - for a periodic state, the witness's turning points: the first at start + P/2, the
;;;;   second at start + P, the first at the other end of AMES's swing;
;;;; - at every sample, each body on a path: the point of AMES's path nearest the witness's
;;;;   position (found by a search over s) is that position, and AMES's velocity there is
;;;;   the witness's (negated on a periodic state's way back); a body with closed forms in
;;;;   tau is compared at tau = the sample's time minus the start;
;;;; - no other event of the witness before its horizon.

(in-package #:ames.witness)

(defun canonical-expression (expression)
  "EXPRESSION (read from AMES's answer in the scenario package) with each operator that
is no Common Lisp symbol (ELLIPTIC-K, ELLIPTIC-F, ...) replaced by the base layer's
symbol of that name, which EXPRESSION-VALUE knows."
  (if (atom expression)
      expression
      (let ((operator (first expression)))
        (cons (or (and (symbolp operator)
                       (not (eq (symbol-package operator) (find-package '#:common-lisp)))
                       (find-symbol (symbol-name operator) '#:ames.base))
                  operator)
              (mapcar #'canonical-expression (rest expression))))))

(defun on-path-p (value)
  "True when VALUE (a position or velocity entry's vector) is given along a path."
  (and (consp value) (eq (first value) :on-path)))

(defun path-state-p (state)
  "True when STATE lasts forever with a body's motion given along a path (or periodic)."
  (and (eq (getf state :end-event) :none)
       (or (getf state :periodic)
           (some (lambda (entry) (on-path-p (second entry))) (getf state :positions)))))

(defun state-period (state values)
  "The period of a periodic STATE: the number AMES printed beside it, or its closed form
under VALUES; NIL when it has none."
  (let ((period (or (getf (getf state :numeric) :period)
                    (let ((form (getf (getf state :periodic) :period)))
                      (and form (number-of form values))))))
    (and (realp period) (plusp period) period)))

(defun witness-sample-times (ames values)
  "The times at which the witness should report the state for AMES's last state (its
answer AMES): a few in the first period of a periodic state, a few in the first half
second of another state along a path; and the ends of the states that end with a
contact reached with no approach speed (compare-grazes.lisp)."
  (let* ((state (car (last (ames-path (getf ames :states)))))
         (start (and state (getf (state-numbers state values) :start))))
    (append (graze-times ames values)
            (when (and state (realp start) (path-state-p state))
              (let ((span (or (state-period state values) 1/2)))
                (mapcar (lambda (f) (+ start (* f span))) '(1/10 1/4 2/5 3/5 4/5 19/20)))))))

(defun witness-horizon-extra (ames values)
  "How much longer than usual the witness runs for AMES's answer: a period and a bit
for a periodic last state."
  (let* ((state (car (last (ames-path (getf ames :states)))))
         (period (and state (state-period state values))))
    (if period (* 11/10 period) 0)))

(defvar *arc-length* 'ames-scenario::s
  "The arc-length symbol of the on-path entry being compared (its :ARC-LENGTH).")

(defun path-value (form s values)
  "The double value of the path's FORM ((X Y) of *ARC-LENGTH*) at S, or NIL."
  (let ((bindings (acons *arc-length* s values)))
    (let ((x (expression-value (canonical-expression (first form)) bindings))
          (y (expression-value (canonical-expression (second form)) bindings)))
      (and x y (list (coerce x 'double-float) (coerce y 'double-float))))))

(defun path-symbol (entry)
  "The arc-length symbol of the on-path ENTRY (:ON-PATH (X Y) :ARC-LENGTH S)."
  (getf (cddr entry) :arc-length))

(defun nearest-on-path (position-form point range values)
  "The arc length in RANGE (LOW HIGH) where the path POSITION-FORM comes nearest POINT:
a grid of 4000, then golden sections about the best."
  (flet ((distance (s)
           (let ((p (path-value position-form s values)))
             (if p (+ (expt (- (first p) (first point)) 2) (expt (- (second p) (second point)) 2))
                 most-positive-double-float))))
    (destructuring-bind (low high) range
      (let* ((count 4000) (step (/ (- high low) count))
             (best (loop with best = low and best-d = (distance low)
                         for k from 1 to count
                         for s = (+ low (* k step))
                         for d = (distance s)
                         when (< d best-d) do (setf best s best-d d)
                         finally (return best)))
             (a (- best step)) (b (+ best step)) (ratio (/ (- (sqrt 5d0) 1) 2)))
        (loop repeat 200
              while (> (- b a) (* 1d-15 (max 1 (abs b))))
              do (let ((c (- b (* ratio (- b a)))) (d (+ a (* ratio (- b a)))))
                   (if (< (distance c) (distance d)) (setf b d) (setf a c))))
        (/ (+ a b) 2)))))

(defun path-range (state velocity-entry start-s elapsed values point speed)
  "Where to look for the arc length of a body on STATE's path at POINT with SPEED (the
witness's) after ELAPSED seconds: between a periodic state's turning points, else about
the start's arc length START-S within twice the reach of the larger of the start speed and
SPEED (or, without START-S, about 0 within POINT's distance from the origin besides)."
  (let ((between (getf (getf state :periodic) :between)))
    (if between
        (let ((ends (sort (mapcar (lambda (x) (coerce (or (expression-value x values) 0) 'double-float)) between) #'<)))
          (list (- (first ends) 1d-6) (+ (second ends) 1d-6)))
        (let* ((v (and start-s (path-value (second velocity-entry) start-s values)))
               (start-speed (if v (sqrt (+ (expt (first v) 2) (expt (second v) 2))) 0))
               (reach (+ 1 (* 2 elapsed (max start-speed speed))
                         (if start-s 0 (* 2 (sqrt (+ (expt (first point) 2) (expt (second point) 2))))))))
          (list (- (or start-s 0) reach) (+ (or start-s 0) reach))))))

(defun peak-sample-speed (walk)
  "The largest speed of a body among the witness's samples (the motion's speed scale)."
  (loop for sample in (getf (walk-witness walk) :samples)
        maximize (loop for (nil (vx vy)) in (getf sample :velocities)
                       maximize (sqrt (+ (* vx vx) (* vy vy))))))

(defun sample-velocity-tolerance (walk a w)
  "The tolerance of a sample's velocity component (AMES's A, the witness's W): the walk's,
and for a first-order witness that tolerance of the motion's speed scale (its peak
speed): the scheme's error in a velocity is a fraction of the speeds the motion reaches,
not of the local speed, which vanishes at a turning point (where v goes as the square
root of the energy left, so that an error in the energy weighs most)."
  (let ((tolerance *value-tolerance*))
    (if (and (witness-step (walk-witness walk)) (realp a) (realp w))
        (/ (* tolerance (max 1d0 (peak-sample-speed walk))) (max 1d0 (abs a) (abs w)))
        tolerance)))

(defun compare-sample (walk state start sample)
  "Set the witness's SAMPLE beside AMES's STATE (started at START) at the sample's time."
  (let* ((time (getf sample :time)) (elapsed (- time start))
         (values (walk-values walk))
         (period (state-period state values))
         (back (and period (> (mod elapsed period) (/ period 2))))
         (start-s (let ((from (getf (getf state :path-coordinates) :arc-length-from)))
                    (and from (expression-value from values)))))
    (loop for (name (wx wy)) in (getf sample :positions)
          for (nil (wvx wvy)) in (getf sample :velocities)
          for entry = (find name (getf state :positions) :key #'first :test (lambda (n s) (name= s n)))
          for ventry = (find name (getf state :velocities) :key #'first :test (lambda (n s) (name= s n)))
          for what = (format nil "~A at ~,4F s" name time)
          do (cond ((null entry) (finish walk :ames-wrong "AMES has no ~A" name))
                   ((on-path-p (second entry))
                    (unless (on-path-p (second ventry))
                      (finish walk :unsupported "~A's velocity is not given along its path" name))
                    (let* ((*arc-length* (or (path-symbol (second entry)) *arc-length*))
                           (form (second (second entry)))
                           (s (nearest-on-path form (list wx wy)
                                               (path-range state ventry start-s elapsed values (list wx wy)
                                                           (sqrt (+ (* wvx wvx) (* wvy wvy)))) values))
                           (p (path-value form s values))
                           (v (path-value (second (second ventry)) s values))
                           (sign (if back -1 1)))
                      (compare-number walk (format nil "path x ~A" what) (first p) wx)
                      (compare-number walk (format nil "path y ~A" what) (second p) wy)
                      ;; a swing: AMES's velocity at its own position at the sample's time
                      ;; (compare-swing.lisp), not at the witness's, which lags near a turn
                      (multiple-value-bind (own-p own-v)
                          (velocity-at-own-time state entry ventry values start-s elapsed)
                        (when own-v
                          (compare-number walk (format nil "own x ~A" what) (first own-p) wx)
                          (compare-number walk (format nil "own y ~A" what) (second own-p) wy)
                          (setf v own-v sign 1)))
                      (compare-number walk (format nil "velocity x ~A" what) (and v (* sign (first v))) wvx
                                      (sample-velocity-tolerance walk (and v (* sign (first v))) wvx))
                      (compare-number walk (format nil "velocity y ~A" what) (and v (* sign (second v))) wvy
                                      (sample-velocity-tolerance walk (and v (* sign (second v))) wvy))))
                   (t (let ((bindings (acons 'tau elapsed values)))
                        (compare-vectors walk (format nil "at ~,4F s" time)
                                         (evaluate-vectors (list entry ventry) bindings)
                                         (list (list name (list wx wy))))))))))

(defun compare-turns (walk state start)
  "A periodic STATE: the witness's first two turning points after START at START + P/2
and START + P (those within its horizon); any other event, or a turn where AMES has no
period, is a disagreement."
  (let* ((period (state-period state (walk-values walk)))
         (events (remove-if (lambda (e) (or (settling-p e) (< (getf e :time) (+ start 1d-9))
                                            (> (getf e :time) (- (walk-t-end walk) 1d-9))))
                            (walk-events walk))))
    (dolist (event events)
      (unless (every (lambda (pair) (eq (first pair) :turns)) (getf event :pairs))
        (finish walk :ames-wrong "AMES has no more events; the witness has ~S at ~A"
                (getf event :pairs) (getf event :time))))
    (when (and events (null period))
      (finish walk :ames-wrong "AMES's state has no turning point; the witness turns at ~A"
              (getf (first events) :time)))
    (when period
      (loop for event in events for k from 1 to 2
            do (compare-number walk (format nil "turning point ~D" k) (+ start (* k period 1/2))
                               (getf event :time))))))

(defun compare-path-state (walk state start)
  "A state that lasts forever along a path (see the file's header)."
  (compare-turns walk state start)
  (let ((samples (remove-if (lambda (s) (<= (getf s :time) (+ start 1d-6)))
                            (getf (walk-witness walk) :samples))))
    (unless samples
      (finish walk :unsupported "the witness reported no state within the state's span"))
    (dolist (sample samples)
      (compare-sample walk state start sample))))
