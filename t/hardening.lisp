;;;; t/hardening.lisp -- issue 27: values that are not physics, runs that cannot crash, output
;;;; that cannot be injected, limits that hold for the whole run, signals and pipes.
;;;;
;;;; The tests that spawn bin/ames (signals, pipes, devices) are in t/hardening-processes.lisp.

(in-package #:ames.tests)

(def-suite hardening :in all-tests
  :description "Physical ranges, crashes, escaping, limits, signals and pipes (issue 27).")

(in-suite hardening)

(defun hardening-run (text &rest arguments &key settings numeric (limits ames.base:*limits*))
  "The histories of every scenario of TEXT (written to a temporary file), run by
AMES:RUN-FILE with SETTINGS and NUMERIC within LIMITS."
  (declare (ignore arguments))
  (let ((path (write-scenario-text text)))
    (unwind-protect
         (let ((*package* (find-package '#:ames-scenario)))
           (ames:run-file path :settings settings :numeric numeric :limits limits))
      (delete-file path))))

(defun hardening-error (text &rest arguments)
  "The AMES-ERROR that running TEXT (see HARDENING-RUN, same ARGUMENTS) signals, or NIL."
  (handler-case (progn (apply #'hardening-run text arguments) nil)
    (ames:ames-error (condition) condition)))

(defun scenario-path (name)
  "The namestring of scenarios/NAME.lisp."
  (namestring (merge-pathnames (format nil "scenarios/~A.lisp" name)
                               (asdf:system-source-directory "ames"))))

(defun scenario-symbol (name)
  "The symbol NAME of the scenario package."
  (intern name '#:ames-scenario))

;;; A crash: a body of a numeric (spring) group that meets an impact at its first instant

(defparameter *spring-pushed-into-floor*
  "(scenario pushed-into-floor \"Two particles on a spring; the second is pushed into the floor.\"
  (parameters (m1 :positive) (m2 :positive) (k :positive) (g :positive) (v0 :positive)
              (l0 :positive))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body first :mass m1 :position (0 0) :velocity (0 0) :shape point)
  (body second :mass m2 :position (l0 0) :velocity (0 (- v0)) :shape point)
  (spring coupling :from (first (0 0)) :to (second (0 0)) :stiffness k)
  (simulate :states 2))")

(test a-numeric-state-that-ends-at-once-ends-where-it-started
  "The second mass, pushed into the floor, meets it at t = 0 (a plastic impact, the default
restitution being 0): the state lasts 0, ends with both bodies where they started, and
the next state has the second at rest at (l0, 0). This crashed with NIL is not REAL."
  (let* ((history (first (hardening-run *spring-pushed-into-floor*)))
         (states (ames:history-states history))
         (first-state (first states))
         (l0 (scenario-symbol "L0")) (v0 (scenario-symbol "V0")))
    (is (>= (length states) 2))
    (is (eql 0 (ames:state-duration first-state)))
    (is (equal `(,l0 0) (second (assoc "SECOND" (ames:state-final-positions first-state)
                                       :key #'symbol-name :test #'string=))))
    (is (equal `(0 (- ,v0)) (second (assoc "SECOND" (ames:state-final-velocities first-state)
                                           :key #'symbol-name :test #'string=))))
    (is (eq :complete (ames:history-outcome history)))))

;;; Physical ranges of the coefficients: on the clause, under the assumptions, and on values

(defun block-on-floor-text (parameters &rest clauses)
  "A block on a rough floor with the PARAMETERS (a string) and the extra CLAUSES (strings)."
  (format nil "(scenario block \"A block on a floor.\"
  (parameters (m :positive) (g :positive) (v0 :positive) ~A)
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body block :mass m :position (0 0) :velocity (v0 0) :shape (polygon (-1 0) (1 0) (1 1) (-1 1)))
  ~{~A~^~%  ~}
  (simulate :states 2))" parameters clauses))

(defun is-refused-at (condition type location &optional (text ""))
  "Check that CONDITION is of TYPE, at LOCATION, and that its message says TEXT."
  (is (typep condition type) "~S is no ~S" condition type)
  (when (typep condition 'ames:scenario-error)
    (is (equal location (ames.scenario::scenario-error-location condition))
        "~S is at ~S, not ~S" condition (ames.scenario::scenario-error-location condition) location))
  (is (search text (princ-to-string condition)) "~S does not say ~S" (princ-to-string condition) text))

(test friction-coefficients-have-their-physical-range
  "A friction coefficient is not negative and the kinetic does not exceed the static: a
literal, a parameter whose assumptions allow otherwise, a default and a --set value are
each refused, naming the friction clause."
  (let ((negative (hardening-error (block-on-floor-text "(mu (:value -1/2))"
                                                        "(friction block floor :static mu)"))))
    (is-refused-at negative 'ames:missing-assumption-error "friction BLOCK FLOOR" "(>= MU 0)"))
  (is-refused-at (hardening-error (block-on-floor-text "(mu (:value -1/2))"
                                                       "(friction block floor :static mu)")
                                  :numeric t)
                 'ames.scenario:parameter-value-error "friction BLOCK FLOOR" "MU = -1/2")
  (is-refused-at (hardening-error (block-on-floor-text "(mu :positive)"
                                                       "(friction block floor :static mu :kinetic (* 2 mu))"))
                 'ames:scenario-expression-error "friction BLOCK FLOOR" "does not exceed")
  (is-refused-at (hardening-error (block-on-floor-text "(mu (>= mu 0)) (muk (>= muk 0))"
                                                       "(friction block floor :static mu :kinetic muk)")
                                  :settings '(("mu" . 1/2) ("muk" . 1)))
                 'ames.scenario:parameter-value-error "friction BLOCK FLOOR" "MUK = 1"))

(test restitution-stiffness-and-gravitation-have-their-physical-range
  "0 <= e <= 1 through --set as through a literal; a stiffness and a gravitational
constant are positive, under the assumptions and at the values."
  (is-refused-at (hardening-error (block-on-floor-text "(e :positive)" "(restitution e)")
                                  :settings '(("e" . 2)))
                 'ames.scenario:parameter-value-error "clause RESTITUTION" "E = 2")
  (is-refused-at (hardening-error (block-on-floor-text "(e :positive)" "(restitution e)"))
                 'ames:missing-assumption-error "clause RESTITUTION" "(<= E 1)")
  (is-refused-at (hardening-error (block-on-floor-text "(k (:value -3))"
                                                       "(body wall :fixed t :position (-3 0) :shape point)"
                                                       "(spring s :from (wall (0 0)) :to (block (0 0)) :stiffness k)")
                                  :numeric t)
                 'ames.scenario:parameter-value-error "spring S" "K = -3")
  (is-refused-at (hardening-error (block-on-floor-text "(k (< k 0))"
                                                       "(body wall :fixed t :position (-3 0) :shape point)"
                                                       "(spring s :from (wall (0 0)) :to (block (0 0)) :stiffness k)"))
                 'ames:scenario-expression-error "spring S" "stiffness is positive")
  (is-refused-at (hardening-error (block-on-floor-text "(big-g (:value -1))" "(gravitation big-g)")
                                  :numeric t)
                 'ames.scenario:parameter-value-error "clause GRAVITATION" "BIG-G = -1"))

(test a-rope-is-at-least-as-long-as-its-path-at-the-start
  "A rope of length 1/10 whose ends are 4 apart could not be tied; one of length 4 starts
taut and runs; one whose length is a parameter is checked at its value."
  (flet ((rope-text (length &optional (parameter ""))
           (format nil "(scenario hang \"A weight on a rope.\"
  (parameters (m :positive) (g :positive) ~A)
  (gravity g)
  (body ceiling :fixed t :position (0 5) :shape point)
  (body bob :mass m :position (0 1) :velocity (0 0) :shape point)
  (rope cord :length ~A :through ((ceiling (0 0)) (bob (0 0))))
  (simulate :states 1))" parameter length)))
    (is-refused-at (hardening-error (rope-text "1/10")) 'ames:scenario-expression-error
                   "rope CORD" "at least as long")
    (is-refused-at (hardening-error (rope-text "l" "(l :positive)") :settings '(("l" . 3)))
                   'ames.scenario:parameter-value-error "rope CORD" "L = 3")
    (is (null (hardening-error (rope-text "l" "(l :positive)") :settings '(("l" . 4))
                               :limits (ames.base:change-limits ames.base:*limits* :time-limit 60))))))

(test queries-have-names-of-their-own
  "Two queries of one name, or a query named like a body, are refused naming the query."
  (is-refused-at (hardening-error (block-on-floor-text "" "(query block (value (x block) :at (:start 0)))"))
                 'ames:duplicate-name-error "clause QUERY" "named like the body")
  (is-refused-at (hardening-error (block-on-floor-text "" "(query where (value (x block) :at (:start 0)))"
                                                       "(query where (value (y block) :at (:start 0)))"))
                 'ames:duplicate-name-error "clause QUERY" "two queries"))

;;; Numbers beyond double precision in the reports

(defun report-in-format (text format &rest arguments &key settings numeric (limits ames.base:*limits*))
  "Run TEXT's scenarios by AMES:RUN-FILES in FORMAT; (values STATUS OUTPUT ERRORS)."
  (declare (ignore arguments))
  (let ((path (write-scenario-text text))
        (output (make-string-output-stream))
        (errors (make-string-output-stream)))
    (unwind-protect
         (let ((status (let ((*error-output* errors)
                             (*package* (find-package '#:ames-scenario)))
                         (ames:run-files (list path) :format format :settings settings
                                                     :numeric numeric :limits limits
                                                     :stream output))))
           (values status (get-output-stream-string output) (get-output-stream-string errors)))
      (delete-file path))))

(defparameter *huge-drop*
  (format nil "(scenario huge-drop \"A ball dropped from 10^400.\"
  (parameters (m :positive (:value 1)) (g :positive (:value 10)) (h :positive (:value ~D)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body ball :mass m :position (0 h) :velocity (0 0) :shape point)
  (simulate :states 2))" (expt 10 400))
  "A scenario whose default height has no double-float.")

(test numbers-beyond-double-precision-do-not-end-any-report
  "A default of 10^400, or a friction coefficient of 10^308, leaves the closed forms alone
in every format (no FLOATING-POINT-OVERFLOW, no lost HTML page); the numbers that do fit
are still printed."
  (dolist (format ames.report:*report-formats*)
    (multiple-value-bind (status output errors) (report-in-format *huge-drop* format :numeric t)
      (is (eql 0 status) "~A: status ~A, ~A" format status errors)
      (is (search "huge-drop" (string-downcase output)) "~A: no report" format)
      (is (zerop (length errors)) "~A: ~A" format errors)
      (when (eq format :text)
        (is (search "a_y = -g = -10" output) "the acceleration's number is printed"))))
  ;; a friction coefficient of 10^308: its squares overflow a double in every printer
  (dolist (format ames.report:*report-formats*)
    (multiple-value-bind (status output errors)
        (report-in-format (uiop:read-file-string (scenario-path "block-sliding-on-rough-floor")) format
                          :settings `(("m" . 1) ("g" . 10) ("b" . 1) ("v0" . 1) ("mu" . ,(expt 10 308))))
      (is (eql 0 status) "~A: status ~A, ~A" format status errors)
      (is (search "block-sliding-on-rough-floor" (string-downcase output)))))
  (is (null (ames.report::report-float (expt 10 400))))
  (is (eql 1d300 (ames.report::report-float (expt 10 300)))))

;;; Output that cannot be injected

(defparameter *hostile-names*
  (format nil "(scenario |evil~%\\\\input{/etc/passwd}~C[31m~C| \"A description with ~C[2J, ~C and~%\\\\input{x}.\"
  (parameters (m :positive (:value 1)) (g :positive (:value 10)) (h :positive (:value 1)))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body |ba~Cll| :mass m :position (0 h) :velocity (0 0) :shape point)
  (simulate :states 2))"
          (code-char 27) (code-char 7) (code-char 27) (code-char 7) (code-char 27))
  "A scenario whose name holds a line break, a LaTeX command, ESC and BEL.")

(defun python-accepts-p (kind text)
  "True when Debian's Python parses TEXT as KIND: :json (every non-empty line, strictly)
or :xml."
  (let ((program (ecase kind
                   (:json "import json,sys
for line in sys.stdin.read().splitlines():
    line.strip() and json.loads(line)")
                   (:xml "import sys, xml.dom.minidom as m; m.parseString(sys.stdin.buffer.read())"))))
    (zerop (nth-value 2 (uiop:run-program (list "/usr/bin/python3" "-c" program)
                                          :input (make-string-input-stream text)
                                          :output nil :error-output nil
                                          :ignore-error-status t)))))

(defun raw-control-characters-p (text)
  "True when TEXT has a control character other than a line break or a tab."
  (some (lambda (c) (and (ames.report::control-character-p c)
                         (not (member c '(#\Newline #\Tab)))))
        text))

(defun latex-user-command-p (text)
  "True when TEXT has an active \\input (the user's command), or when the name in its
header comment goes on past the comment's line."
  (let* ((comment (search "% AMES report" text))
         (line-end (and comment (position #\Newline text :start comment))))
    (or (search "\\input" text)
        (null line-end)
        (not (search "passwd" text :start2 comment :end2 line-end)))))

(test user-text-cannot-break-out-of-any-format
  "A name with a line break and \\input, ESC and BEL: the LaTeX has no active command of
the user's, the JSON parses, the SVG is well-formed XML, and no format (nor the picture,
nor the text report) carries a raw control character."
  (dolist (format ames.report:*report-formats*)
    (multiple-value-bind (status output errors) (report-in-format *hostile-names* format :numeric t)
      (is (eql 0 status) "~A: ~A" format errors)
      ;; the s-expression report carries the names exactly, to be read back by programs
      (unless (eq format :sexp)
        (is (not (raw-control-characters-p output)) "~A has a raw control character" format))
      (case format
        (:latex (is (not (latex-user-command-p output)) "the LaTeX runs the user's \\input"))
        (:json (is (python-accepts-p :json output) "the JSON does not parse"))
        (:html (is (not (search "<script>alert" output)))))))
  (let ((history (first (hardening-run *hostile-names* :numeric t))))
    (let ((svg (with-output-to-string (out) (ames.report:print-history-svg history out))))
      (is (python-accepts-p :xml svg) "the SVG is not well-formed")
      (is (not (raw-control-characters-p svg)))))
  (is (string= "a^[b^G" (ames.report:visible-text (format nil "a~Cb~C" (code-char 27) (code-char 7))))))

;;; Error messages that help: did you mean, where a form should have ended, the vertices

(defun read-error-of (text)
  "The first condition reading and validating TEXT collects, or NIL."
  (let ((*package* (find-package '#:ames-scenario)))
    (first (nth-value 1 (ames:read-scenarios-from-string text :on-error :collect)))))

(test messages-say-what-was-meant
  "A misspelled clause or keyword gets \"did you mean\"; an unclosed ( is reported where
the form should have ended (by the indentation when a clause lacks its )); a clockwise
polygon is answered with its vertices counter-clockwise, numbers or not."
  (is (search "(did you mean gravity?)"
              (princ-to-string (read-error-of (block-on-floor-text "" "(gravty g)")))))
  (is (search "(did you mean :position?)"
              (princ-to-string (read-error-of "(scenario s (body b :mass 1 :positon (0 0) :velocity (0 0) :shape point))"))))
  (is (null (ames.scenario::closest-word "zzzzzz" '("gravity" "body"))))
  (let ((condition (read-error-of (format nil "(scenario s \"x\"~% (parameters (g :positive))~% (gravity g~% (body b :mass 1 :position (0 0) :velocity (0 0) :shape point))~%"))))
    (is (eql 3 (ames.scenario:scenario-read-error-line condition)) "~A" condition)
    (is (search "closed by the end of line 3" (princ-to-string condition))))
  (let ((condition (read-error-of (format nil "(scenario s \"x\"~% (gravity 1)~% (body b :mass 1 :position (0 0) :velocity (0 0) :shape point)~%~%(scenario t \"y\" (body c :mass 1 :position (0 0) :velocity (0 0) :shape point))~%"))))
    (is (search "closed by the end of line 3" (princ-to-string condition)) "~A" condition))
  (is (search "(POLYGON (0 0) (4 0) (4 3))"
              (princ-to-string (read-error-of (block-on-floor-text "" "(body w :fixed t :shape (polygon (0 0) (4 3) (4 0)))")))))
  (let ((condition (hardening-error (block-on-floor-text "(a :positive)" "(body w :fixed t :position (10 0) :shape (polygon (0 0) (a 3) (a 0)))"))))
    (is (typep condition 'ames:scenario-shape-error))
    (is (search "(POLYGON (0 0) (A 0) (A 3))" (princ-to-string condition)) "~A" condition)))

;;; Messages name no internal package

(test messages-show-no-internal-package
  "A condition quoting AMES's own symbols (AMES.KB::CONTACT, ames.simulator::contact-5,
#:L1-EXCESS) is written with their names alone; the message's own \"ames: \" and paths
stay."
  (let ((text (with-output-to-string (out)
                (ames::print-error-message
                 (make-condition 'ames:scenario-syntax-error
                                 :scenario 'ames-scenario::demo
                                 :datum (list (intern "CONTACT" '#:ames.kb)
                                              (intern "CONTACT-5" '#:ames.simulator)
                                              (make-symbol "L1-EXCESS"))
                                 :detail "a test")
                 out))))
    (is (eql 0 (search "ames: " text)))
    (is (not (search "AMES.KB" text)) "~A" text)
    (is (not (search "AMES.SIMULATOR" text)) "~A" text)
    (is (not (search "#:" text)) "~A" text)
    (is (search "CONTACT-5" text)))
  (is (string= "/work/ames/x.lisp: (POS FIRST :X)"
               (ames::without-package-prefixes "/work/ames/x.lisp: (AMES.KB:POS AMES-SCENARIO::FIRST :X)"))))

