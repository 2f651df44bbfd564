;;;; src/maxima-bridge/conditions.lisp -- the conditions the Maxima bridge signals.
;;;;
;;;; Every one is an AMES-ERROR whose DATUM is the expression, relation or request (in AMES's
;;;; prefix algebra) at fault, and whose DETAIL says what went wrong.

(in-package #:ames.maxima)

(define-condition maxima-condition (ames-error)
  ()
  (:documentation "The common parent of every condition the Maxima bridge signals."))

(define-condition maxima-error (maxima-condition)
  ((message :initarg :message :initform nil :reader maxima-error-message
            :documentation "Maxima's own error message, as Maxima printed it."))
  (:documentation "Maxima signalled an error while answering a request. DATUM is the
request's expression in prefix algebra; MAXIMA-ERROR-MESSAGE is Maxima's message.")
  (:report (lambda (condition stream)
             (format stream "Maxima failed~@[ while ~A~]: ~A~@[~%  at fault: ~S~]"
                     (ames-error-detail condition)
                     (maxima-error-message condition)
                     (ames-error-datum condition)))))

(define-condition maxima-question (maxima-condition)
  ((text :initarg :text :initform "" :reader maxima-question-text
         :documentation "The question, with AMES's names in place of Maxima's.")
   (expressions :initarg :expressions :initform nil :reader maxima-question-expressions
                :documentation "The expressions the question is about, in prefix algebra."))
  (:documentation "Maxima wanted to ask a question (\"Is k positive, negative or
zero?\"). The bridge never lets it block: the request ends with this condition. The
restart ASSUME-AND-RETRY (taking a list of facts) retries the request under those facts.")
  (:report (lambda (condition stream)
             (format stream "Maxima asked a question it may not ask: ~A~@[~%  about: ~S~]~@[~%  while: ~S~]"
                     (maxima-question-text condition)
                     (maxima-question-expressions condition)
                     (ames-error-datum condition)))))

(define-condition maxima-timeout (maxima-condition)
  ((seconds :initarg :seconds :initform nil :reader maxima-timeout-seconds
            :documentation "The time limit that was exceeded."))
  (:documentation "A request took longer than the bridge's timeout. The computation was
interrupted (or the process replaced); the bridge stays usable.")
  (:report (lambda (condition stream)
             (format stream "Maxima did not answer within ~,2F s~@[ (~A)~]~@[~%  at fault: ~S~]"
                     (maxima-timeout-seconds condition)
                     (ames-error-detail condition)
                     (ames-error-datum condition)))))

(define-condition maxima-process-died (maxima-condition)
  ()
  (:documentation "The Maxima process ended while answering a request (twice in a row:
the bridge retries once on a fresh process). The next request starts a new process.")
  (:report (lambda (condition stream)
             (format stream "The Maxima process died~@[ (~A)~]~@[~%  at fault: ~S~]"
                     (ames-error-detail condition)
                     (ames-error-datum condition)))))

(define-condition solve-failed (maxima-condition)
  ()
  (:documentation "Maxima could not solve the equations (or the ODE) for the unknowns:
it gave up, answered implicitly, or answered outside the algebra. DATUM is the list of
equations.")
  (:report (lambda (condition stream)
             (format stream "Cannot solve: ~A~@[~%  equations: ~S~]"
                     (ames-error-detail condition)
                     (ames-error-datum condition)))))

(define-condition inconsistent-assumptions (maxima-condition)
  ((fact :initarg :fact :initform nil :reader inconsistent-assumptions-fact
         :documentation "The fact that contradicts the others."))
  (:documentation "Maxima found a fact contradicting the facts already assumed. The
restart RETRACT-ASSUMPTION runs the body without that fact.")
  (:report (lambda (condition stream)
             (format stream "Inconsistent assumptions: ~S contradicts the facts already assumed~@[ (~A)~]~@[~%  facts: ~S~]"
                     (inconsistent-assumptions-fact condition)
                     (ames-error-detail condition)
                     (ames-error-datum condition)))))

(define-condition untranslatable-expression (malformed-expression maxima-condition)
  ()
  (:documentation "An input outside the grammar that the bridge translates: it never
reaches Maxima. DATUM is the offending sub-expression, the EXPRESSION slot the whole."))

(define-condition untranslatable-result (maxima-condition)
  ((maxima-form :initarg :maxima-form :initform nil :reader untranslatable-result-form
                :documentation "Maxima's answer, as it came back."))
  (:documentation "Maxima answered with something outside AMES's algebra (a complex
number, an unevaluated integral, an unknown function). DATUM is the offending part.")
  (:report (lambda (condition stream)
             (format stream "Maxima's answer is outside AMES's algebra: ~A~@[~%  at fault: ~S~]"
                     (ames-error-detail condition)
                     (ames-error-datum condition)))))

(define-condition numeric-evaluation-failed (maxima-condition)
  ()
  (:documentation "An expression did not evaluate to a real number under the given
parameter values (a variable left unbound, a complex value, a division by zero).")
  (:report (lambda (condition stream)
             (format stream "No real value: ~A~@[~%  at fault: ~S~]"
                     (ames-error-detail condition)
                     (ames-error-datum condition)))))

(define-condition invalid-bridge-argument (maxima-condition)
  ()
  (:documentation "A bridge operation was called with an argument outside its contract
(an unknown strategy, an unknown that is not a name, a missing initial value). DATUM is
the argument.")
  (:report (lambda (condition stream)
             (format stream "Invalid argument to the Maxima bridge: ~A~@[~%  at fault: ~S~]"
                     (ames-error-detail condition)
                     (ames-error-datum condition)))))

(define-condition maxima-budget-exceeded (budget-exceeded maxima-condition) ()
  (:documentation "The time left in the budget of the scenario run in progress ran out
before or while Maxima answered a request (see AMES.BASE:CALL-WITH-BUDGET). It is a
BUDGET-EXCEEDED, and a MAXIMA-CONDITION so that the bridge's own clean-ups (leaving an
assumption scope) treat it as the failure of a request. DATUM is the request's
expression.")
  (:report (lambda (condition stream)
             (format-report stream "~@[The run of ~A: ~]the time limit of ~A s was exceeded while Maxima was answering a request~@[~%  at fault: ~S~]"
                            (let ((subject (budget-exceeded-subject condition)))
                              (and subject (not (ames-error-context condition))
                                   (princ-to-string subject)))
                            (budget-exceeded-limit condition)
                            (ames-error-datum condition)))))

(define-condition maxima-output-overflow (maxima-condition)
  ((limit :initarg :limit :initform nil :reader maxima-output-overflow-limit
          :documentation "The most characters a reply may have."))
  (:documentation "Maxima printed a reply longer than the bridge's reply buffer holds
(*REPLY-LIMIT* characters). The process was ended; the next request starts a new one.")
  (:report (lambda (condition stream)
             (format-report stream "Maxima's reply is longer than ~:D characters~@[ (~A)~]~@[~%  at fault: ~S~]"
                            (maxima-output-overflow-limit condition)
                            (ames-error-detail condition)
                            (ames-error-datum condition)))))
