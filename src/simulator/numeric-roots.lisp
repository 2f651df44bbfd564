;;;; src/simulator/numeric-roots.lisp -- the first time a condition fires over a closed-form
;;;; motion that has no closed-form root, searched with numbers.
;;;;
;;;; A spring's motion is closed form, but a gap such as A + D tau + B cos(w tau) + C sin(w
;;;; tau) (a pair on a spring drifting toward a third body) has no closed-form root, and the
;;;; bridge's proven earliest root answers :UNKNOWN (an (:EARLIEST-ROOT-OF ...) fact). When
;;;; every parameter has a number (--set, --numeric, or a scenario without parameters),
;;;; such a condition is watched on its closed form: the event functions of numeric.lisp
;;;; (with no state integrated: the closed-form motion gives them the time) are sampled with
;;;; a step of a 64th of the shortest period in them and, where one crosses zero, its
;;;; root is bisected to double precision. A sign change of the function's rate between
;;;; two samples (a dip that could cross zero twice in one step) is looked into too. A
;;;; condition that does not fire before the earliest other candidate (or within the
;;;; search's reach when there is none) stays undecided: never is not proven by numbers.

(in-package #:ames.simulator)

(defparameter *root-search-steps* 100000
  "The most samples the numeric root search takes over one state.")

(defun numeric-root-fallback-p (run fact)
  "True when an undecided FACT of a closed-form condition is the missing earliest root
of a function of TAU (with sines or cosines of TAU, or with no elementary root: a Lambert
W, ln cosh = c), and the run's numbers are known."
  (and (run-numbers-known-p run)
       (consp fact) (eq (first fact) :earliest-root-of)))

(defun time-frequencies (expression)
  "The rates d(argument)/d(TAU) of the sines and cosines of TAU in EXPRESSION."
  (let ((rates '()))
    (labels ((walk (x)
               (when (consp x)
                 (when (and (member (first x) '(sin cos)) (not (free-of-p 'tau (second x))))
                   (push (time-derivative (second x)) rates))
                 (mapc #'walk (rest x)))))
      (walk expression))
    rates))

(defun condition-time-function (run solved groups condition)
  "CONDITION's violation function over the closed-form motion of GROUPS, a function of
TAU (its gap for a contact)."
  (let* ((relation (ames.engine:termination-condition-relation condition))
         (meeting (relation-meeting run solved relation)))
    (motion-value groups (over-state-terms
                          run solved
                          (if meeting
                              (ames.geometry:meeting-gap meeting)
                              (if (eq (first relation) 'or) 0 (violation-function relation)))))))

(defun sampling-step (run solved groups conditions)
  "A 64th of the shortest period of the sines and cosines of TAU in CONDITIONS' functions,
or NIL when there is none or a rate has no number."
  (let ((rates (loop for condition in conditions
                     append (time-frequencies (condition-time-function run solved groups condition))))
        (bindings (numeric-bindings run)))
    (when rates
      (let ((fastest (loop for rate in rates
                           for value = (handler-case
                                           (funcall (numeric-function (substitute-expressions bindings rate) '(tau))
                                                    (vector 0d0))
                                         (error () nil))
                           unless (realp value) do (return nil)
                           maximize (abs value))))
        (and fastest (plusp fastest) (/ (* 2 pi) (* 64 fastest)))))))

(defun bisect-crossing (function low high)
  "The point where FUNCTION (>= 0 at LOW, < 0 at HIGH) first crosses below zero, by
bisection to double precision."
  (loop repeat 200
        while (> (- high low) (* 4 double-float-epsilon (max 1d0 (abs high))))
        do (let* ((middle (/ (+ low high) 2)) (value (funcall function middle)))
             (if (and value (< value 0)) (setf high middle) (setf low middle))))
  high)

(defun jump-below-zero-p (function time before)
  "True when FUNCTION, found crossing below zero at TIME (BISECT-CROSSING's answer, BEFORE
its value at the start of the step), jumps there rather than crossing: its value just past
TIME is far from zero (more than 1e-6 of the larger of 1 and |BEFORE|). A function gated
by an extent (a contact's gap counted only while its point is within the face: a corner
entering a face's extent behind its line, see guarded-meetings.lisp) jumps; a continuous
one does not."
  (let ((value (funcall function time)))
    (and value (> (abs value) (* 1d-6 (max 1d0 (abs before)))))))

(defun dip-crossing (function rate low high)
  "Within [LOW, HIGH], where FUNCTION is >= 0 at both ends and RATE goes from negative to
positive: the point where FUNCTION is least, when FUNCTION < 0 there (a dip below zero
between two samples), else NIL."
  (let ((a low) (b high))
    (loop repeat 200
          while (> (- b a) (* 4 double-float-epsilon (max 1d0 (abs b))))
          do (let* ((middle (/ (+ a b) 2)) (r (funcall rate middle)))
               (if (and r (< r 0)) (setf a middle) (setf b middle))))
    (let ((value (funcall function b)))
      (and value (< value 0) b))))

(defun first-numeric-crossing (function rate step horizon &optional (tolerance (constantly 0d0)))
  "The first TAU > 0 (up to HORIZON, or *ROOT-SEARCH-STEPS* steps of STEP) where FUNCTION
of TAU crosses below zero, or NIL; (:ROUND-OFF TAU) when it first goes below zero only
within round-off (TOLERANCE, a function of the time giving a non-negative margin; 0 by
default): a crossing needs a sign change the float can tell (a value below -TOLERANCE),
else it is no proof of one (a gap that only tends to zero, evaluated as -1e-15)."
  (let ((before (funcall function 0d0)) (rate-before (funcall rate 0d0)) (time 0d0))
    (loop repeat *root-search-steps*
          for next = (if horizon (min (+ time step) horizon) (+ time step))
          for after = (funcall function next)
          for rate-after = (funcall rate next)
          do (cond ((and before after (>= before 0) (< after 0)
                         ;; a jump below zero is no crossing (guarded-meetings.lisp)
                         (not (jump-below-zero-p function (bisect-crossing function time next) before)))
                    (return-from first-numeric-crossing
                      (if (below-round-off-p after (funcall tolerance next))
                          (bisect-crossing function time next)
                          (round-off-crossing function time next step tolerance))))
                   ((and before after (>= before 0) (>= after 0) rate-before rate-after
                         (< rate-before 0) (> rate-after 0))
                    (let ((dip (dip-crossing function rate time next)))
                      (when dip
                        (return-from first-numeric-crossing
                          (if (below-round-off-p (funcall function dip) (funcall tolerance dip))
                              (bisect-crossing function time dip)
                              (list :round-off dip)))))))
             (when (and horizon (>= next horizon))
               (return-from first-numeric-crossing nil))
             (setf time next before after rate-before rate-after))
    nil))

(defparameter *geometric-root-grid* '(1d-6 1.001d0 1d6)
  "The grid of times the search follows where the functions have no period: (FIRST
RATIO LAST), about 23,000 times from 1e-6 growing by 0.1% a step.")

(defun first-geometric-crossing (function horizon &optional (tolerance (constantly 0d0)))
  "The first TAU > 0 (up to HORIZON, or the grid's end) on *GEOMETRIC-ROOT-GRID* where
FUNCTION of TAU goes from >= 0 to < 0, bisected to double precision, or NIL; (:ROUND-OFF
TAU) when it is below zero only within round-off there (TOLERANCE, as for
FIRST-NUMERIC-CROSSING) and not beyond it at the next grid time. A dip that
starts and ends between two grid times is missed, as by the numeric integrator's own
event search; the search ends where FUNCTION has no value."
  (destructuring-bind (first ratio last) *geometric-root-grid*
    (let ((previous 0d0) (before (funcall function 0d0))
          (last (if horizon (min last horizon) last)))
      (loop for time = first then (min (* time ratio) last)
            for value = (funcall function time)
            do (cond ((null value) (return nil))
                     ((and before (>= before 0) (< value 0)
                           (not (jump-below-zero-p function (bisect-crossing function previous time) before)))
                      (return (if (below-round-off-p value (funcall tolerance time))
                                  (bisect-crossing function previous time)
                                  (round-off-crossing function previous time
                                                      (- (min (* time ratio) last) time) tolerance)))))
               (when (>= time last) (return nil))
               (setf previous time before value)))))

(defun condition-crossing-functions (run solved groups condition)
  "CONDITION's event functions of TAU alone (see NUMERIC-EVENT-FUNCTIONS: one per part
of an OR, a contact's gap only within its extent), and the rate of its violation
function (NIL for an OR)."
  (let ((bindings (numeric-bindings run)))
    (values (mapcar (lambda (event) (lambda (time) (funcall event #() time)))
                    (numeric-event-functions run solved groups '() condition))
            (unless (eq (first (ames.engine:termination-condition-relation condition)) 'or)
              (let ((f (numeric-function
                        (substitute-expressions
                         bindings (time-derivative (condition-time-function run solved groups condition)))
                        '(tau))))
                (lambda (time) (safe-value f (vector time))))))))

(defun trigonometric-placeholders (expression)
  "EXPRESSION with each sine and cosine of an argument in TAU replaced by a fresh
symbol, and the list of those symbols."
  (let ((symbols '()))
    (labels ((walk (x)
               (cond ((atom x) x)
                     ((and (member (first x) '(sin cos)) (not (free-of-p 'tau (second x))))
                      (let ((symbol (gensym (symbol-name (first x)))))
                        (push symbol symbols)
                        symbol))
                     (t (cons (first x) (mapcar #'walk (rest x)))))))
      (let ((replaced (walk expression)))
        (values replaced (nreverse symbols))))))

(defun envelope-reach (run expression)
  "A time after which EXPRESSION, a function of TAU, does not cross zero from above, when
it is a polynomial P(TAU) of degree at most 2 plus sines and cosines of TAU with
constant coefficients b_i, and either P - sum |b_i| (below EXPRESSION) becomes positive
for ever, or P + sum |b_i| (above it) is negative for every TAU >= 0 (then 0). NIL
otherwise (the decomposition is checked on numbers)."
  (multiple-value-bind (replaced symbols) (trigonometric-placeholders expression)
    (let* ((f (handler-case (numeric-function (substitute-expressions (numeric-bindings run) replaced)
                                              (cons 'tau symbols))
                (error () nil)))
           (n (length symbols)))
      (when (and f symbols)
        (flet ((at (time &optional index (value 1d0))
                 (let ((v (make-array (1+ n) :initial-element 0d0)))
                   (setf (svref v 0) (coerce time 'double-float))
                   (when index (setf (svref v (1+ index)) value))
                   (safe-value f v))))
          (let* ((p0 (at 0)) (p1 (at 1)) (p2 (at 2)) (p3 (at 3))
                 (coefficients (loop for i below n
                                     collect (let ((a (and p0 (at 0 i))) (b (and p1 (at 1 i)))
                                                   (c (and p0 (at 0 i 2d0))))
                                               (and a b c
                                                    (< (abs (- (- a p0) (- b p1))) 1d-9)
                                                    (< (abs (- (- c p0) (* 2 (- a p0)))) 1d-9)
                                                    (- a p0))))))
            (when (and p0 p1 p2 p3 (every #'realp coefficients)
                       ;; a polynomial of degree at most 2: third differences vanish
                       (< (abs (- p3 (* 3 p2) (* -3 p1) p0)) (* 1d-9 (max 1d0 (abs p3)))))
              (let* ((size (reduce #'+ (mapcar #'abs coefficients)))
                     ;; linear in TAU (its derivative free of TAU, the sines and cosines
                     ;; held fixed): no square term, whatever the rounding says
                     (c2 (if (free-of-p 'tau (ames.geometry:differentiate replaced 'tau))
                             0d0
                             (/ (+ p2 (* -2 p1) p0) 2)))
                     (c1 (- p1 p0 c2)) (c0 (- p0 size)))
                ;; c0 + c1 t + c2 t^2 > 0 for every t beyond the returned time
                (cond ((plusp c2)
                       (let ((discriminant (- (* c1 c1) (* 4 c2 c0))))
                         (if (< discriminant 0) 0d0
                             (max 0d0 (/ (+ (- c1) (sqrt discriminant)) (* 2 c2))))))
                      ((and (zerop c2) (> c1 0)) (max 0d0 (/ (- c0) c1)))
                      ((and (zerop c2) (zerop c1) (> c0 0)) 0d0)
                      ;; below zero for ever (its upper envelope P + sum |b_i| is): it
                      ;; never crosses from above
                      ((and (<= c2 0) (<= c1 0) (< (+ p0 size) 0)) 0d0))))))))))

(defun closed-form-numeric-candidates (run solved groups conditions horizon)
  "For CONDITIONS over closed-form motion whose earliest root has no closed form (see the
file header): (values CANDIDATES UNFIRED), CANDIDATES those that fire first, at a numeric
time no later than HORIZON (a number or NIL), with their impact events when reached with
a velocity; UNFIRED the conditions not found firing when there is no HORIZON and none
fires within the search's reach."
  (let ((step (sampling-step run solved groups conditions))
        (horizon (and horizon (coerce horizon 'double-float)))
        (found '()) (unfired '()) (touched '()))
    (dolist (condition conditions)
      (multiple-value-bind (functions rate) (condition-crossing-functions run solved groups condition)
        (let* ((reach (let ((reach (and (not (eq (first (ames.engine:termination-condition-relation condition)) 'or))
                                        (envelope-reach run (condition-time-function run solved groups condition)))))
                        ;; proven only as far as the search goes
                        (and reach (< reach (* (1- *root-search-steps*) step)) reach)))
               ;; past REACH it is positive for ever: searched up to there, never is proven
               (until (if (and horizon reach) (min horizon (+ reach step)) (or horizon (and reach (+ reach step)))))
               (tolerance (crossing-tolerance run solved groups condition))
               (times (if (guarded-relation-parts (ames.engine:termination-condition-relation condition))
                          ;; a corner's touching within its face: guarded-meetings.lisp
                          (let ((crossing (guarded-numeric-crossing run solved groups condition rate step until)))
                            (and crossing (list crossing)))
                          (loop for function in functions
                            for crossing = (if step
                                               (first-numeric-crossing
                                                function (or rate (constantly nil)) step until tolerance)
                                               ;; no period: a geometric grid of times
                                               (first-geometric-crossing function until tolerance))
                            when crossing collect crossing)))
               ;; (:ROUND-OFF TAU): zero there to round-off, no sign change proven
               (touches (mapcar #'second (remove-if-not #'consp times)))
               (touch (and touches (reduce #'min touches)))
               (crossings (remove-if-not #'realp times))
               (time (and crossings (reduce #'min crossings))))
          (cond ((and time (plusp time) (or (null touch) (< time touch)))
                 (push (list condition time (and rate (funcall rate time))) found))
                ((and touch (plusp touch)) (push (list condition touch) touched))
                ((and (null horizon) (null reach)) (push condition unfired))))))
    (let ((earliest (loop for (nil time) in found minimize time)))
      (values (loop for (condition time rate) in found
                    when (<= (- time earliest) (* 1d-9 (max 1d0 earliest)))
                      collect (let ((impact (and rate (< rate (- (* 1d-9 (max 1d0 (abs rate))))) rate)))
                                (make-candidate condition (condition-event condition impact) time
                                                :rate (or impact 0))))
              ;; searched past the earliest crossing found, they do not fire before it;
              ;; one that touches zero within round-off no later than it stays undecided
              (append (and (null found) (nreverse unfired))
                      (loop for (condition time) in (reverse touched)
                            when (or (null found) (<= time earliest)) collect condition))))))

(defun add-numeric-roots (run solved groups rooted candidates unknown)
  "CANDIDATES and UNKNOWN (see CANDIDATES-OF) with the conditions of ROOTED, a list of
(CONDITION . FACT) whose earliest root has no closed form, searched with numbers up to
the earliest of CANDIDATES: those that fire first join CANDIDATES; those that do not
fire before it are left out; with no earlier candidate, those not found stay UNKNOWN."
  (if (null rooted)
      (values candidates unknown)
      (let* ((limit (time-limit-candidate run))
             (times (loop for c in (append candidates (and limit (list limit)))
                          for time = (numeric-time run (candidate-time c))
                          when time collect time))
             (horizon (and times (reduce #'min times))))
        (multiple-value-bind (found unfired)
            (closed-form-numeric-candidates run solved groups (mapcar #'car rooted) horizon)
          (values (append found candidates)
                  (append unknown
                          (loop for condition in unfired
                                collect (list (cdr (assoc condition rooted))
                                              (condition-event condition nil)))))))))

;;; The end of a state ended by such a root

(defun closed-form-in-time-p (groups)
  "True when every group of GROUPS has a closed form in TAU."
  (every (lambda (group) (member (group-kind group) '(:constant :linear :speed-line))) groups))

(defun numeric-root-end-p (groups fired)
  "True when the FIRED candidates were found by the numeric root search (numeric times)
and every group has a closed form in TAU."
  (and fired
       (every (lambda (candidate) (floatp (candidate-time candidate))) fired)
       (closed-form-in-time-p groups)))

(defun end-values (run groups fired what)
  "Every body's position (WHAT :POS) or velocity (:VEL) at the end of the state: see
FINAL-VALUES; at a numeric time (NUMERIC-ROOT-END-P), or when the closed forms there are
too large for Maxima to simplify within a request while every parameter has a number,
their numbers (NUMERIC-ROOT-FINAL-VALUES)."
  (if (numeric-root-end-p groups fired)
      (numeric-root-final-values run groups fired what)
      (handler-case (final-values run groups fired what)
        ((or ames.maxima:maxima-timeout ames.maxima:maxima-output-overflow) (condition)
          (if (and (run-numbers-known-p run) (closed-form-in-time-p groups)
                   (numeric-time run (candidate-time (first fired))))
              (numeric-root-final-values run groups fired what)
              (error condition))))))

(defun flat-gap-normal (run contact positions)
  "For CONTACT, whose gap is linear in the relative position (a face), the gap at
POSITIONS (an alist body -> (X Y)) and its gradient (NX NY); NIL for a curved one."
  (destructuring-bind (observer obstacle) (contact-bodies run contact)
    (let* ((q (ames.geometry:v- (second (assoc observer positions)) (second (assoc obstacle positions))))
           (geometry (contact-geometry run contact))
           (gap (lambda (dx dy)
                  (tidy run (ames.geometry:meeting-gap
                             (ames.geometry:contact-meeting geometry (ames.geometry:v+ q (list dx dy)))))))
           (g (funcall gap 0 0))
           (nx (tidy run `(- ,(funcall gap 1 0) ,g)))
           (ny (tidy run `(- ,(funcall gap 0 1) ,g))))
      (when (and (eql 0 (tidy run `(- ,(funcall gap 2 0) (* 2 ,nx) ,g)))
                 (eql 0 (tidy run `(- ,(funcall gap 0 2) (* 2 ,ny) ,g))))
        (values g (list nx ny))))))

(defun snap-onto-contacts (run positions fired)
  "POSITIONS with, for each FIRED candidate's contact with a face, the observer (or the
obstacle when the observer is fixed) moved along the face's normal by the gap left
there (rounding of the numeric time: about 1e-15), so that the next state finds the two
bodies exactly in contact."
  (dolist (candidate fired positions)
    (let ((contact (and (candidate-condition candidate)
                        (gap-relation-contact (ames.engine:termination-condition-relation
                                               (candidate-condition candidate))))))
      (when contact
        (multiple-value-bind (gap normal) (flat-gap-normal run contact positions)
          (when (and gap (not (eql gap 0)))
            (destructuring-bind (observer obstacle) (contact-bodies run contact)
              (let* ((moved (if (body-fixed-p run observer) obstacle observer))
                     (sign (if (eq moved observer) -1 1))
                     (scale `(/ (* ,sign ,gap) ,(ames.geometry:dot normal normal)))
                     (entry (assoc moved positions)))
                (setf positions
                      (substitute (list moved (mapcar (lambda (x n) (tidy run `(+ ,x (* ,scale ,n))))
                                                      (second entry) normal))
                                  entry positions))))))))))

(defun numeric-root-final-values (run groups fired what)
  "Every body's position (WHAT :POS) or velocity (:VEL) at the numeric time of FIRED:
its closed form evaluated there, carried over as exact rationals (see RATIONAL-OF), the
positions put exactly on the contacts reached (SNAP-ONTO-CONTACTS)."
  (let* ((time (coerce (numeric-time run (candidate-time (first fired))) 'double-float))
         (bindings (numeric-bindings run))
         (values (mapcar (lambda (body)
                           (list body
                                 (if (body-fixed-p run body)
                                     (body-motion run groups body what)
                                     (mapcar (lambda (x)
                                               (rational-of
                                                (funcall (numeric-function
                                                          (substitute-expressions bindings x) '(tau))
                                                         (vector time))))
                                             (body-motion run groups body what)))))
                         (body-names run))))
    (valued-end-values ; numbers at the run's values: numeric-ends.lisp
     run (cond ((not (eq what :pos)) values)
               ((run-rotations run)
                (snap-corners-onto-faces run (snap-onto-contacts run values fired)
                                         (rotation-final-values run groups fired 'ames.kb:angle) fired))
               (t (snap-onto-contacts run values fired))))))
