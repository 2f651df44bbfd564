;;;; src/simulator/queries.lisp -- answering a scenario's queries from its history (thesis 3.2.4,
;;;; "Problem Solving Extensions"): analysis (the value of a quantity at an event, a state's
;;;; start or end, or a time), the time of an event, proofs over a state or the whole run,
;;;; extrema over a state, and parameter selection (the conditions on a parameter under
;;;; which an outcome happens, read off the branches of the run's tree).
;;;;
;;;; A run that branched is answered branch by branch: each path from the root to a leaf of
;;;; the tree, with the facts assumed along it. An answer is (NAME VALUE [:ASSUME FACTS]
;;;; [:NUMERIC N]) or (NAME :UNANSWERED :REASON TEXT [:ASSUME FACTS]); a VALUE is an
;;;; expression, a vector, (:TRUE/:FALSE/:UNKNOWN REASON) for a proof, (:WHEN CONJUNCTION...)
;;;; or (:ALWAYS/:NEVER REASON) for a parameter selection (its condition in its simplest
;;;; form, simplest-conditions.lisp), or (:NEVER REASON) for a value never reached.
;;;; Quantities are read as the knowledge base reports them (quantities.lisp); the
;;;; questions of "Queries, more questions" are in questions.lisp. A query that fails, for
;;;; whatever reason, is not answered and says why: it never ends the run.

(in-package #:ames.simulator)

(defun history-paths (history)
  "The paths of HISTORY's tree, each (FACTS OUTCOME . STATES): the facts assumed along it,
how its last branch ended, and its states in order (a fork's branches continue after
the fork state)."
  (labels ((paths (states facts outcome)
             (let ((fork (find-if #'state-branches states)))
               (if (null fork)
                   (list (list* facts outcome states))
                   (let ((before (ldiff states (member fork states))))
                     (loop for branch in (state-branches fork)
                           append (mapcar (lambda (path)
                                            (list* (first path) (second path)
                                                   (append before (list fork) (cddr path))))
                                          (paths (getf branch :states)
                                                 (append facts (list (getf branch :assume)))
                                                 (getf branch :outcome)))))))))
    (paths (history-states history) '() (history-outcome history))))

(defun unsimulated-branch-reason (history facts)
  "Why the branch that ends the path assuming FACTS (a list, the last the branch's own)
of HISTORY's tree was listed unsimulated, when its fork says (a boundary no parameter is
solved for: its :FAILURE), else NIL (the values rule it out)."
  (let ((fact (car (last facts))))
    (labels ((search-states (states)
               (dolist (state states)
                 (dolist (branch (state-branches state))
                   (when (and (equal (getf branch :assume) fact) (null (getf branch :states))
                              (getf branch :failure))
                     (return-from unsimulated-branch-reason (getf branch :failure)))
                   (search-states (getf branch :states))))))
      (search-states (history-states history))
      nil)))

(defun event-matches-p (pattern event)
  "True when the printed EVENT begins with PATTERN, names compared by name. An event
between two bodies matches with the bodies in either order: (:leaves block cart) is the
event printed (:leaves cart block :endpoint) when the cart is the observer."
  (flet ((begins-with-p (pattern)
           (and (consp event) (<= (length pattern) (length event))
                (every (lambda (p e) (or (eql p e) (and (symbolp p) (symbolp e)
                                                        (string= (symbol-name p) (symbol-name e)))))
                       pattern event))))
    (or (begins-with-p pattern)
        (and (>= (length pattern) 3)
             (begins-with-p (list* (first pattern) (third pattern) (second pattern)
                                   (nthcdr 3 pattern)))))))

(defun state-events (state)
  "Every event that ends STATE."
  (let ((event (state-end-event state)))
    (remove-duplicates (append (and (consp event) (list event)) (state-simultaneous-events state))
                       :test #'equal)))

(defun event-state (states pattern)
  "The first of STATES that ends with an event matching PATTERN, or NIL."
  (find-if (lambda (state) (some (lambda (event) (event-matches-p pattern event)) (state-events state)))
           states))

(define-condition unanswerable (simulation-error) ()
  (:documentation "A query cannot be answered from the history; DETAIL says why."))

(defun unanswerable (control &rest arguments)
  "Signal UNANSWERABLE with the reason CONTROL and ARGUMENTS."
  (error 'unanswerable :detail (let ((*print-pretty* nil)) (apply #'format nil control arguments))))

(defun at-point (expression state at)
  "EXPRESSION of STATE evaluated AT :START, :END or a local time: TAU put to 0, the
duration or the time, or (:ARC S) the arc length S; over a curve's or a line's arc length, the arc length put to its
start or end (no time needed: the energy integral gives the speed there)."
  (cond ((and (consp at) (eq (first at) :arc))
         ;; a point along the state's coordinate (reaches-at.lisp)
         (unless (free-of-p 'tau expression)
           (unanswerable "in state ~D the time at that point has no closed form" (state-index state)))
         (substitute-expressions (list (cons +arc-length+ (second at))) expression))
        ((not (free-of-p +arc-length+ expression))
         (substitute-expressions
          (list (cons +arc-length+
                      (case at
                        (:start (or (arc-length-start state)
                                    (unanswerable "where the motion of state ~D starts along its path is not known"
                                                  (state-index state))))
                        (:end (or (arc-length-end state)
                                  (unanswerable "state ~D never ends on its path" (state-index state))))
                        (t (unanswerable "along a path a time inside the state has no closed form")))))
          expression))
        ((free-of-p 'tau expression) expression)
        (t (substitute-expressions
            (list (cons 'tau (case at
                               (:start 0)
                               (:end (let ((d (state-duration state)))
                                       (if (closed-form-p d)
                                           d
                                           (unanswerable "state ~D has no closed-form end" (state-index state)))))
                               (t at))))
            expression))))

(defun vector-of (entry)
  "A per-body vector entry, the :ON-PATH form reduced to its point."
  (cond ((and (consp entry) (eq (first entry) :on-path)) (second entry))
        ((equal entry '(:no-closed-form)) (unanswerable "the motion has no closed form in time"))
        (t entry)))

(defun rotation-of (entry)
  "A rotating body's scalar entry (its angle, angular velocity or acceleration)."
  (if (equal entry '(:no-closed-form))
      (unanswerable "the motion has no closed form in time")
      entry))

(defun reported-force-value (state kind names)
  "The value of the force entry of KIND that STATE reports between NAMES (the names that
lead the entry: AMES.KB:FORCE-DESCRIPTION's :NAMES of them, in this order or reversed,
compared by name), or 0 when the state reports none: that force does not act."
  (let* ((count (getf (ames.kb:force-description kind) :names (length names)))
         (entry (find-if (lambda (f)
                           (and (eq (first f) kind)
                                (let ((leading (subseq (rest f) 0 (min count (length (rest f))))))
                                  (or (every #'named-alike-p leading names)
                                      (every #'named-alike-p leading (reverse names))))))
                         (state-forces state))))
    (if entry (nth (1+ count) entry) 0)))

(defun quantity-expression (scenario state form)
  "The quantity FORM (see src/scenario/queries.lisp) in STATE, over its local time. A
quantity a phenomenon answers (AMES.KB:QUANTITY-DESCRIPTION: a force it reports) is read
off the state's forces."
  (flet ((body (name) (or (find-scenario-body name scenario) (unanswerable "~A is no body" name)))
         (place (b) (vector-of (recorded state (state-positions state) b)))
         (velocity (b) (vector-of (recorded state (state-velocities state) b))))
    (let ((described (ames.kb:quantity-description (first form)))
          (term (ames.kb:query-reported-term (first form))))
      (cond
        (described (reported-force-value state (getf described :force) (rest form)))
        (term (or (reported-body-term state term (second form)
                                      (scenario-body-fixed-p (body (second form))))
                  (unanswerable "state ~D reports no ~(~A~) of ~(~A~)" (state-index state)
                                (substitute #\Space #\- (symbol-name (first form))) (second form))))
        (t
          (ecase (first form)
            (:x (first (place (second form))))
            (:y (second (place (second form))))
            (:position (place (second form)))
            (:velocity (velocity (second form)))
            (:acceleration (vector-of (recorded state (state-accelerations state) (second form))))
            (:angle (rotation-of (recorded state (state-angles state) (second form))))
            (:angular-velocity (rotation-of (recorded state (state-angular-velocities state) (second form))))
            (:angular-acceleration (rotation-of (recorded state (state-angular-accelerations state)
                                                          (second form))))
            (:speed (let ((v (velocity (second form)))) `(sqrt (+ (expt ,(first v) 2) (expt ,(second v) 2)))))
            (:energy (system-energy scenario state))
            (:time (if (closed-form-p (state-start state))
                       `(+ ,(state-start state) tau)
                       (unanswerable "state ~D's start has no closed form" (state-index state))))
            (:component (let ((vector (quantity-expression scenario state (third form))))
                          (if (eq (second form) :x) (first vector) (second vector))))))))))

(defun system-energy (scenario state)
  "The whole system's energy in STATE: the sum of the terms the knowledge base reports,
the report's total T + V (kinetic energy of the free bodies and the potential energy of
the conservative sources; the work of an external force is not in it)."
  (declare (ignore scenario))
  (or (state-total-energy state)
      (unanswerable "state ~D reports no energy" (state-index state))))

(defun quantity-in (scenario state form)
  "FORM, a query's quantity (an expression over quantity forms), in STATE over TAU."
  (cond ((and (consp form) (keywordp (first form)))
         (let ((value (if *known-terms*
                          (substitute-expressions *known-terms* (quantity-expression scenario state form))
                          (quantity-expression scenario state form))))
           (when (mentions-unknown-p value)
             (unanswerable "state ~D's motion has no closed form" (state-index state)))
           value))
        ((consp form) (let ((parts (mapcar (lambda (x) (quantity-in scenario state x)) (rest form))))
                        (when (some #'vector-p* parts)
                          (unanswerable "arithmetic on a vector quantity"))
                        (cons (first form) parts)))
        (t form)))

(defun vector-p* (x)
  "True when X is a two-element vector of expressions (a vector quantity's value)."
  (and (consp x) (= (length x) 2) (not (symbolp (first x)))))

(defun fork-state-p (state)
  "True when STATE is a fork (end event (:BRANCH)): no period of motion, and no number
that queries count (the state it splits, in each branch, has its index)."
  (equal (state-end-event state) '(:branch)))

(defun resolve-when (bridge states when)
  "The STATE and point (:START, :END or a local time) WHEN names among STATES; a state
number N counts periods of motion, never a fork."
  (flet ((indexed (n) (or (find-if (lambda (state) (and (eql n (state-index state))
                                                         (not (fork-state-p state))))
                                    states)
                           (unanswerable "there is no state ~D" n))))
    (ecase (first when)
      (:start (values (indexed (second when)) :start))
      (:end (values (indexed (second when)) :end))
      (:event (values (or (event-state states (second when))
                          (unanswerable "~(~S~) does not happen in this run" (second when)))
                      :end))
      (:time (state-at-time bridge states (second when))))))

(defun closed-form-p (x)
  "True when X is an expression (not :FOREVER, :UNDECIDED or a (:NO-CLOSED-FORM ...))."
  (not (or (keywordp x) (and (consp x) (keywordp (first x))))))

(defun state-at-time (bridge states time)
  "The state of STATES in which the global TIME falls, and the local time there, as
decided under the assumptions in BRIDGE; signals UNANSWERABLE when it is not decided."
  (dolist (state states (run-end-at-time bridge states time))
    (let ((start (state-start state)) (duration (state-duration state)))
      (unless (closed-form-p start) (unanswerable "a state's start has no closed form"))
      (when (eq (ames.algebra:decide bridge `(>= ,time ,start)) :true)
        (cond ((eq duration :forever) (return (values state `(- ,time ,start))))
              ((not (closed-form-p duration)) (unanswerable "state ~D has no closed-form end" (state-index state)))
              (t (case (ames.algebra:decide bridge `(< ,time (+ ,start ,duration)))
                   (:true (return (values state `(- ,time ,start))))
                   (:unknown (unanswerable "whether t = ~A falls in state ~D is not decided" time (state-index state))))))))))

(defun run-end-at-time (bridge states time)
  "The last period of motion of STATES and its local end when the global TIME is decided
to be the instant the run stops (a time limit, the last state's end): a value there is
the final state's; else signals UNANSWERABLE."
  (let ((last (find-if-not #'fork-state-p states :from-end t)))
    (when last
      (let ((start (state-start last)) (duration (state-duration last)))
        (when (and (closed-form-p start) (closed-form-p duration)
                   (eq (ames.algebra:decide bridge `(= ,time (+ ,start ,duration))) :true))
          (return-from run-end-at-time (values last duration)))))
    (unanswerable "the run does not reach t = ~A" time)))

(defun value-at (bridge scenario states quantity when)
  "QUANTITY (a query's) at WHEN among STATES, simplified."
  (multiple-value-bind (state at) (if (eq (first when) :reaches)
                                      (reaches-point bridge scenario states (second when) (third when))
                                      (resolve-when bridge states when))
    (let ((value (let ((*known-terms* (known-terms-at scenario states state at)))
                   (quantity-in scenario state quantity))))
      (simplified bridge (if (vector-p* value)
                             (mapcar (lambda (x) (at-point x state at)) value)
                             (at-point value state at))))))

(defun event-time (bridge states pattern)
  "The global time at which the event PATTERN first happens among STATES."
  (let ((state (or (event-state states pattern) (unanswerable "~(~S~) does not happen in this run" pattern))))
    (unless (and (closed-form-p (state-start state)) (closed-form-p (state-duration state)))
      (unanswerable "the time of ~(~S~) has no closed form" pattern))
    (ames.maxima:simplify bridge `(+ ,(state-start state) ,(state-duration state)) :strategy :full)))

(defun parameter-conditions (bridge parameter fact)
  "The inequality FACT as a condition on PARAMETER alone, (OP PARAMETER VALUE), when it
is linear in it with a coefficient of decided sign; else FACT."
  (let* ((x `(- ,(relation-lhs fact) ,(relation-rhs fact)))
         (coefficient (ames.maxima:simplify bridge (ames.geometry:differentiate x parameter) :strategy :full)))
    (if (or (not (free-of-p parameter coefficient)) (free-of-p parameter x))
        fact
        (let ((sign (cond ((ames.algebra:holds-p bridge `(> ,coefficient 0)) 1)
                          ((ames.algebra:holds-p bridge `(< ,coefficient 0)) -1))))
          (if (null sign)
              fact
              (let ((value (ames.maxima:simplify bridge `(- ,parameter (/ ,x ,coefficient)) :strategy :full))
                    (operator (first fact)))
                (list (if (= sign 1) operator
                          (ecase operator (> '<) (< '>) (>= '<=) (<= '>=) (= '=)))
                      parameter value)))))))

(defun simplified (bridge expression)
  "EXPRESSION in its simplest real form through BRIDGE (each component of a vector)."
  (if (vector-p* expression)
      (mapcar (lambda (x) (ames.algebra:simplify-real bridge x)) expression)
      (ames.algebra:simplify-real bridge expression)))

(defun answer-question (bridge scenario question facts outcome states paths)
  "QUESTION's answer on one path (its FACTS, OUTCOME and STATES); PATHS are all the
run's paths (for parameter selection). Returns the answer's value; signals UNANSWERABLE."
  (declare (ignore facts))
  (ecase (first question)
    (:value (value-at bridge scenario states (second question) (getf (cddr question) :at)))
    (:time (event-time bridge states (second question)))
    (:time-at (value-at bridge scenario states '(:time) (second question)))
    (:rest-time (rest-time bridge scenario states outcome (second question)))
    (:reaches-time (reaches-time bridge scenario states (second question) (third question)))
    (:distance (distance-travelled bridge scenario states outcome (second question)
                                   (getf (cddr question) :during)))
    (:prove (multiple-value-bind (verdict reason)
                (prove-on-path bridge scenario states outcome (second question)
                               (getf (cddr question) :during))
              (list verdict reason)))
    ((:maximum :minimum)
     (extremum-in bridge scenario states (second question)
                  (or (getf (cddr question) :during) (unanswerable "say over which state (:during (start N))"))
                  (eq (first question) :maximum)))
    (:parameter
     (let* ((parameter (second question))
            (condition (getf (cddr question) :such-that))
            (verdicts (loop for (path-facts path-outcome . path-states) in paths
                            collect (cons (ames.maxima:with-assumptions (bridge path-facts)
                                            (prove-on-path bridge scenario path-states path-outcome condition nil))
                                          path-facts)))
            (holding (loop for (verdict . path-facts) in verdicts when (eq verdict :true) collect path-facts))
            (undecided (find :unknown verdicts :key #'first)))
       (when undecided
         (unanswerable "whether it holds is not decided on the branch assuming ~{~(~S~)~^ and ~}"
                       (rest undecided)))
       (cond ((null holding) (list :never "on no branch of the run"))
             ((= (length holding) (length paths)) (list :always "on every branch of the run"))
             (t (let ((plain (simplest-condition bridge holding (scenario-assumption-relations scenario))))
                  (case plain
                    (:true (list :always "under the assumptions"))
                    (:false (list :never "under the assumptions"))
                    (t (cons :when (mapcar (lambda (conjunction)
                                             (mapcar (lambda (fact) (parameter-conditions bridge parameter fact))
                                                     conjunction))
                                           plain)))))))))))

(defun numeric-answer (bridge value values)
  "VALUE's number under the parameter VALUES, when it has one."
  (and values (not (keywordp value))
       (if (vector-p* value)
           (let ((numbers (mapcar (lambda (x) (numeric-or-nil bridge x values)) value)))
             (and (every #'realp numbers) numbers))
           (and (not (and (consp value) (keywordp (first value))))
                (numeric-or-nil bridge value values)))))

(defun answer-queries (history bridge)
  "The answers to the queries of HISTORY's scenario, each (NAME VALUE [:ASSUME FACTS]
[:NUMERIC N]) or (NAME :UNANSWERED :REASON TEXT [:ASSUME FACTS]); one per path of the
run's tree when it branched (a parameter selection once, from every path). Call under
the scenario's assumptions."
  (let* ((scenario (history-scenario history))
         (paths (history-paths history))
         (values (history-parameter-values history))
         (branched (rest paths)))
    (loop for (name question) in (scenario-queries scenario)
          append (loop for (facts outcome . states) in (if (eq (first question) :parameter)
                                                             (list (first paths))
                                                             paths)
                       collect (let ((assume (and branched (not (eq (first question) :parameter))
                                                  (list :assume facts))))
                                 (handler-case
                                     (ames.maxima:with-assumptions (bridge (and assume facts))
                                       (when (eq outcome :not-simulated)
                                         (let ((why (unsimulated-branch-reason history facts)))
                                           (if why
                                               (unanswerable "~A" why)
                                               (unanswerable "the values rule this branch out, and it is not simulated (--all-branches simulates it)"))))
                                       (let ((value (answer-question bridge scenario question facts
                                                                     outcome states paths)))
                                         (when (and (not (member (first question) '(:prove :parameter)))
                                                    (not (and (free-of-p 'tau value) (free-of-p +arc-length+ value))))
                                           (unanswerable "the answer still depends on a state's own time or arc length"))
                                         (append (list name value) assume
                                                 ;; numbers only with values that satisfy
                                                 ;; the path's facts (never beside a branch
                                                 ;; the values rule out)
                                                 (let ((number (and (every (lambda (fact)
                                                                             (values-satisfy-p bridge fact values))
                                                                           facts)
                                                                    (numeric-answer bridge value values))))
                                                   (and number (list :numeric number))))))
                                   (unanswerable (condition)
                                     (append (list name :unanswered :reason (ames-error-detail condition))
                                             assume))
                                   ;; a query that fails never ends the run: it is not answered
                                   (ames-error (condition)
                                     (append (list name :unanswered
                                                   :reason (format nil "it could not be worked out: ~A"
                                                                   (one-line condition)))
                                             assume))
                                   (error (condition)
                                     (append (list name :unanswered
                                                   :reason (format nil "an internal error while answering it: ~A"
                                                                   (one-line condition)))
                                             assume))))))))
