;;;; src/simulator/indeterminate-forces.lisp -- a start whose only candidate model fixes
;;;; the motion but not the forces: statically indeterminate, said as such.
;;;;
;;;; A body held by more supports than the equations of motion fix (a particle at rest on
;;;; a rough incline and tied by a rope up the slope: static friction F and the tension T
;;;; share m g sin a, T + F = m g sin a, nothing more) has, in the assignment of contacts
;;;; and modes that holds it, a model with a family of solutions: SOLVE-MODEL refuses it
;;;; (no unique solution), and with no other assignment consistent the start would get
;;;; the generic "no set of contacts and modes is consistent". Here such an assignment
;;;; is tried again with one unknown of its model left free (each in turn): where the
;;;; rest then has a unique solution and every rate of the state (the motion) is free of
;;;; it, the forces are statically indeterminate by one degree, the free unknown shares
;;;; the load with the unknowns that depend on it, and the range it may take is read off
;;;; the assignment's exit conditions (each must not hold at the start: a normal force
;;;; stays attractive-free, a static friction within its cone, a rope's tension >= 0),
;;;; each linear in it. The refusal, STATICALLY-INDETERMINATE, names the bodies whose
;;;; equations the shared unknowns enter, the shared unknowns (the knowledge base's own
;;;; terms) with their values over the free one, and the bounds. An assignment whose
;;;; exits are decided to fire at once, or whose bounds are decided to leave no room, is
;;;; no such rest and is not reported. The simulator names no force here: the unknowns
;;;; are the model's terms, the words "statically indeterminate" a fact of equations.

(in-package #:ames.simulator)

(define-condition statically-indeterminate (unsolvable-model)
  ((bodies :initarg :bodies :reader indeterminate-bodies
           :documentation "The bodies whose equations of motion the shared unknowns enter.")
   (free :initarg :free :reader indeterminate-free
         :documentation "The model's unknown left free: the others are written over it.")
   (shares :initarg :shares :reader indeterminate-shares
           :documentation "An alist unknown -> its value over FREE, of every unknown that
depends on FREE (FREE itself included, as itself).")
   (lower :initarg :lower :reader indeterminate-lower
          :documentation "The lower bounds of FREE (expressions; FREE is at least each).")
   (upper :initarg :upper :reader indeterminate-upper
          :documentation "The upper bounds of FREE (expressions; FREE is at most each)."))
  (:documentation "The state's only candidate model fixes the motion but not how some
forces share a load: its equations leave one unknown free (a body held by more supports
than the equations fix). DATUM names the bodies; LOWER and UPPER bound the free unknown
where the exit conditions give bounds (empty lists when they do not)."))

(defparameter *indeterminate-tries* 24
  "The most solves (one unknown left free each) STATICALLY-INDETERMINATE-TRIAL spends on
one start, over all its assignments: a refusal's cost stays bounded.")

(defvar *tries-left* 0
  "The solves STATICALLY-INDETERMINATE-TRIAL has left (see *INDETERMINATE-TRIES*).")

(defun rate-terms (derivatives)
  "The rate terms of DERIVATIVES (alist state term -> rate term)."
  (mapcar #'cdr derivatives))

(defun reported-force-terms (model)
  "The quantity terms MODEL's components report among the forces (MODEL-REPORTED): the
scalars the knowledge base names a force by (a tension, a friction force)."
  (let ((terms '()))
    (loop for (section entry) in (model-reported model)
          when (eq section :forces)
            do (dolist (term (remove-if-not #'quantity-term-p (expression-variables entry)))
                 (pushnew term terms :test #'equal)))
    (nreverse terms)))

(defun reported-first (unknowns reported)
  "UNKNOWNS with those among REPORTED first, each part in its order."
  (multiple-value-bind (in out)
      (loop for u in unknowns
            if (member u reported :test #'equal) collect u into in else collect u into out
            finally (return (values in out)))
    (append in out)))

(defun solution-with-free (run compact remaining definitions free)
  "The values of the model's unknowns with FREE left free (an alist over FREE), or NIL
when the COMPACT equations do not then have a unique solution for REMAINING but FREE."
  (handler-case (back-substitute (solve-compact run compact (remove free remaining :test #'equal))
                                 definitions)
    ((or unsolvable-model ames.maxima:maxima-error) () nil)))

(defun one-free-unknown (run model)
  "For MODEL with no unique solution: (values FREE VALUES) when leaving the unknown FREE
free gives the others unique VALUES over it with every rate free of it (the motion is
fixed, some forces are not); NIL otherwise."
  (multiple-value-bind (equations unknowns state derivatives) (model-system run model)
    (multiple-value-bind (compact definitions) (eliminate-definitions equations unknowns)
      (let* ((compact (remove-if (lambda (equation) (identity-p run equation)) compact))
             (remaining (equation-unknowns compact state))
             (rates (rate-terms derivatives)))
        ;; an impact's model has no rates: its impulses are not this file's
        (unless derivatives (return-from one-free-unknown nil))
        (loop for free in (reported-first (remove-if (lambda (u) (member u rates :test #'equal))
                                                     remaining)
                                          (reported-force-terms model))
              while (plusp *tries-left*)
              do (decf *tries-left*)
                 (let ((values (solution-with-free run compact remaining definitions free)))
                   (when (and values
                              (every (lambda (u) (or (equal u free) (assoc u values :test #'equal)))
                                     unknowns)
                              (some (lambda (entry) (not (free-of-p free (cdr entry)))) values)
                              (every (lambda (rate)
                                       (let ((entry (assoc rate values :test #'equal)))
                                         (or (null entry) (free-of-p free (cdr entry)))))
                                     rates))
                     (return (values free values)))))))))

(defun at-start (run values expression)
  "EXPRESSION with the model's VALUES and the state terms' values at the start put in."
  (let* ((expression (with-initial-positions run (substitute-expressions values expression)))
         (state (remove-if-not (lambda (term)
                                 (member (first term) '(ames.kb:pos ames.kb:vel ames.kb:angle ames.kb:angvel
                                                        ames.kb:path-position ames.kb:path-speed)))
                               (remove-if-not #'quantity-term-p (expression-variables expression)))))
    (tidy run (substitute-expressions
               (mapcar (lambda (term) (cons term (initial-state-value run term))) state)
               expression))))

(defun holding-bounds (run relation free values)
  "The bounds on FREE within which the exit RELATION does not hold at the start: a list
of (:LOWER X) and (:UPPER X); :NEVER when it holds whatever FREE (decided); :UNDECIDED when
its truth is not decided or it is not linear in FREE."
  (case (first relation)
    (or (let ((bounds '()))
          (dolist (part (rest relation) bounds)
            (let ((more (holding-bounds run part free values)))
              (if (listp more) (setf bounds (append bounds more)) (return more))))))
    ((< <= > >=)
     (let* ((holds (ecase (first relation) (< '>=) (<= '>) (> '<=) (>= '<)))
            (difference (at-start run values `(- ,(second relation) ,(third relation))))
            (z (ames.maxima:keyed-auxiliary-variable (run-bridge run) (list :indeterminate free)
                                                     "SHARED-FORCE"))
            (coefficients (ames.maxima:call-or-nil
                           (lambda () (ames.maxima:polynomial-coefficients-in
                                       (run-bridge run)
                                       (substitute-expressions (list (cons free z)) difference) z)))))
       (cond ((free-of-p free difference)
              (case (decide run (list holds difference 0)) (:true '()) (:false :never) (t :undecided)))
             ((/= 2 (length coefficients)) :undecided)
             (t (let ((sign (one-sign (sign-of run (second coefficients))))
                      (bound (tidy run `(- (/ ,(first coefficients) ,(second coefficients))))))
                  (case sign
                    (:positive (list (list (if (member holds '(> >=)) :lower :upper) bound)))
                    (:negative (list (list (if (member holds '(> >=)) :upper :lower) bound)))
                    (t :undecided)))))))
    (t :undecided)))

(defun tightest (run bounds keep-p)
  "BOUNDS (expressions) without those another one is decided to be tighter than: KEEP-P,
given two, says whether the first is at least as tight."
  (remove-if (lambda (b)
               (some (lambda (other)
                       (and (not (eq other b)) (eq :true (decide run (funcall keep-p other b)))
                            (or (not (eq :true (decide run (funcall keep-p b other))))
                                ;; equal bounds: keep the first
                                (< (position other bounds) (position b bounds)))))
                     bounds))
             bounds))

(defun shared-range (run model free values)
  "The bounds on FREE from MODEL's exit conditions: (values LOWER UPPER), or :NOT-AT-REST
when an exit is decided to hold at the start or the bounds decided to leave no room."
  (let ((lower '()) (upper '()))
    (dolist (condition (ames.engine:model-termination-conditions model))
      (unless (member (ames.engine:termination-condition-kind condition) '(:activation :watch))
        (let ((bounds (holding-bounds run (ames.engine:termination-condition-relation condition)
                                      free values)))
          (cond ((eq bounds :never) (return-from shared-range :not-at-rest))
                ((listp bounds)
                 (dolist (bound bounds)
                   (if (eq (first bound) :lower)
                       (push (second bound) lower)
                       (push (second bound) upper))))))))
    (let ((lower (tightest run (nreverse (remove-duplicates lower :test #'equal))
                           (lambda (a b) `(>= ,a ,b))))
          (upper (tightest run (nreverse (remove-duplicates upper :test #'equal))
                           (lambda (a b) `(<= ,a ,b)))))
      (if (some (lambda (lo) (some (lambda (hi) (eq :true (decide run `(> ,lo ,hi)))) upper)) lower)
          :not-at-rest
          (values lower upper)))))

(defun sharing-bodies (run equations shared)
  "The free bodies named in EQUATIONS that hold one of the SHARED unknowns."
  (let ((bodies (remove-if (lambda (body) (body-fixed-p run body)) (body-names run))))
    (remove-if-not (lambda (body)
                     (some (lambda (equation)
                             (and (some (lambda (u) (not (free-of-p u equation))) shared)
                                  (some (lambda (term) (and (consp term) (eq (second term) body)))
                                        (expression-variables equation))))
                           equations))
                   bodies)))

(defun indeterminate-refusal (run model)
  "The STATICALLY-INDETERMINATE condition for the current MODEL (see the file header),
or NIL when it is no such rest."
  (multiple-value-bind (free values) (one-free-unknown run model)
    (when free
      (multiple-value-bind (lower upper) (shared-range run model free values)
        (unless (eq lower :not-at-rest)
          (let* ((reported (reported-force-terms model))
                 (shares (cons (cons free free)
                               (loop for (u . value) in values
                                     unless (or (free-of-p free value) (equal u free)
                                                (not (member u reported :test #'equal)))
                                       collect (cons u (at-start run values value)))))
                 (dependent (cons free (loop for (u . value) in values
                                             unless (free-of-p free value) collect u)))
                 (bodies (sharing-bodies run (model-system run model) dependent)))
            (make-condition 'statically-indeterminate
                            :datum bodies :bodies bodies :free free :shares shares
                            :lower lower :upper upper
                            :detail (indeterminate-detail bodies free shares lower upper))))))))

(defun indeterminate-detail (bodies free shares lower upper)
  "The refusal's text: the bodies, the shared unknowns over FREE, the bounds of FREE."
  (with-output-to-string (out)
    (let ((*print-pretty* nil))
      (format out "The forces on ~{~A~^, ~} are statically indeterminate: the equations fix ~
                 the motion but not ~{~(~S~)~^, ~}, which share the load (~{~(~S = ~S~)~^, ~} ~
                 for any ~(~S~))."
            bodies (mapcar #'car shares)
            (loop for (u . value) in (rest shares) append (list u value))
            free)
      (when (or lower upper)
        (format out " ~(~S~) may take any value~@[ from ~{~(~S~)~^ and ~}~]~@[ to ~{~(~S~)~^ and ~}~]~
                   ~:[~; (the greatest of the lower bounds, the least of the upper ones)~]."
                free lower upper (or (rest lower) (rest upper)))))))

(defun statically-indeterminate-trial (run trials points)
  "Among TRIALS (none consistent), the STATICALLY-INDETERMINATE condition of the first
assignment whose model had no unique solution and is such a rest (the model is left in
that assignment), or NIL."
  (let ((*tries-left* *indeterminate-tries*))
    (dolist (trial trials)
      (when (find :unsolvable (trial-notes trial) :key (lambda (note) (and (consp note) (first note))))
        (apply-assignment run points (trial-assignment trial))
        (let ((refusal (handler-case (indeterminate-refusal run (run-model run))
                         ;; a model this analysis cannot read: the generic refusal stands
                         (ames-error () nil))))
          (when refusal (return refusal)))))))
