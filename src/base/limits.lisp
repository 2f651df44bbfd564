;;;; src/base/limits.lisp -- the budget of one scenario run: wall time, and the size of the exact numbers and expressions Lisp builds.
;;;;
;;;; A hostile or careless scenario can make AMES's own Lisp code work for hours: an exact
;;;; (expt 10 (expt 10 9)) in a coordinate, a product of thirty constant sums that doubles
;;;; at every factor, a polygon of ten thousand vertices. Maxima's per-request timeout never
;;;; sees that work. So every scenario run gets a BUDGET, made from the LIMITS in force:
;;;;   - a deadline (TIME-LIMIT seconds of wall time for the whole run),
;;;;   - the largest exact integer, in bits, that the Lisp side may build (INTEGER-BITS;
;;;;     a rational counts by its numerator and its denominator),
;;;;   - the largest expression, in terms of a sum, that the Lisp side may build
;;;;     (EXPRESSION-SIZE),
;;;;   - the time one Maxima request may take (MAXIMA-TIMEOUT; NIL: the bridge's own).
;;;; The layers call the cheap checks at their hot spots: CHECK-BUDGET in loops and
;;;; recursions (a fixnum countdown; the clock is read only every +BUDGET-CHECK-INTERVAL+
;;;; calls), CHECK-NUMBER-SIZE before an exact power or product is computed, and
;;;; CHECK-EXPRESSION-SIZE before a sum is expanded. The Maxima bridge gives each request at
;;;; most the time left (BUDGET-TIME-LEFT). Going over is a BUDGET-EXCEEDED, an AMES-ERROR
;;;; naming the quantity that grew, its limit, and the subject of the run (the scenario).
;;;;
;;;; The size limits hold everywhere, run or not: outside CALL-WITH-BUDGET they are those of
;;;; *LIMITS*. The deadline exists only inside CALL-WITH-BUDGET. As a backstop for work no
;;;; check covers, a budget with a deadline also arms a timer that interrupts the run a
;;;; little after the deadline (*BACKSTOP-GRACE*), with a BUDGET-EXCEEDED marked
;;;; asynchronous: state the interrupted code was changing may then be inconsistent, so the
;;;; caller should start its Maxima bridge afresh (AMES.MAXIMA:RESET-BRIDGE does).

(in-package #:ames.base)

(defconstant +budget-check-interval+ 256
  "CHECK-BUDGET reads the clock once every this many calls.")

(defparameter *backstop-grace* 5
  "Seconds after a budget's deadline at which its backstop timer interrupts the run.")

(define-condition invalid-limit (ames-error) ()
  (:documentation "A limit that is not a positive number (or NIL where no limit is
allowed). DATUM is the value, DETAIL names the limit.")
  (:report (lambda (condition stream)
             (format-report stream "Invalid limit: ~A, not ~S"
                            (ames-error-detail condition) (ames-error-datum condition)))))

(defstruct (limits (:constructor %make-limits
                       (time-limit maxima-timeout integer-bits expression-size))
                   (:copier nil))
  "What one scenario run may use (see the file header). Immutable: make new ones with
MAKE-LIMITS or CHANGE-LIMITS."
  (time-limit nil :read-only t)
  (maxima-timeout nil :read-only t)
  (integer-bits nil :read-only t)
  (expression-size nil :read-only t))

(setf (documentation 'limits-time-limit 'function)
      "Seconds of wall time a whole scenario run may take, or NIL: none."
      (documentation 'limits-maxima-timeout 'function)
      "Seconds one Maxima request may take, or NIL: the bridge's own timeout."
      (documentation 'limits-integer-bits 'function)
      "The most bits of an exact integer (numerator or denominator) the Lisp side builds."
      (documentation 'limits-expression-size 'function)
      "The most terms of a sum the Lisp side builds.")

(defun checked-limit (value what &key (allow-nil t) integer)
  "VALUE when it is a positive real (a positive integer when INTEGER), or NIL when
ALLOW-NIL; else signal INVALID-LIMIT naming WHAT."
  (cond ((and (null value) allow-nil) nil)
        ((and (realp value) (plusp value) (or (not integer) (integerp value))
              (finite-real-p value))
         value)
        (t (error 'invalid-limit :datum value
                                 :detail (format nil "~A must be a positive ~:[number~;integer~]~:[~; or NIL~]"
                                                 what integer allow-nil)))))

(defun make-limits (&key (time-limit 300) maxima-timeout (integer-bits 100000)
                         (expression-size 20000))
  "New LIMITS for scenario runs. TIME-LIMIT: seconds of wall time for a whole run (NIL:
none). MAXIMA-TIMEOUT: seconds one Maxima request may take (NIL: the bridge's own
timeout, 20 s unless set). INTEGER-BITS: the most bits of an exact integer, numerator
or denominator, that the Lisp side builds (at least 64). EXPRESSION-SIZE: the most terms of a sum that
the Lisp side builds. Signals INVALID-LIMIT for a value that is not a positive number
(the sizes must be positive integers and may not be NIL)."
  (%make-limits (checked-limit time-limit "the time limit")
                (checked-limit maxima-timeout "the Maxima timeout")
                (max 64 (checked-limit integer-bits "the integer size limit"
                                       :allow-nil nil :integer t))
                (checked-limit expression-size "the expression size limit"
                               :allow-nil nil :integer t)))

(defun change-limits (limits &rest changes
                      &key (time-limit nil time-limit-p) (maxima-timeout nil maxima-timeout-p)
                        (integer-bits nil integer-bits-p) (expression-size nil expression-size-p))
  "New LIMITS like LIMITS with the given keys (as MAKE-LIMITS takes them) changed.
Signals INVALID-LIMIT like MAKE-LIMITS."
  (declare (ignore changes))
  (make-limits :time-limit (if time-limit-p time-limit (limits-time-limit limits))
               :maxima-timeout (if maxima-timeout-p maxima-timeout (limits-maxima-timeout limits))
               :integer-bits (if integer-bits-p integer-bits (limits-integer-bits limits))
               :expression-size (if expression-size-p expression-size
                                    (limits-expression-size limits))))

(defvar *limits* (make-limits)
  "The current limits: those every scenario run gets unless its caller gives others, and
the size limits of Lisp work outside any run. Bind or set it to a LIMITS from
MAKE-LIMITS, e.g. (setf ames:*limits* (ames:make-limits :time-limit 60)).")

(defstruct (budget (:constructor %make-budget (limits subject deadline time-limit))
                   (:copier nil))
  "The budget of the scenario run in progress: its LIMITS, its SUBJECT (what is run,
for messages), its DEADLINE (an internal-real-time, or NIL), the TIME-LIMIT in seconds
that set the deadline (its own, or an outer budget's when that ends first) and the
countdown to the next reading of the clock."
  (limits nil :read-only t)
  (subject nil :read-only t)
  (deadline nil :read-only t)
  (time-limit nil :read-only t)
  (countdown +budget-check-interval+ :type fixnum))

(defvar *budget* nil
  "The budget of the scenario run in progress (see CALL-WITH-BUDGET), or NIL.")

(defvar *stop-requested* nil
  "NIL, or what asked the process to stop (:SIGTERM, :SIGINT; set by the command line's
signal handlers): every budget's deadline has then passed, so that a run stops where a
time limit would stop it and what remains is done without waiting for Maxima.")

(define-condition budget-exceeded (ames-error)
  ((quantity :initarg :quantity :reader budget-exceeded-quantity
             :documentation ":TIME, :INTEGER-BITS, :EXPRESSION-SIZE, or another quantity a
layer bounds (the bridge's :REPLY-SIZE).")
   (limit :initarg :limit :initform nil :reader budget-exceeded-limit
          :documentation "The limit that was exceeded.")
   (amount :initarg :amount :initform nil :reader budget-exceeded-amount
           :documentation "How much was needed (for sizes), or NIL.")
   (subject :initarg :subject :initform nil :reader budget-exceeded-subject
            :documentation "The subject of the run (the scenario's name), or NIL.")
   (asynchronous :initarg :asynchronous :initform nil :reader budget-exceeded-asynchronous-p
                 :documentation "True when the backstop timer interrupted the run: the
interrupted code may have left its state inconsistent."))
  (:documentation "A scenario run went over its budget: its time, or the size of an
exact number or expression the Lisp side was about to build. DATUM is what grew (the
expression or operation), when known.")
  (:report (lambda (condition stream)
             (let ((limit (budget-exceeded-limit condition))
                   (amount (budget-exceeded-amount condition)))
               (format-report
                stream "~@[The run of ~A: ~]~A~@[~%  while: ~A~]~@[~%  at fault: ~S~]"
                (let ((subject (budget-exceeded-subject condition)))
                  ;; a context, when known, names the scenario already
                  (and subject (not (ames-error-context condition)) (princ-to-string subject)))
                (case (budget-exceeded-quantity condition)
                  (:time (format nil "the time limit of ~A s was exceeded~:[~; (stopped by the backstop timer)~]"
                                 limit (budget-exceeded-asynchronous-p condition)))
                  (:integer-bits
                   (format nil "an exact number of ~:[more than ~D~;~:*~:D~] bits would exceed the limit of ~:D bits"
                           amount limit limit))
                  (:expression-size
                   (format nil "an expression of ~:[more than ~D~;~:*~:D~] terms would exceed the limit of ~:D terms"
                           amount limit limit))
                  (t (format nil "~(~A~) ~@[~:D ~]exceeds the limit of ~:D"
                             (budget-exceeded-quantity condition) amount limit)))
                (ames-error-detail condition)
                (ames-error-datum condition))))))

(setf (documentation 'budget-exceeded-quantity 'function)
      "What went over its limit: :TIME, :INTEGER-BITS, :EXPRESSION-SIZE, or another
quantity a layer bounds (the bridge's :REPLY-SIZE)."
      (documentation 'budget-exceeded-limit 'function)
      "The limit that was exceeded."
      (documentation 'budget-exceeded-amount 'function)
      "How much was needed (for sizes), or NIL."
      (documentation 'budget-exceeded-subject 'function)
      "The subject of the run (the scenario's name), or NIL.")

(defun current-limits ()
  "The limits in force: the running budget's, else *LIMITS*."
  (let ((budget *budget*))
    (if budget (budget-limits budget) *limits*)))

(defun seconds-to-internal (seconds)
  "SECONDS as a count of internal time units."
  (round (* seconds internal-time-units-per-second)))

(defun current-time-limit ()
  "The time limit, in seconds, of the running budget's deadline, or NIL."
  (and *budget* (budget-time-limit *budget*)))

(defun budget-time-left ()
  "Seconds (a double-float, possibly zero or negative) left before the running budget's
deadline, or NIL when no budget with a deadline is running; 0 whenever a stop is
requested (*STOP-REQUESTED*), in a budget or not."
  (let ((deadline (and *budget* (budget-deadline *budget*))))
    (cond (*stop-requested* 0d0)
          (deadline (/ (- deadline (get-internal-real-time))
                       (coerce internal-time-units-per-second 'double-float))))))

(defun signal-budget-exceeded (quantity limit &key amount datum detail asynchronous)
  "Signal BUDGET-EXCEEDED for QUANTITY over LIMIT, naming the running budget's subject."
  (error 'budget-exceeded :quantity quantity :limit limit :amount amount
                          :datum datum :detail detail :asynchronous asynchronous
                          :subject (and *budget* (budget-subject *budget*))))

(defun check-deadline (&optional datum detail)
  "Signal BUDGET-EXCEEDED (quantity :TIME) when the running budget's deadline has
passed; DATUM and DETAIL say what was being done. Reads the clock: call CHECK-BUDGET in
loops instead."
  (let ((budget *budget*))
    (when budget
      (setf (budget-countdown budget) +budget-check-interval+)
      (let ((deadline (budget-deadline budget)))
        (when (and deadline (or *stop-requested* (> (get-internal-real-time) deadline)))
          (signal-budget-exceeded :time (budget-time-limit budget)
                                  :datum datum :detail detail))))))

(declaim (inline check-budget))
(defun check-budget (&optional datum)
  "The cheap check to call in loops and recursions of Lisp work that may grow: every
+BUDGET-CHECK-INTERVAL+ calls it reads the clock and signals BUDGET-EXCEEDED (quantity
:TIME, DATUM what is being worked on) when the running budget's deadline has passed.
Does nothing outside a budget."
  (let ((budget *budget*))
    (when (and budget (minusp (decf (budget-countdown budget))))
      (check-deadline datum))))

(defun check-number-size (bits &optional datum)
  "Signal BUDGET-EXCEEDED (quantity :INTEGER-BITS) when an exact integer of BITS bits is
more than the current limits allow; DATUM is the operation about to build it."
  (let ((limit (limits-integer-bits (current-limits))))
    (when (> bits limit)
      (signal-budget-exceeded :integer-bits limit :amount bits :datum datum))))

(defun rational-bits (x)
  "The size in bits of the rational X: the larger of its numerator's and denominator's."
  (max (integer-length (numerator x)) (integer-length (denominator x))))

(declaim (inline check-rational-size))
(defun check-rational-size (x &optional datum)
  "X, after signalling BUDGET-EXCEEDED (quantity :INTEGER-BITS) when X is a rational
larger than the current limits allow (never for a fixnum: the limit is at least 64
bits); DATUM is the operation that built it."
  (unless (typep x 'fixnum)
    (when (rationalp x)
      (check-number-size (rational-bits x) datum)))
  x)

(defun check-expression-size (size &optional datum)
  "Signal BUDGET-EXCEEDED (quantity :EXPRESSION-SIZE) when an expression of SIZE terms
is more than the current limits allow; DATUM is the operation about to build it."
  (let ((limit (limits-expression-size (current-limits))))
    (when (> size limit)
      (signal-budget-exceeded :expression-size limit :amount size :datum datum))))

(defun call-with-backstop (budget thunk)
  "Call THUNK; when BUDGET has a deadline, a timer interrupts THUNK *BACKSTOP-GRACE*
seconds after it with an asynchronous BUDGET-EXCEEDED (for work no check covers)."
  (let ((deadline (budget-deadline budget)))
    (if (null deadline)
        (funcall thunk)
        (let* ((thread sb-thread:*current-thread*)
               (timer (sb-ext:make-timer
                       (lambda ()
                         (let ((*budget* budget))
                           (signal-budget-exceeded :time (budget-time-limit budget)
                                                   :asynchronous t)))
                       :thread thread :name "AMES budget backstop")))
          (sb-ext:schedule-timer timer
                                 (max 0 (+ (/ (- deadline (get-internal-real-time))
                                              internal-time-units-per-second)
                                           *backstop-grace*)))
          (unwind-protect (funcall thunk)
            (sb-ext:unschedule-timer timer))))))

(defun call-with-budget (thunk &key (limits *limits*) subject)
  "Call THUNK as one scenario run with a budget made from LIMITS (by default *LIMITS*):
its deadline is TIME-LIMIT seconds from now, and its size limits are LIMITS's. SUBJECT
(the scenario's name, say) is named by the BUDGET-EXCEEDED conditions of the run. A
budget inside another ends no later than the outer one. Returns THUNK's values.
Signals INVALID-LIMIT when LIMITS is not a LIMITS; BUDGET-EXCEEDED comes from the checks
THUNK's work makes, or from the backstop timer (see the file header)."
  (unless (limits-p limits)
    (error 'invalid-limit :datum limits :detail "the limits must be made by MAKE-LIMITS"))
  (let* ((time-limit (limits-time-limit limits))
         (own (and time-limit (+ (get-internal-real-time) (seconds-to-internal time-limit))))
         (outer (and *budget* (budget-deadline *budget*)))
         (budget (if (and outer (or (null own) (< outer own)))
                     (%make-budget limits subject outer (budget-time-limit *budget*))
                     (%make-budget limits subject own time-limit))))
    (let ((*budget* budget))
      (call-with-backstop budget thunk))))

(defmacro with-budget ((&rest keys &key limits subject) &body body)
  "Run BODY as one scenario run with a budget: see CALL-WITH-BUDGET, which takes the
same keys (LIMITS, SUBJECT)."
  (declare (ignore limits subject))
  `(call-with-budget (lambda () ,@body) ,@keys))
