;;;; src/simulator/guarded-meetings.lisp -- a termination condition that is a gap reaching 0
;;;; within a range: a contact's touching, as the time searches read it.
;;;;
;;;; A shape contact's touching is (= (contact-gap K) 0), whose meeting the geometry gives
;;;; (the gap and the relations saying the point is within the contact's ends). A
;;;; component may say the same in its own terms: an activation that is an equation and
;;;; inequalities, (and (= A B) GUARD ...), a corner's touching (src/kb/corners.lisp: its
;;;; gap 0 and its point within the face). Such a conjunction is reached when A - B
;;;; closes to 0 from positive while every GUARD holds there: a corner crossing the line
;;;; of a face past its end reaches nothing, and the search goes on to the next crossing.
;;;; RELATION-MEETING gives both as one MEETING (the numeric integrator's event functions,
;;;; the self-check, a path's search read it); the searches along TAU and along a rotating
;;;; body's angle take the first closing of the gap and test the guards there
;;;; (GUARDED-RELATION-TIME-AND-RATE, GUARDED-ANGLE-ROOT), and under numbers the gap itself
;;;; is searched (GUARDED-NUMERIC-CROSSING). A guard the algebra leaves open at a closing
;;;; is the run's parameter values' to settle, else an unknown the caller branches on.

(in-package #:ames.simulator)

(defun guarded-relation-parts (relation)
  "For a conjunction (and (= A B) GUARD ...) of an equation and inequalities (or ORs of
them): (values (- A B) GUARDS); else NIL."
  (when (and (consp relation) (eq (first relation) 'and)
             (consp (second relation)) (eq (first (second relation)) '=)
             (cddr relation)
             (every (lambda (r) (and (consp r) (member (first r) '(< <= > >= or))))
                    (cddr relation)))
    (values `(- ,(relation-lhs (second relation)) ,(relation-rhs (second relation)))
            (cddr relation))))

(defun relation-meeting (run solved relation)
  "The MEETING (over SOLVED's state terms) of RELATION when it is a contact's touching,
(= (contact-gap K) 0) (the geometry's), or a guarded conjunction (GUARDED-RELATION-PARTS:
its gap A - B, its guards as the extent); else NIL."
  (let ((contact (gap-relation-contact relation)))
    (if contact
        (contact-meeting-terms run solved contact)
        (multiple-value-bind (gap guards) (guarded-relation-parts relation)
          (when gap
            (ames.geometry:make-meeting nil (over-state-terms run solved gap) nil
                                        (mapcar (lambda (guard) (over-state-terms run solved guard))
                                                guards)))))))

(defun guarded-violation-function (relation)
  "RELATION's violation function (VIOLATION-FUNCTION), for a guarded conjunction that of
its equation: the gap whose closing reaches it."
  (if (guarded-relation-parts relation)
      (violation-function (second relation))
      (violation-function relation)))

(defun guards-verdict (run guards at)
  "Whether every one of GUARDS holds where AT (a function turning a relation's operands
into their values at the place searched) puts them: :TRUE, :FALSE or (values :UNKNOWN
FACT). What the assumptions leave open the run's parameter values settle when it has
them (the fact recorded as assumed from them), as they settle the order of events; while
they decide first (AMES.ALGEBRA:VALUES-FIRST-P), after only a cheap proof."
  (let ((unknown nil))
    (dolist (guard guards (if unknown (values :unknown unknown) :true))
      (let* ((relation (guard-at guard at))
             (truth (ames.algebra:decide-first-cheaply (run-bridge run) relation)))
        (when (eq truth :unknown)
          (setf truth (or (ames.algebra:decide-by-values relation) :unknown)))
        (case truth
          (:false (return :false))
          (:unknown (setf unknown relation)))))))

(defun guard-at (guard at)
  "GUARD, an inequality or an OR of them, with its operands turned by AT."
  (if (eq (first guard) 'or)
      (cons 'or (mapcar (lambda (part) (guard-at part at)) (rest guard)))
      (list (first guard) (funcall at (relation-lhs guard)) (funcall at (relation-rhs guard)))))

;;; Functions of TAU

(defun guarded-relation-time-and-rate (run condition relation over-time)
  "RELATION-TIME-AND-RATE's answer for the guarded conjunction RELATION (see the file
header): the first time its gap closes to 0 with every guard holding then. A closing
where a guard fails (a corner crossing the face's line past its end) is passed, and the
search goes on to the next closing, up to four."
  (multiple-value-bind (gap guards) (guarded-relation-parts relation)
    (let ((g (tidy run (funcall over-time gap)))
          (at-tau (lambda (time) (lambda (x) (tidy run (at-time (funcall over-time x) time))))))
      (multiple-value-bind (status time rate)
          (relation-time-and-rate run condition (second relation) over-time)
        (loop repeat 4
              do (unless (eq status :at)
                   (return-from guarded-relation-time-and-rate (values status time rate)))
                 (multiple-value-bind (verdict fact) (guards-verdict run guards (funcall at-tau time))
                   (case verdict
                     ;; exactly at the face's end: the corner meets a vertex (face-end-corners.lisp)
                     (:true (return-from guarded-relation-time-and-rate
                              (closed-form-face-end run condition guards (funcall at-tau time)
                                                    over-time time rate)))
                     (:unknown (return-from guarded-relation-time-and-rate (values :unknown fact)))))
                 (multiple-value-setq (status time rate) (next-closing run g time)))
        (values :unknown `(:meets-beyond-the-first-roots (= ,g 0)))))))

(defun next-closing (run g after)
  "The first time strictly after AFTER at which G (a function of TAU) reaches 0 going
down (its slope there proven negative): (values :AT TIME RATE), (values :NEVER) or
(values :UNKNOWN FACT); roots where it rises are passed (up to four)."
  (loop repeat 4
        do (let ((root (earliest-root-after run g after)))
             (case root
               (:none (return-from next-closing (values :never)))
               (:unknown (return-from next-closing (values :unknown (undecided-sign-fact run g after))))
               (t (let* ((root (tidy run root :full))
                         (rate (tidy run (at-time (time-derivative g) root) :full)))
                    (case (decide run `(< ,rate 0))
                      (:true (return-from next-closing (values :at root rate)))
                      (:false (setf after root))
                      (t (return-from next-closing (values :unknown `(< ,rate 0))))))))))
  (values :unknown `(:meets-beyond-the-first-roots (= ,g 0))))

;;; Functions of a rotating body's angle (rotation-path.lisp)

(defun guarded-angle-root (run group relation over-angle)
  "ANGLE-RELATION-ROOT's answer for the guarded conjunction RELATION: the first angle
ahead where its gap closes to 0 with every guard holding there; a closing where a guard
fails is passed, the search going on from it (up to four)."
  (multiple-value-bind (gap guards) (guarded-relation-parts relation)
    (let ((f (funcall over-angle gap))
          (from group))
      (loop repeat 4
            do (multiple-value-bind (status s) (angle-root-ahead run from f)
                 (unless (eq status :at)
                   (return-from guarded-angle-root (values status s)))
                 (multiple-value-bind (verdict fact)
                     (guards-verdict run guards (lambda (x) (tidy run (at-arc (funcall over-angle x) s))))
                   (case verdict
                     (:true (return-from guarded-angle-root (values :at s)))
                     (:unknown (return-from guarded-angle-root (values :unknown fact)))))
                 ;; past the face's end: on from there, once the gap is positive again
                 (setf from (let ((copy (copy-group from))) (setf (group-s0 copy) s) copy))
                 (multiple-value-bind (status s) (angle-root-ahead run from `(- ,f))
                   (unless (eq status :at)
                     (return-from guarded-angle-root (values status s)))
                   (setf from (let ((copy (copy-group from))) (setf (group-s0 copy) s) copy)))))
      (values :unknown `(:meets-beyond-the-first-roots (= ,f 0))))))

;;; Numbers: closed-form motion whose crossing has no closed form (numeric-roots.lisp)

(defun masked-after (function from)
  "FUNCTION of TAU, 1 up to FROM: a search for its next crossing after FROM."
  (lambda (time) (if (<= time from) 1d0 (funcall function time))))

(defun start-touching-crossing-p (gap crossing)
  "True when the CROSSING found of GAP (a function of TAU) is the touching the state
starts with: GAP is 0 at TAU = 0 (a corner left exactly at a face's end by the state
before, put there exactly: corner-snapping.lisp) and the crossing is the round-off of
that zero, before 1e-12. The start's choice search has decided that touching (the
corner does not enter the face: it moves out past its end): it is no event."
  (let ((start (funcall gap 0d0)))
    (and start (<= (abs start) 1d-15) (< crossing 1d-12))))

(defun guarded-numeric-crossing (run solved groups condition rate step until)
  "For CONDITION, a guarded conjunction over closed-form motion whose crossing has no
closed form: the first TAU (up to UNTIL, sampled every STEP, or on the geometric grid
without one) where its gap crosses below zero with every guard holding there, or NIL.
The gap itself is searched, not a gap gated by the guards (a gated gap hides a crossing
inside the face between two samples); a crossing past the face's end is passed, the search
going on once the gap is positive again (up to eight crossings). RATE is the gap's rate."
  (let* ((bindings (numeric-bindings run))
         (over-tau (lambda (x)
                     (let ((f (numeric-function
                               (substitute-expressions bindings (motion-value groups (over-state-terms run solved x)))
                               '(tau))))
                       (lambda (time) (safe-value f (vector time))))))
         (meeting (relation-meeting run solved (ames.engine:termination-condition-relation condition)))
         (gap (funcall over-tau (ames.geometry:meeting-gap meeting)))
         (margins (loop for r in (ames.geometry:meeting-extent meeting)
                        unless (eq (first r) 'or) collect (funcall over-tau (extent-margin r))))
         (negated (lambda (f) (and f (lambda (time) (let ((v (funcall f time))) (and v (- v)))))))
         (search (lambda (f r)
                   (if step
                       (first-numeric-crossing f (or r (constantly nil)) step until)
                       (first-geometric-crossing f until)))))
    (let ((from nil))
      (loop repeat 8
            do (let ((crossing (funcall search (if from (masked-after gap from) gap) rate)))
                 (cond ((null crossing) (return nil))
                       ((and (every (lambda (m) (let ((x (funcall m crossing))) (and x (>= x -1d-9)))) margins)
                             (not (start-touching-crossing-p gap crossing)))
                        (return crossing))
                       (t (let ((back (funcall search (masked-after (funcall negated gap) crossing)
                                               (funcall negated rate))))
                            (if back (setf from back) (return nil))))))))))
