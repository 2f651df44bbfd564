;;;; src/simulator/start-verdicts.lisp -- which contacts touch, and which kinematic relations
;;;; hold, at the start of a state: the deciders of the model's activation and mode entry
;;;; conditions (moved from run.lisp, unchanged).

(in-package #:ames.simulator)

;;; Which contacts touch at the start of a state

(defun touching-on-locus-p (run contact)
  "True when the observer's relative position lies on CONTACT's locus now."
  (ames.geometry:position-on-contact-p (contact-geometry run contact)
                                       (relative-initial-state run contact)))

(defun normal-approach (run contact)
  "The relative velocity's component along CONTACT's outward normal now (the observer
on its locus): positive when separating, negative when approaching."
  (let ((geometry (contact-geometry run contact)))
    (multiple-value-bind (q v) (relative-initial-state run contact)
      (tidy run (ames.geometry:dot v (ames.geometry:contact-outward-normal
                            geometry (contact-parameter-of run geometry q)))))))

(defun touching-alternatives (run contact)
  "The alternatives of CONTACT (see CORNER-ALTERNATIVES) on whose locus the observer
also lies now."
  (remove-if-not (lambda (other) (touching-on-locus-p run other))
                 (cdr (assoc contact (run-alternatives run)))))

(defun approaching-now-p (run contact)
  "True when the observer lies on CONTACT's locus and moves into it (its normal velocity
is negative) while not excused by a corner: not staying outside another face there.
Such a contact is reached with a velocity: an impact at the start of the state."
  (and (touching-on-locus-p run contact)
       (sign-is run (normal-approach run contact) :negative)
       (notany (lambda (other) (sign-is run (normal-approach run other) :zero :positive))
               (touching-alternatives run contact))))

(defun touching-verdict (run contact)
  "Whether CONTACT holds at the start of the state, as the decider answers: :FALSE
when the observer is off its locus, moving away from it, or moving into it (an impact:
see APPROACHING-NOW-P; the contact is not a constraint of the state, which ends at once
in that impact); :CHOICE when it is on the locus with no normal velocity (active or
not is settled by consistency); :UNKNOWN when the sign of the normal velocity is not
decided."
  (if (not (touching-on-locus-p run contact))
      :false
      (case (one-sign (sign-of run (normal-approach run contact)))
        (:zero :choice)
        ((nil) :unknown)
        (t :false))))

(defun gap-relation-contact (relation)
  "The contact K when RELATION is the touching relation (= (contact-gap K) 0), or a probe's
reaching relation (<= (contact-gap K) 0), else NIL."
  (and (consp relation) (member (first relation) '(= <=))
       (consp (second relation)) (eq (first (second relation)) 'ames.kb:contact-gap)
       (second (second relation))))

(defun state-quantity-p (term)
  "True when TERM is a kinematic quantity whose value at the start of the state the run
knows: a body's position or velocity, the arc length along a contact or its rate, a
rotating body's angle or angular velocity."
  (and (quantity-term-p term)
       (member (first term) '(ames.kb:pos ames.kb:vel ames.kb:path-position ames.kb:path-speed
                              ames.kb:angle ames.kb:angvel))))

(defun start-values (run relation)
  "An alist: each kinematic quantity of RELATION (see STATE-QUANTITY-P, and the state's
constants (initial-pos B :x), (initial-vel B :x)) -> its value at the start of the state."
  (loop for term in (expression-variables relation)
        when (state-quantity-p term)
          collect (cons term (initial-state-value run term))
        when (state-constant-term-p term)
          collect (cons term (with-initial-positions run term))))

(defun relation-at-start (run relation)
  "RELATION with its kinematic quantities replaced by their values at the start of the
state (as KINEMATIC-VERDICT decides it): a fact over the parameters."
  (let ((values (start-values run relation)))
    (if values
        (constant-roots-taken run (substitute-expressions values relation))
        relation)))

(defun kinematic-verdict (run relation)
  "RELATION decided on the state's starting values: its kinematic quantities (see
STATE-QUANTITY-P, and the state's constants (initial-pos B :x), (initial-vel B :x)) replaced by their
values at the start, square roots of constant squares taken (CONSTANT-ROOTS-TAKEN), then
Maxima's verdict. :CHOICE when the state's first instant does not settle it: an
equation or inequation over kinematic quantities whose sides are equal at the start (a
rope at exactly its length may stay taut or go slack), or an inequality whose sides are
equal at the start while it mentions a velocity (a body's, or the rate of an arc length)
to the first power: which side the state moves to depends on the accelerations, as for
a contact's sliding at rest. The consistency search settles a :CHOICE. A velocity under
a power or root (a squared transverse rate) only measures how far the state is from the
boundary: such a relation, like a non-strict one, is decided on the values, and an exit
transition leaves the mode at once if the motion does (see the local series). A
relation over no kinematic quantity is decided as it is."
  (let ((values (start-values run relation)))
    (if (null values)
        (decide run relation)
        (let* ((at-start (constant-roots-taken run (substitute-expressions values relation)))
               (operator (first at-start)))
          (flet ((equal-at-start ()
                   (decide run `(= ,(relation-lhs at-start) ,(relation-rhs at-start)))))
            (cond ((member operator '(= /=))
                   (case (equal-at-start)
                     (:true :choice)
                     (:false (if (eq operator '=) :false :true))
                     (t :unknown)))
                  ((and (member operator '(< >))
                        (some (lambda (entry) (velocity-term-p (car entry))) values)
                        (not (velocity-under-power-p relation))
                        (eq :true (equal-at-start)))
                   :choice)
                  (t (decide run at-start))))))))

(defun velocity-term-p (term)
  "True when TERM is a velocity: a body's, the rate of an arc length, or an angular velocity."
  (and (consp term) (member (first term) '(ames.kb:vel ames.kb:path-speed ames.kb:angvel)) t))

(defun velocity-under-power-p (expression)
  "True when a velocity term occurs in EXPRESSION under a power other than 1 or a root."
  (and (consp expression)
       (not (quantity-term-p expression))
       (if (or (eq (first expression) 'sqrt)
               (and (eq (first expression) 'expt) (not (eql (third expression) 1))))
           (some #'velocity-term-p (expression-variables expression))
           (some #'velocity-under-power-p (rest expression)))))

(defun run-decider (run)
  "The decider of the model the run works on: the impact's while one is resolved, else
the state's (STATE-DECIDER)."
  (or (run-decider-override run) (state-decider run)))

(defun state-decider (run)
  "The decider of the current state's activation and mode entry conditions: touching
relations go to the geometry (see TOUCHING-VERDICT, PROBE-VERDICT), relations over
kinematic quantities are decided on their values at the start (see KINEMATIC-VERDICT),
everything else goes to Maxima."
  (lambda (relation)
    (let ((contact (gap-relation-contact relation)))
      (cond ((null contact) (kinematic-verdict run relation))
            ((eq (first relation) '<=) (probe-verdict run contact))
            (t (touching-verdict run contact))))))
