;;;; src/maxima-bridge/assumptions.lisp -- scoped assumptions (Maxima contexts) and the sign facts Maxima misses.
;;;;
;;;; Each WITH-ASSUMPTIONS scope is one Maxima context made with supcontext and ended with
;;;; killcontext, so facts never leak out of their scope. Maxima does not use the range of
;;;; an angle to find the sign of its sine or cosine (with 0 < a < pi/2, is(cos(a) > 0) is
;;;; unknown), so the algebra layer derives those facts from the numeric bounds of each
;;;; variable (exactly, see src/algebra/angles.lisp) and the bridge assumes them too,
;;;; through *DERIVED-FACTS*. The frames are kept in the bridge, so a restarted
;;;; Maxima process gets them replayed.

(in-package #:ames.maxima)

;;; Facts as Maxima can assume them

(defun negate-condition (condition)
  "The prefix condition saying the opposite of CONDITION."
  (let ((operator (expression-operator condition))
        (arguments (expression-arguments condition)))
    (case operator
      (= (list* '/= arguments)) (/= (list* '= arguments))
      (< (list* '>= arguments)) (>= (list* '< arguments))
      (> (list* '<= arguments)) (<= (list* '> arguments))
      (not (first arguments))
      (and (list* 'or (mapcar #'negate-condition arguments)))
      (or (list* 'and (mapcar #'negate-condition arguments))))))

(defun flatten-facts (facts)
  "FACTS with conjunctions spread out and negations pushed inward."
  (loop for fact in facts
        append (case (expression-operator fact)
                 (and (flatten-facts (expression-arguments fact)))
                 (not (flatten-facts (list (negate-condition (second fact)))))
                 (t (list fact)))))

(defun fact-to-maxima (table fact)
  "The Maxima form of the relation FACT, as assume() takes it (= and /= become
equal() and notequal())."
  (let ((form (to-maxima table fact :kind :condition)))
    (case (expression-operator fact)
      (= (apply #'mform +equal+ (mform-arguments form)))
      (/= (apply #'mform +notequal+ (mform-arguments form)))
      (t form))))

(defun subject-p (x)
  "True for what a bound can be about: a variable or a quantity term."
  (or (variable-symbol-p x) (quantity-term-p x)))

;;; What the algebra layer adds to the facts (it sits above the bridge, so it installs
;;; its functions here rather than being called by name)

(defvar *derived-facts* nil
  "The function that reads off, from a list of flattened facts, the facts a physicist
sees at once and Maxima misses (the signs of sin, cos and tan of a bounded angle), to be
assumed with them; NIL derives none. Installed by the algebra layer (src/algebra/bounds.lisp).")

(defvar *told-fact* nil
  "The function of a bridge and a fact that gives the fact as Maxima is to be told it (a
product of square roots of negative radicands written with real roots); NIL tells every
fact as given. Installed by the algebra layer (src/algebra/radicals.lisp).")

(defun derived-facts (facts)
  "The facts *DERIVED-FACTS* reads off FACTS (flattened first), or none."
  (and *derived-facts* (funcall *derived-facts* (flatten-facts facts))))

(defun told-fact (bridge fact)
  "FACT as Maxima is told it: through *TOLD-FACT*, or as given."
  (if *told-fact* (funcall *told-fact* bridge fact) fact))

;;; Scopes

(defun current-assumptions (bridge)
  "The facts in force in BRIDGE, outermost scope first, as they were given (derived
facts not included)."
  (loop for frame in (reverse (bridge-frames bridge))
        append (assumption-frame-facts frame)))

(defun frame-setup-form (frame)
  "The Maxima request that opens FRAME's context and assumes its facts."
  (let ((facts (assumption-frame-maxima-facts frame)))
    (mlist (list* (mform (wire "$SUPCONTEXT") (assumption-frame-context frame))
                  (when facts (list (apply #'mform (wire "$ASSUME") facts)))))))

(defun replay-assumptions (bridge)
  "Open again, in a fresh Maxima process, every active frame of BRIDGE."
  (dolist (frame (reverse (bridge-frames bridge)))
    (multiple-value-bind (status data) (round-trip bridge (list :eval (frame-setup-form frame)))
      (unless (eq status :ok)
        (discard-process bridge)
        (error 'maxima-process-died
               :datum (assumption-frame-facts frame)
               :detail (format nil "replaying assumptions failed: ~S ~S" status data)))
      (setf (assumption-frame-opened frame) t))))

;;; Scopes opened when first needed
;;;
;;; Most scopes of the reasoning (the order substitution's excess > 0, the cases of abs)
;;; are entered again and again with the same facts, and the question asked inside is
;;; then answered from the cache: setting up and killing the Maxima context cost two
;;; round trips for nothing. A scope whose facts in force (all frames) were once set up
;;; in this Maxima process without contradiction is therefore entered without asking
;;; Maxima, and its context is set up only before the first request that reaches
;;; Maxima inside it (OPEN-PENDING-FRAMES), killed only if it was set up. Facts not seen
;;; before are set up at once, as before, so that a contradiction is still signalled
;;; where the scope is entered.

(defvar *consistent-scopes* (make-hash-table :test 'eq :weakness :key)
  "Maxima process -> the set (a hash table) of the assumption numbers (see
ASSUMPTION-KEY) whose scopes were set up in it without contradiction.")

(defun consistent-scopes (bridge)
  "The set of the assumption numbers known consistent in BRIDGE's current process."
  (let ((process (bridge-process bridge)))
    (and process
         (or (gethash process *consistent-scopes*)
             (setf (gethash process *consistent-scopes*) (make-hash-table))))))

(defun known-consistent-p (bridge frame)
  "True when the facts in force with FRAME pushed were set up in BRIDGE's process before
without contradiction."
  (let ((id (gethash (mapcar #'assumption-frame-maxima-facts (cons frame (bridge-frames bridge)))
                     *assumption-ids*))
        (known (consistent-scopes bridge)))
    (and id known (bridge-alive-p bridge) (gethash id known))))

(defun open-pending-frames (bridge timeout)
  "Set up in Maxima, outermost first, the frames of BRIDGE entered without it (see
KNOWN-CONSISTENT-P), each within TIMEOUT seconds. A set-up that does not answer :OK
ends the process (a fresh one replays every frame) and signals MAXIMA-BUDGET-EXCEEDED
(the run's time is up), MAXIMA-TIMEOUT or MAXIMA-PROCESS-DIED."
  (dolist (frame (reverse (bridge-frames bridge)))
    (unless (assumption-frame-opened frame)
      (multiple-value-bind (status data)
          (round-trip bridge (list :eval (frame-setup-form frame)) timeout)
        (unless (eq status :ok)
          (let ((facts (assumption-frame-facts frame)))
            (discard-process bridge)
            (cond ((and (eq status :timeout) (nth-value 1 (request-timeout bridge)))
                   (signal-out-of-time facts))
                  ((eq status :timeout)
                   (error 'maxima-timeout :seconds timeout :datum facts
                                          :detail "setting up assumptions was interrupted"))
                  (t (error 'maxima-process-died
                            :datum facts
                            :detail (format nil "setting up assumptions failed: ~S ~S" status data))))))
        (setf (assumption-frame-opened frame) t)))))

(defun pop-frame (bridge frame)
  "Leave FRAME (the innermost) and kill its Maxima context. When Maxima cannot do that,
the process is discarded: a new one is built from the remaining frames."
  (setf (bridge-frames bridge) (remove frame (bridge-frames bridge)))
  (when (and (bridge-alive-p bridge) (assumption-frame-opened frame))
    (let ((parent (if (bridge-frames bridge)
                      (assumption-frame-context (first (bridge-frames bridge)))
                      +initial-context+)))
      (handler-case
          (maxima-request bridge (mform (wire "$AMES_POP_CONTEXT")
                                        (assumption-frame-context frame) parent)
                          :cache nil)
        (maxima-condition () (discard-process bridge))))))

(defun call-in-pending-frame (bridge frame thunk)
  "Call THUNK with FRAME pushed but not set up in Maxima: OPEN-PENDING-FRAMES sets it up
before the first request that reaches Maxima inside, POP-FRAME kills it only if it was.
Returns THUNK's values."
  (setf (assumption-frame-opened frame) nil)
  (push frame (bridge-frames bridge))
  (unwind-protect (funcall thunk)
    (pop-frame bridge frame)))

(defun call-with-assumptions (bridge facts thunk)
  "Call THUNK with FACTS (a list of relations in prefix algebra, e.g.
((> mp 0) (> a 0) (< a (/ pi 2)))) assumed in BRIDGE's Maxima, in a scope of their own
that ends when THUNK returns or exits; scopes nest. Adds the sign facts of sin, cos and
tan that follow from numeric bounds (0 < a < pi/2 gives sin a > 0, cos a > 0, tan a > 0).
A fact with a product of square roots of negative radicands is told to Maxima with
real roots (sqrt(A) sqrt(B) = -sqrt(-A) sqrt(-B) for A, B < 0). Returns THUNK's values.
Signals UNTRANSLATABLE-EXPRESSION for a fact outside the algebra, MAXIMA-ERROR when
Maxima cannot assume a fact (a disjunction, say), and INCONSISTENT-ASSUMPTIONS naming
the fact that contradicts the facts in force; its restart RETRACT-ASSUMPTION calls THUNK
under the other facts. Facts in force that were set up in this Maxima process before
without contradiction are not set up again until a request needs them (see
CALL-IN-PENDING-FRAME)."
  (unless (listp facts)
    (error 'untranslatable-expression :datum facts :expression facts
                                      :detail "assumptions must be a list of relations"))
  (dolist (fact facts) (check-translatable fact :condition))
  (let* ((table (bridge-names bridge))
         (outer (current-assumptions bridge))
         (already (derived-facts outer))
         (derived (remove-if (lambda (fact) (member fact already :test #'equal))
                             (derived-facts (append outer facts))))
         (flat (flatten-facts facts))
         ;; Derived facts go first, so that a contradiction is laid at a given fact.
         (sources (append derived flat))
         ;; Maxima is told facts with real square roots only (see *TOLD-FACT*)
         (assumed (append derived (mapcar (lambda (fact) (told-fact bridge fact)) flat)))
         (frame (make-assumption-frame (fresh-context-name table) facts
                                       (mapcar (lambda (fact) (fact-to-maxima table fact))
                                               assumed))))
    (when (known-consistent-p bridge frame)
      (return-from call-with-assumptions (call-in-pending-frame bridge frame thunk)))
    (let* ((answer (let ((opened nil))
                     (unwind-protect
                          (prog1 (maxima-request bridge (frame-setup-form frame)
                                                 :cache nil :datum facts)
                            (setf opened t))
                       ;; A failed set-up may have left the context open in Maxima.
                       (unless opened (pop-frame bridge frame)))))
           (verdicts (and (rest (mlist-items answer)) (mlist-items (second (mlist-items answer)))))
           (position (position +inconsistent+ verdicts)))
      (push frame (bridge-frames bridge))
      (if position
          (pop-frame bridge frame)
          (let ((known (consistent-scopes bridge)))
            (when known (setf (gethash (assumption-key bridge) known) t))))
      (when position
        (let ((culprit (nth position sources)))
          (restart-case
              (error 'inconsistent-assumptions :fact culprit :datum facts
                                               :detail "Maxima's assume() says inconsistent")
            (retract-assumption ()
              :report (lambda (stream)
                        (format stream "Retract ~S and go on with the other facts." culprit))
              (return-from call-with-assumptions
                (call-with-assumptions bridge (remove-offending-fact culprit facts) thunk))))))
      (unwind-protect (funcall thunk)
        (pop-frame bridge frame)))))

(defun remove-offending-fact (culprit facts)
  "FACTS without CULPRIT (or without the conjunction or negation that contains it)."
  (remove-if (lambda (fact) (member culprit (flatten-facts (list fact)) :test #'equal))
             facts))

(defmacro with-assumptions ((bridge facts) &body body)
  "Run BODY with FACTS assumed in BRIDGE's Maxima: see CALL-WITH-ASSUMPTIONS."
  `(call-with-assumptions ,bridge ,facts (lambda () ,@body)))
