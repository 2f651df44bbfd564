;;;; src/report/view-branches.lisp -- what the view shows of a run's forks and the times it writes:
;;;; branches labelled by their place in the tree (1, 1.2), a failed branch's reason with its
;;;; formulas read back from the simulator's words, and the definition of t and tau.

(in-package #:ames.report)

(defpackage #:ames.report.read-back (:use #:cl)
  (:documentation "Where FAILURE-PHRASE reads back the formulas a message printed."))

(defun read-back-formula (text start)
  "The formula of the algebra printed in TEXT at START (an open parenthesis) and the
position after it, or NIL. Read with *READ-EVAL* false into a package of its own."
  (handler-case
      (multiple-value-bind (form end)
          (let ((*read-eval* nil) (*package* (find-package '#:ames.report.read-back)))
            (read-from-string text t nil :start start :preserve-whitespace t))
        (and (consp form) (symbolp (first form))
             ;; words in parentheses, (its tangent point wanders ...), read as a term of
             ;; many names: a formula is an operator form or a short quantity term
             (or (compound-expression-p form) (<= (length form) 3))
             (or (valid-expression-p form :kind :arithmetic) (valid-expression-p form :kind :condition))
             (values form end)))
    (error () nil)))

(defun scenario-formula (presenter form)
  "FORM (read back) with its names made the scenario's parameters of the same name, and
presented by PRESENTER; FORM itself when that fails."
  (let* ((parameters (mapcar #'scenario-parameter-name (scenario-parameters (presenter-scenario presenter))))
         (renamed form))
    (labels ((rename (x)
               (cond ((and (symbolp x) (eq (symbol-package x) (find-package '#:ames.report.read-back)))
                      (or (find (symbol-name x) parameters :key #'symbol-name :test #'string=) x))
                     ((consp x) (cons (rename (car x)) (rename (cdr x))))
                     (t x))))
      (setf renamed (rename form))
      (handler-case (if (valid-expression-p renamed :kind :condition)
                        (present-relation presenter renamed)
                        (present presenter renamed))
        (error () form)))))

(defun failure-phrase (text &optional presenter)
  "Why a branch failed, the simulator's TEXT as a phrase: each formula it printed as a
prefix form is read back and becomes a formula of the phrase (written infix by every
format, presented by PRESENTER when given); the rest stays words."
  (let ((parts '()) (words (make-string-output-stream)) (i 0))
    (loop while (< i (length text))
          do (multiple-value-bind (form end)
                 (and (char= (char text i) #\() (read-back-formula text i))
               (if form
                   (progn (push (get-output-stream-string words) parts)
                          (push (list :math (if presenter (scenario-formula presenter form) form)) parts)
                          (setf i end))
                   (progn (write-char (char text i) words) (incf i)))))
    (push (get-output-stream-string words) parts)
    (remove "" (nreverse parts) :test #'equal)))

(defun labelled-branches (states &optional prefix)
  "STATES (views) with each branch of a fork labelled by its place in the tree of
branches, :LABEL \"1\", \"2\" at the top and \"1.2\" for the second branch of a fork
inside branch 1, and :COUNT the number of its fork's branches; each state of a branch
has :BRANCH, the label of the branch it belongs to."
  (mapcar (lambda (state)
            (let ((branches (getf state :branches)))
              (list* :branch prefix
                     :branches (loop for branch in branches
                                     for k from 1
                                     for label = (format nil "~@[~A.~]~D" prefix k)
                                     collect (list* :label label :count (length branches)
                                                    :states (labelled-branches (getf branch :states) label)
                                                    branch))
                     state)))
          states))

(defun time-definitions ()
  "Phrases defining the times a report writes: t from the start of the run, tau within a
state."
  (list (phrase "t is the time from the start of the run; within a state, "
                (list '= 'tau (list '- (make-symbol "T") (make-symbol "T0")))
                " is the time since the state began at " (make-symbol "T0"))))

