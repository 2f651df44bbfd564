;;;; src/engine/transitions.lisp -- updating a model incrementally across a transition, and
;;;; comparing it with a rebuild from scratch.

(in-package #:ames.engine)

;;; Transitions

(defstruct (transition-report (:constructor make-transition-report (changes rederived)))
  "What APPLY-TRANSITION did: the CHANGES applied and the keys of the instances it
re-derived (refreshed because a prerequisite or decision changed)."
  (changes '() :type list)
  (rederived '() :type list))

(setf (documentation 'transition-report-changes 'function)
      "The changes the transition applied."
      (documentation 'transition-report-rederived 'function)
      "The keys of the instances the transition re-derived, in order.")

(defun transition-report-rederived-count (report)
  "How many instances the transition re-derived."
  (length (transition-report-rederived report)))

(defun change-instance (model change)
  "The instance CHANGE is about, after checking CHANGE's shape and that it fits
MODEL; signals INVALID-CHANGE."
  (flet ((fail (detail) (error 'invalid-change :datum change :detail detail)))
    (unless (and (proper-list-p change) (member (first change) '(:deactivate :activate :mode)))
      (fail "A change is (:DEACTIVATE KEY), (:ACTIVATE KEY) or (:MODE KEY :FROM MODE :TO MODE)."))
    (let ((instance (find-instance model (second change))))
      (unless instance (fail "The model has no instance of this key."))
      (ecase (first change)
        (:deactivate
         (unless (= 2 (length change)) (fail "A deactivation is (:DEACTIVATE KEY)."))
         (unless (instance-active-p instance) (fail "The instance is not active."))
         (unless (instance-activation-node instance)
           (fail "The instance's component has no activation or deactivation condition.")))
        (:activate
         (unless (= 2 (length change)) (fail "An activation is (:ACTIVATE KEY)."))
         (when (instance-active-p instance) (fail "The instance is already active."))
         (unless (instance-activation-node instance)
           (fail "The instance's component has no activation or deactivation condition."))
         (unless (instance-qualified-p instance)
           (fail "The instance's qualitative prerequisites are not believed.")))
        (:mode
         (unless (and (= 6 (length change)) (eq (third change) :from) (eq (fifth change) :to))
           (fail "A mode change is (:MODE KEY :FROM MODE :TO MODE)."))
         (unless (instance-active-p instance) (fail "The instance is not active."))
         (unless (eq (fourth change) (instance-mode instance))
           (fail (format nil "The instance is in mode ~S." (instance-mode instance))))
         (unless (find-mode (instance-component instance) (sixth change))
           (fail "The instance's component has no such mode."))
         (when (eq (fourth change) (sixth change))
           (fail "A mode change must lead to another mode."))))
      instance)))

(defun decisions-after (decisions changes)
  "DECISIONS (as MODEL-DECISIONS gives them) with CHANGES applied."
  (let ((decisions (copy-list decisions)))
    (dolist (change changes decisions)
      (let ((decision (ecase (first change)
                        (:deactivate (list :activation (second change) :false))
                        (:activate (list :activation (second change) :true))
                        (:mode (list :mode (second change) (sixth change))))))
        (setf decisions (cons decision
                              (remove-if (lambda (old) (and (eq (first old) (first decision))
                                                            (equal (second old)
                                                                   (second decision))))
                                         decisions)))))))

(defun apply-change (model instance change)
  "Apply CHANGE to INSTANCE: retract or enable its assumptions."
  (ecase (first change)
    (:deactivate
     (setf (instance-activation instance) :false)
     (retract model (instance-activation-node instance)))
    (:activate
     (setf (instance-activation instance) :true)
     (enable model (instance-activation-node instance) (list :transition change)))
    (:mode
     (set-mode model instance (sixth change) (list :transition change))))
  (mark-dirty model instance))

(defun apply-transition (model changes &key (decider (model-decider model)))
  "Update MODEL in place for the next qualitative state, given the CHANGES the
fired termination conditions stand for (their TERMINATION-CONDITION-CHANGE):
retract or enable the matching assumptions, then re-derive, in dependency order,
only the instances whose prerequisites changed. Everything else stays believed.
DECIDER decides the conditions of instances that become qualified; it replaces the
model's decider. Returns MODEL and a TRANSITION-REPORT.

Signals INVALID-CHANGE (before changing anything) when a change is malformed, does
not fit the model, or two changes name one instance; and, while re-deriving, the
conditions BUILD-MODEL signals."
  (let ((instances (mapcar (lambda (change) (change-instance model change)) changes)))
    (loop for (instance . rest) on instances
          for change in changes
          when (member instance rest)
            do (error 'invalid-change :datum change
                                      :detail "Two changes name this instance."))
    (let ((basis (decisions-after (model-decisions model) changes))
          (rank-count (length (engine-order (model-engine model)))))
      (setf (model-decider model) decider
            (model-basis-decisions model) basis
            (model-dirty model) (make-array rank-count :initial-element '()))
      (clrhash (model-pending model))
      (clrhash (model-refreshed model))
      (unwind-protect
           (progn
             (loop for instance in instances
                   for change in changes
                   do (apply-change model instance change))
             (loop for rank = (position-if #'identity (model-dirty model))
                   while rank
                   do (let ((instance (pop (aref (model-dirty model) rank))))
                        (remhash instance (model-pending model))
                        (setf (gethash instance (model-refreshed model)) t)
                        (refresh-instance model instance)))
             (values model
                     (make-transition-report
                      (copy-list changes)
                      (mapcar #'instance-key
                              (remove-if-not (lambda (instance)
                                               (gethash instance (model-refreshed model)))
                                             (model-instances model))))))
        (setf (model-dirty model) nil)))))

;;; Comparing models

(defun model-difference (first second)
  "What differs between the models FIRST and SECOND, compared as sets: their
equations, termination conditions, active instances with their modes, believed
assertions and decisions. NIL when they agree; else a list of entries
(WHAT :ONLY-IN-FIRST ITEMS :ONLY-IN-SECOND ITEMS)."
  (let ((differences '()))
    (flet ((compare (what items-1 items-2)
             (let ((only-1 (set-difference items-1 items-2 :test #'equal))
                   (only-2 (set-difference items-2 items-1 :test #'equal)))
               (when (or only-1 only-2)
                 (push (list what :only-in-first (canonical-sort only-1)
                                  :only-in-second (canonical-sort only-2))
                       differences))))
           (active (model)
             (mapcar (lambda (instance) (list (instance-key instance) (instance-mode instance)))
                     (model-active-instances model)))
           (terminations (model)
             (mapcar #'termination-condition-list (model-termination-conditions model))))
      (compare :equations (model-equations first) (model-equations second))
      (compare :termination-conditions (terminations first) (terminations second))
      (compare :active-instances (active first) (active second))
      (compare :beliefs (model-beliefs first) (model-beliefs second))
      (compare :decisions (model-decisions first) (model-decisions second)))
    (nreverse differences)))

(defun check-incremental (model &key (signal t))
  "Rebuild MODEL from scratch (REBUILD-FROM-SCRATCH) and compare: return NIL when
the rebuild has the same equations, termination conditions, active instances and
modes, beliefs and decisions, else the MODEL-DIFFERENCE -- after signalling
INCREMENTAL-MISMATCH with it when SIGNAL is true (the default)."
  (let ((difference (model-difference model (rebuild-from-scratch model))))
    (when (and difference signal)
      (error 'incremental-mismatch :difference difference :datum (model-basis-decisions model)
                                   :detail "The incremental model differs from the rebuild."))
    difference))
