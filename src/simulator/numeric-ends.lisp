;;;; src/simulator/numeric-ends.lisp -- a state's end found with numbers, written as numbers.
;;;;
;;;; A numerically integrated state ends with rationals near the integration's doubles
;;;; (RATIONAL-OF), at the run's parameter values. Putting a rotating body's corners back on
;;;; their faces (corner-snapping.lisp, flat-corner-snapping.lisp) uses the scenario's
;;;; geometry, written in its parameters: a corner's velocity along the floor becomes
;;;; -(l/2) omega with omega the integration's rational, printed "-225770929 l / 89441190"
;;;; -- a product of a symbol with a number that holds only at l = 1, not a formula of the
;;;; problem. So once a state ends with numbers (values in force), the rotating bodies' end
;;;; values, and what the impact after it derives from them (impulses, the energy lost, the
;;;; rotating bodies' velocities just after: the next state's start), have the parameters'
;;;; values put in: numbers, equal to the formulas they replace at those values; the
;;;; impact's open signs are decided at the values (VALUED-RELATION). A run without values
;;;; is not touched (closed forms stay). Not done: a body that does not turn keeps the
;;;; exact point its contact's geometry gives (a bob on its rope's circle at a + l u, with
;;;; u a rational direction): valued, the next state finds the rope's slack 1 - l, not 0,
;;;; and forks on its sign -- the next state's contacts would have to be decided at the
;;;; values too.

(in-package #:ames.simulator)

(defun valued-expression (run x)
  "X with the run's parameter values put in: a number (an exact constant; a double made
the rational it is, RATIONAL-OF) when that leaves no parameter in it; X itself otherwise
(no values, or X holds something else the values do not fix)."
  (let ((values (run-values run)))
    (if (or (null values) (numberp x)
            (every (lambda (entry) (free-of-p (car entry) x)) values))
        x
        (let ((valued (tidy run (substitute-expressions values x))))
          (cond ((floatp valued) (rational-of valued))
                ((and (every (lambda (entry) (free-of-p (car entry) valued)) values)
                      (notany #'quantity-term-p (expression-variables valued))
                      (not (depends-on-motion-p valued)))
                 valued)
                (t x))))))

(defun valued-tree (run tree)
  "TREE (a list of expressions, nested) with VALUED-EXPRESSION on each leaf expression:
an expression is an atom or a list whose head is a symbol."
  (if (or (atom tree) (symbolp (first tree)))
      (valued-expression run tree)
      (mapcar (lambda (x) (valued-tree run x)) tree)))

(defun valued-end-values (run values)
  "VALUES, an alist body -> (X Y) or body -> (VALUE), the rotating bodies' entries valued
(VALUED-EXPRESSION): their corners put back on the faces made them products of the
integration's rationals and the parameters. A fixed body's stays the scenario's formula;
a body that does not turn keeps the exact point its contact's geometry gives (a bob put
on its rope's circle at a + l u: valued, the next state would find the rope's slack
1 - l, and fork on its sign)."
  (if (null (run-values run))
      values
      (mapcar (lambda (entry)
                (if (or (body-fixed-p run (first entry))
                        (not (assoc (first entry) (run-rotations run))))
                    entry
                    (cons (first entry) (valued-tree run (rest entry)))))
              values)))

(defun numeric-end-state-p (state)
  "True when STATE ended where numbers put it: it was integrated numerically, or its end
time is a double (a root searched with numbers)."
  (or (state-numeric-trajectory state) (floatp (state-duration state))))

(defun valued-impact (run numeric-end after impact)
  "AFTER (velocities just after) and IMPACT (RESOLVE-IMPACT's plist) with the parameters'
values put in (VALUED-EXPRESSION) when NUMERIC-END, the impact following an end found
with numbers (NUMERIC-END-STATE-P): the impulses, the energy lost, the rotating bodies'
velocities and angular velocities just after (VALUED-END-VALUES). Returns (values AFTER
IMPACT)."
  (if (not (and numeric-end (run-values run)))
      (values after impact)
      (let ((impact (copy-list impact)))
        (setf (getf impact :impulses)
              (mapcar (lambda (entry) (append (butlast entry) (list (valued-tree run (car (last entry))))))
                      (getf impact :impulses))
              (getf impact :energy-lost) (valued-expression run (getf impact :energy-lost))
              (getf impact :velocities-after) (valued-end-values run (getf impact :velocities-after)))
        (when (getf impact :angular-velocities-after)
          (setf (getf impact :angular-velocities-after)
                (valued-end-values run (getf impact :angular-velocities-after))))
        (values (valued-end-values run after) impact))))

(defvar *impact-at-values* nil
  "True while an impact after an end found with numbers (NUMERIC-END-STATE-P) is resolved:
its velocities just before are numbers at the run's values, and the relations over the
parameters its consistency search meets hold or not at those values only.")

(defun valued-relation (run relation)
  "RELATION (a comparison, or AND / OR / NOT of them) with the run's parameter values put
in its sides (VALUED-EXPRESSION) while *IMPACT-AT-VALUES*; RELATION itself otherwise. An
impact after an end found with numbers starts where only those values put it: a relation
mixing the parameters' symbols with the integration's numbers (an impulse 225770929 m
(3 - l) / 536647140) is no statement about other values, and is decided at them, exactly."
  (cond ((or (not *impact-at-values*) (null (run-values run)) (atom relation)) relation)
        ((member (first relation) '(< > <= >= = /=))
         (cons (first relation) (mapcar (lambda (side) (valued-expression run side)) (rest relation))))
        ((member (first relation) '(and or not))
         (cons (first relation) (mapcar (lambda (part) (valued-relation run part)) (rest relation))))
        (t relation)))

(defun impact-valued (run x)
  "X with the run's parameter values put in (VALUED-EXPRESSION) while *IMPACT-AT-VALUES*,
else X: see VALUED-RELATION."
  (if *impact-at-values* (valued-expression run x) x))
