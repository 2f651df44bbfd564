;;;; src/scenario/friction.lisp -- validating the (friction BODY1 BODY2 :static MU-S [:kinetic MU-K])
;;;; clauses of the friction extension (scenario-language.md, "Friction").
;;;;
;;;; A clause names two distinct declared bodies and the coefficients of Coulomb friction on
;;;; every contact between them. One clause per pair, in either order. The coefficients
;;;; are expressions over the parameters; where they are constants they must not be
;;;; negative, and MU-K may not exceed MU-S (the textbook's friction: a pair that sticks
;;;; needs a larger force to start sliding than to keep sliding). MU-K defaults to MU-S.
;;;; What the numbers do not settle is the simulator's to decide under the assumptions.

(in-package #:ames.scenario)

(defun check-coefficient (validation expression what)
  "Signal SCENARIO-EXPRESSION-ERROR when EXPRESSION, a friction coefficient named WHAT,
is a negative constant."
  (multiple-value-bind (value exact) (expression-value expression)
    (when (and value (eq (compare-values value exact 0 t) :less))
      (reject validation 'scenario-expression-error expression
              "~A cannot be negative, not ~A" what (show expression)))))

(defun checked-friction (validation clause)
  "The SCENARIO-FRICTION that CLAUSE, (friction BODY1 BODY2 :static MU-S [:kinetic
MU-K]), declares. Signals a SCENARIO-ERROR naming the clause."
  (enter validation "clause FRICTION" clause)
  (when (< (length clause) 3)
    (reject validation 'missing-property-error clause
            "friction names two bodies: (friction BODY1 BODY2 :static MU-S [:kinetic MU-K])"))
  (let ((bodies (list (checked-body-name validation (second clause) "friction")
                      (checked-body-name validation (third clause) "friction"))))
    (enter validation (format nil "friction ~A ~A" (symbol-name (first bodies))
                              (symbol-name (second bodies)))
           clause)
    (when (eq (first bodies) (second bodies))
      (reject validation 'scenario-syntax-error (third clause)
              "friction acts between two different bodies, not ~A and itself"
              (show (first bodies))))
    (let ((arguments (checked-keywords validation (cdddr clause) '(:static :kinetic) "friction")))
      (unless (assoc :static arguments)
        (reject validation 'missing-property-error clause
                "the friction has no :static coefficient"))
      (let* ((static (checked-expression validation (keyword-value :static arguments)))
             (kinetic (multiple-value-bind (value present) (keyword-value :kinetic arguments)
                        (if present (checked-expression validation value) static))))
        (check-coefficient validation static "the :static coefficient")
        (check-coefficient validation kinetic "the :kinetic coefficient")
        (multiple-value-bind (mu-s s-exact) (expression-value static)
          (multiple-value-bind (mu-k k-exact) (expression-value kinetic)
            (when (and mu-s mu-k (eq (compare-values mu-k k-exact mu-s s-exact) :greater))
              (reject validation 'scenario-expression-error kinetic
                      "the :kinetic coefficient ~A exceeds the :static one ~A"
                      (show kinetic) (show static)))))
        (make-instance 'scenario-friction :bodies bodies :static static :kinetic kinetic)))))

(defun checked-frictions (validation clauses)
  "The SCENARIO-FRICTIONs of the (friction ...) CLAUSES, in order. Signals
DUPLICATE-CLAUSE-ERROR naming the second clause for one pair of bodies."
  (let ((frictions '()))
    (dolist (clause clauses (nreverse frictions))
      (let ((friction (checked-friction validation clause)))
        (when (find-if (lambda (other)
                         (null (set-exclusive-or (scenario-friction-bodies other)
                                                 (scenario-friction-bodies friction))))
                       frictions)
          (reject validation 'duplicate-clause-error clause
                  "there is more than one (friction ...) clause for ~A and ~A"
                  (show (first (scenario-friction-bodies friction)))
                  (show (second (scenario-friction-bodies friction)))))
        (push friction frictions)))))

(defun find-scenario-friction (body-1 body-2 scenario)
  "The SCENARIO-FRICTION of SCENARIO between the bodies named BODY-1 and BODY-2 (in
either order, compared by name), or NIL."
  (find-if (lambda (friction)
             (let ((names (mapcar #'symbol-name (scenario-friction-bodies friction))))
               (null (set-exclusive-or names (list (symbol-name body-1) (symbol-name body-2))
                                       :test #'string=))))
           (scenario-frictions scenario)))
