;;;; src/report/sexp.lisp -- a simulation history as the readable s-expression of the scenario language's output section.
;;;;
;;;; The data as solved, for programs: no presentation step. Keys the simulator adds later
;;;; (state notes such as :initial-velocities, history notes) are kept as they come.

(in-package #:ames.report)

(defun history-sexp (history)
  "HISTORY as the s-expression of the scenario language's output section:
(:scenario NAME :states ((:index 0 :start ... :duration ... :contacts ... :accelerations
... :forces ... :positions ... :end-event ... :final-positions ... :final-velocities ...)
...) :outcome ...), with extra keys :velocities, :events and :numeric where known. Its
names are the user's (see OUTPUT-NAMES): no internal symbol of AMES's layers."
  (output-names (history-scenario history) (raw-history-sexp history)))

(defun output-names (scenario tree)
  "TREE with every symbol of another package than the scenario's (AMES-SCENARIO), CL's
and the keywords replaced by the scenario-package symbol of the same name, except the
simulator's arc-length and arc-speed variables, named s and sdot (s1, sdot1 ... when a
parameter of SCENARIO has that name) as the text report names them s and s'."
  (let ((renamings (list (cons +arc-length+ (output-symbol (display-symbol "S" scenario)))
                         (cons +arc-speed+ (output-symbol (display-symbol "SDOT" scenario))))))
    (labels ((walk (x)
               (cond ((consp x) (cons (walk (car x)) (walk (cdr x))))
                     ((or (null x) (not (symbolp x)) (keywordp x)
                          (member (symbol-package x)
                                  (list (find-package '#:ames-scenario) (find-package '#:common-lisp))))
                      x)
                     (t (or (cdr (assoc x renamings)) (output-symbol x))))))
      (walk tree))))

(defun output-symbol (symbol)
  "The symbol of the scenario package named like SYMBOL."
  (intern (symbol-name symbol) '#:ames-scenario))

(defun raw-history-sexp (history)
  "HISTORY-SEXP before its names are the user's."
  (list* :scenario (scenario-name (history-scenario history))
         :states (mapcar #'state-sexp (history-states history))
         :outcome (history-outcome history)
         :answers (history-answers history)
         (let ((stopped (getf (history-notes history) :stopped-by)))
           (append
            (let ((assumed (getf (history-notes history) :assumed)))
              (when assumed (list :assumed-from-values (reverse assumed))))
            ;; which claims the self-check verified under the values (see AMES.CHECK)
            (let ((check (getf (history-notes history) :self-check)))
              (when check (list :self-check check)))
            (when (typep stopped 'ambiguous-transition)
             (list :ambiguity (list :missing-fact (ambiguous-transition-missing-fact stopped)
                                    :candidates (ambiguous-transition-candidates stopped))))))))

(defun state-sexp (state)
  "One QUALITATIVE-STATE as a plist (see HISTORY-SEXP)."
  (let ((notes (state-notes state)))
    (append
     (list :index (state-index state)
           :start (state-start state)
           :duration (state-duration state)
           :contacts (state-contacts state)
           :accelerations (state-accelerations state)
           :forces (state-forces-of state)
           :positions (state-positions state)
           :velocities (state-velocities state)
           :initial-velocities (state-initial-velocities state)
           :end-event (state-end-event state)
           :final-positions (state-final-positions state)
           :final-velocities (state-final-velocities state))
     ;; rotating bodies only: a scenario without any reports as before
     (when (state-angles state)
       (list :angles (state-angles state)
             :angular-velocities (state-angular-velocities state)
             :angular-accelerations (state-angular-accelerations state)
             :final-angles (state-final-angles state)
             :final-angular-velocities (state-final-angular-velocities state)))
     (when (state-branches state)
       (list :branches
             (mapcar (lambda (branch)
                       (list* :assume (getf branch :assume)
                              :states (mapcar #'state-sexp (getf branch :states))
                              (loop for (key value) on branch by #'cddr
                                    unless (member key '(:assume :states))
                                      append (list key value))))
                     (state-branches state))))
     (loop for (key value) on notes by #'cddr
           ;; the line coordinates are the simulator's working, in the knowledge base's
           ;; internal terms; the positions and the path coordinates carry the result
           unless (eq key :line-coordinates)
             append (list key (if (eq key :impact)
                                  ;; the impact model's consistency search is the solver's
                                  ;; working, not a result
                                  (alexandria:remove-from-plist value :choices)
                                  value))))))

(defun state-forces-of (state)
  "The forces slot of STATE (named apart from the report function STATE-FORCES)."
  (state-forces state))

(defun print-history-sexp (history stream)
  "Print HISTORY-SEXP of HISTORY readably on STREAM, symbols in lower case."
  (with-standard-io-syntax
    (let ((*package* (find-package '#:ames-scenario))
          (*print-case* :downcase)
          (*print-readably* nil)
          (*print-right-margin* 100)
          (*print-pretty* t))
      (pprint (history-sexp history) stream)
      (terpri stream))))
