;;;; src/interface/check.lisp -- bin/ames check: AMES's run beside the witness's (Siconos).
;;;;
;;;; WITNESS-CHECK runs one scenario through AMES (in this process, its s-expression
;;;; report read back as data) and through the witness (src/witness/, Siconos), and gives a
;;;; verdict: :AGREE, :AMES-WRONG (a disagreement), :REFUSED (AMES stopped with a message:
;;;; a scenario error, a budget, an undecided run), :CRASH (a defect of AMES: a Lisp error
;;;; that is no AMES-ERROR), :UNSUPPORTED (the witness cannot model the scenario, or AMES
;;;; does not simulate it yet: SCENARIO-AWAITING, a rotating body) or
;;;; :WITNESS-FAILED (the driver did not answer), or :UNCHECKED (AMES gives a state no
;;;; number to compare, e.g. a duration without one: counted apart, neither agree nor wrong). CROSSCHECK (crosscheck.lisp) runs random
;;;; scenarios.

(in-package #:ames)

(defun read-ames-answer (text)
  "The first s-expression of TEXT (AMES's own sexp report), read as data."
  (with-standard-io-syntax
    (let ((*read-eval* nil) (*package* (find-package '#:ames-scenario))
          (*read-default-float-format* 'double-float))
      (read-from-string text))))

(defun ames-answer (scenario &key settings numeric (limits *limits*))
  "Run SCENARIO through AMES. Returns (values ANSWER FAILURE MESSAGE): ANSWER the
s-expression report as data, or NIL with FAILURE :REFUSED or :CRASH and MESSAGE."
  (handler-case
      (let ((history (run-scenario scenario :settings settings :numeric numeric :limits limits)))
        (if (undecided-history-p history)
            (values nil :refused "the run ended ambiguous or undecided")
            (values (read-ames-answer
                     (with-output-to-string (stream)
                       (let ((output (make-report-output :sexp stream)))
                         (report-history output history)
                         (finish-report output))))
                    nil nil)))
    (ames-error (condition) (values nil :refused (princ-to-string condition)))
    (error (condition) (values nil :crash (format nil "~A: ~A" (type-of condition) condition)))))

(defun witness-horizon (answer values)
  "How far the witness runs: a little past AMES's last event (20 ms: a first-order witness
confirms a slide's start or end over a few of its steps, 1 ms for rotating bodies), or a
while into a last state that lasts forever."
  (let ((states (ames.witness:ames-path (getf answer :states)))
        (end (ames.witness:ames-end-time answer values)))
    (when end
      (let ((last-event (getf (car (last states)) :end-event)))
        (cond ((eq last-event :none)
               (+ end 1/2 (ames.witness:witness-horizon-extra answer values)))
              ((and (consp last-event) (eq (first last-event) :time-limit))
               end)                     ; the scenario's own end: nothing to find past it
              (t (+ end (max (* 1d-6 (+ 1 end)) 1/50))))))))

(defun witness-check (scenario &key settings numeric (limits *limits*))
  "Run SCENARIO through AMES and the witness; a plist (:VERDICT V :REASON TEXT
:COMPARISON C :ANSWER A :WITNESS W)."
  (let ((awaiting (scenario-awaiting scenario)))
    ;; what AMES does not simulate yet (a rotating body): said so, not counted as refused
    (when awaiting
      (return-from witness-check
        (list :verdict :unsupported :reason (format nil "by AMES: ~A" (second (first awaiting)))))))
  (multiple-value-bind (answer failure message)
      (ames-answer scenario :settings settings :numeric numeric :limits limits)
    (when failure
      (return-from witness-check (list :verdict failure :reason message)))
    (let* ((values (run-parameter-values scenario :settings settings :numeric numeric))
           (horizon (witness-horizon answer values)))
      (unless horizon
        (return-from witness-check
          (list :verdict :unsupported :answer answer
                :reason "AMES's run has no numeric end time (values missing?)")))
      (handler-case
          (let* ((model (ames.witness:scenario-model scenario values horizon
                                                     :samples (ames.witness:witness-sample-times answer values)))
                 (witness (ames.witness:run-witness model)))
            (case (ames.witness:witness-status witness)
              ;; a first-order witness's disagreement is checked at a finer step (refine.lisp)
              (:ok (multiple-value-bind (comparison witness)
                       (ames.witness:compare-refining answer model witness values :t-end horizon)
                     (list :verdict (ames.witness:comparison-verdict comparison)
                           :reason (ames.witness:comparison-reason comparison)
                           :comparison comparison :answer answer :witness witness)))
              (:unsupported (list :verdict :unsupported :reason (getf witness :message)
                                  :answer answer :witness witness))
              (t (list :verdict :witness-failed :reason (getf witness :message)
                       :answer answer :witness witness))))
        (ames.witness:witness-unsupported (condition)
          (list :verdict :unsupported :reason (princ-to-string condition) :answer answer))))))

(defun check-files (files &key settings numeric (stream *standard-output*) (limits *limits*))
  "bin/ames check: for every scenario of FILES, print AMES's and the witness's values
side by side and the verdict. Returns the exit status: 0 when every scenario agrees, 4
when one disagrees (or AMES crashed), else 1 (refused, not witnessed, or a file that
cannot be read: its AMES-ERROR is printed, naming the form at fault)."
  (unless (ames.witness:siconos-available-p)
    (format *error-output* "ames: the witness needs ~A with Siconos (Debian's python3-siconos)~%"
            ames.witness:*python*)
    (return-from check-files 1))
  (let ((status 0))
    (dolist (file files status)
      ;; a file that cannot be read is said so, by the form at fault, and the others run
      (dolist (scenario (handler-case (read-scenario-file file)
                          (ames-error (condition)
                            (print-error-message condition)
                            (setf status (max status 1))
                            '())))
        (let* ((result (witness-check scenario :settings settings :numeric numeric :limits limits))
               (verdict (getf result :verdict)))
          (format stream "~&scenario ~(~A~) (~A)~%" (scenario-name scenario) file)
          (if (getf result :comparison)
              (ames.witness:print-comparison (getf result :comparison) stream)
              (format stream "verdict: ~(~A~)~@[: ~A~]~%" verdict (getf result :reason)))
          (setf status (max status (verdict-status verdict))))))))

(defun verdict-status (verdict)
  "The exit status of bin/ames check for one scenario's VERDICT: 0 agree, 4 AMES wrong or
crashed, 1 anything else (refused, unsupported, the witness failed)."
  (case verdict
    (:agree 0)
    ((:ames-wrong :crash) 4)
    (t 1)))
