;;;; t/reliability-fuzz.lisp -- the whole path under fuzz: bytes of a file -> reader -> validator -> a run within its budget.
;;;;
;;;; Each case is a scenario file of three scenarios: two kept intact (renamed KEEP-n) around
;;;; one mutated target, all taken from the scenarios of scenarios/ with a fixed seed. The
;;;; target is mutated as text or bytes: a character deleted, a ( ) " | #| ; \ ' , or
;;;; "(scenario" inserted, the text cut short, a line dropped or doubled, a byte that is not
;;;; UTF-8 inserted, a number replaced by a hostile one ((expt 10 (expt 10 9)), a product of
;;;; 26 constant sums, 1e300, (log 0), a sum of 3000 terms...), a shape replaced by a
;;;; polygon of up to 3000 vertices. The file is read with READ-SCENARIO-FILE, and the
;;;; target, when it is a valid scenario, is run by RUN-SCENARIO within a small budget.
;;;; The figures (FUZZ-FIGURES):
;;;;   :FORMS          targets tried
;;;;   :AMES-ERRORS    targets that ended in an AMES-ERROR (reading, validating or running)
;;;;   :HISTORIES      targets that ran to a history
;;;;   :NO-TARGET      targets that left no form at all (cut down to nothing, say)
;;;;   :OTHER          targets that ended in another condition (the target is 0)
;;;;   :HANGS          runs that went on past their budget (plus the backstop's grace and a
;;;;                   margin; the target is 0)
;;;;   :LOST           intact scenarios that did not come back from the reader (target 0)
;;;;   :CONTROL-FAILED checks, every 25 cases, that a quick intact scenario still prints
;;;;                   what it should on the same bridge (target 0)
;;;; `make test` runs *FUZZ-TEST-FORMS* cases; `make fuzz` runs 10,000 (t/fuzz.lisp).

(in-package #:ames.tests)

(in-suite reliability)

(defparameter *fuzz-test-forms* 60
  "How many fuzz cases `make test` runs.")

(defparameter *fuzz-seed* 1994
  "The seed of the whole-path fuzz.")

(defparameter *fuzz-limits* (make-limits :time-limit 3 :maxima-timeout 2)
  "The budget of each fuzz run: 3 s, and 2 s per Maxima request.")

(defparameter *fuzz-hang-margin* 5
  "Seconds past a run's time limit and the backstop's grace after which it is a hang.")

(defun scenario-seed-texts ()
  "The text of each scenario of scenarios/, from its (scenario on."
  (loop for file in (scenario-files)
        for text = (uiop:read-file-string file)
        for start = (cl-ppcre:scan "(?m)^\\(scenario" text)
        when start collect (subseq text start)))

(defun renamed-scenario (text name)
  "TEXT, a scenario's text, with its name replaced by NAME."
  (cl-ppcre:regex-replace "^\\(scenario\\s+[^\\s()\";]+" text
                          (format nil "(scenario ~A" name)))

(defparameter *hostile-numbers*
  (list "(expt 10 (expt 10 9))" "(expt 2 100001)" "(expt 10 4000)" "1e300" "-1e-300" "-0.0"
        "(/ 1 (- 2 2))" "(sqrt -1)" "(log 0)" "(atan 0 0)" "(* 1e200 1e200)"
        "123456789012345678901234567890123456789/7"
        (format nil "(* ~{(+ ~D (sqrt ~D))~^ ~})"
                (loop for k from 1 to 26 append (list k (1+ k))))
        "(expt (+ 1 (sqrt 2) (sqrt 3) (sqrt 5)) 6)"
        (format nil "(+ ~{~A~^ ~})" (make-list 3000 :initial-element "1/3")))
  "Texts put where a scenario has a number.")

(defun random-polygon-text (state)
  "A polygon of 8 to 3000 vertices about the origin, often self-crossing."
  (let ((n (random-element '(8 50 300 3000) state))
        (jitter (random-element '(0 0 1/2 2) state)))
    (format nil "(polygon ~{(~A ~A)~^ ~})"
            (loop for k below n
                  for angle = (/ (* 2 pi k) n)
                  for r = (+ 1 (if (zerop jitter) 0 (random (float jitter 1d0) state)))
                  append (list (/ (round (* 1000 r (cos angle))) 1000)
                               (/ (round (* 1000 r (sin angle))) 1000))))))

(defun mutate-text (text state)
  "TEXT mutated one way, chosen with STATE; second value a list of byte positions (in
the UTF-8 of the result) where a byte that is not UTF-8 goes, third the mutation's name."
  (let ((n (length text)))
    (flet ((at () (random (max 1 n) state))
           (splice (position old-length new)
             (concatenate 'string (subseq text 0 position) new
                          (subseq text (min n (+ position old-length))))))
      (ecase (random 9 state)
        (0 (values (splice (at) 1 "") '() :delete-character))
        (1 (values (splice (at) 0 (random-element '("(" ")" "\"" "|" "#|" ";" "\\" "'" "," "#." "
(scenario ") state))
                   '() :insert-syntax))
        (2 (values (subseq text 0 (at)) '() :cut-short))
        (3 (let ((lines (cl-ppcre:split "\\n" text)))
             (let ((k (random (length lines) state)))
               (values (format nil "~{~A~%~}"
                               (if (zerop (random 2 state))
                                   (append (subseq lines 0 k) (nthcdr (1+ k) lines))
                                   (append (subseq lines 0 (1+ k)) (nthcdr k lines))))
                       '() :line-dropped-or-doubled))))
        (4 (values text (list (random (max 1 (length (sb-ext:string-to-octets
                                                      text :external-format :utf-8)))
                                      state))
                   :bad-byte))
        ((5 6) (let ((numbers (cl-ppcre:all-matches "(?<![\\w.:/-])-?\\d+(?:\\.\\d+)?(?:/\\d+)?(?![\\w./])"
                                                    text)))
                 (if (null numbers)
                     (values text '() :unchanged)
                     (let ((k (* 2 (random (floor (length numbers) 2) state))))
                       (values (splice (nth k numbers) (- (nth (1+ k) numbers) (nth k numbers))
                                       (random-element *hostile-numbers* state))
                               '() :hostile-number)))))
        (7 (let ((shape (cl-ppcre:scan ":shape point" text)))
             (if shape
                 (values (splice shape (length ":shape point")
                                 (format nil ":shape ~A" (random-polygon-text state)))
                         '() :big-polygon)
                 (values (splice (at) 1 "") '() :delete-character))))
        (8 (let ((i (at)) (j (at)))
             (let ((copy (copy-seq text)))
               (when (< (max i j) n) (rotatef (char copy i) (char copy j)))
               (values copy '() :swap-characters))))))))

(defun fuzz-file-octets (before target after bad-positions)
  "The UTF-8 bytes of BEFORE, TARGET and AFTER, each on its own lines, with the byte
#xE9, #xFF or #xC3 inserted at each of BAD-POSITIONS within TARGET's bytes."
  (flet ((octets (text) (sb-ext:string-to-octets text :external-format :utf-8)))
    (let ((target-octets (coerce (octets target) 'list)))
      (dolist (position (sort (copy-list bad-positions) #'>))
        (setf target-octets (append (subseq target-octets 0 (min position (length target-octets)))
                                    (list (random-element '(#xE9 #xFF #xC3) *random-state*))
                                    (nthcdr (min position (length target-octets)) target-octets))))
      (concatenate '(vector (unsigned-byte 8))
                   (octets before) (octets (string #\Newline))
                   target-octets (octets (string #\Newline))
                   (octets after)))))

(defun fuzz-outcome (thunk seconds)
  "What THUNK gives within SECONDS of wall time (a hard guard): its value, the
AMES-ERROR or other condition it ends in, or :HANG."
  (handler-case (sb-ext:with-timeout seconds (funcall thunk))
    (sb-ext:timeout () :hang)
    (ames-error (condition) condition)
    (error (condition) condition)
    (storage-condition (condition) condition)))

(defun fuzz-figures (forms &key (seed *fuzz-seed*) (limits *fuzz-limits*) stream)
  "Run FORMS whole-path fuzz cases (see the file header) and return the figures as a
plist, with :FAILURES (descriptions of the cases that went wrong) and :MUTATIONS (an
alist of mutation names and counts). With STREAM, print a line per case."
  (let* ((state (sb-ext:seed-random-state seed))
         (*random-state* (sb-ext:seed-random-state (1+ seed)))
         (seeds (scenario-seed-texts))
         (control (first (ames:read-scenarios-from-string *drop-text*)))
         (bridge (ames.maxima:make-bridge))
         (figures (list :forms 0 :ames-errors 0 :histories 0 :no-target 0 :other 0 :hangs 0
                        :lost 0 :control-failed 0))
         (failures '()) (mutations '())
         (path (namestring (uiop:tmpize-pathname
                            (merge-pathnames "ames-fuzz.lisp" (uiop:temporary-directory))))))
    (flet ((note (key &optional description)
             (incf (getf figures key))
             (when description (push description failures))))
      (unwind-protect
           (let ((expected-control (printed-run control bridge))
                 (hang-seconds (+ (or (limits-time-limit limits) 60) ames.base::*backstop-grace*
                                  *fuzz-hang-margin*)))
             (dotimes (i forms)
               (multiple-value-bind (target bad-positions mutation)
                   (mutate-text (random-element seeds state) state)
                 (let ((keep-1 (format nil "keep-~D-a" i)) (keep-2 (format nil "keep-~D-b" i)))
                   (incf (getf figures :forms))
                   (let ((entry (assoc mutation mutations)))
                     (if entry (incf (cdr entry)) (push (cons mutation 1) mutations)))
                   (with-open-file (out path :direction :output :if-exists :supersede
                                             :element-type '(unsigned-byte 8))
                     (write-sequence (fuzz-file-octets
                                      (renamed-scenario (random-element seeds state) keep-1)
                                      target
                                      (renamed-scenario (random-element seeds state) keep-2)
                                      bad-positions)
                                     out))
                   (let* ((read (fuzz-outcome (lambda ()
                                                (multiple-value-list
                                                 (ames:read-scenario-file path :on-error :collect)))
                                              60))
                          (scenarios (and (consp read) (first read)))
                          (names (mapcar (lambda (s) (string-downcase (ames:scenario-name s)))
                                         scenarios))
                          (targets (remove-if (lambda (s)
                                                (member (string-downcase (ames:scenario-name s))
                                                        (list keep-1 keep-2) :test #'string=))
                                              scenarios))
                          (outcome
                            (cond ((not (consp read)) read)
                                  ((null targets)
                                   (or (find-if (lambda (c) (not (typep c 'ames-error))) (second read))
                                       (first (second read))
                                       :nothing))
                                  (t (let ((start (get-internal-real-time)))
                                       (let ((run (fuzz-outcome
                                                   (lambda ()
                                                     (ames:run-scenario (first targets) :bridge bridge
                                                                                        :limits limits))
                                                   (* 3 hang-seconds))))
                                         (if (> (seconds-since start) hang-seconds) :hang run)))))))
                     (dolist (keep (list keep-1 keep-2))
                       (unless (member keep names :test #'string=)
                         (note :lost (format nil "case ~D (~(~A~)): ~A was lost" i mutation keep))))
                     (cond ((eq outcome :hang)
                            (note :hangs (format nil "case ~D (~(~A~)): a hang" i mutation))
                            (ames.maxima:reset-bridge bridge :restart t))
                           ((typep outcome 'ames:simulation-history) (note :histories))
                           ((typep outcome 'ames-error) (note :ames-errors))
                           ((eq outcome :nothing) (note :no-target))
                           (t (note :other (format nil "case ~D (~(~A~)): ~A ~A" i mutation
                                                   (type-of outcome)
                                                   (handler-case (princ-to-string outcome)
                                                     (error () "(unprintable)"))))))
                     (when stream
                       (format stream "~&case ~5D ~(~24A~) ~A~%" i mutation
                               (cond ((symbolp outcome) outcome)
                                     ((typep outcome 'ames:simulation-history)
                                      (ames:history-outcome outcome))
                                     (t (type-of outcome))))
                       (finish-output stream)))))
               (when (zerop (mod (1+ i) 25))
                 (unless (equal expected-control (printed-run control bridge))
                   (note :control-failed (format nil "after case ~D the control scenario changed" i))))))
        (ames.maxima:close-bridge bridge)
        (uiop:delete-file-if-exists path)))
    (append figures (list :mutations (sort mutations #'> :key #'cdr)
                          :failures (nreverse failures)))))

(defun print-fuzz-figures (figures &optional (stream *standard-output*))
  "Print the fuzz FIGURES as the issue asks for them."
  (format stream "~&Whole-path fuzz: ~D forms tried, ~D AMES-ERRORs, ~D histories, ~
                  ~D left no form, ~D other conditions, ~D hangs past the budget, ~
                  ~D lost scenarios, ~D control runs changed~%  mutations: ~
                  ~{~(~A~) ~D~^, ~}~%~{  ~A~%~}"
          (getf figures :forms) (getf figures :ames-errors) (getf figures :histories)
          (getf figures :no-target)
          (getf figures :other) (getf figures :hangs) (getf figures :lost)
          (getf figures :control-failed)
          (loop for (name . count) in (getf figures :mutations) append (list name count))
          (getf figures :failures)))

(test whole-path-fuzz-ends-in-histories-or-ames-errors-within-the-budget
  (let ((figures (fuzz-figures *fuzz-test-forms*)))
    (print-fuzz-figures figures)
    (is (= *fuzz-test-forms* (getf figures :forms)))
    (is (zerop (getf figures :other)) "~{~A~%~}" (getf figures :failures))
    (is (zerop (getf figures :hangs)) "~{~A~%~}" (getf figures :failures))
    (is (zerop (getf figures :lost)) "~{~A~%~}" (getf figures :failures))
    (is (zerop (getf figures :control-failed)) "~{~A~%~}" (getf figures :failures))))
