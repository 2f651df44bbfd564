;;;; src/geometry/vectors.lisp -- plane vectors of expressions, directions and angular ranges.
;;;;
;;;; AMES's one toolkit of plane vectors (exported): the simulator and the knowledge base
;;;; build their dot and cross products with it, and the report its points of a drawing
;;;; (numbers are expressions too: the sums and products fold them as CL does).
;;;; A vector is a list (X Y) of prefix expressions. A DIRECTION is a non-zero vector
;;;; (not necessarily of unit length) with, optionally, the angle expression it makes
;;;; with +x. An ANGULAR-RANGE is the set of directions swept counter-clockwise from
;;;; FROM up to TO: half-open [FROM, TO) unless stated otherwise, or the FULL circle.
;;;; Ranges hold the outward normals of boundary features (the Gauss map): a convex
;;;; corner's cone, an arc's normals.

(in-package #:ames.geometry)

;;; Vectors

(defun vec (x y) "The vector (X, Y)." (list x y))
(defun vx (v) "The x component of V." (first v))
(defun vy (v) "The y component of V." (second v))
(defun v+ (&rest vs) "The sum of the vectors VS."
  (vec (apply #'e+ (mapcar #'vx vs)) (apply #'e+ (mapcar #'vy vs))))
(defun v- (a b) "A - B." (vec (e- (vx a) (vx b)) (e- (vy a) (vy b))))
(defun vneg (a) "-A." (vec (e- (vx a)) (e- (vy a))))
(defun vscale (k a) "K times A." (vec (e* k (vx a)) (e* k (vy a))))
(defun vdiv (a k) "A divided by K." (vec (e/ (vx a) k) (e/ (vy a) k)))
(defun dot (a b) "The scalar product of A and B." (e+ (e* (vx a) (vx b)) (e* (vy a) (vy b))))
(defun cross (a b) "The z component of A x B: positive when B is counter-clockwise of A."
  (e- (e* (vx a) (vy b)) (e* (vy a) (vx b))))
(defun rot-cw (a) "A turned a quarter turn clockwise." (vec (vy a) (e- (vx a))))
(defun rot-ccw (a) "A turned a quarter turn counter-clockwise." (vec (e- (vy a)) (vx a)))
(defun norm-squared (a) "|A|^2." (dot a a))
(defun vmid (a b) "The midpoint of A and B." (vscale 1/2 (v+ a b)))
(defun polar (angle) "The unit vector at ANGLE." (vec (ecos angle) (esin angle)))

(defun vector-equal-p (decider a b)
  "True when A and B are the same vector (decided)."
  (and (zero-p decider (e- (vx a) (vx b)))
       (zero-p decider (e- (vy a) (vy b)))))

(defun vector-known-equal-p (decider a b)
  "True when A and B are known to be the same vector; NIL when they differ or when it
cannot be decided (never signals). Rational vectors are compared at once."
  (if (and (rationalp (vx a)) (rationalp (vy a)) (rationalp (vx b)) (rationalp (vy b)))
      (and (= (vx a) (vx b)) (= (vy a) (vy b)))
      (and (fact-known-p decider (list '= (vx a) (vx b)))
           (fact-known-p decider (list '= (vy a) (vy b))))))

(defun unit-vector (decider v)
  "V divided by its length. Axis-aligned vectors give exact unit vectors (deciding the
sign of their one non-zero component); others divide by (SQRT |V|^2)."
  (cond ((eql (vx v) 0)
         (vec 0 (if (positive-p decider (vy v)) 1 -1)))
        ((eql (vy v) 0)
         (vec (if (positive-p decider (vx v)) 1 -1) 0))
        (t (let ((length (esqrt (norm-squared v))))
             (vdiv v length)))))

(defun vector-length (v)
  "The length of V as an expression."
  (cond ((eql (vx v) 0) (let ((y (rational-value (vy v)))) (if y (abs y) (esqrt (norm-squared v)))))
        ((eql (vy v) 0) (let ((x (rational-value (vx v)))) (if x (abs x) (esqrt (norm-squared v)))))
        (t (esqrt (norm-squared v)))))

;;; Directions

(defstruct (direction (:constructor %make-direction (vector %angle)))
  "A direction: a non-zero VECTOR and, when known, the angle expression it makes with +x."
  vector %angle)

(defun make-direction (vector &optional angle)
  "The direction of VECTOR, with ANGLE when a nicer expression than (ATAN Y X) is known."
  (%make-direction vector angle))

(defun direction-at-angle (angle)
  "The direction whose angle is ANGLE."
  (%make-direction (polar angle) angle))

(defun direction-angle-slot (direction)
  "The angle expression given for DIRECTION, or NIL."
  (direction-%angle direction))

(defun opposite-direction (direction)
  "The direction opposite DIRECTION."
  (let ((angle (direction-angle-slot direction)))
    (%make-direction (vneg (direction-vector direction))
                     (and angle (e+ angle 'pi)))))

(defun same-direction-p (decider a b)
  "True when the vectors A and B point the same way (parallel, not opposite)."
  (and (zero-p decider (cross a b)) (positive-p decider (dot a b))))

;;; Angular ranges

(defstruct (angular-range (:constructor %make-angular-range (from to full sweep-class)))
  "The directions swept counter-clockwise from FROM to TO (half-open [FROM, TO)), or
every direction when FULL. SWEEP-CLASS caches how wide it is: :EMPTY, :BELOW-PI, :PI,
:ABOVE-PI or :FULL (NIL until decided)."
  from to full sweep-class)

(defun make-angular-range (from to &key full sweep-class)
  "The range of directions counter-clockwise from the direction FROM to the direction TO.
SWEEP-CLASS may be given when known (e.g. :BELOW-PI for a convex corner's cone)."
  (%make-angular-range from to full (if full :full sweep-class)))

(defun full-angular-range (&optional (start (direction-at-angle 0)))
  "Every direction, starting (for parametrization) at START."
  (%make-angular-range start start t :full))

(defun range-sweep-class (decider range)
  "How wide RANGE is: :EMPTY, :BELOW-PI, :PI, :ABOVE-PI or :FULL."
  (or (angular-range-sweep-class range)
      (setf (angular-range-sweep-class range)
            (let* ((a (direction-vector (angular-range-from range)))
                   (b (direction-vector (angular-range-to range)))
                   (c (sign-of decider (cross a b))))
              (case c
                (:positive :below-pi)
                (:negative :above-pi)
                (t (if (positive-p decider (dot a b)) :empty :pi)))))))

(defun range-empty-p (decider range)
  "True when RANGE holds no direction."
  (eq (range-sweep-class decider range) :empty))

(defun direction-in-range-p (decider v range &key closed)
  "True when the vector V's direction lies in RANGE: [FROM, TO), or [FROM, TO] when
CLOSED."
  (let ((from (direction-vector (angular-range-from range)))
        (to (direction-vector (angular-range-to range))))
    (flet ((same (a b) (same-direction-p decider a b))
           (ccw (a b) (positive-p decider (cross a b))))
      (ecase (range-sweep-class decider range)
        (:full t)
        (:empty (and closed (same v from)))
        (:below-pi (or (same v from)
                       (and closed (same v to))
                       (and (ccw from v) (ccw v to))))
        (:pi (or (same v from)
                 (and closed (same v to))
                 (ccw from v)))
        (:above-pi (or (same v from)
                       (and closed (same v to))
                       (not (or (same v to)
                                (and (ccw to v) (ccw v from))))))))))

(defun range-contains-range-end-p (decider x range-start range-end)
  "True when direction X lies in the closed ccw range from RANGE-START to RANGE-END."
  (let ((probe (make-angular-range range-start range-end)))
    (direction-in-range-p decider (direction-vector x) probe :closed t)))

(defun first-reached (decider start b d)
  "Of the directions B and D, the one met first going counter-clockwise from START."
  (if (range-contains-range-end-p decider d start b) d b))

(defun range-intersection (decider r1 r2)
  "The intersection of the half-open ranges R1 and R2: a list of zero, one or two
ranges, in counter-clockwise order from R1's start."
  (cond ((and (angular-range-full r1) (angular-range-full r2)) (list r1))
        ((angular-range-full r1) (if (range-empty-p decider r2) '() (list r2)))
        ((angular-range-full r2) (if (range-empty-p decider r1) '() (list r1)))
        ((or (range-empty-p decider r1) (range-empty-p decider r2)) '())
        (t
         (let ((a (angular-range-from r1)) (b (angular-range-to r1))
               (c (angular-range-from r2)) (d (angular-range-to r2))
               (pieces '()))
           (flet ((piece-from (start)
                    (let* ((end (first-reached decider start b d))
                           (range (make-angular-range start end)))
                      (unless (range-empty-p decider range) range))))
             (when (direction-in-range-p decider (direction-vector a) r2)
               (let ((p (piece-from a))) (when p (push p pieces))))
             (when (and (direction-in-range-p decider (direction-vector c) r1)
                        (not (same-direction-p decider (direction-vector a)
                                               (direction-vector c))))
               (let ((p (piece-from c))) (when p (push p pieces))))
             (nreverse pieces))))))

(defun angle-of-vector (decider v)
  "The angle of the vector V with +x, exact for axis-aligned vectors."
  (cond ((eql (vx v) 0) (e* (if (positive-p decider (vy v)) 1/2 -1/2) 'pi))
        ((eql (vy v) 0) (if (positive-p decider (vx v)) 0 'pi))
        (t (eatan2 (vy v) (vx v)))))

(defun direction-angle-decided (decider direction)
  "The angle expression of DIRECTION: the given one, else computed from its vector."
  (or (direction-angle-slot direction)
      (angle-of-vector decider (direction-vector direction))))

(defun range-sweep (decider range)
  "The angle RANGE sweeps, an expression in [0, 2 PI] (2 PI for the full circle): the
difference of its ends' angles, shifted by a full turn if need be, so that the end of
an arc built on it is exactly at its end direction's angle."
  (let ((class (range-sweep-class decider range)))
    (if (member class '(:full :empty))
        (if (eq class :full) (e* 2 'pi) 0)
        (let* ((a (direction-vector (angular-range-from range)))
               (b (direction-vector (angular-range-to range)))
               (difference (e- (direction-angle-decided decider (angular-range-to range))
                               (direction-angle-decided decider (angular-range-from range)))))
          (flet ((fits (x)
                   (and (fact-known-p decider (list '> x 0))
                        (ecase class
                          (:below-pi (fact-known-p decider (list '< x 'pi)))
                          (:pi (fact-known-p decider (list '= x 'pi)))
                          (:above-pi (and (fact-known-p decider (list '> x 'pi))
                                          (fact-known-p decider (list '< x (e* 2 'pi)))))))))
            (cond ((fits difference) difference)
                  ((fits (e+ difference (e* 2 'pi))) (e+ difference (e* 2 'pi)))
                  ((fits (e- difference (e* 2 'pi))) (e- difference (e* 2 'pi)))
                  (t (ecase class
                       (:below-pi (eatan2 (cross a b) (dot a b)))
                       (:pi 'pi)
                       (:above-pi (e+ (eatan2 (cross a b) (dot a b)) (e* 2 'pi)))))))))))

(defun angle-from-direction (decider from v &key (sense :ccw))
  "The angle, in [0, 2 PI), turned from the direction vector FROM to the vector V,
counter-clockwise (SENSE :CCW) or clockwise (:CW)."
  (multiple-value-bind (c d)
      (if (eq sense :ccw)
          (values (cross from v) (dot from v))
          (values (cross v from) (dot from v)))
    (let ((angle (eatan2 c d)))
      (if (eq (sign-of decider c) :negative)
          (e+ angle (e* 2 'pi))
          angle))))
