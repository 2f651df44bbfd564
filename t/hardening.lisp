;;;; t/hardening.lisp -- issue 27: values that are not physics, runs that cannot crash, output
;;;; that cannot be injected, limits that hold for the whole run, signals and pipes.
;;;;
;;;; The tests that spawn bin/ames (signals, pipes, devices) keep each run to a second or two.

(in-package #:ames.tests)

(def-suite hardening :in all-tests
  :description "Physical ranges, crashes, escaping, limits, signals and pipes (issue 27).")

(in-suite hardening)

(defun hardening-run (text &rest arguments &key settings numeric (limits ames.base:*limits*))
  "The histories of every scenario of TEXT (written to a temporary file), run by
AMES:RUN-FILE with SETTINGS and NUMERIC within LIMITS."
  (declare (ignore arguments))
  (let ((path (write-scenario-text text)))
    (unwind-protect
         (let ((*package* (find-package '#:ames-scenario)))
           (ames:run-file path :settings settings :numeric numeric :limits limits))
      (delete-file path))))

(defun hardening-error (text &rest arguments)
  "The AMES-ERROR that running TEXT (see HARDENING-RUN, same ARGUMENTS) signals, or NIL."
  (handler-case (progn (apply #'hardening-run text arguments) nil)
    (ames:ames-error (condition) condition)))

(defun scenario-symbol (name)
  "The symbol NAME of the scenario package."
  (intern name '#:ames-scenario))

;;; A crash: a body of a numeric (spring) group that meets an impact at its first instant

(defparameter *spring-pushed-into-floor*
  "(scenario pushed-into-floor \"Two particles on a spring; the second is pushed into the floor.\"
  (parameters (m1 :positive) (m2 :positive) (k :positive) (g :positive) (v0 :positive)
              (l0 :positive))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body first :mass m1 :position (0 0) :velocity (0 0) :shape point)
  (body second :mass m2 :position (l0 0) :velocity (0 (- v0)) :shape point)
  (spring coupling :from (first (0 0)) :to (second (0 0)) :stiffness k)
  (simulate :states 2))")

(test a-numeric-state-that-ends-at-once-ends-where-it-started
  "The second mass, pushed into the floor, meets it at t = 0 (a plastic impact, the default
restitution being 0): the state lasts 0, ends with both bodies where they started, and
the next state has the second at rest at (l0, 0). This crashed with NIL is not REAL."
  (let* ((history (first (hardening-run *spring-pushed-into-floor*)))
         (states (ames:history-states history))
         (first-state (first states))
         (l0 (scenario-symbol "L0")) (v0 (scenario-symbol "V0")))
    (is (>= (length states) 2))
    (is (eql 0 (ames:state-duration first-state)))
    (is (equal `(,l0 0) (second (assoc "SECOND" (ames:state-final-positions first-state)
                                       :key #'symbol-name :test #'string=))))
    (is (equal `(0 (- ,v0)) (second (assoc "SECOND" (ames:state-final-velocities first-state)
                                           :key #'symbol-name :test #'string=))))
    (is (member (ames:history-outcome history) '(:complete :stopped)))))
