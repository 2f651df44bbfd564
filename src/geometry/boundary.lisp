;;;; src/geometry/boundary.lisp -- does a closed boundary cross itself? A sweep for numeric polygons, pairs otherwise.
;;;;
;;;; A polygon or outline must not cross or touch itself away from the joints of
;;;; consecutive pieces. Trying every pair of pieces is quadratic: a thousand vertices took
;;;; half a minute, ten thousand an hour. When every piece is a line piece with numeric
;;;; ends, the crossing is found by the sweep of Shamos and Hoey in exact rational
;;;; arithmetic (the ends taken as exact rationals, floats included):
;;;;   - a vertex met twice is a touching (found first, by hashing the vertices);
;;;;   - events are the segments' ends, in lexicographic order (x, then y), a segment
;;;;     entering at its smaller end and leaving at its larger; at one point, entries come
;;;;     before exits;
;;;;   - the status holds the segments the sweep line cuts, ordered by the height at which
;;;;     they cut it (ties: by slope, a vertical segment above all); an entering segment is
;;;;     tested against its neighbours, and a leaving one's neighbours against each other;
;;;;     a segment found to pass through the entry point of another is a touching at once.
;;;; Every pair of segments that is ever next in the status is tested, and until the first
;;;; crossing the order is right, so the first crossing in the sweep's order is found.
;;;; The sweep makes O(n log n) comparisons; the status is a vector, so entries and exits
;;;; also move O(k) elements for a status of k segments (k is small for real shapes).
;;;; Pairs of consecutive pieces are left to the caller, which checks them on their own.
;;;; The pair the sweep finds is confirmed by the exact test of PIECES-CROSS-P. Arcs and
;;;; symbolic pieces are tested pair by pair, within the budget of the run.

(in-package #:ames.geometry)

(defun exact-coordinate (x)
  "X as an exact rational when it is a number (a float is taken exactly), else NIL."
  (and (realp x) (rational x)))

(defun exact-point (v)
  "The vector V as a cons (X . Y) of exact rationals, or NIL when it is not numeric."
  (let ((x (exact-coordinate (vx v))) (y (exact-coordinate (vy v))))
    (and x y (cons x y))))

(defun point< (p q)
  "True when the point P comes before Q in lexicographic order (x, then y)."
  (or (< (car p) (car q)) (and (= (car p) (car q)) (< (cdr p) (cdr q)))))

(defun orientation (a b c)
  "The sign (-1, 0 or 1) of the turn A -> B -> C (1: counter-clockwise)."
  (signum (- (* (- (car b) (car a)) (- (cdr c) (cdr a)))
             (* (- (cdr b) (cdr a)) (- (car c) (car a))))))

(defun between-p (a b c)
  "True when C, collinear with A and B, lies on the closed segment AB."
  (and (<= (min (car a) (car b)) (car c) (max (car a) (car b)))
       (<= (min (cdr a) (cdr b)) (cdr c) (max (cdr a) (cdr b)))))

(defun segments-meet-p (a b c d)
  "True when the closed segments AB and CD have a point in common."
  (let ((o1 (orientation a b c)) (o2 (orientation a b d))
        (o3 (orientation c d a)) (o4 (orientation c d b)))
    (or (and (/= o1 o2) (/= o3 o4))
        (and (zerop o1) (between-p a b c))
        (and (zerop o2) (between-p a b d))
        (and (zerop o3) (between-p c d a))
        (and (zerop o4) (between-p c d b)))))

(defstruct (sweep-segment (:constructor make-sweep-segment (index left right)))
  "Piece INDEX as a segment from its LEFT end to its RIGHT end (lexicographic order)."
  index left right)

(defun height-at (segment x y)
  "The height at which SEGMENT cuts the vertical line at X; for a vertical SEGMENT, Y
clamped to its extent (the point of it nearest (X, Y))."
  (let ((l (sweep-segment-left segment)) (r (sweep-segment-right segment)))
    (if (= (car l) (car r))
        (max (cdr l) (min (cdr r) y))
        (+ (cdr l) (/ (* (- x (car l)) (- (cdr r) (cdr l))) (- (car r) (car l)))))))

(defun slope-key (segment)
  "SEGMENT's slope, or NIL for a vertical one (which ranks above every slope)."
  (let ((l (sweep-segment-left segment)) (r (sweep-segment-right segment)))
    (and (/= (car l) (car r)) (/ (- (cdr r) (cdr l)) (- (car r) (car l))))))

(defun slope< (a b)
  "True when segment A's slope is below B's (vertical is highest; ties by index)."
  (let ((sa (slope-key a)) (sb (slope-key b)))
    (cond ((and sa sb (/= sa sb)) (< sa sb))
          ((and sa (null sb)) t)
          ((and sb (null sa)) nil)
          (t (< (sweep-segment-index a) (sweep-segment-index b))))))

(defun boundary-sweep (segments adjacent-p)
  "The indices (I J) of two segments of SEGMENTS (SWEEP-SEGMENTs) that ADJACENT-P (of
two indices) calls not adjacent and that have a point in common, or NIL when there are
none. See the file header."
  (let ((events '())
        (status (make-array 16 :adjustable t :fill-pointer 0)))
    (dolist (s segments)
      (push (list (sweep-segment-left s) 0 s) events)
      (push (list (sweep-segment-right s) 1 s) events))
    (setf events (sort events (lambda (a b)
                                (cond ((point< (first a) (first b)) t)
                                      ((point< (first b) (first a)) nil)
                                      (t (< (second a) (second b)))))))
    (labels ((meet (a b)
               (when (and a b
                          (not (funcall adjacent-p (sweep-segment-index a) (sweep-segment-index b)))
                          (segments-meet-p (sweep-segment-left a) (sweep-segment-right a)
                                           (sweep-segment-left b) (sweep-segment-right b)))
                 (return-from boundary-sweep
                   (sort (list (sweep-segment-index a) (sweep-segment-index b)) #'<))))
             (at (i) (and (<= 0 i) (< i (fill-pointer status)) (aref status i)))
             (below-p (s other point)
               ;; S, entering at POINT, goes below OTHER (in the status)?
               (let ((h (height-at other (car point) (cdr point))))
                 (cond ((< (cdr point) h) t)
                       ((> (cdr point) h) nil)
                       (t (meet s other) ; the entry point lies on OTHER
                          (slope< s other)))))
             (insert (s)
               (let ((point (sweep-segment-left s)) (low 0) (high (fill-pointer status)))
                 (loop while (< low high)
                       do (let ((middle (floor (+ low high) 2)))
                            (if (below-p s (aref status middle) point)
                                (setf high middle)
                                (setf low (1+ middle)))))
                 (vector-push-extend s status)
                 (replace status status :start1 (1+ low) :start2 low
                                        :end2 (1- (fill-pointer status)))
                 (setf (aref status low) s)
                 (meet s (at (1- low)))
                 (meet s (at (1+ low)))))
             (remove-segment (s)
               (let ((i (position s status :test #'eq)))
                 (when i
                   (let ((below (at (1- i))) (above (at (1+ i))))
                     (replace status status :start1 i :start2 (1+ i))
                     (decf (fill-pointer status))
                     (meet below above))))))
      (dolist (event events nil)
        (check-budget segments)
        (if (zerop (second event))
            (insert (third event))
            (remove-segment (third event)))))))

(defun repeated-vertex (points)
  "The indices (I J), I < J, of two equal points of the list POINTS, or NIL."
  (let ((seen (make-hash-table :test 'equal)))
    (loop for point in points
          for i from 0
          do (let ((earlier (gethash point seen)))
               (when earlier (return (list earlier i)))
               (setf (gethash point seen) i)))))

(defun numeric-boundary-crossing (pieces)
  "For a closed chain PIECES (a vector) of line pieces with numeric ends: (values
CROSSING T), CROSSING being the indices (I J) of two pieces, not consecutive, that have
a point in common, or NIL when none do. (values NIL NIL) when the chain is not all
numeric line pieces (the sweep does not apply)."
  (let ((n (length pieces)))
    (unless (every (lambda (piece) (and (line-piece-p piece) (not (line-piece-infinite piece))))
                   pieces)
      (return-from numeric-boundary-crossing (values nil nil)))
    (let ((starts (map 'list (lambda (piece) (exact-point (line-piece-start piece))) pieces))
          (ends (map 'list (lambda (piece) (exact-point (line-piece-end piece))) pieces)))
      (unless (and (every #'identity starts) (every #'identity ends))
        (return-from numeric-boundary-crossing (values nil nil)))
      (flet ((adjacent-p (i j)
               (member (mod (- i j) n) (list 1 (1- n)))))
        (let ((repeated (repeated-vertex starts)))
          (when repeated
            ;; vertex J starts piece J and ends piece J - 1: both touch piece I
            (destructuring-bind (i j) repeated
              (return-from numeric-boundary-crossing
                (values (if (adjacent-p i j) (list i (mod (1- j) n)) (list i j)) t)))))
        (values (boundary-sweep
                 (loop for start in starts for end in ends for i from 0
                       collect (if (point< start end)
                                   (make-sweep-segment i start end)
                                   (make-sweep-segment i end start)))
                 #'adjacent-p)
                t)))))

(defun pairwise-boundary-crossing (decider pieces)
  "The indices (I J) of the first pair of pieces of the closed chain PIECES (a vector),
not consecutive, that have a point in common (decided through DECIDER), or NIL."
  (let ((n (length pieces)))
    (loop for i below n
          do (loop for j from (+ i 2) below n
                   unless (and (zerop i) (= j (1- n)))
                     do (check-budget pieces)
                        (when (pieces-cross-p decider (aref pieces i) (aref pieces j))
                          (return-from pairwise-boundary-crossing (list i j)))))))

(defun boundary-crossing (decider pieces)
  "The indices (I J) of two pieces of the closed chain PIECES (a vector of more than
three pieces), not consecutive, that have a point in common, or NIL when there are none:
found by the sweep for numeric line pieces (and confirmed by PIECES-CROSS-P), else pair
by pair through DECIDER. Signals BUDGET-EXCEEDED when the run's deadline passes."
  (multiple-value-bind (crossing applies) (numeric-boundary-crossing pieces)
    (cond ((not applies) (pairwise-boundary-crossing decider pieces))
          ((null crossing) nil)
          ((pieces-cross-p decider (aref pieces (first crossing)) (aref pieces (second crossing)))
           crossing)
          ;; the exact sweep and the decider disagree (floats near a touching): ask the
          ;; decider about every pair
          (t (pairwise-boundary-crossing decider pieces)))))
