;;;; src/check/events.lisp -- a state's end against a numeric search over its termination conditions.
;;;;
;;;; Each termination condition the knowledge base defines for the state (recorded in its
;;;; :CHECK-MODEL) becomes an event function of the integrated state and time, >= 0 while
;;;; the condition has not fired: a contact's gap where the relative position is within
;;;; the contact's extent (positive elsewhere), or the violation function of each part of
;;;; a relation. A relation fires where its function crosses below zero from a place
;;;; where it was not; a gap where it crosses from above zero to below it within the
;;;; contact's extent (a body meets a face from its exterior: a gap already negative, or
;;;; entered from behind the face, is no meeting). "Below" and "above" zero mean by more
;;;; than the function's noise: how much it changes when the integrated state is off by
;;;; 1e-8 of its scale (the scale of its kind of quantity, EVENT-SCALES). On the grid of the
;;;; integration: none may fire before the claimed end (its first crossing located by
;;;; bisection and reported), and a condition naming the claimed end event must be at zero
;;;; (within ten times its noise) at the claimed time.

(in-package #:ames.check)

(defun event-functions (setup condition)
  "The event functions of one recorded CONDITION, or :UNSEARCHABLE: for a relation, a
list of functions of a state vector and a time, one per part; for a contact's gap, a
list of one (:GAP GAP-FUNCTION MARGIN-FUNCTIONS) (see GAP-FIRES-EARLY)."
  (flet ((safely (f) (lambda (y time) (safe f y time))))
    (cond ((getf condition :unsearchable) :unsearchable)
          ((getf condition :gap)
           (list (list :gap (safely (compiled setup (getf condition :gap)))
                       (mapcar (lambda (m) (safely (compiled setup m))) (getf condition :margins)))))
          (t (mapcar (lambda (part) (safely (compiled setup part))) (getf condition :parts))))))

(defun condition-name (condition)
  "A short text naming a recorded CONDITION."
  (datum-string (or (getf condition :event) (getf condition :change))))

(defun first-crossing (setup function low-sample high-sample)
  "The time in [LOW, HIGH] where FUNCTION first goes below zero, by bisection,
integrating from LOW-SAMPLE (TIME . STATE)."
  (let ((low (car low-sample)) (high (car high-sample)) (y (cdr low-sample)) (from (car low-sample)))
    (loop repeat 60
          do (let* ((middle (/ (+ low high) 2))
                    (value (funcall function (integrate-rk4 (setup-rates setup) y from middle) middle)))
               (if (and value (< value 0)) (setf high middle) (setf low middle))))
    high))

(defun event-head (event)
  "EVENT's kind and bodies: its elements before its first keyword option."
  (if (consp event)
      (cons (first event) (loop for x in (rest event) until (keywordp x) collect x))
      event))

(defun ends-as-claimed-p (condition end-event)
  "True when the recorded CONDITION names END-EVENT (as its event, its impact or its
change), options such as an impact's impulse aside."
  (member (event-head end-event)
          (mapcar #'event-head (list (getf condition :event) (getf condition :impact) (getf condition :change)))
          :test #'equal))

(defparameter *state-noise* 1d-8
  "The relative error in the integrated state an event function's noise is measured by.")

(defun state-scales (samples)
  "Per state component, the largest |value| over SAMPLES (1 where it is 0 throughout)."
  (let* ((n (length (cdr (first samples))))
         (scales (make-array n :initial-element 0d0)))
    (loop for (nil . y) in samples
          do (dotimes (i n) (setf (svref scales i) (max (svref scales i) (abs (svref y i))))))
    (dotimes (i n scales)
      (when (zerop (svref scales i)) (setf (svref scales i) 1d0)))))

(defun quantity-kind (term)
  "The kind of quantity the state TERM is, for its scale: lengths (positions, arc
lengths), speeds (velocities, speeds along paths), or its own head (angles ...)."
  (case (first term)
    ((ames.kb:pos ames.kb:path-position) :length)
    ((ames.kb:vel ames.kb:path-speed) :speed)
    (t (first term))))

(defun event-scales (setup samples)
  "The scales the noise of SETUP's event functions is measured by: per state component,
the largest |value| over SAMPLES of any component of its kind (QUANTITY-KIND: the x and
y coordinates of every body share one, as a rotation of the axes would have them); and
when the speeds, over the span of SAMPLES, move nothing by more than *REST-ROUND-OFF*
of the lengths (an equilibrium's start rounded to doubles, drifting by round-off), the
speeds' scale is the lengths' over the span: their signs are round-off, no event."
  (let* ((own (state-scales samples))
         (kinds (mapcar #'quantity-kind (setup-terms setup)))
         (largest (make-hash-table))
         (span (- (car (car (last samples))) (car (first samples)))))
    (loop for kind in kinds for i from 0
          do (setf (gethash kind largest) (max (gethash kind largest 0d0) (svref own i))))
    (let ((lengths (gethash :length largest)) (speeds (gethash :speed largest)))
      (when (and lengths speeds (plusp span) (< (* speeds span) (* *rest-round-off* lengths)))
        (setf (gethash :speed largest) (/ lengths span))))
    (coerce (mapcar (lambda (kind) (gethash kind largest)) kinds) 'simple-vector)))

(defun noise (function y time scales)
  "How much FUNCTION's value at Y may change when each state component is off by
*STATE-NOISE* of its scale: the margin within which its sign is not known."
  (let ((value (funcall function y time)) (largest 0d0))
    (dotimes (i (length y) largest)
      (dolist (sign '(1d0 -1d0))
        (let ((moved (copy-seq y)))
          (incf (svref moved i) (* sign *state-noise* (svref scales i)))
          (let ((other (funcall function moved time)))
            (when (and value other) (setf largest (max largest (abs (- other value)))))))))))

(defun fires-early (setup function samples cutoff scales)
  "The time at which FUNCTION first crosses below zero, by more than its noise, from a
sample where it was not below zero, before CUTOFF (NIL: over all SAMPLES); NIL if never."
  (let ((armed nil))
    (loop for sample in samples
          for (time . y) = sample
          for value = (funcall function y time)
          do (when value
               ;; the noise is needed only below zero
               (let ((margin (if (minusp value) (noise function y time scales) 0d0)))
                 (cond ((>= value (- margin)) (setf armed t))
                       ((and armed (or (null cutoff) (< time cutoff)))
                        (return (first-crossing setup function (previous-sample samples sample) sample)))))))))

(defun within-extent-p (margins y time scales)
  "True when every extent MARGIN function is >= 0 at Y and TIME, within ten times its noise."
  (every (lambda (m)
           (let ((value (funcall m y time)))
             (and value (>= value (- (* 10 (noise m y time scales)))))))
         margins))

(defun gap-fires-early (setup gap margins samples cutoff scales)
  "The time at which the contact's GAP first crosses from above zero to below zero (each
by more than its noise: the body meets the face from its exterior) with the relative
position then within the contact's extent (every MARGIN >= 0), before CUTOFF (NIL: over
all SAMPLES); NIL if never."
  (let ((outside nil))
    (loop for sample in samples
          for (time . y) = sample
          for value = (funcall gap y time)
          do (when (and value (or (plusp value) outside))
               (let ((margin (noise gap y time scales)))
                 (cond ((> value margin) (setf outside sample))
                       ((and outside (< value (- margin)))
                        (let* ((at (first-crossing setup gap outside sample))
                               (there (integrate-rk4 (setup-rates setup) (cdr outside) (car outside) at)))
                          (when (and (within-extent-p margins there at scales)
                                     (or (null cutoff) (< at cutoff)))
                            (return at))
                          (setf outside nil)))))))))

(defun previous-sample (samples sample)
  "The sample before SAMPLE in SAMPLES (SAMPLE itself when it is the first)."
  (loop for (a b) on samples
        when (eq b sample) return a
        finally (return sample)))

(defun at-zero-p (function y time scales)
  "True when FUNCTION is zero at Y and TIME within ten times its noise."
  (let ((value (funcall function y time)))
    (and value (<= (abs value) (* 10 (max (noise function y time scales) 1d-300))))))

(defun velocity-indices (setup)
  "The indices of SETUP's state terms that are velocities: the rates of other state terms."
  (let ((rates (getf (setup-model setup) :rates)))
    (loop for term in (setup-terms setup)
          for i from 0
          when (find term rates :key #'cdr :test #'equal) collect i)))

(defun at-rest-p (setup time from scales)
  "True when every velocity of the state is zero (within 1e-6 of its scale) at TIME,
integrating from the sample FROM: a turning point."
  (let ((y (integrate-rk4 (setup-rates setup) (cdr from) (car from) time)))
    (every (lambda (i) (<= (abs (svref y i)) (* 1d-6 (svref scales i)))) (velocity-indices setup))))

(defun check-events (setup state samples end &key turning-points-allowed)
  "Failures of STATE's end against its termination conditions over SAMPLES (the grid up
to END, a double, or to a horizon when END is NIL: the state claims to last forever),
and a second value: NIL, or the reason the end could not be checked. With
TURNING-POINTS-ALLOWED (a periodic state), a condition that fires where every velocity
is zero is the motion turning back, which the periodic state includes."
  (let ((failures '()) (claimed-checked (null end)) (unsearchable nil)
        (end-event (state-end-event state))
        (cutoff (and end (* end (- 1 1d-6))))
        (scales (event-scales setup samples)))
    (when (and end (consp end-event) (eq (first end-event) :time-limit))
      (setf claimed-checked t))
    (dolist (condition (getf (setup-model setup) :conditions))
      (let ((functions (event-functions setup condition)))
        (if (eq functions :unsearchable)
            (setf unsearchable (condition-name condition))
            (dolist (function functions)
              ;; none earlier
              (let ((at (if (and (consp function) (eq (first function) :gap))
                            (gap-fires-early setup (second function) (third function) samples cutoff scales)
                            (fires-early setup function samples cutoff scales))))
                (when (and at turning-points-allowed
                           (at-rest-p setup at (find-if (lambda (sample) (<= (car sample) at)) samples :from-end t)
                                      scales))
                  (setf at nil))
                (when at
                  (push (make-check-failure
                         (format nil "no condition fires before the end: ~A" (condition-name condition))
                         (if end (- end at) at)
                         (format nil "it fires at tau = ~A~@[, before the claimed end tau = ~A~]"
                                 (number-string at) (and end (number-string end))))
                        failures)))
              ;; the claimed one at the claimed time
              (when (and end (ends-as-claimed-p condition end-event)
                         (at-zero-p (if (consp function) (second function) function)
                                    (cdr (car (last samples))) end scales))
                (setf claimed-checked t))))))
    (when (and end (not claimed-checked) (not unsearchable))
      (push (make-check-failure (format nil "the claimed end ~A at tau = ~A" (datum-string (event-head end-event)) (number-string end))
                                :not-at-end
                                "no termination condition naming it is at zero then")
            failures))
    (values (nreverse failures)
            (and unsearchable
                 (format nil "the condition ~A cannot be searched numerically" unsearchable)))))
