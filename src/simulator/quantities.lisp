;;;; src/simulator/quantities.lisp -- the quantities a query reads off a state, as the knowledge
;;;; base reported them (issue 20, class 6: queries never re-derive physics).
;;;;
;;;; A state holds the sections the knowledge base reports beside the forces (see
;;;; src/kb/terms.lisp and energy.lisp): :ENERGY and :MOMENTUM, entries (KIND SUBJECT
;;;; VALUE) of the kinds the knowledge base declares. A query's energy is the sum of the
;;;; :ENERGY entries, the very terms the report adds up as its total; a query the kb
;;;; declares a kind of term for (AMES.KB:QUERY-REPORTED-TERM: a body's kinetic energy,
;;;; its momentum) is the sum of the body's own entries of that kind. A state reported
;;;; over the arc length of a curve or a line (its positions and velocities are (:ON-PATH
;;;; ...)) is read at its start and end by putting the arc length to its first and last
;;;; values, which needs no time: the energy integral gives the speed there (thesis 4.2.2).

(in-package #:ames.simulator)

(defun named-alike-p (a b)
  "True when the symbols A and B have the same name (scenario names are compared by name)."
  (and (symbolp a) (symbolp b) (string= (symbol-name a) (symbol-name b))))

(defun reported-section (state section)
  "The entries STATE holds for the knowledge-base SECTION (:ENERGY, :MOMENTUM)."
  (getf (state-reported-sections state) section))

(defun state-total-energy (state)
  "The sum of every energy term the knowledge base reports for STATE (kinetic energy of
each free body, potential energy of each conservative source), or NIL when it reports
none."
  (let ((terms (mapcar #'third (reported-section state :energy))))
    (cond ((null terms) nil)
          ((rest terms) (cons '+ terms))
          (t (first terms)))))

(defun sum-of-terms (terms)
  "The sum of the expressions TERMS, written as the one term when there is one."
  (if (rest terms) (cons '+ terms) (first terms)))

(defun reported-body-term (state term body fixed)
  "The sum of BODY's entries of the kind of term TERM (an AMES.KB:REPORTED-TERM) that
STATE reports (those whose subject is BODY or ends in it, see AMES.KB:TERM-SUBJECT-BODY):
an expression, or (X Y) for a vector kind; zero for a FIXED body; NIL when none is
reported."
  (let ((values (and (not fixed)
                     (loop for (nil subject value)
                             in (ames.kb:term-entries term (reported-section state (ames.kb:term-section term)))
                           when (named-alike-p (ames.kb:term-subject-body subject) body)
                             collect value))))
    (cond ((ames.kb:term-vector term)
           (cond (fixed (list 0 0))
                 ((null values) nil)
                 (t (list (sum-of-terms (mapcar #'first values))
                          (sum-of-terms (mapcar #'second values))))))
          (fixed 0)
          (t (and values (sum-of-terms values))))))

(defun arc-length-start (state)
  "The arc length at which STATE's motion along a curve or a line starts, or NIL (no such
motion, or several lines sharing the coordinate)."
  (let ((path (state-path-coordinates state))
        (lines (state-line-coordinates state)))
    (cond (path (getf path :arc-length-from))
          ((and lines (null (rest lines))) (getf (first lines) :from)))))

(defun arc-length-end (state)
  "The arc length at which STATE's motion along a curve or a line ends, or NIL."
  (state-end-arc-length state))

(defun mentions-unknown-p (expression)
  "True when EXPRESSION still holds a knowledge-base quantity term (such as (vel b :x)):
the state's motion was not found in closed form, so the expression is no answer."
  (cond ((quantity-term-p expression) t)
        ((consp expression) (some #'mentions-unknown-p (if (symbolp (first expression))
                                                               (rest expression)
                                                               expression)))
        (t nil)))

(defun recorded (state alist body)
  "BODY's entry in STATE's per-body ALIST (positions, velocities, accelerations). A state
that records no motion of BODY (a fork, which only splits the run) answers nothing."
  (let ((entry (find body alist :key #'first :test #'named-alike-p)))
    (if (and entry (second entry))
        (second entry)
        (error 'unanswerable
               :detail (format nil "state ~D records no motion of ~(~A~)~:[~; (it is a fork: its branches have the motion)~]"
                               (state-index state) body (state-branches state))))))

(defun one-line (condition)
  "CONDITION's report on one line."
  (substitute #\Space #\Newline (princ-to-string condition)))
