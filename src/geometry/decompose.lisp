;;;; src/geometry/decompose.lisp -- shapes as unions of convex parts, each a list of features.
;;;;
;;;; A convex shape is one part. A non-convex polygon is cut by ear clipping into
;;;; triangles, which are then merged back across diagonals while they stay convex
;;;; (Hertel-Mehlhorn). A non-convex outline whose arcs all bulge outward is cut into the
;;;; polygon of its piece ends plus one circular segment per arc. Thin surfaces are
;;;; convex: a segment is the degenerate two-sided plate, a dome track the circular
;;;; segment under its arc; as obstacles their back and their ends beyond a quarter turn
;;;; are marked as giving no contacts. Diagonals and chords are construction lines (no
;;;; name, not exposed): the union step removes what they contribute.

(in-package #:ames.geometry)

(defun point-in-closed-triangle-p (decider p a b c)
  "True when P lies in the closed counter-clockwise triangle A B C."
  (and (nonnegative-p decider (cross (v- b a) (v- p a)))
       (nonnegative-p decider (cross (v- c b) (v- p b)))
       (nonnegative-p decider (cross (v- a c) (v- p c)))))

(defun numeric-ear-clipping (points indices)
  "TRIANGULATE for corners whose coordinates are all exact rationals: POINTS is a vector
of conses (X . Y), indexed by the INDICES. The same ears, in the same order, as the
general case finds, decided by plain rational arithmetic, with a bounding-box test
before the exact one."
  (labels ((x (i) (car (aref points i)))
           (y (i) (cdr (aref points i)))
           (turn (a b c)
             ;; cross (b - a, c - b)
             (- (* (- (x b) (x a)) (- (y c) (y b))) (* (- (y b) (y a)) (- (x c) (x b)))))
           (left-of-or-on-p (a b p)
             ;; cross (b - a, p - a) >= 0
             (>= (- (* (- (x b) (x a)) (- (y p) (y a))) (* (- (y b) (y a)) (- (x p) (x a)))) 0))
           (inside-p (p a b c)
             (and (<= (min (x a) (x b) (x c)) (x p) (max (x a) (x b) (x c)))
                  (<= (min (y a) (y b) (y c)) (y p) (max (y a) (y b) (y c)))
                  (left-of-or-on-p a b p) (left-of-or-on-p b c p) (left-of-or-on-p c a p))))
    (let ((remaining (coerce indices 'vector)) (triangles '()))
      (loop while (> (length remaining) 3)
            do (let* ((n (length remaining))
                      (ear (loop for k below n
                                 for a = (aref remaining (mod (1- k) n))
                                 for b = (aref remaining k)
                                 for c = (aref remaining (mod (1+ k) n))
                                 do (check-budget indices)
                                 when (and (plusp (turn a b c))
                                           (notany (lambda (j)
                                                     (and (/= j a) (/= j b) (/= j c)
                                                          (inside-p j a b c)))
                                                   remaining))
                                   return k)))
                 (unless ear
                   (error 'geometry-error :datum (coerce points 'list)
                                          :detail "internal: no ear found while triangulating the polygon"))
                 (push (list (aref remaining (mod (1- ear) n)) (aref remaining ear)
                             (aref remaining (mod (1+ ear) n)))
                       triangles)
                 (setf remaining (remove (aref remaining ear) remaining))))
      (push (coerce remaining 'list) triangles)
      (nreverse triangles))))

(defun triangulate (decider vertices indices)
  "Ear-clipping triangulation of the simple counter-clockwise polygon whose corners are
the VERTICES at INDICES: a list of index triples. Corners with numeric coordinates are
handled by NUMERIC-EAR-CLIPPING (the same answer, faster)."
  (let ((points (map 'vector #'exact-point vertices)))
    (when (every #'identity points)
      (return-from triangulate (numeric-ear-clipping points indices))))
  (let ((remaining (copy-list indices)) (triangles '())
        (vertices (coerce vertices 'vector)))
    (flet ((point (i) (aref vertices i)))
      (loop while (> (length remaining) 3)
            do (let* ((n (length remaining))
                      (ear (loop for k below n
                                 for a = (nth (mod (1- k) n) remaining)
                                 for b = (nth k remaining)
                                 for c = (nth (mod (1+ k) n) remaining)
                                 do (check-budget indices)
                                 when (and (positive-p decider (cross (v- (point b) (point a))
                                                                      (v- (point c) (point b))))
                                           (notany (lambda (j)
                                                     (and (not (member j (list a b c)))
                                                          (point-in-closed-triangle-p
                                                           decider (point j) (point a) (point b) (point c))))
                                                   remaining))
                                   return k)))
                 (unless ear
                   (error 'geometry-error :datum (coerce vertices 'list)
                                          :detail "internal: no ear found while triangulating the polygon"))
                 (push (list (nth (mod (1- ear) n) remaining) (nth ear remaining)
                             (nth (mod (1+ ear) n) remaining))
                       triangles)
                 (setf remaining (remove (nth ear remaining) remaining))))
      (push remaining triangles)
      (nreverse triangles))))

(defun rotate-to-start (cycle element)
  (let ((k (position element cycle)))
    (append (nthcdr k cycle) (subseq cycle 0 k))))

(defun cycle-edge-p (cycle u v)
  "True when U is followed by V in the cyclic list CYCLE."
  (let ((k (position u cycle)))
    (and k (eql (nth (mod (1+ k) (length cycle)) cycle) v))))

(defun convex-corner-in-cycle-p (decider vertices cycle index)
  (let* ((n (length cycle)) (k (position index cycle))
         (a (nth (nth (mod (1- k) n) cycle) vertices))
         (b (nth index vertices))
         (c (nth (nth (mod (1+ k) n) cycle) vertices)))
    (nonnegative-p decider (cross (v- b a) (v- c b)))))

(defun merge-convex-parts (decider vertices parts original-edge-p)
  "Hertel-Mehlhorn: merge the convex PARTS (index cycles) across their diagonals while
the union stays convex."
  (let ((parts (copy-list parts)))
    (loop
      (let ((merged nil))
        (loop named search
              for p1 in parts
              do (loop for (u v) on (append p1 (list (first p1)))
                       while v
                       unless (funcall original-edge-p u v)
                         do (let ((p2 (find-if (lambda (p) (and (not (eq p p1)) (cycle-edge-p p v u)))
                                               parts)))
                              (when p2
                                (let* ((a (rotate-to-start p1 v))
                                       (b (rotate-to-start p2 u))
                                       (union (append a (butlast (rest b)))))
                                  (when (and (convex-corner-in-cycle-p decider vertices union u)
                                             (convex-corner-in-cycle-p decider vertices union v))
                                    (setf parts (cons union (remove p2 (remove p1 parts))))
                                    (setf merged t)
                                    (return-from search)))))))
        (unless merged (return parts))))))

(defun polygon-parts (decider vertices edge-name vertex-name &key (exposed-edge-p (constantly t)))
  "Convex parts of the simple counter-clockwise polygon VERTICES, each a list of
features. (EDGE-NAME I) names the edge from vertex I to I+1, (VERTEX-NAME I) vertex I;
diagonals get no name and are not exposed."
  (let* ((n (length vertices))
         (indices (alexandria:iota n))
         (original-edge-p (lambda (u v)
                            ;; u -> v is an edge of the polygon
                            (let ((after (member u indices)))
                              (eql v (if (rest after) (second after) (first indices))))))
         (triangles (triangulate decider vertices indices))
         (parts (merge-convex-parts decider vertices triangles original-edge-p)))
    (loop for part in parts
          collect (let ((pieces '()) (names '()) (exposure '()))
                    (loop for (u v) on (append part (list (first part)))
                          while v
                          do (let ((original (funcall original-edge-p u v)))
                               (push (make-line-piece (nth u vertices) (nth v vertices)
                                                      :name (and original (funcall edge-name u)))
                                     pieces)
                               (push (funcall vertex-name u) names)
                               (push (and original (funcall exposed-edge-p u)) exposure)))
                    (closed-convex-features decider (nreverse pieces) (nreverse names)
                                            :exposed (nreverse exposure))))))

(defun outline-parts (decider pieces)
  "Convex parts of a closed counter-clockwise outline whose arcs all bulge outward."
  (let* ((n (length pieces))
         (corners (mapcar #'piece-start pieces))
         (segments
           (loop for piece in pieces for i from 0
                 when (arc-piece-p piece)
                   collect (let ((chord (make-line-piece (piece-end piece) (piece-start piece))))
                             (closed-convex-features
                              decider (list piece chord)
                              (list (list :vertex i) (list :vertex (mod (1+ i) n)))
                              :exposed (list t nil))))))
    (append (if (and (>= n 3)
                     (positive-p decider (polygon-signed-area corners)))
                (polygon-parts decider corners
                               (lambda (i) (and (line-piece-p (nth i pieces)) (piece-name (nth i pieces))))
                               (lambda (i) (list :vertex i))
                               :exposed-edge-p (lambda (i) (line-piece-p (nth i pieces))))
                '())
            segments)))

(defun concave-arc-p (piece)
  (and (arc-piece-p piece) (eq (arc-piece-sense piece) :cw)))

(defun shape-decomposable-p (shape)
  "True when SHAPE can be cut into convex parts (no concave arc)."
  (not (some #'concave-arc-p (shape-boundary shape))))

(defun track-contact-ranges (piece)
  "The closed ranges of contact normals at the start and end of the thin track PIECE:
a quarter turn beyond each end, on its exterior side."
  (let ((start-normal (direction-vector (piece-start-normal piece)))
        (end-normal (direction-vector (piece-end-normal piece))))
    (values (make-angular-range (make-direction (rot-cw start-normal)) (make-direction start-normal)
                                :sweep-class :below-pi)
            (make-angular-range (make-direction end-normal) (make-direction (rot-ccw end-normal))
                                :sweep-class :below-pi))))

(defun track-features (decider track back role)
  "The features of the thin TRACK (a segment or an arc track) as a closed convex part:
TRACK exposed, BACK (its reverse, or its chord) not, its ends as vertices 0 and 1. As
an obstacle (ROLE :OBSTACLE) its ends give contacts only over TRACK-CONTACT-RANGES."
  (multiple-value-bind (start-range end-range) (track-contact-ranges track)
    (closed-convex-features decider (list track back) (list '(:vertex 0) '(:vertex 1))
                            :exposed (list t nil)
                            :contact-ranges (if (eq role :obstacle)
                                                (list start-range end-range)
                                                (list nil nil)))))

(defun convex-parts (decider shape &key (role :obstacle))
  "SHAPE as a list of convex parts, each a list of features (counter-clockwise). ROLE
:OBSTACLE marks the back and far ends of thin surfaces as giving no contacts; as
:OBSERVER a thin surface is its whole plate. Signals UNSUPPORTED-SHAPE-PAIR (without
names; the caller adds them) for concave arcs."
  (let ((boundary (shape-boundary shape)))
    (flet ((whole-convex-boundary ()
             (list (closed-convex-features decider boundary
                                           (loop for i below (length boundary)
                                                 collect (list :vertex i))))))
      (ecase (shape-kind shape)
        (:point (list (list (vertex-feature (vec 0 0) (full-angular-range) '(:point)))))
        (:circle (list (list (arc-feature (first boundary)))))
        (:polygon
         (if (shape-convex-p shape)
             (whole-convex-boundary)
             (polygon-parts decider (shape-vertices shape)
                            (lambda (i) (list :edge i)) (lambda (i) (list :vertex i)))))
        (:outline
         (cond ((shape-convex-p shape) (whole-convex-boundary))
               ((shape-decomposable-p shape) (outline-parts decider boundary))
               (t (error 'unsupported-shape-pair
                         :detail "an outline with a concave arc can only be touched by a point"))))
        (:segment
         (let ((front (first boundary)))
           (list (track-features decider front
                                 (make-line-piece (line-piece-end front) (line-piece-start front))
                                 role))))
        (:arc
         (let ((arc (first boundary)))
           (cond ((eq (shape-solid-side shape) :outside)
                  (error 'unsupported-shape-pair
                         :detail "a bowl (an arc track with its solid outside) can only be touched by a point or a disc"))
                 ((arc-piece-full arc) (list (list (arc-feature arc))))
                 (t (list (track-features decider arc
                                          (make-line-piece (piece-end arc) (piece-start arc))
                                          role))))))
        (:half-plane
         (list (list (edge-feature (first boundary)))))))))
