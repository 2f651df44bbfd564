;;;; t/geometry-tracks.lisp -- geometry tests on half-planes, tracks, thin surfaces and
;;;; non-convex shapes (helpers G-... are in t/geometry.lisp).

(in-package #:ames.tests)

(in-suite geometry)

;;; Half-planes, tracks and thin surfaces

(test geometry-half-plane-ground
  (let* ((pair (g-pair 'wedge '(polygon (0 0) (4 0) (0 3)) 'ground '(half-plane (1 0) (0 0))))
         (ground (first (ames.geometry:pair-contacts pair))))
    (is (eq 'wedge (ames.geometry:pair-observer pair)))
    (is (= 1 (length (ames.geometry:pair-contacts pair))))
    (is (equal '(:edge 0 :of wedge) (ames.geometry:contact-observer-feature ground)))
    (is (equal '(:edge 0 :of ground) (ames.geometry:contact-obstacle-feature ground)))
    (is (g-point= '(0 1) (ames.geometry:contact-outward-normal ground 0)))
    (is (= 1 (length (ames.geometry:contacts-at pair '(0 0)))))
    (is (= 1 (length (ames.geometry:contacts-at pair '(-7 0)))))
    (is (null (ames.geometry:contacts-at pair '(0 1))))
    (is (ames.geometry:penetrates-p pair '(0 -1/10)))
    (is (not (ames.geometry:penetrates-p pair '(0 1/10)))))
  ;; the particle on the ground: the ground's own line
  (let ((pair (g-pair 'ground '(half-plane (1 0) (0 0)) 'particle 'point)))
    (is (eq 'particle (ames.geometry:pair-observer pair)))
    (is (equal '(:point :of particle)
               (ames.geometry:contact-observer-feature (first (ames.geometry:pair-contacts pair)))))
    (is (= 1 (length (ames.geometry:contacts-at pair '(3 0))))))
  ;; a disc rests on the ground when its centre is one radius up
  (let ((pair (g-pair 'ball '(circle 2) 'ground '(half-plane (1 0) (0 0)))))
    (is (= 1 (length (ames.geometry:contacts-at pair '(5 2)))))
    (is (equal '(:circle :of ball)
               (ames.geometry:contact-observer-feature (first (ames.geometry:pair-contacts pair))))))
  ;; a non-convex body on the ground touches with its bottom face
  (let ((pair (g-pair 'l '(polygon (0 0) (2 0) (2 1) (1 1) (1 2) (0 2)) 'ground '(half-plane (1 0) (0 0)))))
    (is (equal '(:edge 0 :of l)
               (ames.geometry:contact-observer-feature (first (ames.geometry:pair-contacts pair)))))
    (is (= 1 (length (ames.geometry:contacts-at pair '(3 0)))))))

(test geometry-one-sided-segment
  ;; a table top along y = 0 (solid below); a disc of radius 1 rests on it or rolls
  ;; round its ends, but nothing touches its underside
  (let* ((pair (g-pair 'disc '(circle 1) 'table '(segment (4 0) (0 0))))
         (contacts (ames.geometry:pair-contacts pair)))
    (is (eq 'disc (ames.geometry:pair-observer pair)))
    (is (= 3 (length contacts)))
    (is (g-contacts-chain-p pair :open t))
    (let ((top (g-contact pair '(:edge 0))))
      (is (g-point= '(4 1) (ames.geometry:contact-start top)))
      (is (g-point= '(0 1) (ames.geometry:contact-end top))))
    (dolist (end '((:vertex 0) (:vertex 1)))
      (is (g-close-p (ames.geometry:contact-length (g-contact pair end)) (/ pi 2))))
    (is (= 1 (length (ames.geometry:contacts-at pair '(2 1)))))
    (is (null (ames.geometry:contacts-at pair '(2 -1))))
    (is (= 1 (length (ames.geometry:contacts-at pair '(5 0)))))
    (is (null (ames.geometry:contacts-at pair '(-1/2 (- (sqrt 3) 0)))))
    (is (ames.geometry:penetrates-p pair '(2 1/2)))
    (is (not (ames.geometry:penetrates-p pair '(2 -1)))))
  (let ((pair (g-pair 'particle 'point 'table '(segment (4 0) (0 0)))))
    (is (= 1 (length (ames.geometry:pair-contacts pair))))
    (is (not (ames.geometry:penetrates-p pair '(2 0))))))

(test geometry-bowl-and-dome-tracks
  ;; a bowl: the lower half circle of radius 2 with its solid outside
  (let* ((form '(arc :center (0 0) :radius 2 :from pi :to (* 2 pi) :solid :outside))
         (point-pair (g-pair 'particle 'point 'bowl form))
         (inside (first (ames.geometry:pair-contacts point-pair))))
    (is (= 1 (length (ames.geometry:pair-contacts point-pair))))
    (is (eql -1 (ames.geometry:contact-sense inside)))
    (is (eql -1/2 (g-exact (ames.geometry:contact-curvature inside))))
    (let ((s (cdr (first (ames.geometry:contacts-at point-pair '(0 -2))))))
      (is (g-close-p s pi))
      ;; at the bottom the normal force pushes up, and the centripetal acceleration too
      (is (g-close-p (ames.geometry:contact-outward-normal inside s) '(0 1)))
      (is (g-close-p (ames.geometry:path-acceleration inside s 3 0) '(0 9/2))))
    (is (not (ames.geometry:penetrates-p point-pair '(0 -3)))))
  (let* ((pair (g-pair 'ball '(circle 1/2) 'bowl '(arc :center (0 0) :radius 2 :from pi :to (* 2 pi)
                                                  :solid :outside)))
         (inner (g-contact pair '(:arc 0))))
    (is (= 3 (length (ames.geometry:pair-contacts pair))))
    (is (g-contacts-chain-p pair :open t))
    (is (eql 3/2 (ames.geometry:contact-radius inner)))
    (is (= 1 (length (ames.geometry:contacts-at pair '(0 -3/2)))))
    (is (ames.geometry:penetrates-p pair '(0 -2)))
    (is (not (ames.geometry:penetrates-p pair '(0 -3/2))))
    (is (not (ames.geometry:penetrates-p pair '(0 0)))))
  ;; a dome: the upper half circle, solid inside
  (let* ((pair (g-pair 'particle 'point 'dome '(arc :center (0 0) :radius 1 :from 0 :to pi)))
         (top (first (ames.geometry:pair-contacts pair))))
    (is (= 1 (length (ames.geometry:pair-contacts pair))))
    (is (eq :arc (ames.geometry:contact-kind top)))
    (is (g-close-p (cdr (first (ames.geometry:contacts-at pair '(0 1)))) (/ pi 2)))
    (is (null (ames.geometry:contacts-at pair '(0 -1))))
    (is (ames.geometry:penetrates-p pair '(0 1/2)))
    (is (not (ames.geometry:penetrates-p pair '(0 -1/2)))))
  ;; a disc rolling over the dome: an arc of radius 3/2, and a quarter turn round each end
  (let ((pair (g-pair 'ball '(circle 1/2) 'dome '(arc :center (0 0) :radius 1 :from 0 :to pi))))
    (is (eq 'ball (ames.geometry:pair-observer pair)))
    (is (= 3 (length (ames.geometry:pair-contacts pair))))
    (is (g-contacts-chain-p pair :open t))
    (is (eql 3/2 (ames.geometry:contact-radius (g-contact pair '(:arc 0)))))
    (is (g-close-p (ames.geometry:contact-length (g-contact pair '(:arc 0))) (* 3/2 pi)))
    (dolist (end '((:vertex 0) (:vertex 1)))
      (is (g-close-p (ames.geometry:contact-length (g-contact pair end)) (/ pi 4))))
    (is (g-point= '(3/2 0) (ames.geometry:contact-start (g-contact pair '(:arc 0)))))
    (is (null (ames.geometry:contacts-at pair '(0 -1/2))))
    (is (ames.geometry:penetrates-p pair '(0 1)))))

(test geometry-outlines-convex-and-concave
  (let* ((pair (g-pair 'particle 'point 'd '(outline (line (0 0) (2 0))
                                             (arc :center (2 1) :radius 1 :from (- (/ pi 2)) :to (/ pi 2))
                                             (line (2 2) (0 2)) (line (0 2) (0 0)))))
         (round (g-contact pair '(:arc 1))))
    (is (= 4 (length (ames.geometry:pair-contacts pair))))
    (is (g-close-p (ames.geometry:contact-length round) pi))
    (is (g-close-p (cdr (first (ames.geometry:contacts-at pair '(3 1)))) (/ pi 2)))
    (is (ames.geometry:penetrates-p pair '(5/2 1)))
    (is (not (ames.geometry:penetrates-p pair '(7/2 1)))))
  (let* ((pair (g-pair 'particle 'point 'bitten *g-bitten-square*))
         (bite (g-contact pair '(:arc 3))))
    (is (= 6 (length (ames.geometry:pair-contacts pair))))
    (is (eql -1 (ames.geometry:contact-sense bite)))
    (let ((s (cdr (first (ames.geometry:contacts-at pair '(2 3))))))
      (is (g-close-p s (/ pi 2)))
      (is (g-close-p (ames.geometry:contact-outward-normal bite s) '(0 1))))
    (is (not (ames.geometry:penetrates-p pair '(2 7/2))))
    (is (ames.geometry:penetrates-p pair '(2 5/2)))
    (is (ames.geometry:penetrates-p pair '(1/2 7/2)))
    (is (not (ames.geometry:penetrates-p pair '(2 3))))))

;;; Non-convex shapes

(defparameter *g-l-shape* '(polygon (0 0) (2 0) (2 1) (1 1) (1 2) (0 2))
  "An L: [0,2]x[0,1] and [0,1]x[1,2].")

(test geometry-point-against-l-shape
  (let ((pair (g-pair 'particle 'point 'l *g-l-shape*)))
    (is (= 6 (length (ames.geometry:pair-contacts pair))))
    (is (equal '(0 1 2 3 4 5)
               (sort (mapcar (lambda (c) (second (ames.geometry:contact-obstacle-feature c)))
                             (ames.geometry:pair-contacts pair))
                     #'<)))
    (loop for (q inside) in '(((1/2 1/2) t) ((3/2 3/2) nil) ((1/2 3/2) t) ((1 1) nil)
                              ((1/2 1) t) ((1 1/2) t) ((3/2 1) nil) ((5/2 1/2) nil))
          do (is (eq inside (ames.geometry:penetrates-p pair q)) "~S" q))
    (is (= 2 (length (ames.geometry:contacts-at pair '(1 1)))))))

(test geometry-block-against-l-shape
  ;; L (+) -[0,1/2]^2 = [-1/2,2]x[-1/2,1] union [-1/2,1]x[1/2,2]: six faces, the
  ;; reflex corner at (1 1)
  (let* ((pair (g-pair 'block '(polygon (0 0) (1/2 0) (1/2 1/2) (0 1/2)) 'l *g-l-shape*)))
    (is (eq 'block (ames.geometry:pair-observer pair)))
    (is (= 6 (length (ames.geometry:pair-contacts pair))))
    (is (g-contacts-chain-p pair))
    (loop for (l-edge block-edge start end)
            in '((0 2 (-1/2 -1/2) (2 -1/2))
                 (1 3 (2 -1/2) (2 1))
                 (2 0 (2 1) (1 1))
                 (3 3 (1 1) (1 2))
                 (4 0 (1 2) (-1/2 2))
                 (5 1 (-1/2 2) (-1/2 -1/2)))
          do (let ((c (g-contact pair (list :edge l-edge) (list :edge block-edge))))
               (is (not (null c)) "no contact of L edge ~D with block edge ~D" l-edge block-edge)
               (when c
                 (is (g-point= start (ames.geometry:contact-start c)))
                 (is (g-point= end (ames.geometry:contact-end c))))))
    (loop for (q inside) in '(((1/2 1/2) t) ((3/2 3/2) nil) ((1 1) nil) ((1/2 1) t)
                              ((-1/2 0) nil) ((3/4 3/4) t) ((0 0) t) ((-1/4 1) t) ((5/4 5/4) nil))
          do (is (eq inside (ames.geometry:penetrates-p pair q)) "~S" q))
    ;; in the reflex corner the block touches both faces
    (is (= 2 (length (ames.geometry:contacts-at pair '(1 1)))))))

(test geometry-disc-against-l-shape
  (let ((pair (g-pair 'disc '(circle 1/4) 'l *g-l-shape*)))
    (is (= 11 (length (ames.geometry:pair-contacts pair))))
    (is (= 5 (count :arc (ames.geometry:pair-contacts pair) :key #'ames.geometry:contact-kind)))
    (is (g-contacts-chain-p pair))
    (is (g-close-p (reduce #'+ (mapcar (lambda (c) (g-value (ames.geometry:contact-length c)))
                                       (remove :segment (ames.geometry:pair-contacts pair)
                                               :key #'ames.geometry:contact-kind)))
                   (* 5/8 pi)))
    ;; the two faces at the reflex corner are cut where they meet, at (5/4, 5/4)
    (is (g-point= '(5/4 5/4) (ames.geometry:contact-end (g-contact pair '(:edge 2)))))
    (is (g-point= '(5/4 5/4) (ames.geometry:contact-start (g-contact pair '(:edge 3)))))
    (is (ames.geometry:penetrates-p pair '(1 1)))
    (is (not (ames.geometry:penetrates-p pair '(3/2 3/2))))))

(test geometry-straight-runs-of-edges
  ;; a 4 x 2 block whose bottom has a vertex in its middle, observed by a unit square:
  ;; the two halves of the bottom stay two contacts that together span the whole face
  (let* ((pair (ames.geometry:make-contact-pair-with-observer
                'square (g-shape '(polygon (0 0) (1 0) (1 1) (0 1)))
                'block (g-shape '(polygon (0 0) (2 0) (4 0) (4 2) (0 2)))))
         (left-half (g-contact pair '(:edge 0)))
         (right-half (g-contact pair '(:edge 1))))
    (is (= 5 (length (ames.geometry:pair-contacts pair))))
    (is (g-contacts-chain-p pair))
    (is (g-point= '(-1 -1) (ames.geometry:contact-start left-half)))
    (is (g-point= '(1 -1) (ames.geometry:contact-end left-half)))
    (is (g-point= '(1 -1) (ames.geometry:contact-start right-half)))
    (is (g-point= '(4 -1) (ames.geometry:contact-end right-half)))
    (is (equal '(:edge 2 :of square) (ames.geometry:contact-observer-feature right-half)))))

(test geometry-overlapping-start-is-reported
  (let ((pair (g-pair 'particle 'point 'wedge '(polygon (0 0) (4 0) (0 3)))))
    (is (equal '(2 3/2) (ames.geometry:check-separation pair '(2 3/2))))
    (let ((condition (handler-case (ames.geometry:check-separation pair '(1 1))
                       (ames.geometry:bodies-overlap (c) c))))
      (is (typep condition 'ames-error))
      (is (eq 'particle (ames.geometry:overlap-observer condition)))
      (is (eq 'wedge (ames.geometry:overlap-obstacle condition)))
      (is (search "overlap" (princ-to-string condition))))
    ;; the CONTINUE restart lets the caller go on
    (is (equal '(1 1) (handler-bind ((ames.geometry:bodies-overlap #'continue))
                        (ames.geometry:check-separation pair '(1 1)))))))
