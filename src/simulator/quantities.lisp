;;;; src/simulator/quantities.lisp -- the quantities a query reads off a state, as the knowledge
;;;; base reported them (issue 20, class 6: queries never re-derive physics).
;;;;
;;;; A state holds the sections the knowledge base reports beside the forces (see
;;;; src/kb/energy.lisp): :ENERGY, entries (:KINETIC BODY E) and (:POTENTIAL SOURCE E), and
;;;; :MOMENTUM, entries (:MOMENTUM BODY (PX PY)). A query's energy is the sum of the
;;;; :ENERGY entries, the very terms the report adds up as "total T + V"; a body's kinetic
;;;; energy and momentum are its own entries. A state reported over the arc length of a
;;;; curve or a line (its positions and velocities are (:ON-PATH ...)) is read at its start
;;;; and end by putting the arc length to its first and last values, which needs no time:
;;;; the energy integral gives the speed there (thesis 4.2.2).

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

(defun reported-kinetic-energy (state body fixed)
  "BODY's kinetic energy as reported for STATE: the sum of its kinetic terms, (:KINETIC BODY
E) and those of its other motions (:KINETIC (KIND BODY) E), such as its rotation's; 0 for a
FIXED body; NIL when not reported."
  (if fixed
      0
      (let ((terms (loop for (kind source energy) in (reported-section state :energy)
                         when (and (eq kind :kinetic)
                                   (named-alike-p (if (consp source) (car (last source)) source) body))
                           collect energy)))
        (cond ((null terms) nil)
              ((rest terms) (cons '+ terms))
              (t (first terms))))))

(defun reported-momentum (state body fixed)
  "BODY's momentum (PX PY) as reported for STATE; (0 0) for a FIXED body; NIL when not
reported."
  (if fixed
      (list 0 0)
      (let ((entry (find-if (lambda (e) (and (eq (first e) :momentum) (named-alike-p (second e) body)))
                            (reported-section state :momentum))))
        (and entry (third entry)))))

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
