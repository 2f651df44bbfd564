;;;; src/witness/refine.lisp -- a first-order witness's disagreement checked at a finer step.
;;;;
;;;; Moreau-Jean time stepping (the rotation driver, step h = 1e-3 s) puts an event on its
;;;; step grid: an impact up to h late, by which time a body spinning at 23 rad/s has turned
;;;; 0.023 rad further, and the impulse, which depends on where the body is struck, differs
;;;; by a few per cent (seed 23 rod-ledge #14: omega after a ledge's impact -4.913 at 1e-3,
;;;; -5.076 at 2.5e-4, -5.0827 at 6.25e-5; AMES's exact -5.0863). The comparator knows no
;;;; physics to bound that sensitivity; the witness's own convergence does: a disagreement
;;;; under a witness that states its step is compared again with the witness run at a
;;;; quarter of that step (at most +REFINEMENTS+ times), its values to the tolerance of the
;;;; finer step (20 steps relative, compare-first-order.lisp), so that an error of AMES of
;;;; the size first seen is still caught, the more tightly. The verdict says which step
;;;; decided it.

(in-package #:ames.witness)

(defconstant +refinements+ 2 "How many times a disagreeing witness's step is divided by 4.")

(defun refinable-p (comparison witness)
  "True when COMPARISON (against WITNESS) is a disagreement under a witness that states its
step (a driver that takes the model's \"step\")."
  (and (eq (comparison-verdict comparison) :ames-wrong)
       (eq (getf witness :scheme) :moreau-jean)
       (realp (getf witness :step))))

(defun compare-refining (answer model witness values &key t-end (timeout 120) (run #'run-witness))
  "COMPARE-RESULTS of AMES's ANSWER with WITNESS (the witness's answer for MODEL); when it
disagrees and the witness is first order with a stated step, the witness is run again on
MODEL with a quarter of its step and compared again (see the file's header), up to
+REFINEMENTS+ times, until it agrees. Returns (VALUES COMPARISON WITNESS), those that
decided, the comparison's reason naming the steps. RUN runs the witness on a model (with
a :TIMEOUT)."
  (let* ((*largest-restitution* (model-largest-restitution model)) ; compare-slow-impacts.lisp
         (comparison (compare-results answer witness values :t-end t-end)))
    (loop with first-reason = (comparison-reason comparison)
          with first-step = (getf witness :step)
          for k from 1 to +refinements+
          while (refinable-p comparison witness)
          do (let* ((step (/ (getf witness :step) 4))
                    (finer (funcall run (append (remove "step" model :key #'car :test #'equal)
                                                (list (cons "step" (coerce step 'double-float))))
                                        :timeout (min 600 (* timeout (expt 4 k))))))
               (unless (and (eq (witness-status finer) :ok)
                            (realp (getf finer :step)) (< (getf finer :step) (* 1.01 step)))
                 (return))
               (setf witness finer
                     comparison (compare-results answer finer values :t-end t-end))
               (setf (comparison-reason comparison)
                     (format nil "at the witness's step ~A s~@[: ~A~]; at its step ~A s: ~A"
                             (coerce (getf finer :step) 'single-float) (comparison-reason comparison)
                             (coerce first-step 'single-float) first-reason))))
    ;; a strike AMES's path clears by less than the witness resolves (compare-grazes.lisp)
    (values (strike-below-resolution comparison answer model witness values run) witness)))
