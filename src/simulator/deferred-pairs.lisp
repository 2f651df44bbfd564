;;;; src/simulator/deferred-pairs.lisp -- the broad phase of the world: pairs of bodies
;;;; proven apart need no contact entity, no loci and no beliefs.
;;;;
;;;; A world holds the contact pairs of every two bodies: N^2 of them, each with its
;;;; configuration-space contacts, whose entities the model carries through every state.
;;;; Two bodies whose shapes are bounded (a point, a circle, a polygon, a segment) and that
;;;; only translate lie, along each axis, between their position plus the least and the
;;;; greatest coordinate of their shape. At the start (PAIR-APART-AT-START-P, the
;;;; *PAIR-SCREEN* that SCENARIO-GEOMETRY asks) a pair whose bounds along one axis are
;;;; strictly apart cannot touch: its contact pair is deferred, not built. In each state
;;;; (CHECK-DEFERRED-PAIRS, called by the termination's candidates) each deferred pair
;;;; must be proven to stay strictly apart over the whole state (its bodies' coordinates
;;;; c0 + c1 tau + c2 tau^2, as broad-phase.lisp reads them: the offsets strictly on one
;;;; side, the rates weakly on the same side): then it is apart at the state's end too,
;;;; the next state's start. A pair that cannot be proven so signals
;;;; DEFERRED-PAIRS-NEEDED: SIMULATE-IN-WORLD builds it and simulates again from the start
;;;; (a pair apart at a state's start touches nothing, so the states before are the same).
;;;; Only what is proven is left out: the events that end a state still include every
;;;; contact that can close in it. The signs are the broad phase's (exact arithmetic, the
;;;; rules of signs over the declared signs, like terms cancelled); never Maxima's but for
;;;; a body's own rates (memoized per body and axis).

(in-package #:ames.simulator)

(defvar *defer-pairs* t
  "When true, SIMULATE leaves out of the world the pairs proven apart at the start (see
this file's header); NIL builds every pair, as before (for comparisons).")

(defvar *deferred-pairings* '()
  "The deferred pairings of the world being simulated (see WORLD-DEFERRED-PAIRINGS):
each (ORDINAL BODY-NAME OTHER-NAME).")

(define-condition deferred-pairs-needed (condition)
  ((pairings :initarg :pairings :reader deferred-pairs-needed-pairings))
  (:documentation "Signalled when deferred PAIRINGS cannot be proven apart over a state:
SIMULATE-IN-WORLD builds them and simulates again."))

(defun shape-extents (shape index)
  "Coordinates along INDEX (0: x, 1: y), in the body's frame, whose least and greatest
bound the validated scenario SHAPE, or NIL for a shape this does not bound (a half-plane,
an outline, an arc)."
  (case (shape-kind shape)
    (:point (list 0))
    (:circle (list `(- ,(second shape)) (second shape)))
    ((:polygon :segment) (mapcar (lambda (point) (nth index point)) (rest shape)))
    (t nil)))

(defun extreme-extents (reach extents side)
  "EXTENTS less those another one is proven to bound on SIDE (:POSITIVE: the greatest,
:NEGATIVE: the least): the least or greatest of EXTENTS is among the rest."
  (let ((kept '()))
    (dolist (extent (remove-duplicates extents :test #'equal) (nreverse kept))
      (flet ((beyond-p (a b)             ; A is proven at least as far to SIDE as B
               (ames.algebra:only-signs-p (cheap-sign reach `(- ,a ,b)) side :zero)))
        (unless (some (lambda (other) (beyond-p other extent)) kept)
          (setf kept (cons extent (remove-if (lambda (other) (beyond-p extent other)) kept))))))))

(defun screenable-body-p (body)
  "True when the scenario BODY only translates with its shape as written and the shape
is bounded (see SHAPE-EXTENTS)."
  (and (not (scenario-body-rotating-p body))
       (eql (scenario-body-angle body) 0)
       (shape-extents (scenario-body-shape body) 0)
       t))

(defun body-bounds (reach table body index)
  "(LEAST . GREATEST) candidates of BODY's shape along INDEX (lists of expressions),
memoized in TABLE."
  (let ((key (cons (scenario-body-name body) index)))
    (or (gethash key table)
        (setf (gethash key table)
              (let ((extents (shape-extents (scenario-body-shape body) index)))
                (cons (extreme-extents reach extents :negative)
                      (extreme-extents reach extents :positive)))))))

(defun placed-polynomial (table key start extent)
  "The expanded monomials of START + EXTENT (a body's coordinate plus a bound of its
shape), or :UNKNOWN, memoized in TABLE under KEY."
  (multiple-value-bind (known found) (gethash key table)
    (if found
        known
        (setf (gethash key table) (expanded-monomials `(+ ,start ,extent))))))

(defun offset-sign (reach table a-name a-start a b-name b-start b index)
  "The sign set of (A-START + A) - (B-START + B), the bound A of the body A-NAME placed
at its coordinate A-START along INDEX, B likewise: from the two placed bounds' expanded
polynomials (memoized in TABLE, each body's once) when both are polynomials, else by
CHEAP-SIGN. Either way by exact rewriting and the rules of signs: proven, or all signs."
  (let ((pa (placed-polynomial table (list a-name index a) a-start a))
        (pb (placed-polynomial table (list b-name index b) b-start b)))
    (if (or (eq pa :unknown) (eq pb :unknown))
        (cheap-sign reach `(- (+ ,a-start ,a) (+ ,b-start ,b)))
        (let ((difference (polynomial-sum pa (polynomial-scaled pb -1))))
          (if (null difference)
              (list :zero)
              (monomials-sign (reach-signs-of-parameters reach) difference))))))

(defun offsets-strictly-p (reach table a-name a-start a-extents b-name b-start b-extents
                           index side)
  "True when every (A-START + a) - (B-START + b), a of A-EXTENTS and b of B-EXTENTS (the
bodies A-NAME and B-NAME along INDEX), is proven strictly on SIDE (see OFFSET-SIGN)."
  (every (lambda (a)
           (every (lambda (b)
                    (eq (one-sign (offset-sign reach table a-name a-start a b-name b-start b index))
                        side))
                  b-extents))
         a-extents))

(defun bounds-apart-p (reach table a-name bounds-a a-start b-name bounds-b b-start index)
  "True when, along INDEX, the shape of A-NAME bounded by BOUNDS-A (see BODY-BOUNDS)
placed at A-START lies strictly below or strictly above the one of B-NAME at B-START."
  (or (offsets-strictly-p reach table a-name a-start (cdr bounds-a) b-name b-start (car bounds-b)
                          index :negative)
      (offsets-strictly-p reach table a-name a-start (car bounds-a) b-name b-start (cdr bounds-b)
                          index :positive)))

(defun queried-pair-p (scenario body other)
  "True when both BODY's and OTHER's names occur in SCENARIO's queries: such a pair is
always built."
  (let ((names '()))
    (labels ((walk (form)
               (cond ((consp form) (walk (car form)) (walk (cdr form)))
                     ((symbolp form) (pushnew form names)))))
      (walk (scenario-queries scenario)))
    (and (member (scenario-body-name body) names) (member (scenario-body-name other) names) t)))

(defun make-pair-screen ()
  "A *PAIR-SCREEN*: a function of a SCENARIO and two of its bodies, true when both are
screenable (SCREENABLE-BODY-P), no query names both, and their shapes at their starting
positions are strictly apart along an axis."
  (let ((reach nil) (scenario nil)
        (table (make-hash-table :test #'equal)) (polynomials (make-hash-table :test #'equal)))
    (lambda (for-scenario body other)
      (unless (eq for-scenario scenario)
        (setf scenario for-scenario
              reach (%make-reach nil (parameter-signs scenario) nil nil))
        (clrhash table)
        (clrhash polynomials))
      (and (screenable-body-p body) (screenable-body-p other)
           (not (queried-pair-p scenario body other))
           (loop for index from 0 to 1
                 thereis (bounds-apart-p reach polynomials
                                         (scenario-body-name body)
                                         (body-bounds reach table body index)
                                         (nth index (scenario-body-position body))
                                         (scenario-body-name other)
                                         (body-bounds reach table other index)
                                         (nth index (scenario-body-position other))
                                         index))))))

(defun stays-apart-p (reach table polynomials entry)
  "True when the deferred pairing ENTRY (ORDINAL NAME OTHER-NAME) is proven to stay
strictly apart over the whole state REACH describes (TABLE memoizes the bounds,
POLYNOMIALS the placed bounds at the state's start)."
  (let* ((run (reach-run reach))
         (body (run-body run (second entry)))
         (other (run-body run (third entry))))
    (loop for axis in '(:x :y)
          for index from 0
          thereis
          (let ((a (body-coefficients reach (second entry) axis))
                (b (body-coefficients reach (third entry) axis)))
            (and (listp a) (listp b)
                 (let ((c1 (difference-sign reach (second a) (second b)))
                       (c2 (difference-sign reach (third a) (third b)))
                       (bounds-a (body-bounds reach table body index))
                       (bounds-b (body-bounds reach table other index)))
                   (flet ((side-p (side)
                            (and (ames.algebra:only-signs-p c1 side :zero)
                                 (ames.algebra:only-signs-p c2 side :zero)
                                 (if (eq side :negative)
                                     (offsets-strictly-p reach polynomials
                                                         (second entry) (first a) (cdr bounds-a)
                                                         (third entry) (first b) (car bounds-b)
                                                         index side)
                                     (offsets-strictly-p reach polynomials
                                                         (second entry) (first a) (car bounds-a)
                                                         (third entry) (first b) (cdr bounds-b)
                                                         index side)))))
                     (or (side-p :negative) (side-p :positive)))))))))

(defun check-deferred-pairs (reach)
  "Signal DEFERRED-PAIRS-NEEDED with the deferred pairings not proven to stay apart over
the state REACH describes; an error when nothing handles it (a deferred pair is never
silently ignored)."
  (when *deferred-pairings*
    (let* ((table (make-hash-table :test #'equal))
           (polynomials (make-hash-table :test #'equal))
           (needed (remove-if (lambda (entry) (stays-apart-p reach table polynomials entry))
                              *deferred-pairings*)))
      (when needed
        (signal 'deferred-pairs-needed :pairings needed)
        (error 'simulation-error
               :detail (format nil "the contact pairs ~S were left out and are needed"
                               (mapcar #'rest needed)))))))
