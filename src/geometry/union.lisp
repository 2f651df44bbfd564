;;;; src/geometry/union.lisp -- the boundary of a union of convex configuration-space obstacles.
;;;;
;;;; When a body is cut into convex parts, its obstacle is the union of the parts'
;;;; obstacles. Each part's boundary piece is cut wherever another part's boundary meets
;;;; it; a sub-piece stays on the union's boundary unless its midpoint lies inside
;;;; another part, or on another part's boundary facing the opposite way (an internal
;;;; seam, such as a diagonal), or on an identical piece of an earlier part (a duplicate).
;;;; Of two identical pieces, the one made by more faces (an edge of the obstacle against
;;;; an edge of the observer rather than a corner against an edge) is kept, so that a
;;;; flat contact is not split by the cut; among equals, the earlier part's.
;;;; Kept sub-pieces that continue one another with the same features are joined again.

(in-package #:ames.geometry)

(defun unique-parameters (decider parameters)
  "PARAMETERS without (decided) repetitions."
  (let ((kept '()))
    (dolist (p parameters (nreverse kept))
      (unless (some (lambda (k) (zero-p decider (e- p k))) kept)
        (push p kept)))))

(defun sort-parameters (decider parameters)
  "PARAMETERS in increasing order (decided)."
  (let ((sorted '()))
    (dolist (p parameters sorted)
      (setf sorted (merge 'list (list p) sorted
                          (lambda (a b) (fact-holds-p decider (list '< a b))))))))

(defun piece-box (piece)
  "The closed box (XMIN YMIN XMAX YMAX) of exact rationals that holds PIECE (for an arc,
its whole circle), or NIL when PIECE is unbounded or not numeric."
  (flet ((box-of (x y dx dy) (list (- x dx) (- y dy) (+ x dx) (+ y dy))))
    (etypecase piece
      (line-piece
       (let ((a (and (not (line-piece-infinite piece)) (exact-point (line-piece-start piece))))
             (b (exact-point (line-piece-end piece))))
         (and a b (list (min (car a) (car b)) (min (cdr a) (cdr b))
                        (max (car a) (car b)) (max (cdr a) (cdr b))))))
      (arc-piece
       (let ((c (exact-point (arc-piece-center piece)))
             (r (exact-coordinate (arc-piece-radius piece))))
         (and c r (box-of (car c) (cdr c) (abs r) (abs r))))))))

(defun boxes-apart-p (a b)
  "True when the boxes A and B (see PIECE-BOX) are known to have no point in common."
  (and a b
       (or (< (third a) (first b)) (< (third b) (first a))
           (< (fourth a) (second b)) (< (fourth b) (second a)))))

(defun cut-parameters (decider piece others &optional (box-of #'piece-box))
  "The parameters along PIECE where the pieces OTHERS meet it, strictly inside it (for
a full circle, anywhere on it), sorted. Pieces whose numeric boxes (BOX-OF a piece) are
apart from PIECE's are not asked (they cannot meet it)."
  (let* ((end (piece-end-parameter decider piece))
         (full (and (arc-piece-p piece) (arc-piece-full piece)))
         (box (funcall box-of piece))
         (parameters
           (loop for other in others
                 unless (boxes-apart-p box (funcall box-of other))
                 nconc (loop for q in (piece-intersections decider piece other)
                             for p = (piece-parameter decider piece q)
                             when (or full
                                      (and (positive-p decider p)
                                           (fact-holds-p decider (list '< p end))))
                               collect p))))
    (sort-parameters decider (unique-parameters decider parameters))))

(defun split-piece (decider piece cuts)
  "PIECE cut at the sorted parameters CUTS."
  (if (and (arc-piece-p piece) (arc-piece-full piece))
      (if (null cuts)
          (list piece)
          (loop for (a b) on (append cuts (list (e+ (first cuts) (e* 2 'pi))))
                while b collect (sub-piece piece a b)))
      (loop for (a b) on (append (list 0) cuts (list (piece-end-parameter decider piece)))
            while b collect (sub-piece piece a b))))

(defun facing (decider a b)
  "How the normal vectors A and B relate: :SAME, :OPPOSITE or NIL."
  (cond ((not (zero-p decider (cross a b))) nil)
        ((positive-p decider (dot a b)) :same)
        (t :opposite)))

(defun face-rank (sum-piece)
  "How many of the two features along SUM-PIECE are edges."
  (+ (if (eq (first (sum-piece-obstacle-feature sum-piece)) :edge) 1 0)
     (if (eq (first (sum-piece-observer-feature sum-piece)) :edge) 1 0)))

(defun on-union-boundary-p (decider midpoint normal sum-piece part-index parts)
  "True when the point MIDPOINT of a sub-piece of SUM-PIECE, of part PART-INDEX, with
outward NORMAL there, lies on the boundary of the union of PARTS (lists of sum pieces)
and is not a duplicate to be dropped."
  (loop for part in parts
        for b from 0
        never (and (/= b part-index)
                   (or (inside-convex-p decider midpoint (mapcar #'sum-piece-piece part) :strict t)
                       (some (lambda (sp)
                               (let ((q (sum-piece-piece sp)))
                                 (and (point-on-piece-p decider midpoint q)
                                      (case (facing decider normal (piece-outward-normal-at q midpoint))
                                        (:opposite t)
                                        (:same (let ((mine (face-rank sum-piece)) (theirs (face-rank sp)))
                                                 (or (> theirs mine)
                                                     (and (= theirs mine) (< b part-index)))))
                                        (t nil)))))
                             part)))))

(defun join-pieces (decider a b)
  "The piece made of A followed by B when B continues A on the same line or circle,
else NIL."
  (cond ((and (line-piece-p a) (line-piece-p b)
              (not (line-piece-infinite a)) (not (line-piece-infinite b))
              (vector-equal-p decider (line-piece-end a) (line-piece-start b))
              (eq (facing decider (line-normal a) (line-normal b)) :same))
         (make-line-piece (line-piece-start a) (line-piece-end b) :name (line-piece-name a)))
        ((and (arc-piece-p a) (arc-piece-p b)
              (not (arc-piece-full a)) (not (arc-piece-full b))
              (eq (arc-piece-sense a) (arc-piece-sense b))
              (vector-equal-p decider (arc-piece-center a) (arc-piece-center b))
              (zero-p decider (e- (arc-piece-radius a) (arc-piece-radius b)))
              (vector-equal-p decider (piece-end a) (piece-start b)))
         (let* ((sweep-a (arc-signed-sweep a)) (sweep-b (arc-signed-sweep b))
                (total (e+ sweep-a sweep-b)))
           (make-arc-piece (arc-piece-center a) (arc-piece-radius a)
                           (arc-piece-from a) (e+ (arc-piece-from a) total)
                           (arc-piece-sense a)
                           :name (arc-piece-name a)
                           :full (zero-p decider (e- (if (eq (arc-piece-sense a) :ccw) total (e- total))
                                                     (e* 2 'pi))))))
        (t nil)))

(defun join-sum-pieces (decider sum-pieces)
  "SUM-PIECES with every pair that continues one another with the same features joined."
  (let ((pieces (copy-list sum-pieces)))
    (loop
      (let ((joined nil))
        (loop named search
              for a in pieces
              do (loop for b in pieces
                       unless (eq a b)
                         do (when (and (equal (sum-piece-obstacle-feature a) (sum-piece-obstacle-feature b))
                                       (equal (sum-piece-observer-feature a) (sum-piece-observer-feature b)))
                              (let ((piece (join-pieces decider (sum-piece-piece a) (sum-piece-piece b))))
                                (when piece
                                  (setf pieces (substitute (make-sum-piece piece
                                                                           (sum-piece-obstacle-feature a)
                                                                           (sum-piece-observer-feature a)
                                                                           (sum-piece-source a))
                                                           a (remove b pieces)))
                                  (setf joined t)
                                  (return-from search))))))
        (unless joined (return pieces))))))

(defun union-boundary (decider parts)
  "The boundary pieces of the union of the convex obstacles PARTS (each a list of sum
pieces, counter-clockwise)."
  (if (null (rest parts))
      (first parts)
      (let ((kept '())
            (boxes (make-hash-table :test 'eq)))
        (flet ((box-of (piece)
                 (multiple-value-bind (box found) (gethash piece boxes)
                   (if found box (setf (gethash piece boxes) (piece-box piece))))))
          (loop for part in parts
                for a from 0
                do (let ((others (loop for other in parts for b from 0
                                       unless (= a b) nconc (mapcar #'sum-piece-piece other))))
                     (dolist (sp part)
                       (check-budget part)
                       (let ((piece (sum-piece-piece sp)))
                         (dolist (sub (split-piece decider piece
                                                   (cut-parameters decider piece others #'box-of)))
                           (let ((midpoint (piece-midpoint decider sub)))
                             (when (on-union-boundary-p decider midpoint
                                                        (piece-outward-normal-at sub midpoint)
                                                        sp a parts)
                               (push (make-sum-piece sub (sum-piece-obstacle-feature sp)
                                                     (sum-piece-observer-feature sp)
                                                     (sum-piece-source sp))
                                     kept))))))))
          (chain-sum-pieces decider (join-sum-pieces decider (nreverse kept)))))))

(defun chain-sum-pieces (decider sum-pieces)
  "SUM-PIECES reordered so that each piece is followed by the one starting where it
ends, loop after loop (counter-clockwise along each boundary curve)."
  (let ((remaining (copy-list sum-pieces)) (ordered '()))
    (loop while remaining
          do (let ((current (pop remaining)))
               (push current ordered)
               (loop
                 (let* ((end (piece-endpoints (sum-piece-piece current)))
                        (next (and end
                                   (find-if (lambda (sp)
                                              (let ((start (piece-endpoints (sum-piece-piece sp))))
                                                (and start
                                                     (vector-known-equal-p decider (second end) (first start)))))
                                            remaining))))
                   (unless next (return))
                   (setf remaining (remove next remaining))
                   (push next ordered)
                   (setf current next)))))
    (nreverse ordered)))
