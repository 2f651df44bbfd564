;;;; src/engine/held-entries.lisp -- the equalities a model's current modes hold.
;;;;
;;;; A mode entered on equalities (a taut rope: its slack and the rate of its length both
;;;; zero; a sticking contact: no relative velocity) holds them while it lasts: its
;;;; equations keep their second derivatives at zero. A state integrated numerically ends
;;;; with them off by the integration's error; the simulator puts the end values back on
;;;; them where it can do so exactly (src/simulator/circle-snapping.lisp), and needs them
;;;; without knowing which phenomenon wrote them.

(in-package #:ames.engine)

(defun held-entry-equations (model)
  "The entry equations of the current mode of every active instance of MODEL, expanded
for the instance, each as the expression LHS - RHS (LHS when RHS is 0)."
  (let ((found '()))
    (dolist (instance (model-active-instances model) (nreverse found))
      (let* ((component (instance-component instance))
             (name (instance-mode instance))
             (mode (and name (rest (component-modes component)) (find-mode component name))))
        (when mode
          (dolist (template (mode-entry-relations mode))
            (let ((relation (expanded-relation model instance template)))
              (when (and (consp relation) (eq (first relation) '=))
                (pushnew (if (eql (third relation) 0)
                             (second relation)
                             (list '- (second relation) (third relation)))
                         found :test #'equal)))))))))
