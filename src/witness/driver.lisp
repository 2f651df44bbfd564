;;;; src/witness/driver.lisp -- running witness/siconos_driver.py and reading its answer.

(in-package #:ames.witness)

(defvar *python* "/usr/bin/python3"
  "The Python that has Siconos (Debian's python3-siconos); the pyenv python3 on PATH has not.")

(defvar *driver-path*
  (merge-pathnames "witness/siconos_driver.py"
                   (asdf:system-source-directory "ames"))
  "The witness's driver script.")

(defvar *siconos-available* :unknown
  "Whether *PYTHON* can import siconos: T, NIL, or :UNKNOWN before the first check.")

(defun siconos-available-p ()
  "True when *PYTHON* exists and can import siconos.kernel (checked once)."
  (when (eq *siconos-available* :unknown)
    (setf *siconos-available*
          (and (probe-file *python*)
               (zerop (nth-value 2 (uiop:run-program (list *python* "-c" "import siconos.kernel")
                                                     :ignore-error-status t
                                                     :output nil :error-output nil))))))
  *siconos-available*)

(defun read-driver-output (text)
  "The s-expression the driver printed in TEXT, read as data (*READ-EVAL* nil, symbols
only keywords; names are strings). What Siconos itself printed before it (a message of
its integrator) is passed over."
  (with-standard-io-syntax
    (let ((*read-eval* nil) (*package* (find-package :keyword))
          (*read-default-float-format* 'double-float))
      (handler-case (read-from-string text t nil :start (or (search "(:status" text :test #'char-equal) 0))
        (error () (list :status :error :message (format nil "unreadable driver output: ~A"
                                                         (subseq text 0 (min 300 (length text))))))))))

(defvar *witness-server* nil
  "The witness's server while WITH-WITNESS-SERVER runs: a WITNESS-SERVER, or :IDLE before
its first model (RUN-WITNESS then starts it); NIL outside (a Python per model).")

(defvar *witness-seconds* 0
  "The real time, in seconds, RUN-WITNESS has spent (make crosscheck's figures).")

(defun run-witness (model &key (timeout 120))
  "Run the driver on MODEL (see SCENARIO-MODEL) and return its answer as a plist:
(:STATUS :OK :EVENTS (...) :END (...)), or :STATUS :UNSUPPORTED / :ERROR with :MESSAGE.
The driver is stopped after TIMEOUT seconds (an :ERROR). Within WITH-WITNESS-SERVER
(server.lisp) the warm server answers instead of a new Python. Adds its time to
*WITNESS-SECONDS*."
  (let ((start (get-internal-real-time)))
    (unwind-protect
         (uiop:with-temporary-file (:pathname path :type "json" :stream stream :direction :output)
           (write-string (model-json model) stream)
           (finish-output stream)
           :close-stream
           (if *witness-server*         ; server.lisp: one warm Python for many models
               (server-answer path timeout)
               (run-driver-process path timeout)))
      (incf *witness-seconds* (/ (- (get-internal-real-time) start)
                                 (float internal-time-units-per-second 1d0))))))

(defun run-driver-process (path timeout)
  "The answer of a new Python running the driver on the model file PATH (killed after
TIMEOUT seconds)."
  (multiple-value-bind (output error-output status)
      (uiop:run-program (list "timeout" (princ-to-string timeout) *python*
                              (namestring *driver-path*) (namestring path))
                        :output :string :error-output :string :ignore-error-status t)
    (if (zerop status)
        (read-driver-output output)
        (list :status :error
              :message (format nil "the driver exited with status ~D: ~A" status
                               (subseq error-output 0 (min 400 (length error-output))))))))

(defun witness-status (answer) (getf answer :status))
(defun witness-events (answer) (getf answer :events))
(defun witness-end (answer) (getf answer :end))
