;;;; t/scale.lisp -- issue 16: the scale families' textbook results, the structure of the
;;;; compact model's solution, the broad phase's signs, and many scenarios across processes.
;;;;
;;;; The chain and the stack are checked on their files in scenarios/ and on forms built
;;;; here for six blocks (the same shape as the benchmark's families); every force is
;;;; compared with the textbook's by Maxima. Timing is the benchmark's business
;;;; (bench/bench-scale.lisp), never a test's.

(in-package #:ames.tests)

(def-suite scale :in all-tests
  :description "Many bodies: the chain, the stack and independent drops against their
textbook results; block-by-block solving; the broad phase's signs; --jobs and GNU parallel.")

(in-suite scale)

(defun block-form (k x y)
  "The body clause of the unit block Bk of mass mK at (X Y), at rest."
  `(body ,(format nil "B~D" k) :mass ,(format nil "M~D" k) :position (,x ,y) :velocity (0 0)
         :shape (polygon (0 0) (1 0) (1 1) (0 1))))

(defun scale-form (kind n)
  "The scenario form (names as strings, interned into AMES-SCENARIO) of a chain of N
blocks pushed by f into a wall (KIND :CHAIN) or a stack of N at rest (:STACK)."
  (let ((form `(scenario ,(format nil "~A-~D" kind n)
                 (parameters ,@(loop for k from 1 to n collect `(,(format nil "M~D" k) :positive))
                             ("G" :positive) ("F" :positive))
                 (gravity "G")
                 (body "FLOOR" :fixed t :shape (half-plane (1 0) (0 0)))
                 ,@(ecase kind
                     (:chain `((body "WALL" :fixed t :shape (half-plane (,n 1) (,n 0)))
                               ,@(loop for k from 1 to n collect (block-form k (1- k) 0))
                               (force "PUSH" :on "B1" :value ("F" 0))))
                     (:stack (loop for k from 1 to n collect (block-form k 0 (1- k)))))
                 (simulate :states 2))))
    (labels ((intern-names (x)
               (cond ((stringp x) (intern x '#:ames-scenario))
                     ((consp x) (cons (intern-names (car x)) (intern-names (cdr x))))
                     (t x))))
      (let ((form (intern-names form)))
        ;; the description, a string, goes in after the names are interned
        (ames:parse-scenario (list* (first form) (second form) "Blocks." (cddr form)))))))

(defun check-at-rest-forever (history)
  "Check that HISTORY is one state, at rest, lasting forever."
  (is (eq :complete (ames:history-outcome history)))
  (is (= 1 (length (ames:history-states history))))
  (let ((state (first (ames:history-states history))))
    (is (eq :forever (ames::state-duration state)))
    (dolist (entry (ames::state-accelerations state))
      (is (equal '(0 0) (second entry)) "~A accelerates: ~S" (first entry) (second entry)))))

(defun check-chain (bridge scenario n)
  "The chain of N: each contact force and the wall's reaction f, the floor's mk g."
  (let* ((history (simulate-stopping-when-ambiguous scenario bridge))
         (state (first (ames:history-states history))))
    (check-at-rest-forever history)
    (flet ((x (form) (in-scenario-terms scenario form)))
      (call-with-scenario-facts
       bridge scenario
       (lambda ()
         (loop for k from 1 below n
               do (is-same bridge (format nil "B~D pushes B~D" k (1+ k))
                           (normal-force-between state (format nil "B~D" k) (format nil "B~D" (1+ k)))
                           (x 'f)))
         (is-same bridge "the wall's reaction" (normal-force-between state (format nil "B~D" n) "WALL")
                  (x 'f))
         (loop for k from 1 to n
               do (is-same bridge (format nil "the floor under B~D" k)
                           (normal-force-between state (format nil "B~D" k) "FLOOR")
                           (x `(* ,(intern (format nil "M~D" k) '#:ames-scenario) g)))))))))

(defun check-stack (bridge scenario n)
  "The stack of N: the normal force under block k is g times the masses from k up."
  (let* ((history (simulate-stopping-when-ambiguous scenario bridge))
         (state (first (ames:history-states history))))
    (check-at-rest-forever history)
    (flet ((above (k) (in-scenario-terms
                       scenario `(* g (+ ,@(loop for j from k to n
                                                 collect (intern (format nil "M~D" j) '#:ames-scenario)))))))
      (call-with-scenario-facts
       bridge scenario
       (lambda ()
         (is-same bridge "the floor under B1" (normal-force-between state "B1" "FLOOR") (above 1))
         (loop for k from 2 to n
               do (is-same bridge (format nil "under B~D" k)
                           (or (normal-force-between state (format nil "B~D" (1- k)) (format nil "B~D" k))
                               (normal-force-between state (format nil "B~D" k) (format nil "B~D" (1- k))))
                           (above k))))))))

(test chain-of-blocks-passes-the-push-to-the-wall
  "A chain of touching blocks pushed by f into a wall stays at rest: every contact
force and the wall's reaction are f, the floor carries each block's weight (the file's
four blocks and a chain of six)."
  (with-fixture simulator-bridge ()
    (check-chain bridge (scenario-named "chain-of-four-blocks") 4)
    (check-chain bridge (scale-form :chain 6) 6)))

(test stack-of-blocks-carries-the-weight-above
  "A stack at rest: the normal force under block k is g (mk + ... + mN) (the file's
four blocks and a stack of six)."
  (with-fixture simulator-bridge ()
    (check-stack bridge (scenario-named "stack-of-four-blocks") 4)
    (check-stack bridge (scale-form :stack 6) 6)))

(test blocks-dropped-side-by-side-land-in-turn
  "Three independent blocks land at t = sqrt(4 k / g), each stopped by a plastic impact,
then rest on the floor forever."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scenario-named "blocks-dropped-side-by-side"))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (states (ames:history-states history)))
      (is (eq :complete (ames:history-outcome history)))
      (is (= 4 (length states)))
      (call-with-scenario-facts
       bridge scenario
       (lambda ()
         (loop for k from 1 to 3
               for state in states
               for end = (if (keywordp (ames::state-duration state))
                             nil
                             `(+ ,(ames::state-start state) ,(ames::state-duration state)))
               do (is (equal (list :collision (format nil "B~D" k) "FLOOR")
                             (event-names (ames::state-end-event state))))
                  (is-same bridge (format nil "B~D lands" k) end
                           (in-scenario-terms scenario `(sqrt (/ ,(* 4 k) g)))))
         (let ((last (car (last states))))
           (is (eq :forever (ames::state-duration last)))
           (loop for k from 1 to 3
                 do (is-same bridge (format nil "the floor under B~D" k)
                             (normal-force-between last (format nil "B~D" k) "FLOOR")
                             (in-scenario-terms
                              scenario `(* ,(intern (format nil "M~D" k) '#:ames-scenario) g))))))))))

;;; Solving by structure

(test blocks-of-a-triangular-system-solve-it
  "The block triangular decomposition orders a chain of definitions, finds the 2x2
block, solves block by block what a whole solve gives, and declines a singular system."
  (let* ((equations '((= (+ x y) 3) (= (- x y) 1) (= z (* 2 x)) (= w (+ z y))))
         (unknowns '(w z y x))
         (occurrences (ames.simulator::equation-unknown-indices equations unknowns))
         (owner (ames.simulator::perfect-matching occurrences 4)))
    (is (not (null owner)))
    (let ((blocks (ames.simulator::equation-blocks occurrences owner)))
      (is (equal '((0 1) (2) (3)) blocks) "blocks ~S" blocks))
    (is (null (ames.simulator::perfect-matching
               (ames.simulator::equation-unknown-indices '((= (+ x y) 1) (= (* 2 (+ x y)) 2)) '(x y z))
               3))))
  (with-fixture simulator-bridge ()
    (let* ((scenario (scale-form :chain 2))
           (run (make-instance 'ames.simulator::run :scenario scenario :bridge bridge
                                                    :shapes '() :contacts '()
                                                    :positions '() :velocities '()))
           (equations '((= (* m a) (- f n)) (= (* k a) n) (= p (+ n a))))
           (solution (ames.simulator::solve-by-blocks run equations '(a n p))))
      (is (= 3 (length solution)))
      (is (same-expression-p bridge (cdr (assoc 'a solution)) '(/ f (+ m k))))
      (is (same-expression-p bridge (cdr (assoc 'n solution)) '(/ (* k f) (+ m k))))
      (is (same-expression-p bridge (cdr (assoc 'p solution)) '(/ (+ (* k f) f) (+ m k)))))))

(test the-rules-of-signs-decide-only-what-they-prove
  "The broad phase's sign algebra over declared parameter signs."
  (let ((signs '((m :positive) (g :positive) (e :positive :zero) (d :negative)))
        (unknown '(:positive :negative :zero)))
    (flet ((sign (x) (ames.simulator::sign-algebra signs x))
           (same (a b) (null (set-exclusive-or a b))))
      (is (same '(:positive) (sign '(* g (+ m m)))))
      (is (same '(:negative) (sign '(- (/ (* m g) 2)))))
      (is (same '(:positive) (sign '(- m d))))
      (is (same unknown (sign '(- m g))))
      (is (same '(:positive :zero) (sign '(* e m))))
      (is (same unknown (sign '(/ m e))) "a divisor that may vanish")
      (is (same '(:positive) (sign '(expt d 2))))
      (is (same unknown (sign '(sin m))))
      (is (same unknown (sign 'h)) "an undeclared name"))))

;;; Many scenarios across processes

(defun bin-ames-streams (&rest arguments)
  "Run the checkout's bin/ames with ARGUMENTS: (values EXIT-CODE OUTPUT ERRORS)."
  (let ((program (namestring (merge-pathnames "bin/ames" (asdf:system-source-directory "ames")))))
    (multiple-value-bind (output errors code)
        (uiop:run-program (cons program arguments) :output :string :error-output :string
                                                   :ignore-error-status t)
      (values code output errors))))

(defun scenario-paths (&rest names)
  "The namestrings of scenarios/NAME.lisp."
  (mapcar (lambda (name)
            (namestring (merge-pathnames (format nil "scenarios/~A.lisp" name)
                                         (asdf:system-source-directory "ames"))))
          names))

(test jobs-option-is-read-and-checked
  (is (equal '(nil ("run" "a.lisp")) (multiple-value-list (ames::jobs-option '("run" "a.lisp")))))
  (is (equal '(3 ("run" "a.lisp" "--format" "sexp"))
             (multiple-value-list (ames::jobs-option '("run" "--jobs" "3" "a.lisp" "--format" "sexp")))))
  (dolist (bad '(("run" "--jobs") ("run" "--jobs" "0") ("run" "--jobs" "two")
                 ("run" "--jobs" "2" "--jobs" "2") ("run" "--jobs" "-1")))
    (is (typep (handler-case (ames::jobs-option bad) (ames-error (c) c)) 'ames:usage-error)
        "~S should be a usage error" bad)))

(test jobs-print-in-input-order-with-the-worst-exit-code
  "bin/ames run --jobs 2 prints what one process prints, file by file in order, and exits
with the worst status (a defective scenario gives 1); --jobs with one HTML page is a
usage error."
  (let ((bad (write-temporary-scenarios *one-bad-one-good*))
        (files (scenario-paths "stack-of-four-blocks" "particle-under-plane" "chain-of-four-blocks")))
    (unwind-protect
         (multiple-value-bind (code-1 output-1) (apply #'bin-ames-streams "run" "--format" "sexp" files)
           (multiple-value-bind (code-2 output-2 errors-2)
               (apply #'bin-ames-streams "run" "--jobs" "2" "--format" "sexp" files)
             (is (eql 0 code-1))
             (is (eql 0 code-2) "errors: ~A" errors-2)
             (is (string= output-1 output-2)))
           (multiple-value-bind (code output errors)
               (apply #'bin-ames-streams "run" "--jobs" "2" (namestring bad) files)
             (is (eql 1 code))
             (is (search "drop" output))
             (is (< (search "DROP" (string-upcase output)) (search "STACK-OF-FOUR" (string-upcase output))))
             (is (search "ames:" errors)))
           (is (eql 2 (bin-ames-streams "run" "--jobs" "2" "--format" "html" (first files)))))
      (delete-file bad))))

(defun program-on-path (name)
  "The pathname of the program NAME on PATH, or NIL."
  (let ((found (uiop:run-program (list "sh" "-c" (format nil "command -v ~A || true" name))
                                 :output :string)))
    (and (plusp (length (string-trim '(#\Newline #\Space) found)))
         (string-trim '(#\Newline #\Space) found))))

(test gnu-parallel-over-ssh-gathers-results-in-order
  "The route across machines that README.md documents: GNU parallel --keep-order runs one
bin/ames per file on the ssh logins given (here two names served by a stand-in for ssh
that runs the command on this machine) and prints the results in input order; its job
log gives each file's exit code. Skipped where GNU parallel is not installed."
  (let ((parallel (program-on-path "parallel")))
    (if (null parallel)
        (skip "GNU parallel is not installed (apt-get install parallel)")
        (let* ((directory (merge-pathnames (format nil "ames-parallel-~36R/" (random (expt 36 8) (make-random-state t)))
                                           (uiop:temporary-directory)))
               (ssh (merge-pathnames "ssh" directory))
               (log (merge-pathnames "jobs.log" directory))
               (program (namestring (merge-pathnames "bin/ames" (asdf:system-source-directory "ames"))))
               (files (scenario-paths "chain-of-four-blocks" "particle-under-plane" "stack-of-four-blocks")))
          (ensure-directories-exist directory)
          (unwind-protect
               (progn
                 (with-open-file (out ssh :direction :output :if-exists :supersede)
                   (format out "#!/bin/sh~%# stands in for ssh: skips the options and the host, runs the command here~%while [ $# -gt 0 ]; do case \"$1\" in -*) shift;; *) break;; esac; done~%shift~%[ \"$1\" = \"--\" ] && shift~%# a login through sshd always has SHELL (parallel's remote worker runs the job with it)~%SHELL=/bin/sh; export SHELL~%exec sh -c \"$*\"~%"))
                 (uiop:run-program (list "chmod" "+x" (namestring ssh)))
                 (multiple-value-bind (expected) (uiop:run-program (list* program "run" "--format" "sexp" files)
                                                                   :output :string)
                   (multiple-value-bind (output errors code)
                       (uiop:run-program (append (list parallel "--will-cite" "--keep-order"
                                                       "--ssh" (namestring ssh)
                                                       "-S" "1/machine-a,1/machine-b"
                                                       "--joblog" (namestring log)
                                                       program "run" "--format" "sexp" "{}" ":::")
                                                 files)
                                         :output :string :error-output :string :ignore-error-status t)
                     (is (eql 0 code) "parallel: ~A" errors)
                     (is (string= expected output)
                         "parallel printed ~D characters, the single run ~D; they differ from ~D on"
                         (length output) (length expected) (mismatch expected output))
                     (is (= 4 (length (uiop:read-file-lines log))) "a header and a line per file"))))
            (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore))))))
