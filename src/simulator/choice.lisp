;;;; src/simulator/choice.lisp -- which contacts and modes hold at the start of a state, chosen
;;;; by consistency (thesis section 3.2.3, "Deductions About the Next State").
;;;;
;;;; The state's initial values leave some decisions open: a contact touching with no
;;;; normal velocity may hold or not, a moded component may start in several modes. The
;;;; engine lists them (AMES.ENGINE:MODEL-CHOICE-POINTS). An assignment of them is
;;;; CONSISTENT when the state it gives lasts: no termination condition of an active
;;;; instance fires at once (a normal force would not be attractive, the observer does
;;;; not leave a contact past its end, a mode's exit condition does not hold), and no
;;;; inactive touching contact is penetrated at once. Contacts at a corner that is not
;;;; concave are alternatives: at most one of them holds.
;;;;
;;;; The search: every combination of the alternatives' and the modes' options (few),
;;;; and for each, the lone contacts by principal pivoting from all active, flipping the
;;;; violated one of least index (Murty's rule, which ends for the frictionless contact
;;;; problem). Among the consistent assignments one is taken when it is the only one that
;;;; is not DEGENERATE (an active contact whose normal force vanishes identically, or an
;;;; inactive one grazed all along); several that differ physically are an ambiguity.
;;;; Modes are a component's: it lists them in its order of preference, and of consistent
;;;; assignments that differ in their modes, one whose modes another's are preferred to
;;;; is dropped (a rough contact that can stick does not start sliding). Where the
;;;; algebra leaves assignments undecided, the run branches on a fact of the one with
;;;; the most contacts holding (choice-preferences.lisp).

(in-package #:ames.simulator)

(defparameter *combination-limit* 64
  "The most combinations of alternatives and modes the choice search tries.")

(defstruct (trial (:constructor make-trial (assignment solved verdict facts degenerate notes)))
  "One assignment of the choice points tried: ASSIGNMENT an alist instance key -> option,
SOLVED its SOLVED-MODEL (when it could be solved), VERDICT :CONSISTENT, :INCONSISTENT
or :UNDECIDED, FACTS the undecided relations, DEGENERATE how many degeneracies it has,
NOTES the reasons, for explanations."
  assignment solved verdict facts (degenerate 0) notes)

(defun point-contact (point)
  "The contact entity whose touching the activation choice POINT is about, or NIL."
  (and (eq (ames.engine:choice-point-kind point) :activation)
       (some #'gap-relation-contact (ames.engine:choice-point-relations point))))

(defun point-groups (run points)
  "POINTS split into the lone activation points and the groups of activation points at
one corner (alternatives), and the mode points: three values."
  (let ((activation (remove :mode points :key #'ames.engine:choice-point-kind))
        (modes (remove :activation points :key #'ames.engine:choice-point-kind))
        (groups '()))
    (dolist (point activation)
      (let* ((contact (point-contact point))
             (partners (and contact (touching-alternatives run contact)))
             (group (find-if (lambda (g)
                               (some (lambda (p) (member (point-contact p) partners)) g))
                             groups)))
        (if group
            (push point (cdr (last group)))
            (push (list point) groups))))
    (let ((lone (loop for g in groups unless (rest g) collect (first g)))
          (cornered (remove-if-not #'rest groups)))
      (values (reverse lone) (reverse cornered) modes))))

(defun group-options (group)
  "The assignments of a corner GROUP: none active, or exactly one."
  (cons (mapcar (lambda (p) (cons (ames.engine:choice-point-instance p) :false)) group)
        (loop for chosen in group
              collect (mapcar (lambda (p) (cons (ames.engine:choice-point-instance p)
                                                (if (eq p chosen) :true :false)))
                              group))))

(defun mode-options (point)
  "The assignments of a mode choice POINT."
  (mapcar (lambda (mode) (list (cons (ames.engine:choice-point-instance point) mode)))
          (ames.engine:choice-point-options point)))

(defun combinations (option-lists)
  "Every way of taking one option (an alist) from each of OPTION-LISTS, appended."
  (if (null option-lists)
      (list '())
      (loop for option in (first option-lists)
            append (mapcar (lambda (rest) (append option rest))
                           (combinations (rest option-lists))))))

(defun apply-assignment (run points assignment)
  "Bring the model's choices to ASSIGNMENT (alist key -> option over POINTS' instances):
the activations first, then the modes of the instances active after them (an instance
that is not active has no mode to choose; its option is then NIL)."
  (dolist (kind '(:activation :mode))
    (let ((changes (loop for point in points
                         for key = (ames.engine:choice-point-instance point)
                         for entry = (assoc key assignment :test #'equal)
                         for change = (and entry (cdr entry)
                                           (eq kind (ames.engine:choice-point-kind point))
                                           (or (eq kind :activation) (instance-active-p run key))
                                           (ames.engine:choice-change (run-model run) point
                                                                      (cdr entry)))
                         when change collect change)))
      (when changes
        (ames.engine:apply-transition (run-model run) changes :decider (run-decider run))))))

(defun active-contacts (run)
  "The contact entities whose CONTACT instance is active in the current model: those
named by a believed (in-contact A B :along K)."
  (loop for belief in (ames.engine:model-beliefs (run-model run))
        when (eq (first belief) 'ames.kb:in-contact)
          collect (getf (cdddr belief) :along)))

(defun instance-active-p (run key)
  "True when the instance KEY is active in the current model."
  (let ((instance (ames.engine:find-instance (run-model run) key)))
    (and instance (ames.engine:instance-active-p instance))))

(defun immediate-violations (run solved points)
  "What fires at once in the current model (solved as SOLVED): a list of entries
(KEY VERDICT FACT WHAT [CONDITION]), KEY the instance, VERDICT :TRUE or :UNKNOWN, WHAT the
condition's event or change, CONDITION the termination condition. Inactive touching
contacts among POINTS count when they are penetrated."
  (let ((violations '())
        (active (active-contacts run)))
    (dolist (condition (ames.engine:model-termination-conditions (run-model run)))
      ;; a watch compares the motion with the state's own start (its direction), so it
      ;; holds at no start: not tested here (its state constants need the solved start)
      (unless (member (ames.engine:termination-condition-kind condition) '(:activation :watch))
        (multiple-value-bind (verdict fact)
            (fires-at-once run solved (ames.engine:termination-condition-relation condition))
          (unless (eq verdict :false)
            (push (list (ames.engine:termination-condition-instance condition) verdict fact
                        (or (ames.engine:termination-condition-event condition)
                            (ames.engine:termination-condition-change condition))
                        condition)
                  violations)))))
    (dolist (point points)
      (let ((contact (point-contact point))
            (key (ames.engine:choice-point-instance point)))
        (when (and (eq (ames.engine:choice-point-kind point) :activation)
                   (not (instance-active-p run key)))
          (multiple-value-bind (verdict fact)
              (if contact
                  (penetrates-at-once run solved contact active)
                  (multiple-value-call #'corner-verdict-at-vertex
                   run solved key
                   (fires-at-once run solved
                                 ;; the whole activation condition: a corner on a face's
                                 ;; line exactly at the face's end (decided within it at the
                                 ;; start) enters only if it does not move out of the face
                                 (or (activation-relation run key)
                                     (let ((relations (ames.engine:choice-point-relations point)))
                                       (if (rest relations) (cons 'and relations) (first relations)))))))
            (unless (eq verdict :false)
              (push (list key verdict fact (list :penetrates contact)) violations))))
        (when (and (eq (ames.engine:choice-point-kind point) :activation)
                   (null contact) (instance-active-p run key))
          (let ((relation (departing-relation run solved point)))
            (when relation
              (push (list key :true relation (list :departs key)) violations))))))
    ;; settling one cluster of bodies, the others' violations are theirs (choice-clusters.lisp)
    (in-cluster-violations run (nreverse violations))))

(defun activation-relation (run key)
  "The activation condition (a conjunction of all its relations, those decided at the
start too) of the inactive instance KEY in the current model, or NIL."
  (let ((condition (find-if (lambda (c)
                              (and (eq (ames.engine:termination-condition-kind c) :activation)
                                   (equal (ames.engine:termination-condition-instance c) key)))
                            (ames.engine:model-termination-conditions (run-model run)))))
    (and condition (ames.engine:termination-condition-relation condition))))

(defun degeneracies (run solved points)
  "How degenerate the current assignment is: the active touching contacts whose every
termination relation's function vanishes identically (a normal force of zero all
along) plus the inactive touching contacts grazed all along (gap identically zero)."
  (let ((count 0)
        (conditions (make-hash-table :test #'equal)))
    (dolist (condition (ames.engine:model-termination-conditions (run-model run)))
      (push condition (gethash (ames.engine:termination-condition-instance condition) conditions)))
    (dolist (point points count)
      (let ((contact (point-contact point))
            (key (ames.engine:choice-point-instance point)))
        (when contact
          (if (instance-active-p run key)
              (when (some (lambda (condition)
                            (and (eq (ames.engine:termination-condition-kind condition) :deactivation)
                                 (member (first (ames.engine:termination-condition-relation condition))
                                         '(< > <= >=))
                                 (vanishes-identically-p
                                  run solved (violation-function
                                              (ames.engine:termination-condition-relation condition)))))
                          (reverse (gethash key conditions)))
                (incf count))
              (when (vanishes-identically-p run solved `(ames.kb:contact-gap ,contact))
                (incf count))))))))

(defun current-assignment (run points)
  "The current options of POINTS' instances: an alist key -> option."
  (mapcar (lambda (point)
            (let* ((key (ames.engine:choice-point-instance point))
                   (instance (ames.engine:find-instance (run-model run) key)))
              (cons key (if (eq (ames.engine:choice-point-kind point) :mode)
                            (ames.engine:instance-mode instance)
                            (if (ames.engine:instance-active-p instance) :true :false)))))
          points))

(defun forced-exit (points violations)
  "Among VIOLATIONS (see IMMEDIATE-VIOLATIONS), a mode's exit that surely holds at once
for an instance whose mode is no choice among POINTS: that instance leaves its mode at
once (a stay of no duration), so the transition's change is applied before the state
starts. Returns the change, or NIL. A mode point with one option is no choice either: a
stale mode whose only possible successor is judged at the instant of the start (a rope
piece at rest can only keep its direction there, its entry to turning needs a rate), and
whose exit, judged by the local series just after the start, surely holds (it turns at
once, the body accelerating across it): the exit's transition is taken."
  (let ((modal (loop for point in points
                     when (and (eq (ames.engine:choice-point-kind point) :mode)
                               (rest (ames.engine:choice-point-options point)))
                       collect (ames.engine:choice-point-instance point))))
    (loop for (key verdict nil nil condition) in violations
          when (and (eq verdict :true) condition
                    (eq (ames.engine:termination-condition-kind condition) :mode-transition)
                    (not (member key modal :test #'equal)))
            return (ames.engine:termination-condition-change condition))))

(defun forced-changes (trial)
  "The mode changes forced on TRIAL's model by exits that held at once (see FORCED-EXIT)."
  (loop for note in (trial-notes trial)
        when (and (consp note) (eq (first note) :leaves-mode)) collect (second note)))

(defun undo-forced-changes (run trial)
  "Put back the modes that TRIAL's forced exits changed (of the instances still active).
An instance among TRIAL's choice points (a one-option point, see FORCED-EXIT) gets back
in TRIAL's assignment the option it was forced out of: the assignment is applied, then
its forced changes (SETTLE-POINTS)."
  (let ((undo (loop for (nil key nil from nil to) in (reverse (forced-changes trial))
                    collect (list :mode key :from to :to from))))
    (dolist (change undo)
      (when (mode-change-applies-p run change)
        (ames.engine:apply-transition (run-model run) (list change) :decider (run-decider run)))
      (let ((entry (assoc (second change) (trial-assignment trial) :test #'equal)))
        (when entry
          (setf (trial-assignment trial)
                (substitute (cons (car entry) (getf (cddr change) :to)) entry
                            (trial-assignment trial))))))))

(defun pivot (run points lone)
  "From the current model, flip the LONE activation points by Murty's least-index rule
until the assignment is consistent, or shown inconsistent or undecided; an instance whose
mode's exit holds at once (and is no choice) leaves that mode first (see FORCED-EXIT,
noted (:LEAVES-MODE CHANGE)). Returns a TRIAL."
  (let ((notes '()))
    (loop repeat (+ 8 (* 2 (length lone)))
          do (let* ((solved (handler-case (solve-model run (run-model run))
                              ((or unsolvable-model ames.maxima:maxima-error) (condition)
                                ;; no unique solution: redundant or contradictory
                                ;; constraints, settled by trying every subset
                                (return-from pivot
                                  (make-trial (current-assignment run points) nil
                                              (if lone :singular :inconsistent)
                                              '() 0 (cons (list :unsolvable (ames-error-detail condition))
                                                          notes))))))
                    (violations (handler-case (immediate-violations run solved points)
                                  (ames.maxima:maxima-error (condition)
                                    ;; the solution is singular at this state: redundant
                                    ;; constraints (two contacts pushing along one normal)
                                    (return-from pivot
                                      (make-trial (current-assignment run points) nil :singular
                                                  '() 0 (cons (list :singular (ames-error-detail condition))
                                                              notes))))))
                    (sure (remove :unknown violations :key #'second))
                    (sure-keys (remove-duplicates (mapcar #'first sure) :test #'equal))
                    (flippable (loop for point in lone
                                     when (member (ames.engine:choice-point-instance point) sure-keys
                                                  :test #'equal)
                                       collect point)))
               (cond ((null violations)
                      (return-from pivot
                        (make-trial (current-assignment run points) solved :consistent '()
                                    (degeneracies run solved points) (reverse notes))))
                     ((forced-exit points violations)
                      (let ((change (forced-exit points violations)))
                        (push (list :leaves-mode change) notes)
                        (ames.engine:apply-transition (run-model run) (list change)
                                                      :decider (run-decider run))))
                     ((and sure (= (length sure-keys) (length flippable)))
                      (let* ((point (first flippable))
                             (key (ames.engine:choice-point-instance point))
                             (option (if (instance-active-p run key) :false :true)))
                        (push (list :flip key option :because (fourth (find key sure :key #'first :test #'equal)))
                              notes)
                        (apply-assignment run points (list (cons key option)))))
                     (sure
                      (return-from pivot
                        (make-trial (current-assignment run points) solved :inconsistent '() 0
                                    (reverse (cons (list :violates (mapcar #'fourth sure)) notes)))))
                     (t
                      (return-from pivot
                        (make-trial (current-assignment run points) solved :undecided
                                    (mapcar #'third violations) 0 (reverse notes)))))))
    (make-trial (current-assignment run points) nil :inconsistent '() 0
                (reverse (cons '(:no-convergence) notes)))))

(defparameter *subset-limit* 6
  "The most lone contacts whose every subset the choice search tries when pivoting
meets a singular assignment.")

(defun lone-subsets (lone)
  "Every assignment of the LONE activation points (all active first). Signals
UNSUPPORTED-SITUATION beyond *SUBSET-LIMIT* points."
  (when (> (length lone) *subset-limit*)
    (error 'unsupported-situation
           :datum (mapcar #'ames.engine:choice-point-instance lone)
           :detail "Redundant contacts (a singular model) among more lone contacts than the choice search enumerates."))
  (combinations (mapcar (lambda (point)
                          (list (list (cons (ames.engine:choice-point-instance point) :true))
                                (list (cons (ames.engine:choice-point-instance point) :false))))
                        lone)))

(defun settle-choices (run)
  "Choose by consistency the contacts and modes that hold at the start of the current
state, leave the model in that assignment and return its TRIAL, with the others tried
as its notes. Signals AMBIGUOUS-TRANSITION or UNSOLVABLE-MODEL (see CHOOSE-TRIAL). Beyond
*COMBINATION-LIMIT* combinations, the choice points of bodies that do not interact are
settled apart (choice-clusters.lisp)."
  (let ((points (handler-bind ((ames.engine:undecided-relation
                                  ;; a choice held up by an undecided condition (a corner's
                                  ;; place within its face): an ambiguity the state's
                                  ;; caller branches on, or settles by the values
                                  (lambda (condition) (undecided-to-ambiguity condition run))))
                  (ames.engine:model-choice-points (run-model run) :decider (run-decider run)))))
    (multiple-value-bind (lone groups modes) (point-groups run points)
      (or (and (> (combination-count groups modes) *combination-limit*)
               (settle-by-clusters run points))
          (settle-points run points lone groups modes)))))

(defun combination-count (groups modes)
  "How many combinations of the alternatives' GROUPS and the MODES' options there are."
  (reduce #'* (append (mapcar (lambda (g) (1+ (length g))) groups)
                      (mapcar (lambda (m) (length (ames.engine:choice-point-options m))) modes))))

(defun settle-points (run points &optional (lone nil groups-p) groups modes)
  "SETTLE-CHOICES over the choice POINTS (split by POINT-GROUPS into LONE, GROUPS and
MODES, when they are not given)."
  (unless groups-p
    (multiple-value-setq (lone groups modes) (point-groups run points)))
  (let* ((option-lists (append (mapcar #'group-options groups) (mapcar #'mode-options modes)))
         (combos (combinations option-lists))
         (base (mapcar (lambda (p) (cons (ames.engine:choice-point-instance p) :true)) lone))
         (trials '()))
    (when (> (length combos) *combination-limit*)
      (error 'unsupported-situation
             :datum (mapcar #'ames.engine:choice-point-instance points)
             :detail (format nil "~D combinations of corner contacts and modes to try: more than ~D."
                             (length combos) *combination-limit*)))
    (dolist (combo combos)
      (apply-assignment run points (append combo base))
      (let ((trial (pivot run points lone)))
        (undo-forced-changes run trial)
        (if (eq (trial-verdict trial) :singular)
            ;; pivoting cannot go through a singular assignment: try every subset
            (setf trials (revappend (subset-trials run points combo lone) trials))
            (push trial trials))))
    (setf trials (nreverse trials))
    (when (and lone (every (lambda (trial) (member (trial-verdict trial) '(:inconsistent :singular)))
                           trials))
      ;; pivoting stops where a mode's exit fires beside a contact's violation (a
      ;; friction impulse that would slip on a contact that would pull): before
      ;; refusing, every subset of the lone contacts with every combination
      (setf trials (loop for combo in combos append (subset-trials run points combo lone))))
    (let ((chosen (choose-trial run trials points)))
      (apply-assignment run points (trial-assignment chosen))
      (dolist (change (forced-changes chosen))
        (when (mode-change-applies-p run change)
          (ames.engine:apply-transition (run-model run) (list change) :decider (run-decider run))))
      (setf (trial-notes chosen)
            (list :points (mapcar #'ames.engine:choice-point-instance points)
                  :chosen (trial-assignment chosen)
                  :tried (mapcar (lambda (trial)
                                   (list :assignment (trial-assignment trial)
                                         :verdict (trial-verdict trial)
                                         :degenerate (trial-degenerate trial)
                                         :why (trial-notes trial)))
                                 trials)))
      chosen)))
