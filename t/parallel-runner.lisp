;;;; t/parallel-runner.lisp -- `make test` in parallel: worker processes take tests from a
;;;; shared queue, the coordinator merges their results into FiveAM's plain closing line.
;;;;
;;;; The coordinator (RUN-AMES-TESTS-IN-PARALLEL, called by t/run.lisp) lists every test under
;;;; ALL-TESTS, longest first by the costs recorded in t/test-costs.sexp, and starts
;;;; AMES_TEST_JOBS worker processes (default: the number of cores plus one, at least 2, at
;;;; most 4). Each worker (t/worker.lisp) loads the compiled system once, keeps its one warm
;;;; Maxima, and answers one test at a time over its standard streams. A worker that dies, or
;;;; that runs one test longer than AMES_TEST_TIMEOUT seconds (default 1200), counts as a
;;;; failed check of that test and is replaced; nothing is ever counted as passed that did
;;;; not report passing. The measured seconds of every test are written to
;;;; build/test-timings.sexp (copy it over t/test-costs.sexp to refresh the schedule).

(in-package #:ames.tests)

(defparameter +result-marker+ "@@AMES-RESULT"
  "The line a worker prints before the form of one test's result.")

(defparameter +ready-marker+ "@@AMES-READY"
  "The line a worker prints once it has loaded the system.")

;;; ------------------------------------------------------------------ the worker side

(defun test-check-counts (results)
  "Passed, failed and skipped check counts of FiveAM RESULTS, as three values."
  (multiple-value-bind (ok failed skipped) (results-status results)
    (declare (ignore ok))
    (values (- (length results) (length failed) (length skipped))
            (length failed) (length skipped))))

(defun run-one-test (name)
  "Run the FiveAM test NAME with its output captured; return the plist
(:name :passed :failed :skipped :seconds :details), DETAILS explaining any failure."
  (let ((start (get-internal-real-time))
        (captured (make-string-output-stream))
        (results '()))
    (unless (get-test name)
      (return-from run-one-test
        (list :name name :passed 0 :failed 1 :skipped 0 :seconds 0
              :details (format nil "~A: no such test in the worker" name))))
    (handler-case
        (let ((*standard-output* captured) (*test-dribble* captured))
          (setf results (run name)))
      (serious-condition (condition)
        (return-from run-one-test
          (list :name name :passed 0 :failed 1 :skipped 0 :seconds (seconds-since start)
                :details (format nil "~A: ~A" (type-of condition) condition)))))
    (multiple-value-bind (passed failed skipped) (test-check-counts results)
      (list :name name :passed passed :failed failed :skipped skipped
            :seconds (seconds-since start)
            :details (if (zerop failed)
                         ""
                         (with-output-to-string (stream)
                           (explain (make-instance 'it.bese.fiveam::detailed-text-explainer)
                                    results stream)))))))

(defun serve-tests (&key (input *standard-input*) (output *standard-output*))
  "The worker's loop: print the ready line, then for each test name read from INPUT run the
test and print the result marker and its result form on OUTPUT, until end of file."
  (format output "~A~%" +ready-marker+)
  (finish-output output)
  (let ((*read-eval* nil))
    (loop for line = (read-line input nil nil)
          while line
          unless (string= (string-trim " " line) "")
            do (let ((result (run-one-test (read-from-string line))))
                 (with-standard-io-syntax
                   (let ((*package* (find-package :keyword)))
                     (format output "~A~%~S~%" +result-marker+ result)))
                 (finish-output output)))))

;;; ------------------------------------------------------------------ the test list

(defun suite-leaf-tests (suite-name)
  "Every test case under the suite (or test) SUITE-NAME, depth first, as names."
  (let ((suite (get-test suite-name)) (names '()))
    (labels ((walk (object)
               (etypecase object
                 (null (error "No test or suite named ~S." suite-name))
                 (symbol (walk (get-test object)))
                 (it.bese.fiveam::test-suite
                  (loop for child being the hash-values of (it.bese.fiveam::tests object)
                        do (walk child)))
                 (it.bese.fiveam::test-case
                  (push (it.bese.fiveam::name object) names)))))
      (walk suite))
    (nreverse names)))

(defun test-costs-file ()
  "The committed schedule of test costs, t/test-costs.sexp."
  (asdf:system-relative-pathname "ames" "t/test-costs.sexp"))

(defun read-test-costs (path)
  "An EQUAL hash table from test name strings to recorded seconds, from the alist at PATH
(empty when PATH does not exist or cannot be read)."
  (let ((table (make-hash-table :test #'equal)))
    (ignore-errors
     (with-open-file (stream path :if-does-not-exist nil)
       (when stream
         (let ((*read-eval* nil) (*package* (find-package :ames.tests)))
           (loop for (name . seconds) in (read stream nil '())
                 do (setf (gethash (string name) table) seconds))))))
    table))

(defun scheduled-tests (&optional (suite 'all-tests))
  "The tests under SUITE (a suite or test name, or a list of them), longest recorded cost
first; unrecorded tests (new ones) are taken as 10 s."
  (let ((costs (read-test-costs (test-costs-file))))
    (stable-sort (remove-duplicates (mapcan #'suite-leaf-tests (alexandria:ensure-list suite))
                                    :from-end t)
                 #'>
                 :key (lambda (name) (gethash (symbol-name name) costs 10)))))

;;; ------------------------------------------------------------------ the coordinator side

(defstruct (worker (:constructor %make-worker))
  "A worker process, the test it is running (or NIL) and when that test started."
  process index log test started ready)

(defun worker-count ()
  "AMES_TEST_JOBS, or the number of cores plus one, between 2 and 4."
  (let ((given (uiop:getenv "AMES_TEST_JOBS")))
    (or (and given (parse-integer given :junk-allowed t))
        (let ((cores (or (ignore-errors
                          (parse-integer (uiop:run-program '("nproc") :output :string)
                                         :junk-allowed t))
                         2)))
          (max 2 (min 4 (1+ cores)))))))

(defun test-timeout ()
  "AMES_TEST_TIMEOUT in seconds (default 1200): the longest one test may run in a worker."
  (let ((given (uiop:getenv "AMES_TEST_TIMEOUT")))
    (or (and given (parse-integer given :junk-allowed t)) 1200)))

(defun start-worker (index)
  "Start worker process INDEX running t/worker.lisp, its errors logged under build/."
  (let ((log (asdf:system-relative-pathname "ames" (format nil "build/test-worker-~D.log" index))))
    (ensure-directories-exist log)
    (%make-worker
     :index index :log log :started (get-internal-real-time)
     :process (uiop:launch-program
               (list (or (uiop:getenv "SBCL") "sbcl") "--noinform" "--non-interactive"
                     "--no-sysinit" "--no-userinit" "--load"
                     (namestring (asdf:system-relative-pathname "ames" "t/worker.lisp")))
               :input :stream :output :stream
               :error-output (namestring log) :if-error-output-exists :supersede))))

(defun worker-alive-p (worker)
  "True while WORKER's process runs."
  (uiop:process-alive-p (worker-process worker)))

(defun stop-worker (worker)
  "Kill WORKER's process and close its streams."
  (ignore-errors (uiop:terminate-process (worker-process worker) :urgent t))
  (ignore-errors (uiop:wait-process (worker-process worker)))
  (ignore-errors (uiop:close-streams (worker-process worker))))

(defun log-tail (path &optional (lines 15))
  "The last LINES lines of the file at PATH, as one string."
  (let ((all (ignore-errors (uiop:read-file-lines path))))
    (format nil "~{    ~A~%~}" (last all lines))))

(defun lost-test-result (worker why)
  "The result of the test WORKER was running when it was lost: one failed check."
  (list :name (worker-test worker) :passed 0 :failed 1 :skipped 0
        :seconds (seconds-since (worker-started worker))
        :details (format nil "~&~A: worker ~D ~A while running it; the end of its log:~%~A"
                         (worker-test worker) (worker-index worker) why
                         (log-tail (worker-log worker)))))
;;; The coordinator loop

(defun read-worker-lines (worker on-result)
  "Take every complete message WORKER has written so far: the ready line marks it ready, a
result is passed to ON-RESULT and frees the worker. Other lines are ignored."
  (let ((stream (uiop:process-info-output (worker-process worker)))
        (*read-eval* nil))
    (loop while (ignore-errors (listen stream))
          do (let ((line (read-line stream nil nil)))
               (cond ((null line) (return))
                     ((string= line +ready-marker+) (setf (worker-ready worker) t))
                     ((string= line +result-marker+)
                      (let ((result (read stream nil nil)))
                        (when result
                          (funcall on-result result)
                          (setf (worker-test worker) nil)))))))))

(defun give-test (worker name)
  "Send the test NAME to WORKER."
  (let ((stream (uiop:process-info-input (worker-process worker))))
    (with-standard-io-syntax
      (let ((*package* (find-package :keyword)))
        (format stream "~S~%" name)))
    (finish-output stream)
    (setf (worker-test worker) name
          (worker-started worker) (get-internal-real-time))))

(defun worker-lost-p (worker timeout)
  "Why WORKER must be replaced (a string), or NIL: its process ended, its test has run
longer than TIMEOUT seconds, or it has not loaded the system after 600 s."
  (cond ((not (worker-alive-p worker))
         (format nil "ended (exit code ~A)"
                 (ignore-errors (uiop:wait-process (worker-process worker)))))
        ((and (worker-test worker) (> (seconds-since (worker-started worker)) timeout))
         (format nil "ran out of time (~D s)" timeout))
        ((and (not (worker-ready worker)) (> (seconds-since (worker-started worker)) 600))
         "did not load the system within 600 s")))

(defun run-test-queue (tests jobs &key (timeout (test-timeout)) (on-result #'identity))
  "Run the test names TESTS on JOBS worker processes; call ON-RESULT with each result plist
as it arrives, lost tests included. Workers that end are replaced while tests remain; when
workers keep dying before taking a test, the tests left count as failed, never as run."
  (let ((queue (copy-list tests))
        (workers (loop for i below jobs collect (start-worker i)))
        (restarts 0))
    (unwind-protect
         (loop while (or queue (some #'worker-test workers))
               do (dolist (worker workers)
                    (read-worker-lines worker on-result)
                    (let ((why (worker-lost-p worker timeout)))
                      (when why (read-worker-lines worker on-result)) ; its last words
                      (cond (why
                             (when (worker-test worker)
                               (funcall on-result (lost-test-result worker why)))
                             (unless (worker-ready worker) (incf restarts))
                             (stop-worker worker)
                             (when (> restarts (* 2 jobs))
                               (dolist (name queue)
                                 (funcall on-result
                                          (list :name name :passed 0 :failed 1 :skipped 0
                                                :seconds 0
                                                :details (format nil "~A: not run, the test ~
workers could not start; see ~A~%~A" name (worker-log worker) (log-tail (worker-log worker))))))
                               (setf queue '()))
                             (let ((fresh (start-worker (worker-index worker))))
                               (setf (worker-process worker) (worker-process fresh)
                                     (worker-started worker) (worker-started fresh)
                                     (worker-test worker) nil (worker-ready worker) nil)))
                            ((and queue (worker-ready worker) (null (worker-test worker)))
                             (give-test worker (pop queue))))))
                  (sleep 0.05))
      (mapc #'stop-worker workers))))

(defun write-test-timings (results)
  "Write the seconds of every result to build/test-timings.sexp, longest first."
  (let ((path (asdf:system-relative-pathname "ames" "build/test-timings.sexp")))
    (ensure-directories-exist path)
    (with-open-file (stream path :direction :output :if-exists :supersede)
      (with-standard-io-syntax
        (let ((*package* (find-package :ames.tests)))
          (format stream "(~{~S~^~% ~})~%"
                  (mapcar (lambda (r) (cons (getf r :name) (/ (round (getf r :seconds) 0.01) 100.0)))
                          (sort (copy-list results) #'> :key (lambda (r) (getf r :seconds))))))))))

(defun tests-from-environment ()
  "The suites and tests AMES_TESTS names (separated by commas or spaces, as in
AMES_TESTS=simulator,cli), or ALL-TESTS."
  (let ((given (uiop:getenv "AMES_TESTS")))
    (if (and given (string/= (string-trim " ," given) ""))
        (mapcar (lambda (name) (intern (string-upcase name) '#:ames.tests))
                (remove "" (uiop:split-string given :separator ", ") :test #'string=))
        'all-tests)))

(defun run-ames-tests-in-parallel (&key (exit t) (suite (tests-from-environment))
                                        (jobs (worker-count)))
  "Run every test under SUITE (see SCHEDULED-TESTS; by default what AMES_TESTS names, or
every suite) on JOBS worker processes; print a line per test as it ends (with the
explanation of a failure), the failed tests' names, the slowest tests, the skipped count
(when any) and the plain closing line 'N passed, N failed'. With EXIT, quit with 0 when nothing failed, 1 otherwise;
otherwise return the passed and failed counts."
  (let* ((tests (scheduled-tests suite))
         (start (get-internal-real-time))
         (results '()) (done 0))
    (format t "~&Running ~D tests on ~D worker processes.~%" (length tests) jobs)
    (finish-output)
    (run-test-queue tests jobs
                    :on-result (lambda (result)
                                 (push result results)
                                 (format t "~&[~D/~D] ~A ~,1F s~:[~; FAILED~]~%" (incf done)
                                         (length tests) (getf result :name) (getf result :seconds)
                                         (plusp (getf result :failed)))
                                 ;; a failure is explained at once (a run cut short keeps it)
                                 (when (plusp (getf result :failed))
                                   (format t "~A~%" (getf result :details)))
                                 (finish-output)))
    ;; every test must have reported; one that did not is a failure
    (dolist (name (set-difference tests (mapcar (lambda (r) (getf r :name)) results)))
      (push (list :name name :passed 0 :failed 1 :skipped 0 :seconds 0
                  :details (format nil "~A: never reported a result" name))
            results))
    (write-test-timings results)
    (print-parallel-summary results (seconds-since start) exit)))

(defun print-parallel-summary (results wall exit)
  "Print the failures, timing figures and closing line of RESULTS; quit when EXIT."
  (let ((passed (reduce #'+ results :key (lambda (r) (getf r :passed))))
        (failed (reduce #'+ results :key (lambda (r) (getf r :failed))))
        (skipped (reduce #'+ results :key (lambda (r) (getf r :skipped))))
        (slowest (subseq (sort (copy-list results) #'> :key (lambda (r) (getf r :seconds)))
                         0 (min 10 (length results)))))
    (let ((failing (remove-if-not (lambda (r) (plusp (getf r :failed))) results)))
      (when failing
        (format t "~&~%Failed (explained above, as each ended):~%~{  ~A~%~}"
                (mapcar (lambda (r) (getf r :name)) (reverse failing)))))
    (format t "~&~%Wall time ~,1F s; the tests' own time adds up to ~,1F s. Slowest:~%~
               ~:{  ~6,1F s  ~A~%~}"
            wall (reduce #'+ results :key (lambda (r) (getf r :seconds)))
            (mapcar (lambda (r) (list (getf r :seconds) (getf r :name))) slowest))
    (when (plusp skipped)
      (format t "~&~D skipped~%" skipped))
    (format t "~&~D passed, ~D failed~%" passed failed)
    (finish-output)
    (if exit
        (uiop:quit (if (zerop failed) 0 1))
        (values passed failed))))
