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
                 (mapcar (lambda (c) (quantity-numbers presenter c state)) position))))))

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

(defun path-note (presenter value)
  "The phrases of a :PATH-COORDINATES note."
  (let ((s (arc-length-symbol presenter))
        (speed (cdr (assoc +arc-speed+ (presenter-renamings presenter))))
        (energy (getf value :energy-integral)))
    (remove nil
            (list (phrase (format nil "~A is the arc length along the contact of ~{~A~^ with ~}; it starts at "
                                  (name-text s) (mapcar #'name-text (getf value :contact)))
                          (list '= s (present presenter (getf value :arc-length-from))))
                  (and (getf value :tangential-acceleration)
                       (phrase "tangential acceleration "
                               (list '= (make-symbol (format nil "~A''" (symbol-name s)))
                                     (present presenter (getf value :tangential-acceleration)))))
                  (and energy
                       (phrase "energy integral "
                               (if (and (consp energy) (eq (first energy) '=))
                                   (list '= (list 'expt speed 2) (present presenter (third energy)))
                                   (present presenter energy))
                               (if (eq (getf value :ode) :closed-form)
                                   " (the motion also has a closed form in time)"
                                   " (no closed form in time)")))))))

(defun end-on-curve-phrase (presenter value)
  "\"at s = VALUE\"; when VALUE is presented as A asin(E) or A acos(E), also the angle as
a textbook gives it: \"where sin(s/A) = E\"."
  (let* ((s (arc-length-symbol presenter))
         (shown (present presenter value))
         (factors (and (consp shown) (eq (first shown) '*) (rest shown)))
         (inverse (find-if (lambda (f) (and (consp f) (member (first f) '(asin acos)) (= 2 (length f))))
                           factors))
         (scale (and inverse (remove inverse factors :count 1))))
    (append (phrase "at " (list '= s shown))
            (and inverse scale
                 (phrase ", where "
                         (list '= (list (if (eq (first inverse) 'asin) 'sin 'cos)
                                        (list '/ s (if (rest scale) (cons '* scale) (first scale))))
                               (second inverse)))))))

(defun note-views (presenter state)
  "The notes of STATE as (LABEL . PHRASES), those the view shows elsewhere left out."
  (loop for (key value) on (state-notes state) by #'cddr
        append (case key
                 ;; :line-coordinates is the simulator's working (the coordinate along the
                 ;; line of two bodies, in the knowledge base's terms): the positions show it
                 ((:numeric :events :line-coordinates :fork))
                 (:numeric-trajectory
                  (list (cons "integrated numerically" (numeric-trajectory-phrases value))))
                 (:undecided (list (cons "undecided" (list (list (datum-text value))))))
                 (:end-arc-length (list (cons "ends on the curve"
                                              (list (end-on-curve-phrase presenter value)))))
                 (:path-coordinates (list (cons "on the curve" (path-note presenter value))))
                 (:periodic (list (cons "periodic" (periodic-phrases presenter state value))))
                 (:impact (list (cons "the impact" (impact-phrases presenter value))))
                 (:accumulation
                  (list (cons "the impacts repeat" (accumulation-phrases presenter value))))
                 (:energy (list (cons "energy" (energy-phrases presenter value))))
                 (:momentum (list (cons "momentum" (momentum-phrases presenter value))))
                 (:missing-fact
                  (list (cons "the run branches on" (list (phrase (present-relation presenter value))))))
                 (:initial-velocities
                  (list (cons "velocities just after the impact"
                              (initial-velocity-phrases presenter value))))
                 (t (list (cons (keyword-words key) (other-note-phrases presenter value)))))))

(defun numeric-trajectory-phrases (groups)
  "The phrases of a state's :NUMERIC-TRAJECTORY note, GROUPS (plists with :SAMPLES): how
many samples of the motion were integrated."
  (list (list (format nil "~D sample~:P of the motion" 
                      (reduce #'+ (mapcar (lambda (g) (length (getf g :samples))) groups))))))

(defun periodic-phrases (presenter state value)
  "The phrases of STATE's :PERIODIC note VALUE (a plist: :PERIOD, :COORDINATE or none
for the arc length, :BETWEEN the two turning points): the period, with its number when
STATE has one, and the turning points."
  (list (let ((number (getf (state-numbers state) :period)))
          (phrase "period " (present presenter (getf value :period))
                  (if number (format nil " (~A)" (number-text number)) "")))
        ;; along a curve the arc length; else the coordinate
        ;; that oscillates (a position term)
        (let ((coordinate (if (getf value :coordinate)
                              (present presenter (getf value :coordinate))
                              (arc-length-symbol presenter))))
          (phrase "between turning points at "
                  (list '= coordinate
                        (present presenter (first (getf value :between))))
                  " and "
                  (list '= coordinate
                        (present presenter (second (getf value :between))))))))

(defun impact-phrases (presenter value)
  "The phrases of a state's :IMPACT note VALUE: each body's velocity just before and
just after (bodies at rest throughout left out), each non-zero impulse, and the kinetic
energy lost."
  (append
   (loop for (body after) in (getf value :velocities-after)
         for before = (body-entry (getf value :velocities-before) body)
         unless (and (equal before '(0 0)) (equal after '(0 0)))
           collect (phrase (format nil "~A: velocity (" (name-text body))
                           (present presenter (first before)) ", "
                           (present presenter (second before)) ") just before, ("
                           (present presenter (first after)) ", "
                           (present presenter (second after)) ") just after"))
   (loop for entry in (getf value :impulses)
         for (label magnitude) = (multiple-value-list (impulse-entry entry))
         unless (or (null magnitude) (eql magnitude 0))
           collect (phrase (format nil "~A: " label)
                           (present presenter magnitude)))
   (list (phrase "kinetic energy lost: " (present presenter (getf value :energy-lost))))))

(defun accumulation-phrases (presenter value)
  "The phrases of a state's :ACCUMULATION note VALUE (:FACTOR, :CYCLE, :TIME): impacts
repeating with a shrinking cycle that accumulate at a finite time."
  (list (phrase "each cycle " (present presenter (getf value :factor))
                " times the one before (the first lasted "
                (present presenter (getf value :cycle))
                "): they accumulate at t = "
                (present presenter (getf value :time))
                ", and the run goes on from there at rest")))

(defun initial-velocity-phrases (presenter velocities)
  "The phrases of a state's :INITIAL-VELOCITIES note, VELOCITIES ((BODY (VX VY)) ...):
each body's velocity."
  (loop for (body velocity) in velocities
        collect (phrase (format nil "~A: (" (name-text body))
                        (present presenter (first velocity)) ", "
                        (present presenter (second velocity)) ")")))

(defun other-note-phrases (presenter value)
  "The phrases of a note no view knows, VALUE: the expression presented when it is one,
else the datum as text."
  (list (if (valid-expression-p value :kind :arithmetic)
            (phrase (present presenter value))
            (list (datum-text value)))))

(defun energy-phrases (presenter entries)
  "The kinetic, potential and total energy of a state's :ENERGY note ENTRIES ((:kinetic
BODY E) and (:potential SOURCE E) ...), each sum presented: the total is constant where
the forces are conservative and nothing is lost. Written K and U, since T names a
tension."
  (let ((kinetic (loop for entry in entries when (eq (first entry) :kinetic) collect (third entry)))
        (potential (loop for entry in entries when (eq (first entry) :potential) collect (third entry))))
    (flet ((sum (terms) (present presenter (if (rest terms) (cons '+ terms) (or (first terms) 0)))))
      (list (phrase "kinetic K = " (sum kinetic))
            (phrase "potential U = " (sum potential))
            (phrase "total K + U = " (sum (append kinetic potential)))))))

(defun momentum-phrases (presenter entries)
  "The total momentum of a state's :MOMENTUM note ENTRIES ((:momentum BODY (PX PY)) ...)."
  (flet ((sum (axis)
           (let ((terms (mapcar (lambda (entry) (funcall axis (third entry))) entries)))
             (present presenter (if (rest terms) (cons '+ terms) (or (first terms) 0))))))
    (list (phrase "total: (" (sum #'first) ", " (sum #'second) ")"))))

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
                                                              (second (assoc body (getf numeric :final-velocities))))))
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
                                         (present-relation presenter (getf assumed :fact))))
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
