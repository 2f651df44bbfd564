;;;; t/cli.lisp -- tests of the command line: arguments, numbers, exit codes, the sexp report.

(in-package #:ames.tests)

(def-suite cli :in all-tests :description "bin/ames and the reports it prints.")

(in-suite cli)

(test decimals-are-read-exactly-without-the-lisp-reader
  (is (eql 981/100 (ames::parse-decimal "9.81")))
  (is (eql -3 (ames::parse-decimal "-3")))
  (is (eql 1/1000 (ames::parse-decimal "1e-3")))
  (is (eql 250 (ames::parse-decimal "2.5E2")))
  (is (eql 981/100 (ames::parse-decimal "981/100")))
  (is (eql 1/2 (ames::parse-decimal ".5")))
  (dolist (bad '("" "." "abc" "1.2.3" "1/0" "#.(quit)" "1e" "--3" "1/2/3" "9,81"))
    (is (null (ames::parse-decimal bad)) "~S should not be a number" bad)))

(test command-lines-that-are-malformed-are-usage-errors
  (dolist (arguments '(() ("frobnicate") ("run") ("run" "--format") ("run" "x.lisp" "--format" "xml")
                       ("run" "x.lisp" "--set") ("run" "x.lisp" "--set" "g")
                       ("run" "x.lisp" "--set" "g=abc") ("run" "x.lisp" "--verbose")))
    (let ((condition (handler-case (ames::parse-command-line arguments)
                       (ames-error (c) c))))
      (is (typep condition 'ames:usage-error) "~S gave ~S" arguments condition)))
  (let ((options (ames::parse-command-line
                  '("run" "a.lisp" "b.lisp" "--format" "sexp" "--set" "g=9.81" "h=1/2"))))
    (is (equal '("a.lisp" "b.lisp") (getf options :files)))
    (is (eq :sexp (getf options :format)))
    (is (equal '(("g" . 981/100) ("h" . 1/2)) (getf options :settings)))))

(defun write-temporary-scenarios (text)
  "Write TEXT to a fresh temporary scenario file and return its pathname."
  (let ((path (uiop:tmpize-pathname (merge-pathnames "ames-cli-test.lisp" (uiop:temporary-directory)))))
    (with-open-file (out path :direction :output :if-exists :supersede)
      (write-string text out))
    path))

(defparameter *one-bad-one-good*
  "(scenario broken \"No velocity.\"
     (parameters (m :positive))
     (body b :mass m :position (0 0) :shape point))
   (scenario drop \"A ball dropped from height h.\"
     (parameters (m :positive) (g :positive) (h :positive))
     (gravity g)
     (body floor :fixed t :shape (half-plane (1 0) (0 0)))
     (body ball :mass m :position (0 h) :velocity (0 0) :shape point))"
  "A scenario file whose first scenario is defective and whose second is fine.")

(test a-bad-scenario-does-not-stop-the-others-and-sets-the-status
  (with-fixture simulator-bridge ()
    (let* ((path (write-temporary-scenarios *one-bad-one-good*))
           (errors (make-string-output-stream))
           (output (make-string-output-stream))
           (status (let ((*error-output* errors))
                     (unwind-protect
                          (ames:run-files (list (namestring path)) :format :sexp
                                                                   :stream output :bridge bridge)
                       (delete-file path)))))
      (is (eql 1 status))
      (is (search "BROKEN" (string-upcase (get-output-stream-string errors))))
      ;; the good scenario's report reads back as data, and says what physics says
      (let* ((report (let ((*read-eval* nil) (*package* (find-package '#:ames-scenario)))
                       (read-from-string (get-output-stream-string output))))
             (state (first (getf report :states)))
             (duration (getf state :duration))
             (velocity (second (second (assoc "BALL" (getf state :final-velocities)
                                              :key #'symbol-name :test #'string=)))))
        (is (string= "DROP" (symbol-name (getf report :scenario))))
        (is (eq :complete (getf report :outcome)) "the ball lands and rests")
        (flet ((p (name) (find-symbol name '#:ames-scenario)))
          (ames.maxima:with-assumptions (bridge `((> ,(p "G") 0) (> ,(p "H") 0)))
            (is (ames.maxima:equivalent-p bridge duration `(sqrt (/ (* 2 ,(p "H")) ,(p "G")))))
            (is (ames.maxima:equivalent-p bridge velocity
                                          `(- (sqrt (* 2 ,(p "G") ,(p "H"))))))))))))

(defun run-bin-ames (&rest arguments)
  "Run the checkout's bin/ames with ARGUMENTS; return its exit code and its output."
  (let ((program (namestring (merge-pathnames "bin/ames" (asdf:system-source-directory "ames")))))
    (multiple-value-bind (output error-output code)
        (uiop:run-program (cons program arguments) :output :string :error-output :string
                                                   :ignore-error-status t)
      (values code (concatenate 'string output error-output)))))

(test bin-ames-exit-codes
  "0 for success, 1 for a scenario error, 2 for usage (the image is built on first use)."
  (is (eql 2 (run-bin-ames)))
  (is (eql 2 (run-bin-ames "run" "--format" "xml" "x.lisp")))
  (let ((path (write-temporary-scenarios *one-bad-one-good*)))
    (unwind-protect
         (multiple-value-bind (code output) (run-bin-ames "run" (namestring path))
           (is (eql 1 code))
           (is (search "drop" output)))
      (delete-file path)))
  (multiple-value-bind (code output)
      (run-bin-ames "run" (namestring (merge-pathnames "scenarios/particle-under-plane.lisp"
                                                        (asdf:system-source-directory "ames")))
                    "--set" "g=9.81" "m=1")
    (is (eql 0 code))
    (is (search "contacts: none" output))
    (is (search "a_y = -g = -9.81" output))))
