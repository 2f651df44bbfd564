;;;; src/interface/runs.lisp -- one scenario run as the REPL and the command line make it: a fresh bridge state, a budget, and errors that say where.
;;;;
;;;; RUN-SCENARIO is what RUN-FILES and RUN-FILE do for each scenario:
;;;;   - the bridge is reset (AMES.MAXIMA:RESET-BRIDGE), so that what a scenario prints
;;;;     does not depend on what ran before it in the process;
;;;;   - the run gets a budget (AMES.BASE:CALL-WITH-BUDGET) from the LIMITS given, by
;;;;     default *LIMITS*: wall time, and the size of exact numbers and expressions;
;;;;   - the parameter values are checked (RUN-PARAMETER-VALUES, by CHECK-PARAMETER-VALUES);
;;;;   - an AMBIGUOUS-TRANSITION stops the run (its history says so);
;;;;   - every AMES-ERROR that leaves the run, but a SCENARIO-ERROR (which names its
;;;;     place itself), gets an ERROR-CONTEXT: the file, the scenario, the line of the
;;;;     clause involved (the first body its datum names, else the scenario) and the
;;;;     bodies. The simulator knows no files: the context is added here, by a handler
;;;;     that only looks at the condition on its way out.
;;;; After a run cut short by its time limit, the bridge's process is replaced: a request
;;;; may still be running in it.

(in-package #:ames)

(define-condition internal-error (ames-error) ()
  (:documentation "A defect of AMES itself, met while running a scenario: a Lisp error
that is no AMES-ERROR. DATUM is that error. RUN-FILES reports it as it reports the
others, and goes on with the next scenario.")
  (:report (lambda (condition stream)
             (format-report stream "Internal error of AMES (please report it): ~A~%  condition: ~S"
                            (let ((error (ames-error-datum condition)))
                              (handler-case (princ-to-string error)
                                (error () "(a condition that cannot be printed)")))
                            (type-of (ames-error-datum condition))))))

(defconstant +largest-datum-walk+ 100000
  "BODIES-NAMED looks at no more than this many conses of a condition's datum.")

(defun bodies-named (scenario datum)
  "The names of SCENARIO's bodies that occur in the tree DATUM, in order of first
occurrence (looking at no more than +LARGEST-DATUM-WALK+ conses)."
  (let ((names (mapcar #'scenario-body-name (scenario-bodies scenario)))
        (found '())
        (budget +largest-datum-walk+))
    (labels ((walk (x)
               (loop while (and (consp x) (plusp (decf budget)))
                     do (walk (car x))
                        (setf x (cdr x)))
               (when (and x (symbolp x) (member x names) (not (member x found)))
                 (push x found))))
      (walk datum))
    (nreverse found)))

(defun scenario-file (scenario)
  "The file SCENARIO was read from, or NIL."
  (let ((positions (scenario-positions scenario)))
    (and positions (source-text-file positions))))

(defun run-error-context (scenario condition)
  "The ERROR-CONTEXT of CONDITION, signalled while SCENARIO ran: its file, the line of
the clause of the first body CONDITION's datum names (else the scenario's line), the
scenario's name, and the bodies named (\"body B\", \"bodies A and B\")."
  (let* ((bodies (bodies-named scenario (ames-error-datum condition)))
         (positions (scenario-positions scenario))
         (line (and positions
                    (or (and bodies
                             (let ((clause (find-if (lambda (clause)
                                                      (and (consp clause) (consp (cdr clause))
                                                           (eq (second clause) (first bodies))))
                                                    (scenario-form scenario))))
                               (and clause (form-line positions clause))))
                        (form-line positions (scenario-form scenario))))))
    (make-error-context
     :file (scenario-file scenario) :line line :scenario (scenario-name scenario)
     :location (cond ((null bodies) nil)
                     ((null (rest bodies)) (format nil "body ~A" (symbol-name (first bodies))))
                     (t (format nil "bodies ~{~A~^, ~} and ~A"
                                (mapcar #'symbol-name (butlast bodies))
                                (symbol-name (car (last bodies)))))))))

(defun call-with-scenario-context (scenario thunk)
  "Call THUNK; give every AMES-ERROR that leaves it without a context, but a
SCENARIO-ERROR, the context of SCENARIO (see RUN-ERROR-CONTEXT). Returns THUNK's
values."
  (handler-bind ((ames-error
                   (lambda (condition)
                     (unless (or (ames-error-context condition) (typep condition 'scenario-error))
                       (setf (ames-error-context condition)
                             (run-error-context scenario condition))))))
    (funcall thunk)))

(defun run-scenario (scenario &key (bridge (current-bridge)) settings numeric (limits *limits*))
  "Simulate SCENARIO (a SCENARIO) as one run of RUN-FILES or RUN-FILE and return its
SIMULATION-HISTORY (see this file's header): BRIDGE reset first, a budget of LIMITS,
SETTINGS (an alist (PARAMETER-NAME . NUMBER)) checked, with NUMERIC the scenario's
(:value N) defaults under them (RUN-PARAMETER-VALUES: every assumption is checked), an
AMBIGUOUS-TRANSITION that cannot be branched on stopping the run, and errors given the
scenario's context. The facts the values decided outside the simulator's own transitions
(geometric checks) are added to the history's notes as :ASSUMED, with :STATE NIL.
Signals PARAMETER-VALUES-ERROR or UNDECLARED-SYMBOL-ERROR for malformed SETTINGS,
PARAMETER-VALUE-ERROR for values that break an assumption, INVALID-LIMIT for bad LIMITS,
BUDGET-EXCEEDED when the run goes over its budget before its first state (or over a size
limit), and whatever SIMULATE signals. A run that goes over its time limit after that
(or that a signal stops, see *STOP-REQUESTED*) returns the states that finished: its
outcome is :STOPPED and its notes' :STOPPED-BY is the BUDGET-EXCEEDED."
  (let ((values (run-parameter-values scenario :settings settings :numeric numeric))
        (out-of-time nil))
    (ames.maxima:reset-bridge bridge)
    (unwind-protect
         (call-with-scenario-context
          scenario
          (lambda ()
            (handler-bind ((budget-exceeded
                             (lambda (condition)
                               (when (eq (budget-exceeded-quantity condition) :time)
                                 (setf out-of-time t)
                                 ;; the states that finished are the run's history
                                 (let ((restart (find-restart 'stop-simulation condition)))
                                   (when restart (invoke-restart restart condition)))))))
              (call-with-budget
               (lambda ()
                 (ames.algebra:with-parameter-values (values)
                   (let ((history (handler-bind ((ambiguous-transition #'stop-simulation))
                                    ;; the values decide first (a cheap proof, else assumed)
                                    (ames.algebra:call-with-values-first
                                     (lambda ()
                                       (simulate scenario :bridge bridge :parameter-values values
                                                          :limits limits))))))
                     (dolist (fact (ames.algebra:facts-from-values))
                       (unless (member fact (getf (history-notes history) :assumed)
                                       :key (lambda (entry) (getf entry :fact)) :test #'equal)
                         (push (list :state nil :fact fact)
                               (getf (history-notes history) :assumed))))
                     ;; under values, the claims are checked before they are printed
                     (ames.check:self-check-history history)
                     history)))
               :limits limits :subject (scenario-name scenario)))))
      (when out-of-time
        (ames.maxima:reset-bridge bridge :restart t)))))
