;;;; src/geometry/minkowski.lisp -- the Minkowski sum of two convex shapes, by their normals.
;;;;
;;;; A convex boundary is a cyclic list of FEATURES in counter-clockwise order: corners
;;;; (:VERTEX, whose outward normals sweep a cone), straight edges (:EDGE, one normal)
;;;; and convex arcs (:ARC, normals sweeping the arc's range). The configuration-space
;;;; obstacle B (+) (-A) of two convex bodies is traced by pairing the features whose
;;;; normal ranges meet (thesis section 2.5.2; the "convolution" of the two boundaries):
;;;;   edge of B   + the point of -A that supports B's normal  -> a segment
;;;;   edge of -A  + the point of B that supports its normal   -> a segment
;;;;   parallel edges of B and -A                              -> one longer segment
;;;;   corner/arc of B + corner/arc of -A over common normals  -> an arc of radius r1 + r2
;;;;                                                              (none for two corners)
;;;; Normal ranges are half-open [from, to) so every direction is claimed exactly once.
;;;; Every piece remembers the feature of B and of A that touch along it.

(in-package #:ames.geometry)

(defstruct (feature (:constructor %make-feature))
  "A feature of a convex boundary. KIND is :VERTEX, :EDGE or :ARC; NAME names it in
its shape ((:edge 2), (:vertex 0), ...; NIL for a construction line such as the back of
a thin surface). A vertex has CENTER (its point) and RADIUS 0, an arc its CENTER and
RADIUS; both have the RANGE of their outward normals. An edge has its PIECE and NORMAL.
CONTACT-RANGE, when set, is the closed range of normals that may give simple contacts;
EXPOSED is false for features that never give contacts."
  kind name center (radius 0) range piece normal contact-range (exposed t))

(defun vertex-feature (point range name &key contact-range (exposed t))
  (%make-feature :kind :vertex :name name :center point :radius 0 :range range
                 :contact-range contact-range :exposed exposed))

(defun edge-feature (piece &key (exposed t) name)
  (%make-feature :kind :edge :name (or name (piece-name piece)) :piece piece
                 :normal (line-normal piece) :exposed exposed))

(defun arc-feature (piece &key (exposed t))
  (%make-feature :kind :arc :name (arc-piece-name piece) :center (arc-piece-center piece)
                 :radius (arc-piece-radius piece) :range (arc-normal-range piece)
                 :piece piece :exposed exposed))

(defun feature-edge-p (feature) (eq (feature-kind feature) :edge))

(defun merge-collinear-pieces (decider pieces vertex-names)
  "PIECES (a closed chain) and the names of the vertices at their starts, with
consecutive line pieces of the same name that continue straight on merged into one.
(Differently named pieces stay apart: CONVEX-SUM handles such straight runs.)"
  (let ((chain (mapcar #'cons pieces vertex-names)))
    (loop
      (let ((n (length chain)) (merged nil))
        (when (< n 2) (return))
        (loop for i below n
              for a = (nth i chain) for b = (nth (mod (1+ i) n) chain)
              when (and (line-piece-p (car a)) (line-piece-p (car b))
                        (equal (line-piece-name (car a)) (line-piece-name (car b)))
                        (same-direction-p decider (line-normal (car a)) (line-normal (car b))))
                do (let ((joined (cons (make-line-piece (line-piece-start (car a))
                                                        (line-piece-end (car b))
                                                        :name (line-piece-name (car a)))
                                       (cdr a))))
                     (setf chain (loop for j below n
                                       for entry = (nth j chain)
                                       unless (= j (mod (1+ i) n))
                                         collect (if (= j i) joined entry)))
                     (setf merged t)
                     (return)))
        (unless merged (return))))
    (values (mapcar #'car chain) (mapcar #'cdr chain))))

(defun closed-convex-features (decider pieces vertex-names &key exposed contact-ranges)
  "The features, in counter-clockwise order, of the convex solid bounded by the closed
chain PIECES. VERTEX-NAMES name the corners at the pieces' starts. EXPOSED (a list
parallel to PIECES, default all true) marks pieces that can give contacts;
CONTACT-RANGES (parallel to VERTEX-NAMES) restricts corners' contact normals."
  (let ((exposed (or exposed (make-list (length pieces) :initial-element t)))
        (contact-ranges (or contact-ranges (make-list (length pieces) :initial-element nil))))
    (let ((table (mapcar #'list pieces exposed contact-ranges)))
      (multiple-value-bind (pieces vertex-names) (merge-collinear-pieces decider pieces vertex-names)
        (let ((n (length pieces)) (features '()))
          (loop for i below n
                for piece = (nth i pieces)
                for previous = (nth (mod (1- i) n) pieces)
                for entry = (or (find piece table :key #'first)
                                (find (piece-name piece) table
                                      :key (lambda (e) (piece-name (first e))) :test #'equal))
                do (unless (and (= n 1) (arc-piece-p piece) (arc-piece-full piece))
                     (let ((cone (make-angular-range (piece-end-normal previous)
                                                     (piece-start-normal piece))))
                       (unless (range-empty-p decider cone)
                         (push (vertex-feature (piece-start piece) cone (nth i vertex-names)
                                               :contact-range (third entry))
                               features))))
                   (push (etypecase piece
                           (line-piece (edge-feature piece :exposed (second entry)))
                           (arc-piece (arc-feature piece :exposed (second entry))))
                         features))
          (nreverse features))))))

(defun negated-range (range)
  (if (angular-range-full range)
      (full-angular-range (opposite-direction (angular-range-from range)))
      (make-angular-range (opposite-direction (angular-range-from range))
                          (opposite-direction (angular-range-to range))
                          :sweep-class (angular-range-sweep-class range))))

(defun negate-feature (feature)
  "FEATURE of the body reflected through its reference point (a feature of -A)."
  (ecase (feature-kind feature)
    (:vertex (%make-feature :kind :vertex :name (feature-name feature)
                            :center (vneg (feature-center feature)) :radius 0
                            :range (negated-range (feature-range feature))))
    (:edge (let* ((piece (feature-piece feature))
                  (negated (make-line-piece (vneg (line-piece-start piece))
                                            (vneg (line-piece-end piece))
                                            :name (line-piece-name piece)
                                            :infinite (line-piece-infinite piece))))
             (%make-feature :kind :edge :name (feature-name feature) :piece negated
                            :normal (line-normal negated))))
    (:arc (%make-feature :kind :arc :name (feature-name feature)
                         :center (vneg (feature-center feature))
                         :radius (feature-radius feature)
                         :range (negated-range (feature-range feature))))))

(defun support-point (decider feature normal)
  "The point of the corner or arc FEATURE whose outward normal is the vector NORMAL."
  (if (eq (feature-kind feature) :vertex)
      (feature-center feature)
      (v+ (feature-center feature)
          (vscale (feature-radius feature) (unit-vector decider normal)))))

;;; The pieces of a configuration-space obstacle

(defstruct (sum-piece (:constructor make-sum-piece (piece obstacle-feature observer-feature source)))
  "A piece of the boundary of B (+) (-A): the segment or arc PIECE (solid on its left),
the names of the features of the obstacle B and of the observer A that touch along it,
and SOURCE, the feature of B (a FEATURE) it comes from."
  piece obstacle-feature observer-feature source)

(defun range-arc-piece (decider center radius range)
  "The convex arc of the circle (CENTER, RADIUS) whose outward normals sweep RANGE."
  (let* ((from (direction-angle-decided decider (angular-range-from range)))
         (sweep (range-sweep decider range)))
    (make-arc-piece center radius from (e+ from sweep) :ccw
                    :full (angular-range-full range))))

(defun observer-feature-containing (decider alphas direction-vector)
  "The corner or arc among ALPHAS (the observer's features) whose normal range holds
DIRECTION-VECTOR. Signals GEOMETRY-ERROR when there is none (their ranges do not cover
the circle)."
  (or (find-if (lambda (alpha)
                 (and (not (feature-edge-p alpha))
                      (direction-in-range-p decider direction-vector
                                            (feature-range alpha))))
               alphas)
      (error 'geometry-error
             :datum direction-vector
             :detail "internal: no feature of the observer has this normal (its normal ranges do not cover the circle)")))

(defun translated-line-piece (piece offset-start offset-end)
  "The line PIECE with its start moved by OFFSET-START and its end by OFFSET-END."
  (make-line-piece (v+ (line-piece-start piece) offset-start)
                   (v+ (line-piece-end piece) offset-end)
                   :infinite (line-piece-infinite piece)))

(defun edge-sum-pieces (decider beta alphas continued)
  "The sum pieces, in order, of the edge BETA of the obstacle with the observer's
features ALPHAS: the edge moved by the observer's parallel edge, or by the support
point of the corner facing it. CONTINUED: the next feature of the obstacle is an edge
going straight on; the observer's parallel edge is then added after the last edge of
the run."
  (let* ((n (feature-normal beta))
         (parallel (find-if (lambda (alpha)
                              (and (feature-edge-p alpha)
                                   (same-direction-p decider n (feature-normal alpha))))
                            alphas)))
    (if parallel
        (list (make-sum-piece (translated-line-piece
                               (feature-piece beta)
                               (line-piece-start (feature-piece parallel))
                               (if continued
                                   (line-piece-start (feature-piece parallel))
                                   (line-piece-end (feature-piece parallel))))
                              (feature-name beta) (feature-name parallel) beta))
        (let* ((alpha (observer-feature-containing decider alphas n))
               (offset (support-point decider alpha n)))
          (list (make-sum-piece (translated-line-piece (feature-piece beta) offset offset)
                                (feature-name beta) (feature-name alpha) beta))))))

(defun observer-start-index (decider alphas alpha-vector range)
  "The index in ALPHA-VECTOR (the observer's features ALPHAS) of the feature where the
normal range RANGE begins: the edge with that normal, else the feature containing it."
  (let ((from (direction-vector (angular-range-from range))))
    (or (position-if (lambda (alpha)
                       (and (feature-edge-p alpha)
                            (same-direction-p decider from (feature-normal alpha))))
                     alpha-vector)
        (position (observer-feature-containing decider alphas from) alpha-vector))))

(defun corner-sum-pieces (decider beta alphas previous-edge-normal)
  "The sum pieces, in order, of the corner or arc BETA of the obstacle with the
observer's features ALPHAS, walking them counter-clockwise from where BETA's normal range
begins: each observer edge whose normal lies in the range (unless it is the
PREVIOUS-EDGE-NORMAL, already joined to the previous edge) moved by BETA's support
point, and each arc of positive radius over the common range. An arc whose common range
wraps around is split, its second part last."
  (let* ((alpha-vector (coerce alphas 'vector))
         (m (length alphas))
         (range (feature-range beta)) (deferred nil) (pieces '()))
    (flet ((emit (piece alpha)
             (push (make-sum-piece piece (feature-name beta) (feature-name alpha) beta) pieces)))
      (unless (range-empty-p decider range)
        (let ((j0 (observer-start-index decider alphas alpha-vector range)))
          (dotimes (k m)
            (let ((alpha (aref alpha-vector (mod (+ j0 k) m))))
              (if (feature-edge-p alpha)
                  (let ((normal (feature-normal alpha)))
                    (when (and (direction-in-range-p decider normal range)
                               (not (and previous-edge-normal
                                         (same-direction-p decider normal
                                                           previous-edge-normal))))
                      (let ((offset (support-point decider beta normal)))
                        (emit (translated-line-piece (feature-piece alpha) offset offset)
                              alpha))))
                  (let ((common (range-intersection decider range (feature-range alpha)))
                        (radius (e+ (feature-radius beta) (feature-radius alpha))))
                    (unless (eql radius 0)
                      (when (and (= k 0) (= (length common) 2))
                        (setf deferred (second common) common (list (first common))))
                      (dolist (sub common)
                        (emit (range-arc-piece decider
                                               (v+ (feature-center beta) (feature-center alpha))
                                               radius sub)
                              alpha)))))))
          (when deferred
            (emit (range-arc-piece decider
                                   (v+ (feature-center beta)
                                       (feature-center (aref alpha-vector j0)))
                                   (e+ (feature-radius beta)
                                       (feature-radius (aref alpha-vector j0)))
                                   deferred)
                  (aref alpha-vector j0))))))
    (nreverse pieces)))

(defun previous-edge-normals (betas)
  "For each feature of BETAS (a closed counter-clockwise boundary), the normal of the
feature before it when that is an edge (and there is more than one feature), else NIL."
  (loop for beta in betas
        for i from 0
        collect (let ((previous (nth (mod (1- i) (length betas)) betas)))
                  (and (feature-edge-p previous) (> (length betas) 1)
                       (feature-normal previous)))))

(defun edge-continues-p (decider betas i)
  "True when the feature after the Ith edge of BETAS (a closed boundary) is another edge
going straight on."
  (let ((beta (nth i betas))
        (next (nth (mod (1+ i) (length betas)) betas)))
    (and (not (eq next beta)) (feature-edge-p next)
         (same-direction-p decider (feature-normal beta)
                           (feature-normal next)))))

(defun convex-sum (decider betas alphas)
  "The boundary pieces, counter-clockwise, of B (+) (-A) where BETAS are the features of
the convex obstacle B and ALPHAS those of -A (already reflected), both counter-clockwise."
  (loop for beta in betas
        for i from 0
        for previous-edge-normal in (previous-edge-normals betas)
        append (if (feature-edge-p beta)
                   (edge-sum-pieces decider beta alphas (edge-continues-p decider betas i))
                   (corner-sum-pieces decider beta alphas previous-edge-normal))))

(defun exposed-sum-pieces (decider sum-pieces)
  "The SUM-PIECES that are simple contacts: those from exposed features of the
obstacle, clipped to the features' contact ranges (the front of a thin surface)."
  (loop for sp in sum-pieces
        for source = (sum-piece-source sp)
        for piece = (sum-piece-piece sp)
        when (feature-exposed source)
          nconc (let ((allowed (feature-contact-range source)))
                  (cond ((null allowed) (list sp))
                        ((line-piece-p piece)
                         (when (direction-in-range-p decider (line-normal piece) allowed :closed t)
                           (list sp)))
                        (t (loop for sub in (range-intersection decider (arc-normal-range piece) allowed)
                                 collect (make-sum-piece
                                          (let ((arc (range-arc-piece decider (arc-piece-center piece)
                                                                      (arc-piece-radius piece) sub)))
                                            arc)
                                          (sum-piece-obstacle-feature sp)
                                          (sum-piece-observer-feature sp)
                                          source)))))))

;;; Inside tests for a convex region given by its boundary pieces.

(defun inside-convex-p (decider q pieces &key strict)
  "True when the point Q lies in the convex region bounded counter-clockwise by PIECES
(line and convex arc pieces): in its interior when STRICT, else in the closed region.
A region without pieces (a single point) has no interior."
  (flet ((below (x bound)
           (fact-holds-p decider (list (if strict '< '<=) x bound))))
    (and (or pieces (not strict))
         (every (lambda (piece)
                  (etypecase piece
                    (line-piece (below (dot (line-normal piece) (v- q (line-piece-start piece))) 0))
                    (arc-piece
                     (let* ((w (v- q (arc-piece-center piece)))
                            (r (arc-piece-radius piece))
                            (within-disc (below (norm-squared w) (esquare r))))
                       (if (arc-piece-full piece)
                           within-disc
                           (and (below (dot (polar (arc-piece-from piece)) w) r)
                                (below (dot (polar (arc-piece-to piece)) w) r)
                                (or (not (direction-in-range-p decider w (arc-position-range piece)
                                                               :closed t))
                                    within-disc)))))))
                pieces))))
