;;;; src/witness/server.lisp -- the witness kept warm: one Python with Siconos for many models.
;;;;
;;;; make crosscheck simulates hundreds of models; starting Python and importing Siconos and
;;;; numpy for each costs about a third of the witness's time. WITH-WITNESS-SERVER starts
;;;; witness/siconos_server.py once; RUN-WITNESS (driver.lisp) then hands it each model
;;;; (a request line: an id, the model's file, the answer's file) and waits for its line
;;;; "@@done ID", each model under its own time limit. A server that overruns the limit or
;;;; dies is killed and the next model starts a new one: one model's failure loses no other.

(in-package #:ames.witness)

(defvar *server-path*
  (merge-pathnames "witness/siconos_server.py" (asdf:system-source-directory "ames"))
  "The witness's server script.")

(defvar *server-models-limit* 200
  "A server is restarted after this many models (Siconos's objects are not all freed).")

(defstruct (witness-server (:constructor %make-witness-server (process)))
  "A running witness/siconos_server.py: its PROCESS (uiop's process info) and the COUNT of
models it has answered."
  process (count 0))

(defun start-witness-server ()
  "A new witness server process."
  (%make-witness-server
   (uiop:launch-program (list *python* "-u" (namestring *server-path*))
                        :input :stream :output :stream :error-output nil)))

(defun stop-witness-server (server)
  "Stop SERVER's process (closing its input, then killing it) and reap it."
  (when (witness-server-p server)
    (let ((process (witness-server-process server)))
      (ignore-errors (close (uiop:process-info-input process)))
      (when (uiop:process-alive-p process)
        (ignore-errors (uiop:terminate-process process :urgent t)))
      (ignore-errors (uiop:wait-process process))
      (ignore-errors (close (uiop:process-info-output process))))))

(defmacro with-witness-server (() &body body)
  "Run BODY with RUN-WITNESS answered by one warm witness server (started at the first
model, restarted after a failure), stopped when BODY ends."
  `(let ((*witness-server* :idle))
     (unwind-protect (progn ,@body)
       (stop-witness-server *witness-server*))))

(defun await-done (server ident timeout)
  "Wait up to TIMEOUT seconds for SERVER's line \"@@done IDENT\": T when it came, NIL
when the time ran out or the server's output ended."
  (let ((output (uiop:process-info-output (witness-server-process server)))
        (marker (format nil "@@done ~A" ident))
        (deadline (+ (get-internal-real-time) (* timeout internal-time-units-per-second))))
    (loop
      (cond ((> (get-internal-real-time) deadline) (return nil))
            ((listen output)
             (let ((line (read-line output nil :eof)))
               (cond ((eq line :eof) (return nil))
                     ((string= line marker) (return t)))))
            ((not (uiop:process-alive-p (witness-server-process server)))
             (return (and (listen output) (await-done server ident 1))))
            (t (sleep 0.005))))))

(defun server-answer (model-path timeout)
  "The witness's answer for the model file MODEL-PATH from the warm server (started or
restarted as needed), as RUN-WITNESS returns it."
  (when (or (not (witness-server-p *witness-server*))
            (not (uiop:process-alive-p (witness-server-process *witness-server*)))
            (>= (witness-server-count *witness-server*) *server-models-limit*))
    (stop-witness-server *witness-server*)
    (setf *witness-server* (start-witness-server)))
  (let ((server *witness-server*) (ident (random 1000000000)))
    (uiop:with-temporary-file (:pathname answer-path :type "sexp")
      (let ((input (uiop:process-info-input (witness-server-process server))))
        (format input "~D~C~A~C~A~%" ident #\Tab (namestring model-path) #\Tab (namestring answer-path))
        (finish-output input))
      (incf (witness-server-count server))
      (cond ((await-done server ident timeout)
             (read-driver-output (uiop:read-file-string answer-path)))
            (t (stop-witness-server server)
               (setf *witness-server* :idle)
               (list :status :error
                     :message (format nil "the witness's server gave no answer within ~D s" timeout)))))))
