;;;; src/simulator/horizon-phase.lisp -- the broad phase up to a state's horizon: contacts
;;;; between bodies that do not touch, proven out of reach before an event that surely ends
;;;; the state, are not screened.
;;;;
;;;; The broad phase (broad-phase.lisp) proves a contact out of reach for every tau > 0. Two
;;;; bodies that roll or slide side by side, each on its own support, drift toward each
;;;; other's supports without bound, so it cannot; their meeting times are then worked out
;;;; in full (earliest roots of quartics over the parameters, the costliest requests of a
;;;; run), though each state ends long before: the disc leaves its slope at its foot. A
;;;; candidate that fires at a time T in closed form bounds the state: it ends at T at the
;;;; latest. A contact whose observer stays, along one axis, strictly on one side of its
;;;; locus for every tau in (0, T] cannot end the state, nor be met in it.
;;;;
;;;; Along an axis the relative coordinate minus a bound of the locus is f(tau) = c0 + c1 tau
;;;; + c2 tau^2 (broad-phase.lisp's coefficients). On [0, T], f lies between f(0) and f(T)
;;;; when c1 and c2 have one weak sign (f monotone), and above the lesser of them when it
;;;; is concave toward the side kept (c2 weakly opposite to it). So f keeps the strict side
;;;; on (0, T] when f(0) and f(T) do and one of those holds. Convex with c1 toward the
;;;; locus (a body overtaking another that speeds up), its least value on [0, T] is f(T)
;;;; while its rate c1 + 2 c2 T is still toward the locus, else at most f's vertex,
;;;; c0 - c1^2 / (4 c2): either of those of the side kept will do. The signs of c1 and c2 are the
;;;; broad phase's, else the algebra's (two bodies both rolling down, one faster than the
;;;; other: the sign of the difference); f(0)'s cheaply else by the algebra, f(T)'s by the algebra under the
;;;; run's facts (the scenario's assumptions: the second incline far enough). Only what is
;;;; proven is set aside; a pair that touches (a contact holding between them) is screened
;;;; as before, and the conditions keep their order (the candidates, the undecided facts).

(in-package #:ames.simulator)

(defparameter *horizon-tries* 2
  "The most candidates' times the horizon phase tries as the state's bound.")

(defun touching-pairs (run)
  "The pairs of bodies (A B) between which a contact holds in the current model."
  (loop for contact in (active-contacts run)
        when contact collect (contact-bodies run contact)))

(defun horizon-deferrable-p (run reach relation touching)
  "True when RELATION is the meeting of a contact between two bodies that do not touch
(none of TOUCHING, pairs), both moving with constant accelerations or fixed: the horizon
phase may set it aside."
  (let ((contact (gap-relation-contact relation)))
    (and contact
         (not (assoc contact (run-locus-kinds run)))
         (let ((bodies (contact-bodies run contact)))
           (and (notany (lambda (pair) (or (equal pair bodies) (equal pair (reverse bodies))))
                        touching)
                (every (lambda (body)
                         (every (lambda (axis) (listp (body-coefficients reach body axis)))
                                '(:x :y)))
                       bodies))))))

(defun horizon-times (candidates)
  "The times in closed form of at most *HORIZON-TRIES* of CANDIDATES: each bounds the
state's end."
  (let ((times (loop for candidate in candidates
                     for time = (candidate-time candidate)
                     unless (and (consp time) (keywordp (first time)))
                       collect time)))
    (subseq times 0 (min (length times) *horizon-tries*))))

(defun strict-side-p (run reach expression side)
  "True when EXPRESSION is proven strictly of SIDE (:POSITIVE or :NEGATIVE): cheaply, else
by the algebra."
  (or (eq (one-sign (cheap-sign reach expression)) side)
      (holds run (if (eq side :positive) `(> ,expression 0) `(< ,expression 0)))))

(defun rate-difference-sign (run reach a b)
  "The sign set of A - B, two bodies' rate coefficients: the broad phase's
(DIFFERENCE-SIGN), else the algebra's (two bodies both accelerating one way, one faster)."
  (let ((signs (difference-sign reach a b)))
    (if (known-signs-p signs) signs (sign-of run `(- ,a ,b)))))

(defun apart-until-p (run reach offsets c1 c2 signs horizon side)
  "True when each of OFFSETS + C1 tau + C2 tau^2 keeps the strict SIDE for tau in (0,
HORIZON]: of SIDE at 0, and, as SIGNS (those of C1 and C2) shape it, at HORIZON where it
is monotone or concave toward SIDE, or where it is convex and still heading away from
SIDE at HORIZON (its least distance there), or at its vertex (see the file header)."
  (destructuring-bind (s1 s2) signs
    (let ((toward (if (eq side :positive) :negative :positive)))
      (flet ((weak (s sign) (ames.algebra:only-signs-p s sign :zero))
             (holds-side (expression) (strict-side-p run reach expression side))
             (at-horizon (offset) `(+ ,offset (* ,c1 ,horizon) (* ,c2 (expt ,horizon 2)))))
        (and (every #'holds-side offsets)
             (cond ((or (and (weak s1 side) (weak s2 side)) (weak s2 toward))
                    (every (lambda (offset) (holds-side (at-horizon offset))) offsets))
                   ((and (weak s1 toward) (eq (one-sign s2) side))
                    ;; convex, heading toward the locus first: its least value on
                    ;; [0, HORIZON] is at HORIZON while the rate is still toward it there,
                    ;; else at its vertex, OFFSET - C1^2 / (4 C2)
                    (every (lambda (offset)
                             (or (and (strict-side-p run reach `(+ ,c1 (* 2 ,c2 ,horizon))
                                                     toward)
                                      (holds-side (at-horizon offset)))
                                 (holds-side `(- ,offset (/ (expt ,c1 2) (* 4 ,c2))))))
                           offsets))))))))

(defun out-of-reach-until-p (run reach contact horizon)
  "True when the observer of CONTACT is proven, along one axis, strictly on one side of
the contact's locus for every tau in (0, HORIZON] (see the file header)."
  (let ((geometry (contact-geometry run contact)))
    (destructuring-bind (observer obstacle) (contact-bodies run contact)
      (dolist (axis '(:x :y) nil)
        (let ((a (body-coefficients reach observer axis))
              (b (body-coefficients reach obstacle axis))
              (bounds (locus-bounds geometry axis)))
          (when (and bounds (listp a) (listp b))
            (let* ((c1 `(- ,(second a) ,(second b)))
                   (c2 `(- ,(third a) ,(third b)))
                   (signs (list (rate-difference-sign run reach (second a) (second b))
                                (rate-difference-sign run reach (third a) (third b))))
                   (offsets (mapcar (lambda (bound) `(- (- ,(first a) ,(first b)) ,bound)) bounds))
                   ;; the side the observer starts on, from the first bound
                   (side (cond ((strict-side-p run reach (first offsets) :positive) :positive)
                               ((strict-side-p run reach (first offsets) :negative) :negative))))
              (when (and side (apart-until-p run reach offsets c1 c2 signs horizon side))
                (return t)))))))))

(defun beyond-horizon-p (run reach relation horizons)
  "True when the meeting RELATION (a contact's gap) is proven out of reach until one of
HORIZONS, times at which the state surely ends at the latest."
  (let ((contact (gap-relation-contact relation)))
    (some (lambda (horizon) (out-of-reach-until-p run reach contact horizon)) horizons)))

(defun condition-results (run reach conditions result-of)
  "A hash table CONDITION -> its result (see CONDITION-RESULT, which RESULT-OF computes) for
each of CONDITIONS: first those that are no meeting of bodies that do not touch, then
those, each set aside as (:NEVER) when it is proven out of reach until the time of one
of the first ones' candidates (BEYOND-HORIZON-P)."
  (let ((results (make-hash-table :test #'eq))
        (touching (touching-pairs run))
        (deferred '()))
    (dolist (condition conditions)
      (if (horizon-deferrable-p run reach (ames.engine:termination-condition-relation condition)
                                touching)
          (push condition deferred)
          (setf (gethash condition results) (funcall result-of condition))))
    (when deferred
      (let ((horizons (horizon-times
                       (loop for condition in conditions
                             for result = (first (gethash condition results))
                             when (candidate-p result) collect result))))
        (dolist (condition (reverse deferred))
          (setf (gethash condition results)
                (if (and horizons
                         (beyond-horizon-p run reach (ames.engine:termination-condition-relation condition)
                                           horizons))
                    (list :never)
                    (funcall result-of condition))))))
    results))
