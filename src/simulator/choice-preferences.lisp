;;;; src/simulator/choice-preferences.lisp -- which of the consistent assignments of the
;;;; start's choice search is taken: one motion, the modes a component prefers, and the
;;;; fork's fact taken from the assignment with the most contacts holding (see choice.lisp).

(in-package #:ames.simulator)

(defun same-motion-p (run a b)
  "True when the trials A and B give the same motion: every body's acceleration at the
start of a state (or velocity after an impact) is the same."
  (let ((terms (remove-if-not (lambda (term) (member (first term) '(ames.kb:acc ames.kb:vel-after)))
                              (mapcar #'car (solved-model-values (trial-solved a))))))
    (every (lambda (term)
             (flet ((value (trial)
                      (substitute-expressions (solved-model-initial (trial-solved trial))
                                              (quantity-value (trial-solved trial) term))))
               (ames.maxima:equivalent-p (run-bridge run) (value a) (value b))))
           terms)))

(defun mode-ranks (points trial)
  "TRIAL's option at each mode choice point of POINTS as its place among the point's
options, which are in the order its component lists its modes; NIL where the
instance has no mode in TRIAL (it is not active there)."
  (loop for point in points
        when (eq (ames.engine:choice-point-kind point) :mode)
          collect (position (cdr (assoc (ames.engine:choice-point-instance point)
                                        (trial-assignment trial) :test #'equal))
                            (ames.engine:choice-point-options point))))

(defun preferred-over-p (points a b)
  "True when the modes of trial A are preferred to those of trial B: a component lists
its modes in its order of preference, and at every mode choice point of POINTS where
both have a mode, A's comes no later than B's, and at one at least earlier."
  (let ((earlier nil))
    (loop for rank-a in (mode-ranks points a)
          for rank-b in (mode-ranks points b)
          when (and rank-a rank-b)
            do (cond ((> rank-a rank-b) (return-from preferred-over-p nil))
                     ((< rank-a rank-b) (setf earlier t))))
    earlier))

(defun holding-count (trial)
  "How many activation choices TRIAL makes active."
  (count :true (trial-assignment trial) :key #'cdr))

(defun choose-trial (run trials &optional points)
  "The trial to take among TRIALS, the assignments of the choice POINTS tried (see
the file header). Among consistent assignments whose modes differ, those whose modes
another one's are preferred to are dropped (a component lists its modes in its order
of preference: where a friction contact can stick, it does not start sliding); an
undecided assignment preferred to the rest leaves the choice undecided. Signals
AMBIGUOUS-TRANSITION or UNSOLVABLE-MODEL."
  (let* ((consistent (remove :consistent trials :key #'trial-verdict :test-not #'eq))
         (best (and consistent (reduce #'min consistent :key #'trial-degenerate)))
         (preferred (remove best consistent :key #'trial-degenerate :test-not #'eql))
         (undecided (remove :undecided trials :key #'trial-verdict :test-not #'eq))
         (preferred (remove-if (lambda (trial)
                                 (some (lambda (other) (preferred-over-p points other trial))
                                       preferred))
                               preferred))
         (blocking (and preferred
                        (remove-if-not (lambda (trial)
                                         (some (lambda (other) (preferred-over-p points trial other))
                                               preferred))
                                       undecided)))
         (preferred (if blocking '() preferred))
         (undecided (or blocking undecided)))
    (cond ((and preferred
                (every (lambda (trial) (same-motion-p run (first preferred) trial)) (rest preferred)))
           ;; equal motions: the one with the fewest active contacts, the least arbitrary force
           (first (sort (copy-list preferred) #'<
                        :key (lambda (trial) (count :true (trial-assignment trial) :key #'cdr)))))
          (preferred
           (error 'ambiguous-transition
                  :datum (mapcar #'trial-assignment preferred)
                  :missing-fact (list :which-contacts-and-modes-hold)
                  :candidates (mapcar #'trial-assignment preferred)
                  :detail "start of a state (several consistent contact and mode sets)"))
          (undecided
           ;; the fork's fact is asked of the assignment with the most contacts holding:
           ;; the textbook's first hypothesis (the block stays flat on the floor, its
           ;; normal forces decide), so that the run branches on its criterion first
           (let ((fact (first (trial-facts (first (stable-sort (copy-list undecided) #'>
                                                               :key #'holding-count))))))
             (error 'ambiguous-transition
                    :datum fact :missing-fact fact
                    :candidates (mapcar #'trial-assignment undecided)
                    :detail "start of a state (which contacts and modes hold)")))
          ;; a model with a family of solutions fixing the motion: said as such
          ;; (indeterminate-forces.lisp)
          (t (error (or (and points (statically-indeterminate-trial run trials points))
                        (make-condition 'unsolvable-model
                                        :datum (mapcar #'trial-assignment trials)
                                        :detail "No set of contacts and modes is consistent at the start of the state.")))))))
