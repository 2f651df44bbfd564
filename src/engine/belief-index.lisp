;;;; src/engine/belief-index.lisp -- the index of a model's beliefs, for matching the
;;;; belief arguments of components.

(in-package #:ames.engine)

;;; An index of the beliefs by their first positional element and by each property's
;;; value, so that a pattern whose arguments are partly bound (the forces :ON one body)
;;; is matched against the few beliefs that can match it, not against every belief of
;;; its head: model building is then near linear in the number of beliefs.

(defun belief-index-keys (belief)
  "The keys under which BELIEF is indexed: (HEAD 0 FIRST-POSITIONAL), where that element
is an atom (a name) or a ground form (the (derivative (path-position C) ...) of N^2
contacts), and (HEAD KEY VALUE) for each of its properties whose value is an atom."
  (let ((head (pattern-head belief))
        (positional (positional-part belief)))
    (append (and positional (ground-p (first positional))
                 (list (list head 0 (first positional))))
            (loop for (key value) on (property-part belief) by #'cddr
                  when (atom value)
                    collect (list head key value)))))

(defun index-belief (model belief node)
  "Enter the new BELIEF (with its NODE) in MODEL's belief index, whose entries are
(COUNT . PAIRS), newest first."
  (dolist (key (cons (list (pattern-head belief)) (belief-index-keys belief)))
    (let ((entry (or (gethash key (model-belief-index model))
                     (setf (gethash key (model-belief-index model)) (cons 0 '())))))
      (incf (car entry))
      (push (cons belief node) (cdr entry)))))

(defun ground-p (form)
  "True when FORM holds no pattern variable."
  (cond ((pattern-variable-p form) nil)
        ((consp form) (and (ground-p (car form)) (ground-p (cdr form))))
        (t t)))

(defun candidate-beliefs (model pattern bindings)
  "The (belief . node) pairs of MODEL that may match PATTERN under BINDINGS, oldest
first: a superset of the matches (MATCH-PATTERN decides), in the order of
BELIEFS-WITH-HEAD. Narrowed by the index on the parts of PATTERN that BINDINGS make
ground, the shortest list winning."
  (let* ((pattern (substitute-bindings bindings pattern))
         (head (pattern-head pattern))
         (best (or (gethash (list head) (model-belief-index model)) (cons 0 '())))
         (positional (positional-part pattern)))
    (flet ((narrow (key)
             (let ((entry (gethash key (model-belief-index model) '(0))))
               (when (< (car entry) (car best))
                 (setf best entry)))))
      (when (and positional (ground-p (first positional)))
        (narrow (list head 0 (first positional))))
      (loop for (key value) on (property-part pattern) by #'cddr
            when (and (atom value) (ground-p value))
              do (narrow (list head key value))))
    (reverse (cdr best))))
