;;;; src/report/view.lisp -- what a report for people shows, presented once for every format.
;;;;
;;;; HISTORY-VIEW turns a simulation history into plists of phrases (see phrases.lisp) and
;;;; presented formulas, with numbers beside them under parameter values: the text, LaTeX and
;;;; HTML reports only lay them out. Fixed bodies are listed once, at the top; each state
;;;; lists its contacts, forces, and per moving body its acceleration and trajectory (a
;;;; polynomial in tau written x0 + v0 tau + (1/2) a_x tau^2 when its tau^2 coefficient is
;;;; half the acceleration shown above it), its end and what holds then. Notes the view does
;;;; not know are kept, as (LABEL . PHRASE), for the renderers to print generically.

(in-package #:ames.report)

(defun acceleration-symbol (axis)
  "The quantity term standing for the acceleration component AXIS (:X or :Y) of the body
a report block is about; printed a_x, a_y."
  (list 'acceleration axis))

(defun datum-text (datum)
  "Any datum as text without package prefixes: symbols by their lower-case names,
keywords with their colon, numbers as NUMBER-TEXT writes them, lists in parentheses
(an improper list with its dot: \"(a . :true)\")."
  (cond ((null datum) "()")
        ((keywordp datum) (format nil ":~(~A~)" (symbol-name datum)))
        ((symbolp datum) (name-text datum))
        ((stringp datum) datum)
        ((realp datum) (number-text datum))
        ((consp datum)
         (let ((tail (cdr (last datum))))
           (format nil "(~{~A~^ ~}~@[ . ~A~])"
                   (loop for cell on datum while (consp cell) collect (datum-text (car cell)))
                   (and tail (datum-text tail)))))
        (t (princ-to-string datum))))

(defun parameter-phrases (presenter)
  "One phrase per parameter saying what is assumed of it: \"mp > 0\", \"0 < a < pi/2\"."
  (loop for parameter in (scenario-parameters (presenter-scenario presenter))
        for name = (scenario-parameter-name parameter)
        for relations = (mapcar (lambda (a) (case a (:positive `(> ,name 0)) (:nonnegative `(>= ,name 0)) (t a)))
                                (scenario-parameter-assumptions parameter))
        for lower = (find-if (lambda (r) (and (member (first r) '(> >=)) (eq (second r) name))) relations)
        for upper = (find-if (lambda (r) (and (member (first r) '(< <=)) (eq (second r) name))) relations)
        collect (if (and lower upper)
                    (phrase (list :math (present presenter (third lower)))
                            (format nil " ~(~A~) " (if (eq (first lower) '>) '< '<=))
                            (list :math name)
                            (format nil " ~(~A~) " (first upper))
                            (list :math (present presenter (third upper))))
                    (if relations
                        (loop for relation in relations
                              for first = t then nil
                              unless first collect ", "
                              collect (list :math (present-relation presenter relation)))
                        (list (list :math name) " (no assumption)")))))

(defun numbers-of (presenter expression)
  "EXPRESSION's numbers under the presenter's values: a number, a numeric polynomial in
tau, or NIL."
  (if (keywordp expression) nil (numeric-polynomial presenter expression)))

(defun arc-range-numbers (presenter expression state)
  "For an EXPRESSION of the arc length s in STATE: (:FROM A :TO B), its numbers where the
state starts and ends along the curve, when known; else NIL."
  (let* ((from (getf (state-path-coordinates state) :arc-length-from))
         (to (state-end-arc-length state)))
    (when (and (presenter-values presenter) from)
      (flet ((at (s) (and s (numeric presenter (substitute-expressions (list (cons +arc-length+ s)) expression)))))
        (let ((a (at from)) (b (at to)))
          (and a (list :from a :to b)))))))

(defun quantity-numbers (presenter expression state)
  "The numbers shown beside EXPRESSION in STATE (see NUMBERS-OF and ARC-RANGE-NUMBERS)."
  (cond ((or (realp expression) (not (valid-expression-p expression :kind :arithmetic))) nil)
        ((not (free-of-p +arc-length+ expression)) (arc-range-numbers presenter expression state))
        (t (numbers-of presenter expression))))

(defun force-view (presenter entry state)
  "The plist a report shows for the force ENTRY of STATE: :LABEL :SYMBOL :VALUE
:VECTOR-P :NUMBERS :OPTIONS."
  (multiple-value-bind (label symbol value options) (force-entry entry)
    (list :label label :symbol symbol
          :value (if (vector-value-p value)
                     (mapcar (lambda (c) (present presenter c)) value)
                     (and value (present presenter value)))
          :vector-p (vector-value-p value)
          :numbers (if (vector-value-p value)
                       (let ((numbers (mapcar (lambda (c) (if (realp c) c (quantity-numbers presenter c state)))
                                              value)))
                         (and (every #'identity numbers) (notevery #'realp value) numbers))
                       (and value (quantity-numbers presenter value state)))
          :options (loop for (key datum) on options by #'cddr
                         collect (format nil "~A ~A" (keyword-words key)
                                         (if (keywordp datum) (keyword-words datum) (datum-text datum)))))))

(defun numbered-symbols (forces)
  "FORCES (plists of FORCE-VIEW) with every :SYMBOL that more than one of them has
numbered in order, N_1, N_2 ..., so that two normal forces are told apart."
  (let ((counts (make-hash-table :test 'equal)) (seen (make-hash-table :test 'equal)))
    (dolist (force forces)
      (when (getf force :symbol) (incf (gethash (getf force :symbol) counts 0))))
    (mapcar (lambda (force)
              (let ((symbol (getf force :symbol)))
                (if (and symbol (> (gethash symbol counts) 1))
                    (list* :symbol (format nil "~A_~D" symbol (incf (gethash symbol seen 0))) force)
                    force)))
            forces)))

(defun half-acceleration-p (presenter coefficient acceleration)
  "True when COEFFICIENT is proven to be ACCELERATION / 2."
  (and (not (eql acceleration 0))
       (handler-case (ames.maxima:equivalent-p (presenter-bridge presenter)
                                               (list '* 2 coefficient) acceleration)
         (ames.maxima:maxima-condition () nil))))

(defun coordinate-view (presenter position acceleration axis)
  "The presented POSITION of one axis: x0 + v0 tau + (1/2) a_x tau^2 when its tau^2
coefficient is ACCELERATION / 2, else the presented polynomial."
  (let ((coefficients (and (valid-expression-p position :kind :arithmetic)
                           (handler-case (ames.maxima:polynomial-coefficients
                                          (presenter-bridge presenter) position 'tau)
                             (ames.maxima:maxima-condition () nil)))))
    (if (and coefficients (= 3 (length coefficients)) (valid-expression-p acceleration :kind :arithmetic)
             (half-acceleration-p presenter (third coefficients) acceleration))
        (let ((lower (polynomial-form presenter (subseq coefficients 0 2) 'tau))
              (half `(* 1/2 ,(acceleration-symbol axis) (expt tau 2))))
          (if (eql lower 0) half (list '+ lower half)))
        (present presenter position))))

(defun body-view (presenter state body)
  "What STATE shows of the moving BODY: acceleration, trajectory, and their numbers."
  (let ((acceleration (body-entry (state-accelerations state) body))
        (position (body-entry (state-positions state) body)))
    (list :name body
          :acceleration (mapcar (lambda (c) (present presenter c)) acceleration)
          :acceleration-numbers (mapcar (lambda (c) (quantity-numbers presenter c state)) acceleration)
          :position
          (cond ((equal position '(:no-closed-form)) :no-closed-form)
                ((and (consp position) (eq (first position) :on-path))
                 (list :on-path (mapcar (lambda (c) (present presenter c)) (second position))))
                ((vector-value-p position)
                 (loop for c in position for a in acceleration for axis in '(:x :y)
                       collect (coordinate-view presenter c a axis)))
                (t position))
          :position-numbers
          (cond ((and (consp position) (eq (first position) :on-path))
                 (mapcar (lambda (c) (quantity-numbers presenter c state)) (second position)))
                ((vector-value-p position)
                 (mapcar (lambda (c) (quantity-numbers presenter c state)) position)))
          :rotation (rotation-view presenter state body))))

(defun rotation-view (presenter state body)
  "What STATE shows of the rotating BODY's turning: its angular acceleration, angle and
angular velocity over the state, presented (:NO-CLOSED-FORM for a numeric motion);
NIL for a body that does not rotate."
  (let ((angle (assoc body (state-angles state))))
    (when angle
      (flet ((shown (entry)
               (if (equal (second entry) '(:no-closed-form))
                   :no-closed-form
                   (present presenter (second entry)))))
        (list :angular-acceleration (shown (assoc body (state-angular-accelerations state)))
              :angle (shown angle)
              :angular-velocity (shown (assoc body (state-angular-velocities state))))))))

(defun final-rotation-view (presenter entries numbers body)
  "BODY's final angle or angular velocity among ENTRIES, presented, with its number among
NUMBERS when it is not a number itself (a string, as the text report prints it), or NIL."
  (let ((entry (assoc body entries))
        (number (second (assoc body numbers))))
    (and entry
         (let ((shown (present presenter (second entry))))
           (if (and (realp number) (not (realp (second entry))))
               (list :value shown :number number)
               (list :value shown))))))

(defun time-phrase (presenter time)
  "A phrase for a state's start or duration."
  (cond ((eq time :forever) (list "forever"))
        ((eq time :undecided) (list "undecided"))
        ((and (consp time) (eq (first time) :no-closed-form) (getf (rest time) :after-state))
         (list (format nil "the end of state ~D (no closed form in time)" (getf (rest time) :after-state))))
        ((and (consp time) (eq (first time) :no-closed-form) (getf (rest time) :needs))
         (list "not found: no closed form in time, and no numbers to integrate with"))
        ((and (consp time) (eq (first time) :no-closed-form))
         (let ((s (arc-length-symbol presenter))
               (speed (cdr (assoc +arc-speed+ (presenter-renamings presenter)))))
           (phrase "no closed form in time: the time to travel from "
                   (list '= s (present presenter (getf (rest time) :from-arc-length))) " to "
                   (list '= s (present presenter (getf (rest time) :to-arc-length)))
                   " along the contact, with "
                   (list '= (list 'expt speed 2) (present presenter (getf (rest time) :speed-squared))))))
        ((valid-expression-p time :kind :arithmetic) (phrase (present presenter time)))
        (t (list (datum-text time)))))

(defun moving-p (presenter body)
  "True unless the scenario body named BODY is fixed."
  (let ((object (find-scenario-body body (presenter-scenario presenter))))
    (not (and object (scenario-body-fixed-p object)))))

(defun state-view (presenter state)
  "The plist a report shows for STATE (see the file header)."
  (let* ((numeric (state-numbers state))
         (events (state-simultaneous-events state)))
    (list :index (state-index state)
          ;; a fork is no period of motion: its index is the state it splits (see
          ;; the simulator's branching)
          :fork (and (state-fork-p state) t)
          :start (time-phrase presenter (state-start state))
          :start-number (let ((n (getf numeric :start)))
                          (and (realp n) (not (realp (state-start state))) n))
          :duration (time-phrase presenter (state-duration state))
          :duration-number (let ((n (getf numeric :duration)))
                             (and (realp n) n))
          :contacts (mapcar (lambda (c) (contact-phrase presenter c)) (state-contacts state))
          :forces (numbered-symbols (mapcar (lambda (f) (force-view presenter f state)) (state-forces state)))
          ;; a body's motion where it is known (a fork's state has none of its own)
          :bodies (loop for (body) in (state-positions state)
                        when (and (moving-p presenter body)
                                  (body-entry (state-accelerations state) body))
                          collect (body-view presenter state body))
          :end (event-phrase presenter (state-end-event state) state)
          :events (mapcar (lambda (e) (event-phrase presenter e state)) events)
          :final (loop for (body position) in (state-final-positions state)
                       for velocity = (body-entry (state-final-velocities state) body)
                       when (moving-p presenter body)
                         collect (list :name body
                                       :position (mapcar (lambda (c) (present presenter c)) position)
                                       :position-numbers (and (notevery #'realp position)
                                                              (second (assoc body (getf numeric :final-positions))))
                                       :velocity (mapcar (lambda (c) (present presenter c)) velocity)
                                       :velocity-numbers (and (notevery #'realp velocity)
                                                              (second (assoc body (getf numeric :final-velocities))))
                                       :angle (final-rotation-view presenter (state-final-angles state)
                                                                   (getf numeric :final-angles) body)
                                       :angular-velocity
                                       (final-rotation-view presenter (state-final-angular-velocities state)
                                                            (getf numeric :final-angular-velocities) body)))
          :notes (note-views presenter state)
          :branches (loop for branch in (state-branches state)
                          collect (list :assume (phrase (present-relation presenter (getf branch :assume)))
                                        :selected (getf branch :selected)
                                        :outcome (getf branch :outcome)
                                        :failure (and (getf branch :failure)
                                                      (failure-phrase (getf branch :failure) presenter))
                                        :states (mapcar (lambda (s) (state-view presenter s))
                                                        (getf branch :states)))))))

(defun answer-views (presenter history)
  "The answers to HISTORY's queries as phrases: (NAME PHRASE)."
  (loop for entry in (history-answers history)
        collect (destructuring-bind (name value &rest options) entry
                  (list name
                        (append
                         (cond ((eq value :unanswered)
                                (list (format nil "not answered: ~A" (getf options :reason))))
                               ((and (consp value) (member (first value) '(:true :false :unknown)))
                                (list (format nil "~(~A~) (~A)" (first value) (second value))))
                               ((and (consp value) (member (first value) '(:never :always)))
                                (list (format nil "~(~A~): ~A" (first value) (second value))))
                               ((and (consp value) (eq (first value) :when))
                                (cons "when "
                                      (loop for conditions in (rest value)
                                            for first = t then nil
                                            unless first collect " or "
                                            append (loop for c in conditions
                                                         for f = t then nil
                                                         unless f collect " and "
                                                         collect (list :math (present-relation presenter c))))))
                               ((vector-value-p value)
                                (phrase "(" (present presenter (first value)) ", " (present presenter (second value)) ")"))
                               ((valid-expression-p value :kind :arithmetic) (phrase (present presenter value)))
                               (t (list (datum-text value))))
                         (let ((number (getf options :numeric)))
                           (and number (list (format nil " (~A)" (if (listp number)
                                                                     (format nil "~{~A~^, ~}" (mapcar #'number-text number))
                                                                     (number-text number))))))
                         (let ((facts (getf options :assume)))
                           (and facts (cons ", assuming "
                                            (loop for fact in facts
                                                  for first = t then nil
                                                  unless first collect " and "
                                                  collect (list :math (present-relation presenter fact)))))))))))

(defun history-view (presenter history)
  "The plist a report shows for HISTORY: :NAME :DESCRIPTION :PARAMETERS :VALUES :FIXED
:STATES :OUTCOME :ASSUMED :AMBIGUITY :STOPPED :SELF-CHECK (lines of text)."
  (let* ((scenario (history-scenario history))
         (stopped (getf (history-notes history) :stopped-by)))
    (list :name (scenario-name scenario)
          :description (scenario-description scenario)
          :parameters (parameter-phrases presenter)
          :values (mapcar (lambda (entry)
                            (cons (car entry) (if (integerp (cdr entry)) (cdr entry)
                                                 (or (report-float (cdr entry)) (cdr entry)))))
                          (history-parameter-values history))
          :fixed (loop for body in (scenario-fixed-bodies scenario)
                       for position = (scenario-body-position body)
                       collect (if (and position (not (every (lambda (c) (eql c 0)) position)))
                                   (phrase (format nil "~A at (" (name-text (scenario-body-name body)))
                                           (present presenter (first position)) ", "
                                           (present presenter (second position)) ")")
                                   (list (name-text (scenario-body-name body)))))
          :states (labelled-branches (mapcar (lambda (s) (state-view presenter s)) (history-states history)))
          :definitions (time-definitions)
          :outcome (history-outcome history)
          :answers (answer-views presenter history)
          :assumed (loop for assumed in (reverse (getf (history-notes history) :assumed))
                         collect (phrase (if (getf assumed :state)
                                             (format nil "at state ~D: " (getf assumed :state))
                                             "elsewhere in the run (the geometry, an impact): ")
                                         (present-cheaply presenter (getf assumed :fact))))
          :ambiguity
          (when (typep stopped 'ambiguous-transition)
            (list :missing-fact (phrase (present-relation presenter (ambiguous-transition-missing-fact stopped)))
                  :candidates
                  (loop for (event time . more) in (ambiguous-transition-candidates stopped)
                        collect (append (event-phrase presenter event)
                                        (if (eq time :undecided)
                                            (phrase ", at a time not decided: "
                                                    (present-relation presenter (first more)))
                                            (cons ", at t = " (time-phrase presenter time)))))))
          :self-check (self-check-lines history)
          :stopped (and stopped (not (typep stopped 'ambiguous-transition))
                        ;; its first line: what stopped the run (not the Lisp form at fault)
                        (let ((text (princ-to-string stopped)))
                          (list (subseq text 0 (position #\Newline text))))))))
