;;;; src/report/text.lisp -- the text report: a simulation history for people, state by state.

(in-package #:ames.report)

(defun text-name (name)
  "How the text report writes a name: a_x for the acceleration terms, else lower case."
  (if (and (consp name) (eq (first name) 'acceleration))
      (format nil "a_~(~A~)" (second name))
      (default-name name)))

(defun text (expression)
  "EXPRESSION (presented) as plain text."
  (text-form expression :name-function #'text-name))

(defun phrase-string (phrase)
  "PHRASE as plain text."
  (phrase-text phrase #'text))

(defun text-phrase (phrase)
  "PHRASE (see PHRASE) as the text report writes it."
  (phrase-string phrase))

(defun event-text (presenter event &optional state)
  "The end EVENT of STATE in words, as the text report writes it: \"particle collides
with ground\"."
  (phrase-string (event-phrase presenter event state)))

(defun numbers-text (numbers)
  "The text put beside a formula for NUMBERS (see VIEW's :NUMBERS): \" = 7.357\",
\" = 0.9152 + 0.5 tau^2\", \" (0 at the start, 29.43 at the end)\", or \"\"."
  (cond ((null numbers) "")
        ((and (consp numbers) (eq (first numbers) :from))
         (format nil " (~A at the start~@[, ~A at the end~])" (number-text (getf numbers :from))
                 (and (getf numbers :to) (number-text (getf numbers :to)))))
        (t (format nil " = ~A" (text numbers)))))

(defun vector-numbers-text (numbers)
  "The text beside a vector for NUMBERS, a list of two (see NUMBERS-TEXT)."
  (cond ((or (null numbers) (notevery #'identity numbers)) "")
        ((every #'realp numbers)
         (format nil " = (~{~A~^, ~})" (mapcar #'number-text numbers)))
        (t (format nil " (~{~A~^; ~})"
                   (loop for n in numbers for axis in '("x" "y")
                         collect (format nil "~A~A" axis (numbers-text n)))))))

(defun indented-lines (text indent stream)
  "Write TEXT on STREAM with INDENT before each of its non-empty lines."
  (dolist (line (cl-ppcre:split "\\n" text))
    (if (string= line "")
        (format stream "~A~%" (string-right-trim " " indent))
        (format stream "~A~A~%" indent line))))

(defun branch-heading (branch)
  "\"Branch 1.2 of 3 (selected by the given values)\": the heading words of a BRANCH view."
  (format nil "Branch ~A of ~D~:[~; (selected by the given values)~]" (getf branch :label)
          (getf branch :count) (getf branch :selected)))

(defun branch-end-words (branch)
  "How a BRANCH view ends, in words: its outcome, or, for a branch listed with its fact
alone, that it was not simulated. (Why it failed is its :FAILURE phrase.)"
  (let ((outcome (getf branch :outcome)))
    (if (and (null (getf branch :states)) (member outcome '(nil :not-simulated)))
        "not simulated (only its fact is known)"
        (keyword-words (or outcome :unknown)))))

(defun print-branch-text (branch stream)
  "Print a BRANCH view of a fork: its heading and fact, its states marked \"| \" (once per
level of the tree of branches), and how it ends."
  (format stream "~%~A, assuming ~A:~%" (branch-heading branch) (phrase-string (getf branch :assume)))
  (indented-lines (with-output-to-string (out)
                    (dolist (state (getf branch :states)) (print-state-text state out)))
                  "| " stream)
  (format stream "End of branch ~A: ~A~@[ (~A)~]~%" (getf branch :label) (branch-end-words branch)
          (and (getf branch :failure) (phrase-string (getf branch :failure)))))

(defun rotation-text (view)
  "A final angle's or angular velocity's VIEW (:VALUE V [:NUMBER N]) as text, or NIL."
  (and view (format nil "~A~A" (text (getf view :value)) (numbers-text (getf view :number)))))

(defun print-body-motion-text (body stream)
  "Print one body's motion of a state's view (an element of its :BODIES) on STREAM: its
acceleration, position and, for a rotating body, its rotation."
  (format stream "  ~A:~%" (name-text (getf body :name)))
  (destructuring-bind (&optional ax ay) (getf body :acceleration)
    (destructuring-bind (&optional nx ny) (getf body :acceleration-numbers)
      (format stream "    acceleration: a_x = ~A~A, a_y = ~A~A~%"
              (text ax) (numbers-text nx) (text ay) (numbers-text ny))))
  (let ((position (getf body :position))
        (numbers (getf body :position-numbers)))
    (cond ((eq position :no-closed-form)
           (format stream "    position:     no closed form in time (integrated numerically)~%"))
          ((and (consp position) (eq (first position) :on-path))
           (format stream "    position:     on the curve at arc length s: x = ~A~A, y = ~A~A~%"
                   (text (first (second position))) (numbers-text (first numbers))
                   (text (second (second position))) (numbers-text (second numbers))))
          ((consp position)
           (format stream "    position:     x = ~A~A~%                  y = ~A~A~%"
                   (text (first position)) (numbers-text (first numbers))
                   (text (second position)) (numbers-text (second numbers))))
          (t (format stream "    position:     ~A~%" (datum-text position)))))
  (let ((rotation (getf body :rotation)))
    (when rotation
      (if (eq (getf rotation :angle) :no-closed-form)
          (format stream "    rotation:     no closed form in time (integrated numerically)~%")
          (format stream "    rotation:     ~@[alpha = ~A, ~]theta = ~A, omega = ~A~%"
                  (and (getf rotation :angular-acceleration) (text (getf rotation :angular-acceleration)))
                  (text (getf rotation :angle)) (text (getf rotation :angular-velocity)))))))

(defun print-state-text (view stream)
  "Print one state's VIEW (see STATE-VIEW) on STREAM."
  (format stream "~%~:[State ~D~;Fork at the start of state ~D (no period of motion)~]~@[ (branch ~A)~], ~
                  from t = ~A~@[ (~A)~]~%" (getf view :fork) (getf view :index) (getf view :branch)
          (phrase-string (getf view :start))
          (and (getf view :start-number) (number-text (getf view :start-number))))
  (format stream "  contacts:~:[ none~;~]~%" (getf view :contacts))
  (dolist (contact (getf view :contacts))
    (format stream "    ~A~%" (phrase-string contact)))
  (format stream "  forces:~:[ none~;~]~%" (getf view :forces))
  (dolist (force (getf view :forces))
    (let ((value (getf force :value)))
      (format stream "    ~A~{ (~A)~}~@[: ~A~]~%" (getf force :label) (getf force :options)
              (cond ((null value) nil)
                    ((getf force :vector-p)
                     (format nil "(~A, ~A)~A" (text (first value)) (text (second value))
                             (vector-numbers-text (getf force :numbers))))
                    (t (format nil "~@[~A = ~]~A~A" (getf force :symbol) (text value)
                               (numbers-text (getf force :numbers))))))))
  (dolist (body (getf view :bodies))
    (print-body-motion-text body stream))
  (loop for (label . phrases) in (getf view :notes)
        do (format stream "  ~A:~%~{    ~A~%~}" label (mapcar #'phrase-string phrases)))
  (format stream "  ends: ~A~%" (phrase-string (getf view :end)))
  (dolist (event (remove (getf view :end) (getf view :events) :test #'equal))
    (format stream "    and at the same instant ~A~%" (phrase-string event)))
  (format stream "  duration: ~A~@[ (~A)~]~%" (phrase-string (getf view :duration))
          (and (getf view :duration-number) (number-text (getf view :duration-number))))
  (when (getf view :final)
    (format stream "  at the end:~%")
    (dolist (final (getf view :final))
      (format stream "    ~A at (~A, ~A)~A, velocity (~A, ~A)~A~@[, angle ~A~]~@[, angular velocity ~A~]~%"
              (name-text (getf final :name))
              (text (first (getf final :position))) (text (second (getf final :position)))
              (vector-numbers-text (getf final :position-numbers))
              (text (first (getf final :velocity))) (text (second (getf final :velocity)))
              (vector-numbers-text (getf final :velocity-numbers))
              (rotation-text (getf final :angle)) (rotation-text (getf final :angular-velocity)))))
  ;; a fork's branches come after its own values, each nested under it
  (dolist (branch (getf view :branches))
    (print-branch-text branch stream)))

(defun print-view-text (view stream)
  "Print a HISTORY-VIEW on STREAM as the text report."
  (format stream "~&Scenario ~A~@[: ~A~]~%" (name-text (getf view :name)) (getf view :description))
  (when (getf view :parameters)
    (format stream "  parameters: ~{~A~^, ~}~%" (mapcar #'phrase-string (getf view :parameters))))
  (when (getf view :values)
    (format stream "  with ~{~A~^, ~}~%"
            (loop for (name . value) in (getf view :values)
                  collect (format nil "~A = ~A" (name-text name) (number-text value)))))
  (when (getf view :fixed)
    (format stream "  fixed: ~{~A~^, ~}~%" (mapcar #'phrase-string (getf view :fixed))))
  (when (getf view :states)
    (format stream "~{  ~A~%~}" (mapcar #'phrase-string (getf view :definitions))))
  (dolist (state (getf view :states))
    (print-state-text state stream))
  (dolist (assumed (getf view :assumed))
    (format stream "~%Assumed from the given values ~A~%" (phrase-string assumed)))
  (format stream "~%Outcome: ~(~A~)~%" (getf view :outcome))
  (when (getf view :answers)
    (format stream "Answers:~%")
    (loop for (name phrase) in (getf view :answers)
          do (format stream "  ~A: ~A~%" (name-text name) (phrase-string phrase))))
  (let ((ambiguity (getf view :ambiguity)))
    (when ambiguity
      (format stream "  Which event ends the last state is not decided by the assumptions.~%")
      (format stream "  Missing fact: ~A~%" (phrase-string (getf ambiguity :missing-fact)))
      (format stream "  Candidates:~%~{    ~A~%~}" (mapcar #'phrase-string (getf ambiguity :candidates)))))
  (when (getf view :stopped)
    (format stream "  ~A~%" (phrase-string (getf view :stopped))))
  (dolist (line (getf view :self-check))
    (format stream "~A~%" line)))

(defun print-history-text (history stream &key (bridge (current-bridge)))
  "Print HISTORY on STREAM as a report for people: the parameters and fixed bodies once,
then state by state the contacts named by their features, the forces, each moving
body's acceleration and trajectory written as a textbook would (see PRESENT), the end
event, the duration and what holds at the end; numbers beside the formulas under
parameter values. Asks BRIDGE for the presentation forms."
  (let ((view (call-with-presenter history bridge
                                   (lambda (presenter) (history-view presenter history)))))
    ;; names and descriptions are the user's: no control character reaches a terminal
    (write-string (visible-text (with-output-to-string (out) (print-view-text view out))
                                :keep '(#\Newline #\Tab))
                  stream)))
