;;;; src/maxima-bridge/framing.lisp -- one round trip to Maxima: request lines, reply frames, a bounded buffer, timeouts.
;;;;
;;;; Requests are lines `(ID :EVAL FORM)`, each preceded by an empty line (a SIGINT that
;;;; lands while the server waits eats one character); replies are frames between markers
;;;; that carry a random nonce, so nothing Maxima prints by itself can be taken for a reply.
;;;; Reading never blocks past the deadline: characters are taken with READ-CHAR-NO-HANG,
;;;; at most +READ-CHUNK+ at a time, and the descriptor is waited on with a timeout.
;;;;
;;;; Bounds. A request may take the bridge's timeout (or the MAXIMA-TIMEOUT of the limits in
;;;; force, see src/base/limits.lisp), and never more than the time left in the budget of
;;;; the scenario run in progress (REQUEST-TIMEOUT). The reply buffer holds at most
;;;; *REPLY-LIMIT* characters: what Maxima prints outside a frame is dropped, and a reply
;;;; longer than that ends the process with MAXIMA-OUTPUT-OVERFLOW, so a Maxima that floods
;;;; its output cannot exhaust the heap.

(in-package #:ames.maxima)

(defparameter *reply-limit* 8000000
  "The most characters one reply of Maxima may have; a longer one is MAXIMA-OUTPUT-OVERFLOW.")

(defconstant +read-chunk+ 65536
  "The most characters READ-AVAILABLE takes at once, so that a flood of output cannot keep
the bridge from looking at the clock.")

(defun print-request (id kind arguments)
  "The request line for ID, KIND and ARGUMENTS, as the server reads it."
  (let ((*package* (find-package '#:ames.maxima.wire))
        (*print-pretty* nil) (*print-base* 10) (*print-radix* nil) (*print-case* :upcase)
        (*print-readably* nil) (*print-circle* nil) (*print-level* nil) (*print-length* nil)
        (*read-default-float-format* 'double-float))
    (format nil "~%~S~%" (list* id kind arguments))))

(defun send-line (bridge text)
  "Write TEXT to BRIDGE's process. Signals SERVER-GONE when the pipe is closed."
  (let ((stream (sb-ext:process-input (bridge-process bridge))))
    (handler-case (progn (write-string text stream) (finish-output stream))
      (stream-error () (error 'server-gone)))))

(defun drop-buffer-start (bridge start)
  "Remove the first START characters of BRIDGE's buffer."
  (let ((buffer (bridge-buffer bridge)))
    (replace buffer buffer :start2 start)
    (setf (fill-pointer buffer) (- (fill-pointer buffer) start)
          (bridge-scanned bridge) 0)))

(defun take-frame (bridge)
  "The text of the first complete frame in BRIDGE's buffer, removed from it, or NIL.
Only the characters not yet scanned are searched for the end marker."
  (let* ((buffer (bridge-buffer bridge))
         (marker (bridge-frame-end bridge))
         (end (search marker buffer :start2 (min (bridge-scanned bridge) (length buffer)))))
    (if (null end)
        (progn (setf (bridge-scanned bridge) (max 0 (- (length buffer) (length marker))))
               nil)
        (let* ((begin (search (bridge-frame-begin bridge) buffer :end2 end :from-end t))
               (text (and begin (subseq buffer (+ begin (length (bridge-frame-begin bridge))) end))))
          (drop-buffer-start bridge (+ end (length marker)))
          (or text "")))))

(defun bound-buffer (bridge)
  "Keep BRIDGE's buffer within *REPLY-LIMIT*: drop what Maxima printed before the last
frame's begin marker (it belongs to no reply); when the frame itself is longer, end the
process and signal MAXIMA-OUTPUT-OVERFLOW."
  (let ((buffer (bridge-buffer bridge)))
    (when (> (length buffer) *reply-limit*)
      (let ((begin (search (bridge-frame-begin bridge) buffer :from-end t)))
        (cond (begin (drop-buffer-start bridge begin))
              ;; no frame has begun: keep only what could be the start of a marker
              (t (drop-buffer-start bridge (- (length buffer)
                                              (length (bridge-frame-begin bridge))))))
        (when (> (length buffer) *reply-limit*)
          (discard-process bridge)
          (error 'maxima-output-overflow :limit *reply-limit*
                                         :detail "the process was ended; the next request starts a new one"))))))

(defun parse-frame (text)
  "The reply (ID STATUS SECONDS . DATA) in frame TEXT, or NIL when unreadable."
  (let ((*read-eval* nil)
        (*package* (find-package '#:ames.maxima.wire))
        (*read-default-float-format* 'double-float)
        (*read-base* 10))
    (handler-case (let ((reply (read-from-string text)))
                    (and (consp reply) (consp (cdr reply)) (consp (cddr reply)) reply))
      (reader-error () nil)
      (end-of-file () nil))))

(defun read-available (bridge)
  "Move what Maxima has written into the buffer, at most +READ-CHUNK+ characters.
Returns :EOF at end of output, T when something was read, NIL otherwise. Signals
MAXIMA-OUTPUT-OVERFLOW when a reply outgrows *REPLY-LIMIT* (see BOUND-BUFFER)."
  (let ((stream (sb-ext:process-output (bridge-process bridge)))
        (buffer (bridge-buffer bridge))
        (got nil))
    (prog1 (loop repeat +read-chunk+
                 do (let ((c (read-char-no-hang stream nil :eof)))
                      (cond ((eq c :eof) (return :eof))
                            ((null c) (return got))
                            (t (vector-push-extend c buffer) (setf got t))))
                 finally (return got))
      (bound-buffer bridge))))

(defun await-reply (bridge id deadline)
  "Wait until DEADLINE for the reply to request ID. Returns the reply
(ID STATUS SECONDS . DATA), or :TIMEOUT. Signals SERVER-GONE when the process ends."
  (let ((fd (sb-sys:fd-stream-fd (sb-ext:process-output (bridge-process bridge)))))
    (loop
      (let ((text (take-frame bridge)))
        (if text
            (let ((reply (parse-frame text)))
              ;; Only one request is ever outstanding. Frames of earlier (interrupted)
              ;; requests are dropped; a frame without id (NIL: the server could not read
              ;; the request) is ours, and so is a frame SBCL cannot read.
              (cond ((null reply)
                     (return (list id :lisp-error 0
                                   (format nil "unreadable reply: ~A"
                                           (subseq text 0 (min 200 (length text)))))))
                    ((or (eql (first reply) id) (eq (first reply) +false+))
                     (return reply))))
            (let ((got (read-available bridge))
                  (remaining (- deadline (now))))
              ;; the clock is read even while output keeps coming (a flood)
              (cond ((eq got :eof) (error 'server-gone))
                    ((<= remaining 0) (return :timeout))
                    (got)
                    (t (sb-sys:wait-until-fd-usable fd :input remaining)))))))))

(defun configured-timeout (bridge)
  "The seconds a request of BRIDGE may take: the MAXIMA-TIMEOUT of the limits in force,
else the bridge's own timeout."
  (or (limits-maxima-timeout (current-limits)) (bridge-timeout bridge)))

(defun request-timeout (bridge)
  "The seconds the next request of BRIDGE may take: its configured timeout, or the time
left in the budget of the run in progress when that is shorter. Second value true when
the budget is what limits it."
  (let ((configured (configured-timeout bridge))
        (left (budget-time-left)))
    (if (and left (< left configured))
        (values (max 0 left) t)
        (values configured nil))))

(defvar *request-log* nil
  "When a function of four arguments, each round trip is reported to it after its reply:
the BRIDGE, the REQUEST (KIND . ARGUMENTS) sent, the seconds Maxima spent on it (NIL
after a timeout) and the wall seconds of the round trip. For profiling which requests
cost the time (bench/profile-requests.lisp); NIL, the default, costs nothing.")

(defun round-trip (bridge request &optional (timeout (request-timeout bridge)))
  "Send REQUEST (KIND . ARGUMENTS) and return the reply's STATUS, DATA and SECONDS as
values; after TIMEOUT seconds, interrupt Maxima and return :TIMEOUT (killing the process
when the interrupt does not take). Signals SERVER-GONE when the process ends, and
MAXIMA-OUTPUT-OVERFLOW for a reply longer than *REPLY-LIMIT*."
  (let* ((id (prog1 (bridge-next-id bridge) (incf (bridge-next-id bridge))))
         (start (now))
         (record (bridge-statistics-record bridge)))
    (send-line bridge (print-request id (first request) (rest request)))
    (incf (statistics-maxima-calls record))
    (let ((reply (await-reply bridge id (+ start timeout))))
      (when (eq reply :timeout)
        (incf (statistics-timeouts record))
        (sb-ext:process-kill (bridge-process bridge) +sigint+)
        (let ((late (handler-case (await-reply bridge id (+ (now) (bridge-interrupt-grace bridge)))
                      (server-gone () :gone))))
          (when (member late '(:timeout :gone)) (discard-process bridge))
          (setf reply (if (and (consp late) (eq (second late) :ok)) late :timeout))))
      (incf (statistics-round-trip-seconds record) (- (now) start))
      (when *request-log*
        (funcall *request-log* bridge request (and (consp reply) (third reply)) (- (now) start)))
      (if (eq reply :timeout)
          (values :timeout nil (- (now) start))
          (destructuring-bind (reply-id status seconds &rest data) reply
            (declare (ignore reply-id))
            (when (realp seconds) (incf (statistics-maxima-seconds record) seconds))
            (values status data seconds))))))

