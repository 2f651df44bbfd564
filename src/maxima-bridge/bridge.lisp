;;;; src/maxima-bridge/bridge.lisp -- the bridge object: one Maxima process, its restarts, its requests and cache.
;;;;
;;;; The process is Debian's `maxima` script run with `-p maxima-server.lisp`; the script
;;;; `exec`s the GCL binary, so the pid SBCL knows is the pid that must receive SIGINT.
;;;; The framing of requests and replies, the bounded reply buffer and the timeout of one
;;;; round trip are in framing.lisp.

(in-package #:ames.maxima)

(defconstant +sigint+ 2 "The signal that interrupts a busy GCL Maxima.")
(defconstant +sigkill+ 9 "The signal that ends a wedged Maxima.")

(defparameter *cache-limit* 100000
  "When a bridge's cache holds this many answers, it is emptied before the next is stored.")

(defparameter *server-file*
  (asdf:system-relative-pathname "ames" "src/maxima-bridge/maxima-server.lisp")
  "The Lisp file Maxima preloads: the request server.")

(defun cache-key-hash (key)
  "A hash of the whole tree KEY (SXHASH looks only a few levels and elements deep, and
the bridge's keys, Maxima forms under the facts in force, differ deep inside: with
SXHASH a scenario with a thousand contacts spent most of its time comparing keys)."
  (let ((hash 0))
    (labels ((mix (x) (setf hash (logand (+ (* hash 31) x) most-positive-fixnum)))
             (walk (x)
               (loop while (consp x)
                     do (mix 17)
                        (walk (car x))
                        (setf x (cdr x)))
               (mix (sxhash x))))
      (walk key))
    hash))

(defun cache-key-equal (a b)
  "EQUAL, as the test of the bridge's cache (hashed by CACHE-KEY-HASH)."
  (equal a b))

(sb-ext:define-hash-table-test cache-key-equal cache-key-hash)

(defun make-cache ()
  "An empty cache table: keys compared by EQUAL, hashed over their whole tree."
  (make-hash-table :test 'cache-key-equal))

(defstruct (assumption-frame (:constructor make-assumption-frame (context facts maxima-facts)))
  "One WITH-ASSUMPTIONS scope: its Maxima context, the facts as given, and the facts as
assumed in Maxima (including derived trigonometric sign facts); OPENED false while its
context is not yet set up in Maxima (see OPEN-PENDING-FRAMES)."
  context facts maxima-facts (opened t))

(defclass bridge ()
  ((program :initarg :program :reader bridge-program
            :documentation "The command that starts Maxima (searched on PATH).")
   (timeout :initarg :timeout :accessor bridge-timeout
            :documentation "Seconds a request may take before it is interrupted.")
   (interrupt-grace :initarg :interrupt-grace :initform 2 :accessor bridge-interrupt-grace
                    :documentation "Seconds an interrupted request may take to stop
before the process is killed and replaced.")
   (process :initform nil :accessor bridge-process)
   (greeted :initform nil :accessor bridge-greeted
            :documentation "True once the process has greeted (see PRESTART-BRIDGE).")
   (nonce :initform nil :accessor bridge-nonce)
   (frame-begin :initform nil :accessor bridge-frame-begin)
   (frame-end :initform nil :accessor bridge-frame-end)
   (buffer :initform (make-array 256 :element-type 'character :adjustable t :fill-pointer 0)
           :reader bridge-buffer
           :documentation "Characters read from Maxima and not yet consumed.")
   (scanned :initform 0 :accessor bridge-scanned
            :documentation "No end marker starts in the buffer before this index.")
   (next-id :initform 1 :accessor bridge-next-id)
   (names :initform (make-instance 'name-table) :accessor bridge-names)
   (frames :initform '() :accessor bridge-frames
           :documentation "Active assumption frames, innermost first.")
   (cache :initform (make-cache) :accessor bridge-cache
          :documentation "Answers to requests, and DECIDE's verdicts, under the facts in force.")
   (excess-names :initform (make-hash-table :test 'equal) :accessor bridge-excess-names
                 :documentation "Key -> the auxiliary variable KEYED-AUXILIARY-VARIABLE made
for it (a variable's excess over its bound, an angle's sine, for DECIDE).")
   (statistics :initform (make-statistics) :accessor bridge-statistics-record))
  (:documentation "A connection to one persistent Maxima process, started lazily, with
its name table, assumption scopes, cache and counters. Use a bridge from one thread."))

(defstruct statistics
  (calls 0) (cache-hits 0) (maxima-calls 0) (restarts 0) (timeouts 0) (questions 0)
  (errors 0) (maxima-seconds 0d0) (round-trip-seconds 0d0))

(defun make-bridge (&key (timeout 20) (program "maxima"))
  "A new BRIDGE to Maxima. No process starts until the first request. TIMEOUT is the
number of seconds one request may take (settable with (SETF BRIDGE-TIMEOUT)); PROGRAM
the command that starts Debian's GCL Maxima, searched on PATH.
Signals INVALID-BRIDGE-ARGUMENT for a timeout that is not a positive number or a
program that is not a string."
  (unless (and (realp timeout) (plusp timeout))
    (error 'invalid-bridge-argument :datum timeout :detail "the timeout must be a positive number of seconds"))
  (unless (stringp program)
    (error 'invalid-bridge-argument :datum program :detail "the program must be a string"))
  (make-instance 'bridge :timeout timeout :program program))

(defmethod print-object ((bridge bridge) stream)
  (print-unreadable-object (bridge stream :type t :identity t)
    (format stream "~A ~:[idle~;running~]" (bridge-program bridge) (bridge-alive-p bridge))))

(defun bridge-statistics (bridge)
  "A plist of BRIDGE's counters: :CALLS (requests asked of the bridge, DECIDE's own
verdict lookups included), :CACHE-HITS (requests and verdicts answered from the cache),
:MAXIMA-CALLS (round trips to Maxima), :RESTARTS (processes started), :TIMEOUTS,
:QUESTIONS, :ERRORS, :MAXIMA-SECONDS (evaluation time measured inside Maxima) and
:ROUND-TRIP-SECONDS (wall time of the round trips)."
  (let ((s (bridge-statistics-record bridge)))
    (list :calls (statistics-calls s) :cache-hits (statistics-cache-hits s)
          :maxima-calls (statistics-maxima-calls s) :restarts (statistics-restarts s)
          :timeouts (statistics-timeouts s) :questions (statistics-questions s)
          :errors (statistics-errors s) :maxima-seconds (statistics-maxima-seconds s)
          :round-trip-seconds (statistics-round-trip-seconds s))))

(defun reset-bridge-statistics (bridge)
  "Set every counter of BRIDGE to zero (the cache itself is kept)."
  (setf (bridge-statistics-record bridge) (make-statistics))
  bridge)

(defun clear-bridge-cache (bridge)
  "Forget every cached answer of BRIDGE (for benchmarks; answers never go stale)."
  (clrhash (bridge-cache bridge))
  bridge)

(defun bridge-in-scope-p (bridge)
  "True when an assumption scope (WITH-ASSUMPTIONS) of BRIDGE is open."
  (and (bridge-frames bridge) t))

(defun reset-bridge (bridge &key restart)
  "Make BRIDGE answer as a new one would, so that what a scenario run prints does not
depend on what ran before it: a fresh name table (the Maxima names of variables are
given in order of first use, and Maxima orders terms by them), an empty cache and fresh
excess names. With RESTART true the process is also ended and every assumption scope
forgotten (for a run cut short: a request may still be running, a scope may not have
been left); the next request starts a new process. Call it between scenario runs.
Returns BRIDGE. Signals INVALID-BRIDGE-ARGUMENT when an assumption scope is open and
RESTART is false."
  (when (and (bridge-in-scope-p bridge) (not restart))
    (error 'invalid-bridge-argument
           :datum (current-assumptions bridge)
           :detail "the bridge cannot be reset inside an assumption scope (WITH-ASSUMPTIONS)"))
  (when restart
    (setf (bridge-frames bridge) '())
    (discard-process bridge))
  ;; fresh tables rather than CLRHASH: an interrupted run may have left one inconsistent.
  ;; The names of contexts and auxiliary variables are never given twice in one process:
  ;; a context or fact of an earlier run left in Maxima must not reappear under them.
  (let ((old (bridge-names bridge)) (new (make-instance 'name-table)))
    (when old
      (maphash (lambda (prefix count)
                 (unless (string= prefix "$AMESV")
                   (setf (gethash prefix (name-table-counts new)) count)))
               (name-table-counts old)))
    (setf (bridge-names bridge) new))
  (setf (bridge-cache bridge) (make-cache)
        (bridge-excess-names bridge) (make-hash-table :test 'equal))
  bridge)

(defun bridge-alive-p (bridge)
  "True when BRIDGE has a running Maxima process."
  (let ((process (bridge-process bridge)))
    (and process (sb-ext:process-alive-p process) t)))

(defun bridge-process-id (bridge)
  "The pid of BRIDGE's Maxima process (the GCL binary itself), or NIL when none runs."
  (and (bridge-alive-p bridge) (sb-ext:process-pid (bridge-process bridge))))

(defun now ()
  "Wall-clock seconds, as a double-float."
  (/ (get-internal-real-time) (coerce internal-time-units-per-second 'double-float)))

;;; The process

(defun discard-process (bridge)
  "Forget BRIDGE's process, ending it with SIGKILL when it still runs, and reap it."
  (let ((process (bridge-process bridge)))
    (setf (bridge-process bridge) nil
          (bridge-greeted bridge) nil
          (fill-pointer (bridge-buffer bridge)) 0
          (bridge-scanned bridge) 0)
    (when process
      (when (sb-ext:process-alive-p process)
        (sb-ext:process-kill process +sigkill+))
      ;; SIGKILL ends it at once; waiting reaps it, so that no zombie stays behind.
      (sb-ext:process-wait process)
      (sb-ext:process-close process))))

(defun close-bridge (bridge)
  "Stop BRIDGE's Maxima process, if any. The bridge stays usable: the next request
starts a new process and replays the active assumptions. Returns BRIDGE."
  (let ((process (bridge-process bridge)))
    (when process
      (when (sb-ext:process-alive-p process)
        ;; End of input makes the server leave Maxima; wait a moment, then insist.
        (close (sb-ext:process-input process) :abort t)
        (let ((deadline (+ (now) 1)))
          (loop while (and (sb-ext:process-alive-p process) (< (now) deadline))
                do (sleep 0.01))))
      (discard-process bridge)))
  bridge)

(define-condition server-gone (error) ()
  (:documentation "Internal: the pipe to Maxima closed (the process ended)."))

(defun spawn-process (bridge)
  "Start a Maxima process for BRIDGE, without waiting for it (see GREET-PROCESS).
Signals MAXIMA-PROCESS-DIED when Maxima cannot be started."
  (let ((process
          (handler-case
              (sb-ext:run-program (bridge-program bridge)
                                  (list "--very-quiet" "--init=ames-bridge-no-init"
                                        "-p" (namestring (truename (server-file-to-load))))
                                  :search t :wait nil :input :stream :output :stream
                                  :error :output :external-format :latin-1)
            (error (c)
              (error 'maxima-process-died
                     :datum (bridge-program bridge)
                     :detail (format nil "cannot start ~A: ~A" (bridge-program bridge) c))))))
    (unless (and process (sb-ext:process-alive-p process))
      (error 'maxima-process-died :datum (bridge-program bridge)
                                  :detail "Maxima exited at once"))
    (incf (statistics-restarts (bridge-statistics-record bridge)))
    (setf (bridge-process bridge) process
          (fill-pointer (bridge-buffer bridge)) 0
          (bridge-scanned bridge) 0
          (bridge-nonce bridge) (random (expt 2 60) (make-random-state t)))
    (setf (bridge-frame-begin bridge) (format nil "@AMES~D@BEGIN" (bridge-nonce bridge))
          (bridge-frame-end bridge) (format nil "@AMES~D@END" (bridge-nonce bridge))
          (bridge-greeted bridge) nil)
    process))

(defun greet-process (bridge)
  "Greet BRIDGE's freshly started process (it answers once Maxima has loaded the server)
and replay the assumption frames. Signals MAXIMA-PROCESS-DIED when it does not greet."
  (let ((process (bridge-process bridge)))
    (multiple-value-bind (status data)
        (round-trip bridge (list :hello (bridge-nonce bridge)))
      (unless (eq status :ok)
        (discard-process bridge)
        (error 'maxima-process-died :datum (bridge-program bridge)
                                    :detail (format nil "Maxima did not greet: ~S ~S" status data))))
    (replay-assumptions bridge)
    (setf (bridge-greeted bridge) t)
    process))

(defun ensure-process (bridge)
  "Make sure BRIDGE has a live, greeted Maxima process (starting one, replaying its
set-up; a process started ahead by PRESTART-BRIDGE is greeted now)."
  (unless (bridge-alive-p bridge)
    (when (bridge-process bridge) (discard-process bridge))
    (spawn-process bridge))
  (unless (bridge-greeted bridge)
    (greet-process bridge)))

(defun prestart-bridge (bridge)
  "Start BRIDGE's Maxima now, without waiting for it, when none runs: it loads while the
caller reads its scenarios (a cold command-line run), and the first request greets it.
A failure is not signalled here: the first request starts it again and says why.
Returns BRIDGE."
  (unless (bridge-alive-p bridge)
    (handler-case (progn (when (bridge-process bridge) (discard-process bridge))
                         (spawn-process bridge))
      (error () (ignore-errors (discard-process bridge)))))
  bridge)

;;; Requests

(defvar *assumption-ids* (make-cache)
  "The facts in force of every scope seen (lists of the frames' Maxima facts), each to a
number of its own: two scopes with the same facts have the same number. Never emptied,
so a number always stands for the same facts.")

(defvar *assumption-key-memo* nil
  "(BRIDGE FRAMES . NUMBER): the last ASSUMPTION-KEY given, and for which frames.")

(defun assumption-key (bridge)
  "What the answer to a request may depend on besides the request: the facts in force,
as the number *ASSUMPTION-IDS* gives them (the same facts, the same number), so that a
cache key holds the facts without being hashed and compared over all of them each time."
  (let ((frames (bridge-frames bridge))
        (memo *assumption-key-memo*))
    (if (and memo (eq (first memo) bridge) (eq (second memo) frames))
        (cddr memo)
        (let* ((facts (mapcar #'assumption-frame-maxima-facts frames))
               (id (or (gethash facts *assumption-ids*)
                       (setf (gethash facts *assumption-ids*) (hash-table-count *assumption-ids*)))))
          (setf *assumption-key-memo* (list* bridge frames id))
          id))))

(defun unmangle-text (bridge text)
  "TEXT (printed by Maxima) with each mangled name replaced by the AMES name it stands for."
  (cl-ppcre:regex-replace-all
   "(?i)\\$?ames([vx][a-z]+)" text
   (lambda (match letters)
     (multiple-value-bind (name found)
         (user-name (bridge-names bridge) (wire (concatenate 'string "$AMES" (string-upcase letters))))
       (if found (let ((*print-case* :downcase)) (prin1-to-string name)) match)))
   :simple-calls t))

(defun question-condition (bridge parts datum)
  "The MAXIMA-QUESTION for the question PARTS (strings and Maxima forms)."
  (let ((expressions '()))
    (flet ((render (part)
             (if (stringp part)
                 part
                 (handler-case (let ((expression (from-maxima (bridge-names bridge) part)))
                                 (push expression expressions)
                                 (let ((*print-case* :downcase)) (prin1-to-string expression)))
                   (untranslatable-result () (unmangle-text bridge (prin1-to-string part)))))))
      (let ((text (format nil "~{~A~}" (mapcar #'render parts))))
        (make-condition 'maxima-question :text text :expressions (nreverse expressions)
                                         :datum datum)))))

(defun signal-out-of-time (datum)
  "Signal MAXIMA-BUDGET-EXCEEDED: the run's time is up, DATUM was being asked."
  (error 'maxima-budget-exceeded
         :quantity :time :limit (current-time-limit) :datum datum
         :subject (and *budget* (budget-subject *budget*))
         :detail "Maxima was answering a request"))

(defun maxima-request (bridge form &key (cache t) datum)
  "Evaluate the Maxima FORM (built by the bridge's translation) in BRIDGE's Maxima and
return Maxima's answer as a wire form. Identical requests under identical assumptions
are answered from the cache when CACHE is true. DATUM (prefix algebra) names what the
request is about in conditions. A request waits at most the configured timeout, and no
longer than the time left in the budget of the run in progress (see REQUEST-TIMEOUT).
Signals MAXIMA-ERROR, MAXIMA-QUESTION (restart ASSUME-AND-RETRY), MAXIMA-TIMEOUT,
MAXIMA-BUDGET-EXCEEDED (the run's time is up, before or during the request),
MAXIMA-OUTPUT-OVERFLOW or MAXIMA-PROCESS-DIED."
  (let* ((record (bridge-statistics-record bridge))
         (key (and cache (request-key bridge form))))
    (incf (statistics-calls record))
    (multiple-value-bind (answer found) (and key (known-answer bridge form key))
      (when found
        (incf (statistics-cache-hits record))
        (return-from maxima-request answer)))
    (multiple-value-bind (timeout budget-bound) (request-timeout bridge)
      (when (and budget-bound (<= timeout 0)) (signal-out-of-time datum))
      (multiple-value-bind (status data) (request-with-restart bridge form datum timeout)
        (ecase status
          (:ok (let ((answer (first data))
                     (cache (bridge-cache bridge)))
                 (when key
                   (when (>= (hash-table-count cache) *cache-limit*) (clrhash cache))
                   (setf (gethash key cache) answer))
                 answer))
          (:timeout
           (if budget-bound
               (signal-out-of-time datum)
               (error 'maxima-timeout :seconds timeout :datum datum
                                      :detail "the computation was interrupted")))
          (:interrupted
           (incf (statistics-errors record))
           (error 'maxima-error :datum datum :message "interrupted"
                                :detail "the computation was interrupted from outside"))
          ((:error :lisp-error)
           (incf (statistics-errors record))
           (error 'maxima-error :datum datum :message (unmangle-text bridge (first data))))
          (:rejected
           (incf (statistics-errors record))
           (error 'maxima-error :datum datum :message (first data)
                                :detail "the server refused a request of the bridge"))
          (:question
           (incf (statistics-questions record))
           (let ((condition (question-condition bridge data datum)))
             (restart-case (error condition)
               (assume-and-retry (facts)
                 :report "Assume some facts and ask again."
                 :interactive (lambda ()
                                (format *query-io* "~&Facts (a list of relations): ")
                                (finish-output *query-io*)
                                (list (let ((*read-eval* nil)) (read *query-io*))))
                 (call-with-assumptions bridge facts
                                        (lambda ()
                                          (maxima-request bridge form :cache cache :datum datum))))))))))))

(defun request-with-restart (bridge form datum timeout)
  "Send FORM on a live process, to be answered within TIMEOUT seconds; when the process
turns out to be gone, start a fresh one and try once more. Returns the reply's STATUS
and DATA."
  (flet ((attempt ()
           (ensure-process bridge)
           (open-pending-frames bridge timeout)
           (round-trip bridge (list :eval form) timeout)))
    (handler-case (attempt)
      (server-gone ()
        (discard-process bridge)
        (handler-case (attempt)
          (server-gone ()
            (discard-process bridge)
            (error 'maxima-process-died :datum datum
                                        :detail "Maxima ended twice while answering")))))))

(defun request-list (bridge forms &rest keys)
  "Evaluate the Maxima FORMS in one round trip; return the list of answers."
  (mlist-items (apply #'maxima-request bridge (mlist forms) keys)))
