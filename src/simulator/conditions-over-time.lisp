;;;; src/simulator/conditions-over-time.lisp -- the termination conditions of a state as
;;;; functions of its state variables, and whether one fires at once.
;;;;
;;;; A condition speaks of model quantities (a normal force), of state variables, and of
;;;; the geometry of a contact (its gap and the observer's arc length along it). Each is
;;;; written here as an expression over the parameters and the state terms (a fixed
;;;; body's position is a constant), so that one expression serves the local series at
;;;; the start (does the condition fire at once?) and, with the state's motion put in,
;;;; the search for when it fires.

(in-package #:ames.simulator)

(defun body-position-terms (run solved body)
  "BODY's position (X Y) as expressions over SOLVED's state terms: its position terms
when it moves, its position now when it is fixed."
  (if (member `(ames.kb:pos ,body :x) (solved-model-state solved) :test #'equal)
      (list `(ames.kb:pos ,body :x) `(ames.kb:pos ,body :y))
      (body-position run body)))

(defun body-velocity-terms (run solved body)
  "BODY's velocity (VX VY) as expressions over SOLVED's state terms."
  (declare (ignore run))
  (if (member `(ames.kb:vel ,body :x) (solved-model-state solved) :test #'equal)
      (list `(ames.kb:vel ,body :x) `(ames.kb:vel ,body :y))
      (list 0 0)))

(defun relative-position-terms (run solved contact)
  "The observer's position relative to CONTACT's obstacle, over SOLVED's state terms."
  (destructuring-bind (observer obstacle) (contact-bodies run contact)
    (ames.geometry:v- (body-position-terms run solved observer) (body-position-terms run solved obstacle))))

(defun contact-meeting-terms (run solved contact)
  "The geometry's MEETING of CONTACT for the relative position over SOLVED's state
terms (its gap, positive outside; its extent relations)."
  (ames.geometry:contact-meeting (contact-geometry run contact)
                                 (relative-position-terms run solved contact)))

(defun straight-arc-length-terms (run solved contact)
  "The arc length along the straight CONTACT of the observer's relative position, over
SOLVED's state terms."
  (let* ((geometry (contact-geometry run contact))
         (q0 (relative-initial-state run contact))
         (s0 (contact-parameter-of run geometry q0)))
    `(+ ,s0 ,(ames.geometry:dot (ames.geometry:v- (relative-position-terms run solved contact) q0)
                      (ames.geometry:contact-unit-tangent geometry s0)))))

(defun straight-arc-speed-terms (run solved contact)
  "The rate of the arc length along the straight CONTACT -- the observer's velocity
relative to the obstacle along the contact's constant unit tangent -- over SOLVED's
state terms."
  (let* ((geometry (contact-geometry run contact))
         (s0 (contact-parameter-of run geometry (relative-initial-state run contact))))
    (destructuring-bind (observer obstacle) (contact-bodies run contact)
      (ames.geometry:dot (ames.geometry:v- (body-velocity-terms run solved observer)
                     (body-velocity-terms run solved obstacle))
               (ames.geometry:contact-unit-tangent geometry s0)))))

(defun quantity-terms (run solved term)
  "The quantity TERM of a condition as an expression over SOLVED's state terms."
  (cond ((member term (solved-model-state solved) :test #'equal) term)
        ((eq (first term) 'ames.kb:path-position)
         (straight-arc-length-terms run solved (second term)))
        ((eq (first term) 'ames.kb:path-speed)
         (straight-arc-speed-terms run solved (second term)))
        ((eq (first term) 'ames.kb:contact-gap)
         (ames.geometry:meeting-gap (contact-meeting-terms run solved (second term))))
        ((state-constant-term-p term) (with-initial-positions run term))
        ((eq (first term) 'ames.kb:initial-turn) (initial-turn run solved (second term)))
        (t (quantity-value solved term))))

(defun initial-turn (run solved body)
  "The direction BODY starts turning in over the state, the state constant (initial-turn
BODY): 1 or -1, the sign of the first derivative of its angular velocity that is not
zero at the start (omega0, else the angular acceleration, ...: the leading term of its
local series), 0 when every one is (it does not turn). Signals AMBIGUOUS-TRANSITION
with the missing fact when the assumptions leave that sign open."
  (multiple-value-bind (signs coefficient)
      (leading-sign-of run solved `(ames.kb:angvel ,body))
    (case (one-sign signs)
      (:positive 1)
      (:negative -1)
      (:zero 0)
      (t (or (open-sign-question run coefficient
                                 (format nil "the direction ~A starts turning in" body))
             (error 'unsupported-situation
                    :datum body
                    :detail (format nil "The direction ~A starts turning in, the sign of ~S, ~
                                         is not decided." body coefficient)))))))

(defun over-state-terms (run solved expression)
  "EXPRESSION with every quantity term written over SOLVED's state terms."
  (substitute-expressions
   (loop for term in (expression-variables expression)
         when (quantity-term-p term)
           collect (cons term (quantity-terms run solved term)))
   expression))

(defun violation-function (relation)
  "For a strict or loose inequality RELATION, an expression F with RELATION true exactly
when F < 0 (strict) or F <= 0 (loose), and whether it is loose. An equation (= X 0) over
a gap (a corner's touching, src/kb/corners.lisp) is reached as the loose X <= 0: the
gap closing from outside."
  (ecase (first relation)
    (= (values `(- ,(relation-lhs relation) ,(relation-rhs relation)) t))
    (< (values `(- ,(relation-lhs relation) ,(relation-rhs relation)) nil))
    (<= (values `(- ,(relation-lhs relation) ,(relation-rhs relation)) t))
    (> (values `(- ,(relation-rhs relation) ,(relation-lhs relation)) nil))
    (>= (values `(- ,(relation-rhs relation) ,(relation-lhs relation)) t))))

(defun fires-at-once (run solved relation)
  "Whether the termination RELATION holds just after the start of the state (a state
in which it did would last no time): :TRUE, :FALSE, or (values :UNKNOWN FACT) with the
relation whose truth is not decided. A relation whose function vanishes identically
holds at once only when it is loose."
  (case (first relation)
    (or (let ((unknown nil))
          (dolist (part (rest relation) (if unknown (values :unknown unknown) :false))
            (multiple-value-bind (verdict fact) (fires-at-once run solved part)
              (case verdict
                (:true (return :true))
                (:unknown (setf unknown fact)))))))
    (and (let ((unknown nil))
           (dolist (part (rest relation) (if unknown (values :unknown unknown) :true))
             (multiple-value-bind (verdict fact) (fires-at-once run solved part)
               (case verdict
                 (:false (return :false))
                 (:unknown (setf unknown fact)))))))
    (t (multiple-value-bind (function loose) (violation-function relation)
         (multiple-value-bind (signs coefficient)
             (leading-sign-of run solved (over-state-terms run solved function))
           (case (one-sign signs)
             (:negative :true)
             (:positive :false)
             (:zero (if loose :true :false))
             (t (or (and (run-decider-override run)
                         (impact-verdict-by-values (impact-valued run coefficient))) ; numeric-ends.lisp
                    (values :unknown `(< ,coefficient 0))))))))))

(defun impact-verdict-by-values (coefficient)
  "While an impact is resolved, whether a relation whose leading COEFFICIENT's sign the
assumptions leave open fires (:TRUE when it is negative, :FALSE when positive) at the
run's parameter values, the fact recorded as assumed from them; NIL when there are no
values or they do not settle it. An impact has one outcome: it is not branched on. A
COEFFICIENT that is a number (after an end found with numbers: IMPACT-VALUED) is its own
verdict, nothing assumed."
  (cond ((realp coefficient) (cond ((minusp coefficient) :true) ((plusp coefficient) :false)))
        ((eq (ames.algebra:decide-by-values `(< ,coefficient 0)) :true) :true)
        ((eq (ames.algebra:decide-by-values `(> ,coefficient 0)) :true) :false)))

(defun vanishes-identically-p (run solved expression)
  "True when EXPRESSION (over quantity terms) vanishes identically near the start, as
far as its local series shows."
  (eq :zero (one-sign (leading-sign-of run solved (over-state-terms run solved expression)))))

(defun goes-negative-at-once (run solved expression)
  "Whether EXPRESSION (over quantity terms) is negative just after the start: :TRUE,
:FALSE or (values :UNKNOWN FACT)."
  (fires-at-once run solved `(< ,expression 0)))

(defun penetrates-at-once (run solved contact active)
  "Whether the observer of the inactive touching CONTACT enters its obstacle through it
just after the start: :TRUE, :FALSE or (values :UNKNOWN FACT). ACTIVE lists the active
contacts. Through a face alone it enters when its gap turns negative while it stays
within the face's ends; at a corner that is not concave (CONTACT's touching
alternatives) it enters only when it goes inside every face there, and never while one
of them is active."
  (let ((corner (touching-alternatives run contact)))
    (flet ((gap-of (k) `(ames.kb:contact-gap ,k)))
      (if corner
          (if (intersection corner active)
              :false
              (let ((unknown nil))
                (dolist (k (cons contact corner) (if unknown (values :unknown unknown) :true))
                  (multiple-value-bind (verdict fact) (goes-negative-at-once run solved (gap-of k))
                    (case verdict
                      (:false (return :false))
                      (:unknown (setf unknown fact)))))))
          (multiple-value-bind (verdict fact) (goes-negative-at-once run solved (gap-of contact))
            (if (not (eq verdict :true))
                (values verdict fact)
                (let ((unknown nil))
                  (dolist (relation (ames.geometry:meeting-extent
                                     (contact-meeting-terms run solved contact))
                                    (if unknown (values :unknown unknown) :true))
                    ;; within the ends just after the start: the extent's negation does not hold
                    (multiple-value-bind (outside fact)
                        (fires-at-once run solved (negated-extent relation))
                      (case outside
                        (:true (return :false))
                        (:unknown (setf unknown fact))))))))))))

(defun negated-extent (relation)
  "The negation of an extent RELATION (>= X Y), (<= X Y) or an OR of them."
  (case (first relation)
    (>= (list '< (relation-lhs relation) (relation-rhs relation)))
    (<= (list '> (relation-lhs relation) (relation-rhs relation)))
    (or (cons 'and (mapcar #'negated-extent (rest relation))))
    (t (error 'unsupported-situation :datum relation
                                     :detail "An extent relation of an unexpected form."))))

(defun departing-relation (run solved point)
  "The equation (= X Y) among the activation choice POINT's relations, over kinematic
state quantities only (a rotating body's corner on a face: its gap), whose difference
X - Y changes at once at the start of the state, its rate there decided non-zero under
SOLVED; else NIL. An active instance held by such an equation is inconsistent: the
bodies move apart through it (a corner leaving the floor it bounced on) or into it."
  (loop for relation in (ames.engine:choice-point-relations point)
        when (and (consp relation) (eq (first relation) '=)
                  (every (lambda (term) (or (not (quantity-term-p term)) (state-quantity-p term)))
                         (expression-variables relation))
                  (some #'quantity-term-p (expression-variables relation))
                  (member (one-sign (sign-of run (second (series-coefficients
                                                          run solved
                                                          (over-state-terms run solved
                                                                            `(- ,(relation-lhs relation)
                                                                                ,(relation-rhs relation)))
                                                          2))))
                          '(:positive :negative)))
          return relation))
