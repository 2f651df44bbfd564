;;;; src/interface/jobs.lisp -- bin/ames run --jobs N FILE...: scenario files in parallel processes.
;;;;
;;;; Each file is run by a process of its own (the same bin/ames image, so each has its own
;;;; Maxima), at most N at a time. Their reports are printed in the order of the files on
;;;; the command line, each as soon as it and every file before it have finished; what a
;;;; child writes on its standard error goes to ours, in the same order. The exit code is
;;;; the worst of the children's (see WORSE-STATUS: 0 success, 3 undecided, 5 a failed
;;;; self-check, 1 a scenario error; a child that could not be run or died counts as 1 at
;;;; least). The unit of work is a file: scenarios meant to run
;;;; side by side go in files of their own.
;;;;
;;;; The formats that concatenate (text, sexp, json, latex) can be split this way; the
;;;; HTML page and the --svg pictures are one output for the whole run, so --jobs refuses
;;;; them. Across several machines, run one bin/ames per file with an existing tool (GNU
;;;; parallel --keep-order over ssh, or a batch system's job array): see README.md.

(in-package #:ames)

(defun jobs-option (arguments)
  "Take --jobs N out of ARGUMENTS (strings): (values N OTHER-ARGUMENTS), N NIL when the
option is absent. Signals USAGE-ERROR when N is not a positive integer or the option is
given twice."
  (let ((jobs nil) (others '()))
    (loop while arguments
          do (let ((argument (pop arguments)))
               (if (string= argument "--jobs")
                   (let* ((text (pop arguments))
                          (value (and text (every #'digit-char-p text) (plusp (length text))
                                      (parse-integer text))))
                     (when jobs
                       (error 'usage-error :datum argument :detail "--jobs is given twice"))
                     (unless (and value (plusp value))
                       (error 'usage-error :datum (or text argument)
                                           :detail "--jobs takes a positive number of processes"))
                     (setf jobs value))
                   (push argument others))))
    (values jobs (nreverse others))))

(defun child-arguments (file options)
  "The command line of the child process that runs FILE with the OPTIONS parsed from
ours (the plist of PARSE-COMMAND-LINE): run FILE, its format, its settings, --numeric,
the limits and --verbose."
  (flet ((seconds (option key)
           (let ((value (getf options key)))
             (when value (list option (format nil "~A" value))))))
    (append (list "run" file "--format" (string-downcase (getf options :format)))
            (when (getf options :numeric) (list "--numeric"))
            (when (getf options :all-branches) (list "--all-branches"))
            (seconds "--time-limit" :time-limit)
            (seconds "--maxima-timeout" :maxima-timeout)
            (when (getf options :verbose) (list "--verbose"))
            (when (getf options :no-check) (list "--no-check"))
            (when (getf options :settings)
              (cons "--set" (loop for (name . value) in (getf options :settings)
                                  collect (format nil "~A=~A" name value)))))))

(defun worse-status (a b)
  "The worse of the exit statuses A and B: a usage error (2), then a scenario error (1,
or any status AMES does not use: a crashed child), then a failed self-check (5), then an
undecided run (3), then 0."
  (flet ((rank (status)
           (case status (0 0) (3 1) (5 2) (2 4) (t 3))))
    (if (> (rank b) (rank a)) b a)))

(defun check-jobs-options (options)
  "Signal USAGE-ERROR when OPTIONS ask for an output that is one for the whole run."
  (when (eq (getf options :format) :html)
    (error 'usage-error :datum "--format html"
                        :detail "--jobs cannot split one HTML page; use text, sexp, json or latex"))
  (when (getf options :svg)
    (error 'usage-error :datum "--svg" :detail "--jobs cannot draw one picture set; run without --jobs"))
  (when (getf options :standalone)
    (error 'usage-error :datum "--standalone" :detail "--jobs cannot write one LaTeX document; run without --jobs")))

(defstruct (job (:constructor make-job (file)))
  "One file's run: its FILE, the PROCESS, the temporary files holding its OUTPUT and
ERRORS, and its exit STATUS once it has finished."
  file process output errors status)

(defun start-job (job program options)
  "Start JOB's child process: PROGRAM (the bin/ames image) on JOB's file."
  (let ((output (uiop:tmpize-pathname (merge-pathnames "ames-job-out" (uiop:temporary-directory))))
        (errors (uiop:tmpize-pathname (merge-pathnames "ames-job-err" (uiop:temporary-directory)))))
    (setf (job-output job) output (job-errors job) errors)
    (handler-case
        (setf (job-process job)
              (sb-ext:run-program program (child-arguments (job-file job) options)
                                  :wait nil :search nil :input nil
                                  :environment (cons (format nil "~A=~D" *job-parent-variable*
                                                             (sb-unix:unix-getpid))
                                                     (remove-if (lambda (entry)
                                                                  (eql 0 (search *job-parent-variable* entry)))
                                                                (sb-ext:posix-environ)))
                                  :output output :if-output-exists :supersede
                                  :error errors :if-error-exists :supersede))
      (error (condition)
        ;; the program could not be started: the job fails, the others go on
        (with-open-file (stream errors :direction :output :if-exists :supersede)
          (format stream "ames: cannot run ~A: ~A~%" program condition))
        (setf (job-status job) 1)))))

(defun job-finished-p (job)
  "True when JOB's process has ended (its STATUS then set)."
  (or (job-status job)
      (let ((process (job-process job)))
        (unless (sb-ext:process-alive-p process)
          (setf (job-status job)
                (let ((code (sb-ext:process-exit-code process)))
                  (if (and (eq (sb-ext:process-status process) :exited) code)
                      code
                      (max 1 (or code 1)))))
          (sb-ext:process-close process)
          t))))

(defun stop-jobs (jobs)
  "Send SIGTERM to the process of each of JOBS still running (each then stops its
Maxima and prints its finished states), wait up to 10 s for them, then kill those left."
  (let ((processes (loop for job in jobs
                         for process = (job-process job)
                         when (and process (sb-ext:process-alive-p process))
                           collect process)))
    (dolist (process processes)
      (ignore-errors (sb-ext:process-kill process 15)))
    (let ((deadline (+ (get-internal-real-time) (* 10 internal-time-units-per-second))))
      (loop while (and (some #'sb-ext:process-alive-p processes)
                       (< (get-internal-real-time) deadline))
            do (sleep 0.02)))
    (dolist (process processes)
      (when (sb-ext:process-alive-p process)
        (ignore-errors (sb-ext:process-kill process 9))
        (ignore-errors (sb-ext:process-wait process))))))

(defun copy-file-to-stream (path stream &key skip)
  "Write the contents of the file PATH to STREAM, and delete it; with SKIP (a string),
leave out the lines that begin with it."
  (when (and path (probe-file path))
    (with-open-file (in path :external-format :utf-8)
      (if skip
          (loop for line = (read-line in nil)
                while line
                unless (eql 0 (search skip line))
                  do (write-line line stream))
          (let ((buffer (make-string 8192)))
            (loop for count = (read-sequence buffer in)
                  while (plusp count)
                  do (write-string buffer stream :end count)))))
    (delete-file path))
  (finish-output stream))

(defun run-jobs (jobs options &key (program sb-ext:*runtime-pathname*)
                                   (stream *standard-output*) (error-stream *error-output*))
  "Run every file of OPTIONS (the plist of PARSE-COMMAND-LINE) in a child process of
PROGRAM, at most JOBS at a time; print each child's report on STREAM and its errors on
ERROR-STREAM in the order of the files. Returns the worst exit status (WORSE-STATUS). Signals
USAGE-ERROR for the options --jobs cannot split (see CHECK-JOBS-OPTIONS)."
  (check-jobs-options options)
  (let* ((queue (mapcar #'make-job (getf options :files)))
         (pending queue)
         (running '())
         (worst 0))
    (loop while (or queue running)
          do (when (and *stop-requested* (or running pending))
               ;; a signal: no new worker; the running ones stop and print what finished
               (setf pending '())
               (stop-jobs running)
               (dolist (job queue) (unless (job-process job) (setf (job-status job) 1))))
             (loop while (and pending (< (length running) jobs))
                   do (let ((job (pop pending)))
                        (start-job job program options)
                        (unless (job-status job) (push job running))))
             (setf running (remove-if #'job-finished-p running))
             ;; print, in order, every finished job at the head of the queue
             (loop while (and queue (job-status (first queue))
                              (not (member (first queue) running)))
                   do (let ((job (pop queue)))
                        (copy-file-to-stream (job-output job) stream)
                        (if *stop-requested*
                            ;; the parent says it once for the whole run
                            (copy-file-to-stream (job-errors job) error-stream
                                                 :skip "ames: stopped by ")
                            (copy-file-to-stream (job-errors job) error-stream))
                        (setf worst (worse-status worst (job-status job)))))
             (when (and running (or queue pending))
               (sleep 0.02)))
    worst))
