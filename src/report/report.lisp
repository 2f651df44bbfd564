;;;; src/report/report.lisp -- a simulation history as a report for people and as a readable s-expression.

(in-package #:ames.report)

(defun history-sexp (history)
  "HISTORY as the s-expression of the scenario language's output section:
(:scenario NAME :states ((:index 0 :start ... :duration ... :contacts ... :accelerations
... :forces ... :positions ... :end-event ... :final-positions ... :final-velocities ...)
...) :outcome ...), with extra keys :velocities, :events and :numeric where known."
  (list* :scenario (scenario-name (history-scenario history))
         :states (mapcar #'state-sexp (history-states history))
         :outcome (history-outcome history)
         (let ((stopped (getf (history-notes history) :stopped-by)))
           (append
            (let ((assumed (getf (history-notes history) :assumed)))
              (when assumed (list :assumed-from-values (reverse assumed))))
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
           :end-event (state-end-event state)
           :final-positions (state-final-positions state)
           :final-velocities (state-final-velocities state))
     (loop for (key value) on notes by #'cddr
           unless (eq key :numeric-duration)
             append (list key value)))))

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

(defun infix (expression)
  "A one-line conventional rendering of EXPRESSION for people: mp*g*cos(a)/(mw + mp*sin(a)^2).
Lower case; parentheses only where precedence needs them."
  (let ((*print-case* :downcase) (*print-pretty* nil)
        (*package* (find-package '#:ames-scenario)))
    (labels ((negative-p (x)
               (or (and (realp x) (minusp x))
                   (and (consp x) (eq (first x) '-) (null (cddr x)))))
             (negated (x) (if (realp x) (- x) (second x)))
             (wrap (text own context) (if (> context own) (format nil "(~A)" text) text))
             (render (x context)
               (cond ((and (rationalp x) (not (integerp x)))
                      (wrap (format nil "~A" x) 2 context))
                     ((and (realp x) (minusp x)) (wrap (format nil "~A" x) 1 context))
                     ((atom x) (format nil "~A" x))
                     ((keywordp (first x)) (format nil "~S" x))
                     (t
                      (let ((args (rest x)))
                        (case (first x)
                          (+ (wrap (with-output-to-string (out)
                                     (loop for (term . more) on args
                                           for first = t then nil
                                           do (cond (first (write-string (render term 1) out))
                                                    ((negative-p term)
                                                     (format out " - ~A" (render (negated term) 2)))
                                                    (t (format out " + ~A" (render term 1))))))
                                   1 context))
                          (- (if (rest args)
                                 (wrap (format nil "~A~{ - ~A~}" (render (first args) 1)
                                               (mapcar (lambda (a) (render a 2)) (rest args)))
                                       1 context)
                                 (wrap (format nil "-~A" (render (first args) 2)) 1 context)))
                          (* (wrap (format nil "~{~A~^*~}" (mapcar (lambda (a) (render a 2)) args))
                                   2 context))
                          (/ (wrap (if (rest args)
                                       (format nil "~A/~A" (render (first args) 2)
                                               (render (if (cddr args) (cons '* (rest args)) (second args)) 3))
                                       (format nil "1/~A" (render (first args) 3)))
                                   2 context))
                          (expt (wrap (format nil "~A^~A" (render (first args) 4) (render (second args) 4))
                                      3 context))
                          (t (if (member (first x) '(sin cos tan asin acos atan sqrt exp log abs))
                                 (format nil "~(~A~)(~{~A~^, ~})" (first x)
                                         (mapcar (lambda (a) (render a 0)) args))
                                 (format nil "~S" x)))))))))
      (render expression 0))))

(defun print-history-text (history stream)
  "Print HISTORY on STREAM as a report for people: state by state, the contacts named by
their features, the forces, accelerations and trajectories, the end event and its time."
  (let* ((scenario (history-scenario history))
         (*print-case* :downcase))
    (format stream "~&Scenario ~(~A~)~@[: ~A~]~%" (scenario-name scenario)
            (scenario-description scenario))
    (when (history-parameter-values history)
      (format stream "  with ~{~{~(~A~) = ~A~}~^, ~}~%"
              (mapcar (lambda (e) (list (car e) (cdr e))) (history-parameter-values history))))
    (dolist (state (history-states history))
      (let ((numeric (getf (state-notes state) :numeric)))
        (format stream "~%State ~D, from t = ~A" (state-index state) (infix (state-start state)))
        (when (and numeric (getf numeric :start)) (format stream " (~,4F)" (getf numeric :start)))
        (format stream "~%  contacts:~:[ none~;~]~%" (state-contacts state))
        (dolist (contact (state-contacts state))
          (destructuring-bind (b1 b2 &key feature observer-feature) contact
            (format stream "    ~(~A~) on ~(~A~): ~A against ~A~%" b1 b2
                    (feature-phrase observer-feature) (feature-phrase feature))))
        (format stream "  forces:~%")
        (dolist (force (state-forces-of state))
          (case (first force)
            (:normal (format stream "    normal force of ~(~A~) on ~(~A~): N = ~A~%"
                             (third force) (second force) (infix (fourth force))))
            (:gravity (format stream "    weight of ~(~A~): (~A, ~A)~%" (second force)
                              (infix (first (third force))) (infix (second (third force)))))
            (:external (format stream "    external force ~(~A~) on ~(~A~): (~A, ~A)~%"
                               (second force) (third force)
                               (infix (first (fourth force))) (infix (second (fourth force)))))))
        (format stream "  accelerations (fixed frame):~%")
        (dolist (entry (state-accelerations state))
          (format stream "    ~(~A~): (~A, ~A)~%" (first entry)
                  (infix (first (second entry))) (infix (second (second entry)))))
        (format stream "  positions over the state (tau from its start):~%")
        (dolist (entry (state-positions state))
          (format stream "    ~(~A~): ~A~%" (first entry)
                  (if (and (consp (second entry)) (keywordp (first (second entry))))
                      (let ((path (getf (second entry) :on-path)))
                        (format nil "on the contact at arc length s: (~A, ~A)"
                                (infix (first path)) (infix (second path))))
                      (format nil "(~A, ~A)" (infix (first (second entry)))
                              (infix (second (second entry)))))))
        (loop for (key value) on (state-notes state) by #'cddr
              do (case key
                   ((:numeric :numeric-duration :lift-off-arc-length))
                   (:events (format stream "  simultaneous events:~{~%    ~A~}~%"
                                    (mapcar #'event-phrase value)))
                   (:path-coordinates
                    (format stream "  on the curve, with s the arc length along the contact:~%")
                    (format stream "    s starts at ~A~%" (infix (getf value :arc-length-from)))
                    (format stream "    tangential acceleration s'' = ~A~%"
                            (infix (getf value :tangential-acceleration)))
                    (format stream "    energy integral: (s')^2 = ~A (~A)~%"
                            (infix (relation-rhs (getf value :energy-integral)))
                            (if (eq (getf value :ode) :closed-form)
                                "the ODE also has a closed form"
                                "the ODE has no closed form in time"))
                    (format stream "    normal force N(s) = ~A~%" (infix (getf value :normal-force))))
                   (t (let ((*package* (find-package '#:ames-scenario)))
                        (format stream "  ~(~A~): ~S~%" key value)))))
        (let ((duration (state-duration state)))
          (format stream "  ends: ~A~%" (event-phrase (state-end-event state)))
          (format stream "  duration: ~A~@[ (~,4F)~]~%"
                  (cond ((eq duration :forever) "forever")
                        ((eq duration :undecided) "undecided")
                        ((and (consp duration) (eq (first duration) :no-closed-form))
                         (format nil "no closed form in time; it ends after travelling from arc length ~A to ~A along the contact (see the energy integral)"
                                 (infix (getf (rest duration) :from-arc-length))
                                 (infix (getf (rest duration) :to-arc-length))))
                        (t (infix duration)))
                  (let ((number (or (getf (state-notes state) :numeric-duration)
                                    (and numeric (getf numeric :duration)))))
                    (and (realp number) number))))
        (when (state-final-positions state)
          (format stream "  at the end:~%")
          (loop for (body position) in (state-final-positions state)
                for velocity = (second (assoc body (state-final-velocities state)))
                for numbers = (and numeric (second (assoc body (getf numeric :final-positions))))
                do (format stream "    ~(~A~) at (~A, ~A)~@[ ~A~], velocity (~A, ~A)~%" body
                           (infix (first position)) (infix (second position))
                           (and numbers (every #'realp numbers)
                                (format nil "= (~,4F, ~,4F)" (first numbers) (second numbers)))
                           (infix (first velocity)) (infix (second velocity)))))))
    (dolist (assumed (reverse (getf (history-notes history) :assumed)))
      (format stream "~%Assumed from the given values~:[ while checking the geometry~; at state ~:*~D~]: ~A~%"
              (getf assumed :state) (infix-relation (getf assumed :fact))))
    (format stream "~%Outcome: ~(~A~)~%" (history-outcome history))
    (let ((stopped (getf (history-notes history) :stopped-by)))
      (cond ((typep stopped 'ambiguous-transition)
             (format stream "  Which event ends the last state is not decided by the assumptions.~%")
             (format stream "  Missing fact: ~A~%"
                     (infix-relation (ambiguous-transition-missing-fact stopped)))
             (format stream "  Candidates:~%")
             (dolist (candidate (ambiguous-transition-candidates stopped))
               (destructuring-bind (event time &rest more) candidate
                 (if (eq time :undecided)
                     (format stream "    ~A, at a time not decided: ~A~%"
                             (event-phrase event) (infix-relation (first more)))
                     (format stream "    ~A, at t = ~A~%" (event-phrase event) (infix time))))))
            (stopped (format stream "  ~A~%" stopped))))))

(defun infix-relation (relation)
  "A relation such as (> X 0) rendered for people."
  (if (and (consp relation) (symbolp (first relation)) (relation-operator-p (first relation)))
      (format nil "~A ~(~A~) ~A" (infix (relation-lhs relation)) (first relation)
              (infix (relation-rhs relation)))
      (infix relation)))

(defun feature-phrase (feature)
  "A phrase naming a contact FEATURE such as (:edge 1 :of wedge)."
  (if feature (ames.geometry:feature-description feature) "?"))

(defun event-phrase (event)
  "A phrase for an end EVENT."
  (case event
    (:none "never (nothing more changes)")
    (:undecided "undecided: the assumptions do not decide which event comes first (see below)")
    (t
      (destructuring-bind (kind &rest more) event
        (case kind
          (:leaves (format nil "~(~A~) leaves ~(~A~) past the end of the contact" (first more) (second more)))
          (:lift-off (format nil "~(~A~) lifts off ~(~A~) (the normal force would turn attractive)"
                             (first more) (second more)))
          (:contact (format nil "~(~A~) comes into contact with ~(~A~)" (first more) (second more)))
          (:collision (format nil "~(~A~) collides with ~(~A~) (no collision model: the simulation ends)"
                              (first more) (second more)))
          (:time-limit (format nil "the simulation reaches its time limit, t = ~A" (infix (first more))))
          (:contact-ends (format nil "the contact of ~(~A~) with ~(~A~) ends" (first more) (second more)))
          (t (format nil "~(~S~)" event)))))))
