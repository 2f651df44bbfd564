;;;; src/simulator/speed-line-roots.lisp -- when a termination condition fires over a
;;;; :SPEED-LINE motion (speed-line.lisp): the root Maxima finds, proven the only one in the
;;;; state by the motion's monotony.
;;;;
;;;; Over a :SPEED-LINE group the velocities are e p(tau) and the positions q0 + e P(tau),
;;;; with p monotone and P nondecreasing while the state lasts. A condition whose violation
;;;; function depends on the motion through p alone (written over the state it has no
;;;; position), or through P alone (no velocity), and linearly, is monotone in time: it has at
;;;; most one root in the state (|p| and |P| are p and P there: a speed or distance is no
;;;; obstacle). TAU-CANDIDATE answers first; where it leaves the root
;;;; undecided (solve() found it, the earliest-root proof does not cover tan, exp and log),
;;;; the one candidate that is positive and a root (simplified to 0 by Maxima) and at which
;;;; the function is proven to cross downward is that root.

(in-package #:ames.simulator)

(defun one-coordinate-function (run solved group function)
  "FUNCTION (over SOLVED's state terms) as a function of TAU over GROUP's motion, when it
depends on the motion linearly through its speed p along the line alone or its distance P
along it alone (see ALONG-SPEED-LINE); else NIL."
  (multiple-value-bind (positions velocities) (group-positions-and-velocities group)
    (let* ((p (make-symbol "P")) (x (make-symbol "X"))
           (others (set-difference (solved-model-state solved) (append positions velocities)
                                   :test #'equal))
           (h (along-speed-line run group function p x)))
      (flet ((linear-in (y) (let ((d (ames.geometry:differentiate h y)))
                              (and (free-of-p p d) (free-of-p x d)))))
        (when (free-of-all-p others h)
          (cond ((and (free-of-p x h) (linear-in p))
                 (tidy run (substitute-expressions (list (cons p (getf (group-line group) :speed))) h) :full))
                ((and (free-of-p p h) (linear-in x))
                 (tidy run (substitute-expressions (list (cons x (getf (group-line group) :distance))) h)
                       :full))))))))

(defun monotone-root (run g)
  "The one root of G (a function of TAU) that Maxima finds after 0 which is proven
real, positive, a root, and a downward crossing; NIL unless there is exactly one such."
  (multiple-value-bind (root candidates)
      (ames.algebra:earliest-root (run-bridge run) g 'tau :after 0 :strictly t :candidates t)
    (when (eq root :unknown)
      (let ((roots (remove-if-not
                    (lambda (c)
                      (and (free-of-p 'tau c)
                           ;; sign() takes a square root of a radicand of open sign for
                           ;; real: a complex root would pass the tests below
                           (ames.algebra:proven-real-p (run-bridge run) c)
                           (holds run `(> ,c 0))
                           (eql 0 (tidy run (at-time g c) :full))
                           (holds run `(< ,(tidy run (at-time (time-derivative g) c) :full) 0))))
                    candidates)))
        (and roots (null (rest roots)) (tidy run (first roots) :full))))))

(defun speed-line-candidate (run solved groups group condition)
  "TAU-CANDIDATE's answer for CONDITION over the :SPEED-LINE GROUP, with an undecided
root settled by the motion's monotony where it applies (see the file header)."
  (multiple-value-bind (result fact not-before) (tau-candidate run solved groups condition)
    (let ((relation (ames.engine:termination-condition-relation condition)))
      (if (or (not (eq result :unknown)) (gap-relation-contact relation)
              (not (member (first relation) '(< <= > >=))))
          (values result fact not-before)
          (let* ((g (one-coordinate-function run solved group
                                             (over-state-terms run solved (violation-function relation))))
                 (root (and g (monotone-root run g))))
            (if root
                (let ((rate (and (ames.engine:termination-condition-impact condition)
                                 (tidy run (at-time (time-derivative g) root) :full))))
                  (make-candidate condition (condition-event condition rate) root :rate rate))
                (values result fact not-before)))))))

(defun reversal-watched-p (run solved group)
  "True when a termination condition of the state's model fires where GROUP's speed p
along its line reaches 0: its function, written along the line, is linear in p alone and
vanishes at p = 0 (a quadratic drag's turning point: src/kb/drag.lisp)."
  (let ((p (make-symbol "P")) (x (make-symbol "X")))
    (some (lambda (condition)
            (let ((relation (ames.engine:termination-condition-relation condition)))
              (and (member (first relation) '(< <= > >=))
                   (let ((h (along-speed-line run group (over-state-terms run solved (violation-function relation))
                                              p x)))
                     (and (free-of-p x h) (not (free-of-p p h))
                          (free-of-p p (ames.geometry:differentiate h p))
                          (eql 0 (tidy run (substitute-expressions (list (cons p 0)) h) :full)))))))
          (ames.engine:model-termination-conditions (run-model run)))))
