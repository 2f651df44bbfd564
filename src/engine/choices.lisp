;;;; src/engine/choices.lisp -- the choices a model's components leave open at the start of a
;;;; state: activations and modes that the state's initial values allow either way.
;;;;
;;;; The thesis (section 3.2.3, "Deductions About the Next State") notes that the state
;;;; variables do not always say which qualitative state comes next: a contact that is
;;;; touching with no normal velocity may or may not hold, a friction contact at rest may
;;;; stick or slide. The decider marks such conditions :CHOICE. The engine takes a default
;;;; (active; the first mode that is a choice) and lists the choice points here; the
;;;; caller (the simulator) settles them by consistency, applying its choices as ordinary
;;;; changes with APPLY-TRANSITION, so that every choice is an assumption of the JTMS.

(in-package #:ames.engine)

(defstruct (choice-point (:constructor make-choice-point (instance kind options current relations)))
  "A decision the state's initial values leave open: the activation (KIND :ACTIVATION,
OPTIONS (:TRUE :FALSE)) or the mode (KIND :MODE, OPTIONS the candidate mode names) of
the instance whose key is INSTANCE; CURRENT is the model's present decision, and
RELATIONS the conditions the decider answered :CHOICE."
  (instance nil)
  (kind :activation :type (member :activation :mode))
  (options '() :type list)
  (current nil)
  (relations '() :type list))

(defun activation-choice (model instance decider)
  "The CHOICE-POINT of INSTANCE's activation under DECIDER, or NIL."
  (let ((templates (component-activation-relations (instance-component instance))))
    (when (and templates (instance-activation-node instance) (instance-qualified-p instance))
      (let* ((relations (mapcar (lambda (template) (expanded-relation model instance template))
                                templates))
             (answers (make-hash-table :test #'equal))
             (verdict (conjunction-answer model relations answers decider)))
        (when (and (eq verdict :unknown)
                   (some (lambda (r) (eq (gethash r answers) :choice)) relations))
          ;; the activation would be a choice but for a condition the decider leaves
          ;; open (a corner touching its face's line, its place within the face not
          ;; decided): resolved as DECIDE-ACTIVATION resolves it, never guessed
          (dolist (relation relations)
            (when (eq (gethash relation answers) :unknown)
              (setf (gethash relation answers) (resolve-unknown instance relation))))
          (setf verdict (conjunction-answer model relations answers decider)))
        (when (eq verdict :choice)
          (make-choice-point (instance-key instance) :activation '(:true :false)
                             (if (instance-active-p instance) :true :false)
                             (remove-if-not (lambda (r) (eq (gethash r answers) :choice))
                                            relations)))))))

(defun mode-choice (model instance decider)
  "The CHOICE-POINT of the active INSTANCE's mode under DECIDER, or NIL."
  (let ((component (instance-component instance)))
    (when (and (rest (component-modes component)) (instance-active-p instance))
      (let ((answers (make-hash-table :test #'equal)) (candidates '()) (choices '()))
        (dolist (mode (component-modes component))
          (when (mode-valid-p instance (mode-name mode))
            (let* ((relations (mapcar (lambda (template)
                                        (expanded-relation model instance template))
                                      (mode-entry-relations mode)))
                   (verdict (conjunction-answer model relations answers decider)))
              (when (member verdict '(:true :choice))
                (push (mode-name mode) candidates))
              (when (eq verdict :choice)
                (setf choices (append choices (remove-if-not
                                               (lambda (r) (eq (gethash r answers) :choice))
                                               relations)))))))
        (when (or (and choices (rest candidates))
                  ;; a stale mode: a jump of the state variables (an impact's) has left
                  ;; the current mode's entry conditions false while others' hold
                  (and candidates (not (member (instance-mode instance) candidates))))
          (make-choice-point (instance-key instance) :mode (reverse candidates)
                             (instance-mode instance) choices))))))

(defun model-choice-points (model &key (decider (model-decider model)))
  "The CHOICE-POINTs of MODEL under DECIDER (by default the model's): every qualified
instance whose activation conditions DECIDER answers :CHOICE, and every active
instance with modes of which several are possible and one at least by a :CHOICE, or
whose current mode is not possible while others are (a stale mode: the caller changes
it to one of them). In the order the instances were made. Signals what the decider
signals."
  (let ((points '()))
    (dolist (instance (model-instances model) (nreverse points))
      (let ((point (or (activation-choice model instance decider)
                       (mode-choice model instance decider))))
        (when point (push point points))))))

(defun choice-change (model point option)
  "The change (for APPLY-TRANSITION) that gives the choice POINT of MODEL the OPTION,
or NIL when MODEL already has it. Signals INVALID-CHANGE when OPTION is not one of the
point's options."
  (unless (member option (choice-point-options point))
    (error 'invalid-change :datum option
                           :detail (format nil "~S is not an option of the choice ~S."
                                           option (choice-point-instance point))))
  (let ((instance (find-instance model (choice-point-instance point))))
    (ecase (choice-point-kind point)
      (:activation
       (cond ((and (eq option :true) (not (instance-active-p instance)))
              (list :activate (instance-key instance)))
             ((and (eq option :false) (instance-active-p instance))
              (list :deactivate (instance-key instance)))))
      (:mode
       (unless (eq option (instance-mode instance))
         (list :mode (instance-key instance) :from (instance-mode instance) :to option))))))

(defun stale-activation-changes (model &key (decider (model-decider model)))
  "The changes that bring every qualified instance's activation in line with DECIDER's
fresh verdict where that verdict is decided (:TRUE or :FALSE) and disagrees: after a
transition that changed what the activation conditions read without firing them (an
impact changes velocities at once). A :CHOICE or :UNKNOWN verdict changes nothing (the
choice is the caller's to settle)."
  (let ((changes '()))
    (dolist (instance (model-instances model) (nreverse changes))
      (let ((templates (component-activation-relations (instance-component instance))))
        (when (and templates (instance-activation-node instance) (instance-qualified-p instance))
          (let* ((relations (mapcar (lambda (template) (expanded-relation model instance template))
                                    templates))
                 (verdict (conjunction-answer model relations (make-hash-table :test #'equal)
                                              decider)))
            (cond ((and (eq verdict :false) (instance-active-p instance))
                   (push (list :deactivate (instance-key instance)) changes))
                  ((and (eq verdict :true) (not (instance-active-p instance)))
                   (push (list :activate (instance-key instance)) changes)))))))))

(defun unsettled-active-instances (model &key (decider (model-decider model)))
  "The keys of the active, qualified instances whose activation DECIDER now answers :FALSE
or :UNKNOWN: a contact held through a state that, where that state ends, is no longer
shown to touch (its gap off zero by a round-off, or undecided)."
  (loop for instance in (model-instances model)
        for templates = (component-activation-relations (instance-component instance))
        when (and templates (instance-activation-node instance) (instance-qualified-p instance)
                  (instance-active-p instance)
                  (member (conjunction-answer model
                                              (mapcar (lambda (template)
                                                        (expanded-relation model instance template))
                                                      templates)
                                              (make-hash-table :test #'equal) decider)
                          '(:false :unknown)))
          collect (instance-key instance)))

(defun stale-mode-changes (model &key (decider (model-decider model)))
  "The changes that move every active instance whose current mode's entry conditions
DECIDER now answers :FALSE into the first mode whose entry conditions it answers :TRUE
(else :CHOICE): after a transition that changed what the entry conditions read without
firing a transition (an impact changes velocities at once). Instances whose current mode
is still possible, or that have no possible mode, are left alone."
  (let ((changes '()))
    (dolist (instance (model-instances model) (nreverse changes))
      (let ((component (instance-component instance))
            (mode (instance-mode instance)))
        (when (and mode (rest (component-modes component)) (instance-active-p instance))
          (flet ((verdict (mode-name)
                   (if (mode-valid-p instance mode-name)
                       (conjunction-answer model
                                           (mapcar (lambda (template)
                                                     (expanded-relation model instance template))
                                                   (mode-entry-relations (find-mode component mode-name)))
                                           (make-hash-table :test #'equal) decider)
                       :false)))
            (when (eq (verdict mode) :false)
              (let* ((verdicts (mapcar (lambda (m) (cons (mode-name m) (verdict (mode-name m))))
                                       (component-modes component)))
                     (next (or (car (find :true verdicts :key #'cdr))
                               (car (find :choice verdicts :key #'cdr)))))
                (when next
                  (push (list :mode (instance-key instance) :from mode :to next) changes))))))))))
