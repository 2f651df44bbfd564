;;;; src/witness/compare.lisp -- the comparator: AMES's states beside the witness's events.
;;;;
;;;; AMES's side is its s-expression output (bin/ames run --format sexp with values), read
;;;; as data; only the numbers it prints are compared (the :numeric plist of each state, and
;;;; for a last state that lasts forever its closed forms evaluated at the witness's end).
;;;; Per state: the start time, the end event (kind and bodies), the positions and the
;;;; velocities at its end (just before its event), to *VALUE-TOLERANCE* relative, and a
;;;; rotating body's angle and angular velocity (compare-angles.lisp). The
;;;; witness finds events by Lsodar's root finding (about 1e-12 here); where AMES sums a
;;;; Zeno sequence of impacts, Siconos stops the sequence when the rebound speed falls
;;;; under its own tolerance, so the accumulation time is compared to
;;;; *ACCUMULATION-TOLERANCE* only.

(in-package #:ames.witness)

(defvar *value-tolerance* 1d-7 "Relative tolerance of times, positions and velocities.")
(defvar *settle-speed* 1d-4
  "Impacts slower than this (m/s, the models' speeds are of order 1) outside a Zeno
sequence are the residue of Siconos's end of such a sequence (a body left with a
rebound speed under its tolerance), not events.")

(defvar *first-order-tolerance* 5d-3
  "Relative tolerance (absolute below 1) where the witness used Moreau-Jean time stepping
(friction): its step is 1e-4 s and the scheme is first order.")

(defvar *curved-tolerance* 1d-6
  "Relative tolerance (absolute below 1) where the witness has a contact with an arc or a
circle: Lsodar finds a lift-off from an arc as a root of the contact force that the
acceleration-level LCP computes, to about 3e-8 relative (the bodies' motions themselves to
about 1e-11).")

(defvar *accumulation-tolerance* 1d-5
  "Relative tolerance of the time where a Zeno sequence of impacts accumulates.")

(defstruct (comparison (:constructor make-comparison (verdict reason rows)))
  "The result of COMPARE-RESULTS: VERDICT is :AGREE or :AMES-WRONG (a disagreement; the
witness has been checked on textbook cases, so it is taken as the reference), or
:UNSUPPORTED (an event the witness does not model), or :UNCHECKED (AMES gives a state
no number to compare: neither agreement nor disagreement); REASON the first disagreement, ROWS
the values set side by side: (STATE WHAT AMES WITNESS DIFFERENCE OK)."
  verdict reason rows)

(defun close-p (a b tolerance)
  "True when the reals A and B agree to TOLERANCE relative (absolute below 1)."
  (<= (abs (- a b)) (* tolerance (max 1d0 (abs a) (abs b)))))

(defun name= (symbol string)
  (string-equal (if (stringp symbol) symbol (symbol-name symbol)) string))

(defun settling-p (event)
  "True for the witness's impacts slower than *SETTLE-SPEED* (see there)."
  (let ((speed (getf event :speed)))
    (and speed (plusp speed) (< speed *settle-speed*))))

(defun ames-path (states)
  "The states of AMES's run along the branch its values select: a fork (end event
(:BRANCH)) is replaced by its selected branch's states."
  (loop for state in states
        for branches = (getf state :branches)
        append (if branches
                   (let ((chosen (or (find-if (lambda (b) (getf b :selected)) branches)
                                     (and (= 1 (length branches)) (first branches)))))
                     (and chosen (ames-path (getf chosen :states))))
                   (list state))))

(defun event-kind (event) (if (consp event) (first event) event))

(defun witness-kind-matches-p (ames-kind witness-kind)
  (case ames-kind
    ((:collision :contact) (member witness-kind '(:collision :contact)))
    (:leaves (eq witness-kind :leaves))
    (:lift-off (member witness-kind '(:lift-off :leaves)))
    (:turns (eq witness-kind :turns))
    ((:tightens :slackens :stops-sliding :starts-sliding) (eq witness-kind ames-kind))
    ;; a rope's piece closing at its pulley: with a speed, AMES's impact (:strikes-pulley)
    ((:rope-piece-closes :strikes-pulley) (eq witness-kind :strikes-pulley))
    (t nil)))

(defparameter +witnessed-events+
  '(:collision :contact :leaves :lift-off :tightens :slackens :stops-sliding :starts-sliding :turns
    :rope-piece-closes :strikes-pulley)
  "The kinds of end events the witness reports.")

(defun event-head (event)
  "EVENT's kind and the names that follow it (one or two), without its keyword data."
  (cons (first event) (loop for x in (rest event) until (keywordp x) collect x)))

(defun event-pair-names (event)
  "The names of EVENT the witness names in its pair: a piece of rope closing at its pulley,
(:ROPE-PIECE-CLOSES ROPE HOLDER BODY) or, with a speed, (:STRIKES-PULLEY HOLDER BODY), is
the witness's (:STRIKES-PULLEY BODY HOLDER)."
  (let ((names (rest (event-head event))))
    (if (eq (event-kind event) :rope-piece-closes) (rest names) names)))

(defun event-matches-p (ames-event witness-event)
  "True when the witness's event has a pair of AMES's event's kind and names (a rope's
event names the rope once, the witness twice)."
  (let ((kind (event-kind ames-event)) (names (event-pair-names ames-event)))
    (some (lambda (pair)
            (destructuring-bind (wkind x y) pair
              (and (witness-kind-matches-p kind wkind)
                   (every (lambda (name) (or (name= name x) (name= name y))) names)
                   (every (lambda (w) (some (lambda (name) (name= name w)) names)) (list x y)))))
          (getf witness-event :pairs))))

(defun precise-value (expression bindings)
  "EXPRESSION's value under BINDINGS computed in rational arithmetic, roots, pi, sines,
cosines and inverse tangents and sines to +PRECISE-DIGITS+ digits (precise-functions.lisp;
other functions in double precision on precise arguments), or NIL when it has none."
  (labels ((value (x)
             (cond ((rationalp x) x)
                   ((floatp x) (rational x))
                   ((symbolp x)
                    (let ((entry (assoc x bindings)))
                      (cond (entry (rational (cdr entry)))
                            ((string-equal (symbol-name x) "PI") (precise-pi))
                            (t (return-from precise-value nil)))))
                   ((not (consp x)) (return-from precise-value nil))
                   (t (let ((arguments (mapcar #'value (rest x))))
                        (case (first x)
                          (+ (apply #'+ arguments))
                          (- (apply #'- arguments))
                          (* (apply #'* arguments))
                          (/ (if (some #'zerop (rest arguments))
                                 (return-from precise-value nil)
                                 (apply #'/ arguments)))
                          (sqrt (power (first arguments) 1/2))
                          (expt (power (first arguments) (second arguments)))
                          ((sin cos tan atan asin acos)
                           (or (and (= 1 (length arguments)) (precise-function (first x) (first arguments)))
                               (return-from precise-value nil)))
                          (t (let ((double (expression-value (cons (first x) (mapcar (lambda (a) (coerce a 'double-float)) arguments)))))
                               (if double (rational double) (return-from precise-value nil)))))))))
           (power (base exponent)
             (cond ((integerp exponent)
                    (if (and (zerop base) (minusp exponent)) (return-from precise-value nil) (expt base exponent)))
                   ((and (rationalp exponent) (>= base (- (precise-zero))) (< (denominator exponent) 100))
                    ;; a radicand that is 0 to the digits kept (a speed at a turning point,
                    ;; exactly 0, computed to 1e-150) is 0, whatever the sign of its residue
                    (let ((root (precise-root (expt (max base 0) (abs (numerator exponent)))
                                              (denominator exponent))))
                      (cond ((plusp exponent) root)
                            ((zerop root) (return-from precise-value nil))
                            (t (/ root)))))
                   (t (let ((double (expression-value (list 'expt (coerce base 'double-float)
                                                            (coerce exponent 'double-float)))))
                        (if double (rational double) (return-from precise-value nil)))))))
    (value expression)))

(defun number-of (expression bindings)
  "EXPRESSION's value under BINDINGS as a double (computed by PRECISE-VALUE, so that
the cancellations of AMES's nested radicals do not count against it), EXPRESSION itself
when it is a keyword (:FOREVER), NIL when it has none."
  (cond ((keywordp expression) expression)
        (t (let* ((expression (canonical-expression expression)) ; compare-curved.lisp
                  (value (or (precise-value expression bindings)
                            (expression-value expression bindings)
                            (complex-real-value expression bindings)))) ; complex-values.lisp
             (and value (coerce value 'double-float))))))

(defun evaluate-vectors (entries bindings)
  "ENTRIES ((BODY (X Y)) ...) with X and Y closed forms, evaluated under BINDINGS."
  (loop for (body (x y)) in entries
        collect (list body (list (number-of x bindings) (number-of y bindings)))))

(defun state-numbers (state bindings &key closed-form)
  "The numbers AMES gives for STATE: its :NUMERIC plist (:START :DURATION
:FINAL-POSITIONS :FINAL-VELOCITIES) when it printed one (a run with parameter values),
else (or when CLOSED-FORM) its exact closed forms evaluated; a :NUMERIC plist with a
duration only (the number of a travel-time integral in a scenario without parameters)
gives that duration beside the closed forms of the rest."
  (let ((printed (and (not closed-form) (getf state :numeric))))
    (if (and printed (get-properties printed '(:start)))
        printed
        (list :start (number-of (getf state :start) bindings)
              :duration (or (getf printed :duration) (number-of (getf state :duration) bindings))
              :final-positions (evaluate-vectors (getf state :final-positions) bindings)
              :final-velocities (evaluate-vectors (getf state :final-velocities) bindings)))))

(defun ames-end-time (ames &optional bindings)
  "The time where AMES's run (its s-expression ANSWER) ends along its selected branch:
the end of its last state, or its start when it lasts forever (the later of its printed
number and its closed form, so that a wrong number does not cut the witness short); NIL
when not numeric."
  (let ((last (car (last (ames-path (getf ames :states))))))
    (flet ((end (numbers)
             (and (realp (getf numbers :start))
                  (if (realp (getf numbers :duration))
                      (+ (getf numbers :start) (getf numbers :duration))
                      (getf numbers :start)))))
      (let ((ends (remove nil (list (end (state-numbers last bindings))
                                    (end (state-numbers last bindings :closed-form t))))))
        (and ends (reduce #'max ends))))))

;;; The walk along AMES's states and the witness's events

(defstruct (walk (:constructor make-walk (witness values t-end events)))
  "Where COMPARE-RESULTS is: the witness's answer, the parameter VALUES, the horizon, the
witness's EVENTS not yet matched, the TIME the current state should start at (to
TIME-TOLERANCE), the state's INDEX, and the ROWS set side by side so far (newest first)."
  witness values t-end events (time 0d0) (time-tolerance *value-tolerance*) (index 0)
  (rows '()))

(defun finish (walk verdict &optional control &rest arguments)
  "End the comparison with VERDICT (and a reason from CONTROL and ARGUMENTS, naming the
state)."
  (throw 'comparison
    (make-comparison verdict
                     (and control (format nil "state ~D: ~?" (walk-index walk) control arguments))
                     (reverse (walk-rows walk)))))

(defun compare-number (walk what a w &optional (tolerance *value-tolerance*))
  "Set A (AMES) beside W (the witness) as WHAT; a disagreement ends the comparison."
  (let ((ok (and (realp a) (realp w) (close-p a w tolerance))))
    (push (list (walk-index walk) what a w (and (realp a) (realp w) (- a w)) ok) (walk-rows walk))
    (unless ok (finish walk :ames-wrong "~A: AMES ~A, witness ~A" what a w))))

(defun compare-vectors (walk what ames-entries witness-entries)
  "Compare, body by body, the vectors (BODY (X Y)) the witness gives with AMES's."
  (loop for (name (wx wy)) in witness-entries
        for entry = (find name ames-entries :key #'first :test (lambda (n s) (name= s n)))
        do (unless entry (finish walk :ames-wrong "~A: AMES has no ~A" what name))
           (compare-number walk (format nil "~A x ~A" what name) (first (second entry)) wx)
           (compare-number walk (format nil "~A y ~A" what name) (second (second entry)) wy)))

(defun compare-last-state (walk state start)
  "A state that lasts forever: the witness has no more events before its horizon, and
AMES's closed forms at the witness's end give its positions and velocities."
  (let ((late (find-if (lambda (e) (and (< (getf e :time) (- (walk-t-end walk) 1d-9))
                                        (not (settling-p e)) (not (turns-only-p e))))
                       (walk-events walk))))
    (when late
      (finish walk :ames-wrong "AMES has no more events; the witness has ~S at ~A"
              (getf late :pairs) (getf late :time))))
  (let* ((end (witness-end (walk-witness walk)))
         (bindings (acons 'tau (- (getf end :time) start) (walk-values walk))))
    (when (>= (- (getf end :time) start) 1d-6)
      (compare-vectors walk "position at the witness's end"
                       (evaluate-vectors (getf state :positions) bindings) (getf end :positions))
      (compare-vectors walk "velocity at the witness's end"
                       (evaluate-vectors (getf state :velocities) bindings) (getf end :velocities))
      (compare-angles-at-end walk state bindings end)))) ; compare-angles.lisp

(defun check-witnessable (walk event)
  "End the comparison as :UNSUPPORTED when the witness cannot say anything of EVENT: a
kind it does not model, a run it cut short, or a contact reached with no approach speed
(a double root of the gap, which Lsodar's root finding, a change of sign, cannot see)."
  (unless (and (consp event) (member (event-kind event) +witnessed-events+))
    (finish walk :unsupported "it ends with ~S, an event the witness does not model" event))
  (setf (walk-events walk) (member-if-not #'settling-p (walk-events walk)))
  (let ((events (walk-events walk)) (witness (walk-witness walk)))
    (when (and (null events) (getf witness :truncated))
      (finish walk :unsupported "the witness stopped at ~A: ~A"
              (getf (witness-end witness) :time) (getf witness :truncated)))
    (when (and (eq (event-kind event) :contact)
               (not (and events (event-matches-p event (first events)))))
      (finish walk :unsupported "it ends with ~S, a contact reached with no approach speed (a double root the witness cannot locate)"
              (event-head event)))))

(defun check-numbered (walk start duration event)
  "End the comparison as :UNCHECKED when AMES gives the state no number to compare: no
START (a state after one whose duration has none), or no DURATION where an EVENT ends
it (a travel-time integral the quadrature gave no number). Neither agrees nor
disagrees: nothing was witnessed."
  (cond ((not (realp start))
         (finish walk :unchecked "AMES gives its start no number"))
        ((and (not (realp duration)) (not (eq event :none)) (not (eq duration :forever)))
         (finish walk :unchecked "AMES gives its duration no number: ~S"
                 (let ((*print-pretty* nil) (*print-length* 4) (*print-level* 3))
                   (prin1-to-string duration))))))

(defun turns-only-p (event)
  "True when the witness's EVENT is only turning points (compare-curved.lisp)."
  (every (lambda (pair) (eq (first pair) :turns)) (getf event :pairs)))

(defun compare-event-state (walk state numeric event end)
  "A state that ends with EVENT at END: the witness's next event is at that time, of that
kind and bodies, with AMES's final positions and velocities just before it. The
witness's turning points before it are passed over unless EVENT is one: AMES splits a
state at a turning point only where its motion is given along a path (a mass on a
bumper turns within one state of closed forms in time)."
  (unless (eq (event-kind event) :turns)
    (loop while (and (walk-events walk) (turns-only-p (first (walk-events walk))))
          do (pop (walk-events walk))))
  (when (check-graze walk numeric event end) ; compare-grazes.lisp: a contact at no approach speed
    (return-from compare-event-state))
  (check-witnessable walk event)
  (check-seeable-impact walk event)     ; compare-slow-impacts.lisp
  (unless (walk-events walk)
    (finish walk :ames-wrong "AMES ends the state with ~S at ~A; the witness has no more events"
            (event-head event) end))
  (let ((witness-event (merge-simultaneous-events walk (pop (walk-events walk))))) ; compare-first-order.lisp
    (compare-number walk "end time" end (getf witness-event :time))
    (let ((ok (or (event-matches-p event witness-event)
                  (handed-over-p walk event witness-event end)))) ; compare-handover.lisp
      (push (list (walk-index walk) "end event" (format nil "~(~{~A~^ ~}~)" (event-head event))
                  (format nil "~(~{~{~A~^ ~}~^, ~}~)" (getf witness-event :pairs)) nil ok)
            (walk-rows walk))
      (unless ok
        (finish walk :ames-wrong "AMES's end event ~S, the witness's ~S" (event-head event)
                (getf witness-event :pairs))))
    (compare-vectors walk "final position" (getf numeric :final-positions) (getf witness-event :positions))
    (compare-vectors walk "final velocity" (getf numeric :final-velocities) (getf witness-event :velocities))
    (compare-final-angles walk state numeric witness-event) ; compare-angles.lisp
    (setf (walk-time walk) (getf witness-event :time))
    (when (getf state :accumulation)
      (skip-accumulation walk event))))

(defun skip-accumulation (walk event)
  "After a state whose impacts AMES sums (a Zeno sequence), pass over the witness's own
run of impacts of the same pair, to its end (its intervals shrink; a later one after a
long pause is Siconos's residue); the next state's start is compared to
*ACCUMULATION-TOLERANCE*."
  (loop with interval = nil
        for events = (walk-events walk)
        while (and events (event-matches-p event (first events))
                   (or (null interval)
                       (<= (- (getf (first events) :time) (walk-time walk)) (* 2 interval))))
        do (let ((next (getf (pop (walk-events walk)) :time)))
             (setf interval (- next (walk-time walk)) (walk-time walk) next)))
  (setf (walk-time-tolerance walk) *accumulation-tolerance*))

(defun compare-results (ames witness values &key (t-end (ames-end-time ames values)))
  "Compare AMES's s-expression answer AMES for one scenario with the witness's answer
WITNESS (see RUN-WITNESS), the scenario's parameter VALUES (for closed forms) and the
witness's horizon T-END. Returns a COMPARISON."
  (let ((*value-tolerance* (case (getf witness :scheme)
                              (:moreau-jean (first-order-tolerance witness)) ; compare-first-order.lisp
                              (:curved *curved-tolerance*) ; compare-curved.lisp
                              (t *value-tolerance*))))
    (catch 'comparison
      (let ((walk (make-walk witness values t-end (motion-events (witness-events witness))))) ; compare-time-limit.lisp
        (dolist (state (ames-path (getf ames :states)))
          (let* ((numeric (state-numbers state values))
                 (start (getf numeric :start))
                 (duration (getf numeric :duration))
                 (event (getf state :end-event)))
            (setf (walk-index walk) (getf state :index))
            (check-numbered walk start duration event)
            (compare-number walk "start" start (walk-time walk) (walk-time-tolerance walk))
            (setf (walk-time-tolerance walk) *value-tolerance*)
            (when (eq event :none)
              (if (path-state-p state)  ; compare-curved.lisp
                  (compare-path-state walk state start)
                  (compare-last-state walk state start))
              (return))
            (when (time-limit-event-p event)  ; compare-time-limit.lisp
              (compare-time-limit-state walk state numeric (and (realp duration) (+ start duration))))
            (compare-event-state walk state numeric event (and (realp duration) (+ start duration)))))
        (finish walk :agree)))))

(defun print-comparison (comparison stream)
  "Print COMPARISON's rows side by side, then its verdict, on STREAM."
  (format stream "~&~5A ~38A ~22A ~22A ~10A~%" "state" "what" "AMES" "witness" "difference")
  (dolist (row (comparison-rows comparison))
    (destructuring-bind (state what a w difference ok) row
      (format stream "~5D ~38A ~22A ~22A ~10A~A~%" state what
              (if (realp a) (format nil "~,12G" a) (format nil "~(~A~)" a))
              (if (realp w) (format nil "~,12G" w) (format nil "~(~A~)" w))
              (if difference (format nil "~,2E" difference) "")
              (if ok "" "  <-- differs"))))
  (format stream "verdict: ~(~A~)~@[ (~A)~]~%" (comparison-verdict comparison)
          (comparison-reason comparison)))
