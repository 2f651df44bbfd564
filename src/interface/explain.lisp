;;;; src/interface/explain.lisp -- "why?": explanations of a run from what the simulator kept of
;;;; each state's model (thesis 3.2.2: every belief has its justification in the JTMS).
;;;;
;;;; For a state, EXPLAIN says in plain language
;;;;   - why these contacts and modes hold: every assignment the consistency search tried
;;;;     and why it was kept or rejected (a force that would pull, a contact penetrated at
;;;;     once, a degenerate choice);
;;;;   - where each equation comes from: the component that asserted it (its own
;;;;     description, with the thesis's figure or section where it cites one);
;;;;   - why the state ends when it does: the event, and every other termination
;;;;     condition with its time, or why it never fires.

(in-package #:ames)

(defun component-summary (name)
  "The first sentence of the mechanics component NAME's description and the thesis
figure or section it cites, or NIL."
  (let* ((component (some (lambda (kb) (ames.engine:find-component kb name nil))
                          (ames.kb:knowledge-bases)))
         (text (and component (ames.engine:component-documentation component))))
    (when text
      (let* ((flat (substitute #\Space #\Newline text))
             (end (or (search ". " flat) (length flat)))
             (cite (cl-ppcre:scan-to-strings "(figures? [0-9]-[0-9]+( to [0-9]-[0-9]+)?|section [0-9.]+)" flat)))
        (values (subseq flat 0 (min (length flat) (1+ end))) cite)))))

(defvar *contact-names* '()
  "While a state is explained: an alist entity the simulator named (a contact, a rope's
segment) -> its phrase (\"particle on wedge\", \"rope, piece 1\").")

(defvar *explain-presenter* nil
  "While a history is explained: the report's PRESENTER of it, which words its events.")

(defvar *explained-state* nil
  "While a state is explained: the state.")

(defun segment-names (scenario)
  "An alist entity a phenomenon made of SCENARIO's clauses -> the phrase naming it to
people (\"rope, piece 1\"): AMES.KB:ENTITY-PHRASES-OF."
  (ames.kb:entity-phrases-of scenario))

(defun entity-text (x)
  "A body, contact, segment or other name in an explanation, without package or colon; a
list (an instance's key) with the entities in it by their phrases."
  (cond ((and (symbolp x) (assoc x *contact-names*)) (format nil "[~A]" (cdr (assoc x *contact-names*))))
        ((keywordp x) (string-downcase (substitute #\Space #\- (symbol-name x))))
        ((symbolp x) (string-downcase (symbol-name x)))
        ((consp x) (format nil "(~{~A~^ ~})" (mapcar #'entity-text x)))
        (t (string-downcase (princ-to-string x)))))

(defun mentions-entity-p (x)
  "True when X holds, at any depth, an entity named in *CONTACT-NAMES*."
  (if (consp x)
      (some #'mentions-entity-p x)
      (and (symbolp x) (assoc x *contact-names*) t)))

(defparameter *term-words* '(("PATH-POSITION" . "s") ("ARC-LENGTH" . "s"))
  "Quantity terms an explanation writes by the letter the reports use: the arc length
along a curved contact is s.")

(defun readable-terms (x)
  "X with every quantity term written as a readable symbol: (acc particle :x) as
acc_x(particle), a contact entity by its bodies."
  (cond ((and (symbolp x) (assoc x *contact-names*))
         (make-symbol (format nil "[~A]" (cdr (assoc x *contact-names*)))))
        ((quantity-term-p x)
         (let* ((axis (find-if #'keywordp (rest x)))
                (names (mapcar #'entity-text (remove-if #'keywordp (rest x)))))
           (make-symbol (format nil "~(~A~)~@[_~(~A~)~](~{~A~^, ~})"
                                (or (cdr (assoc (symbol-name (first x)) *term-words* :test #'string=))
                                    (first x))
                                axis names))))
        ((consp x) (cons (first x) (mapcar #'readable-terms (rest x))))
        (t x)))

(defun phrase (x)
  "X for people: an expression in infix (its quantity terms readable), an event or
anything else as written, lower case."
  (let ((*package* (find-package '#:ames-scenario)) (*print-case* :downcase))
    (cond ((and (consp x) (keywordp (first x)) *explain-presenter*
                (not (mentions-entity-p (rest x))))
           (ames.report:event-text *explain-presenter* x *explained-state*))
          ((and (consp x) (keywordp (first x)))
           (format nil "~(~A~)~{ ~A~}" (keyword-words (first x))
                   (loop for (item . rest) on (rest x)
                         until (keywordp item)
                         collect (entity-text item))))
          ((or (consp x) (symbolp x) (numberp x)) (infix (readable-terms x)))
          (t (princ-to-string x)))))

(defun key-phrase (key)
  "A phrase for the instance KEY: its component and the bodies its contact joins."
  (format nil "~(~A~)~@[ (~A)~]" (first key)
          (some (lambda (x) (cdr (assoc x *contact-names*))) (rest key))))

(defun describe-assignment (assignment)
  "A phrase for the ASSIGNMENT of the open choices: which are active, which modes."
  (format nil "~{~A~^, ~}"
          (mapcar (lambda (entry)
                    (let ((key (car entry)) (option (cdr entry)))
                      (format nil "~A ~A" (key-phrase key)
                              (case option (:true "on") (:false "off") (t (format nil "in mode ~(~A~)" option))))))
                  assignment)))

(defun explain-choices (state stream)
  "Print why STATE's contacts and modes hold."
  (let ((choices (getf (state-analysis state) :choices)))
    (format stream "~&Why these contacts and modes:~%")
    (if (null (getf choices :tried))
        (format stream "  nothing was open: every contact and mode followed from the state's start.~%")
        (dolist (trial (getf choices :tried))
          (format stream "  ~A: ~(~A~)~:[~;, degenerate (a contact with no force, or one only grazed)~]~%"
                  (describe-assignment (getf trial :assignment)) (getf trial :verdict)
                  (plusp (getf trial :degenerate 0)))
          (dolist (why (getf trial :why))
            (format stream "      ~A~%"
                    (case (first why)
                      (:flip (format nil "turned ~A ~A because ~A at once" (key-phrase (second why))
                                     (if (eq (third why) :true) "on" "off") (phrase (fifth why))))
                      (:violates (format nil "rejected: ~{~A~^, ~} at once" (mapcar #'phrase (second why))))
                      (:singular "redundant constraints: no unique solution")
                      ;; the solver's own message names internal terms: say what it means
                      (:unsolvable "no unique solution: the equations leave a force or an acceleration undetermined")
                      (t (phrase why)))))))
    (when (getf choices :chosen)
      (format stream "  kept: ~A~%" (describe-assignment (getf choices :chosen))))))

(defun tidied (expression)
  "EXPRESSION with its sums and products tidied (zeros dropped, like terms and equal
factors collected) by the reports' arrangement, which keeps the value and knows no sign;
EXPRESSION itself where it is not arithmetic."
  (if (valid-expression-p expression :kind :arithmetic)
      (handler-case (arrange expression (make-arrangement :symbol-key (lambda (name)
                                                                        ;; numbers, parameters, then quantities: m1 acc_x(heavy)
                                                                        (list (if (quantity-term-p name) 4 3)
                                                                              (princ-to-string name)))
                                                          :negative-p (constantly nil)))
        (error () expression))
      expression))

(defun explain-equations (state stream)
  "Print where each equation of STATE's model comes from, grouped by component."
  (format stream "~&Where the equations come from:~%")
  (let ((by-component '()))
    (dolist (entry (getf (state-analysis state) :equations))
      (destructuring-bind (equation component &optional instance) entry
        (declare (ignore instance))
        (push equation (cdr (or (assoc component by-component)
                                (car (push (list component) by-component)))))))
    (dolist (group (reverse by-component))
      (multiple-value-bind (summary cite) (component-summary (first group))
        (format stream "  ~(~A~)~@[ (thesis ~A)~]: ~@[~A~]~%" (first group) cite summary)
        (dolist (equation (reverse (rest group)))
          (format stream "      ~A = ~A~%" (phrase (tidied (relation-lhs equation)))
                  (phrase (tidied (relation-rhs equation)))))))))

(defun explain-end (state stream)
  "Print why STATE ends when it does."
  (format stream "~&Why the state ends then:~%")
  (let ((candidates (getf (state-analysis state) :candidates)))
    (format stream "  it ends with ~A~@[ after ~A~].~%" (phrase (state-end-event state))
            (let ((d (state-duration state))) (and (not (keywordp d)) (phrase d))))
    ;; two conditions of one event (a contact with two faces of a body) read alike: once
    (let ((lines '()))
      (dolist (candidate candidates)
        (let* ((event (first candidate)) (plist (rest candidate))
               (line (cond ((eq (first plist) :never) (format nil "  ~A: never in this state." (phrase event)))
                           ((getf plist :fired) (format nil "  ~A: at ~A, first." (phrase event) (phrase (getf plist :at))))
                           (t (format nil "  ~A: at ~A, later." (phrase event) (phrase (getf plist :at)))))))
          (unless (member line lines :test #'string=)
            (push line lines)
            (format stream "~A~%" line)))))))

(defun explain (history &key state (stream *standard-output*) (bridge (current-bridge)))
  "Explain HISTORY (a SIMULATION-HISTORY, or a scenario file's pathname: its first
scenario is run) state by state, or only the state whose index is STATE: why its
contacts and modes hold, where each equation comes from, and why it ends when it does.
BRIDGE words the events (the features of a contact). Signals what SIMULATE and RUN-FILE signal."
  (let ((history (if (typep history 'simulation-history)
                     history
                     (or (first (run-file history))
                         (error 'usage-error :datum history :detail "the file holds no scenario")))))
    (labels ((walk (states &optional prefix)
               (dolist (s states)
                 (when (or (null state) (eql state (state-index s)))
                   (let ((*contact-names* (append (getf (state-analysis s) :contact-names)
                                                  (segment-names (history-scenario history))))
                         (*explained-state* s))
                     (format stream "~&~%State ~D~@[ (branch ~A)~]~%" (state-index s) prefix)
                     (explain-choices s stream)
                     (explain-equations s stream)
                     (explain-end s stream)))
                 (loop for branch in (state-branches s)
                       for k from 1
                       for label = (format nil "~@[~A.~]~D" prefix k)
                       do (format stream "~&~%Branch ~A of ~D~:[~; (selected by the given values)~], assuming ~A:~%"
                                  label (length (state-branches s)) (getf branch :selected)
                                  (phrase (getf branch :assume)))
                          (cond ((getf branch :states) (walk (getf branch :states) label))
                                ((member (getf branch :outcome) '(nil :not-simulated))
                                 (format stream "  not simulated (only its fact is known)~%"))
                                (t (format stream "  no state of its own: it ended ~A~@[ (~A)~]~%"
                                           (keyword-words (getf branch :outcome))
                                           (and (getf branch :failure)
                                                (text-phrase (failure-phrase (getf branch :failure)))))))))))
      (format stream "~&Scenario ~(~A~)~%" (scenario-name (history-scenario history)))
      (call-with-presenter history bridge
                           (lambda (presenter)
                             (let ((*explain-presenter* presenter))
                               (walk (history-states history))))))
    history))
