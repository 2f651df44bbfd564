;;;; t/geometry-properties.lisp -- property tests (FiveAM for-all) on random convex polygons.
;;;;
;;;; The expected obstacles are computed here independently of the geometry layer: the
;;;; Minkowski sum B (+) (-A) of convex polygons is the convex hull of the differences
;;;; b - a of their vertices, and its support function in a direction n is the largest
;;;; n . (b - a).

(in-package #:ames.tests)

(def-suite geometry-properties :in geometry
  :description "Invariants of configuration-space obstacles on random convex shapes.")

(in-suite geometry-properties)

(defun g-cross (o a b)
  "The z component of (A - O) x (B - O), for rational points (lists)."
  (- (* (- (first a) (first o)) (- (second b) (second o)))
     (* (- (second a) (second o)) (- (first b) (first o)))))

(defun g-convex-hull (points)
  "The strictly convex hull of the rational POINTS, counter-clockwise (monotone chain)."
  (let ((sorted (sort (remove-duplicates (copy-list points) :test #'equal)
                      (lambda (p q) (or (< (first p) (first q))
                                        (and (= (first p) (first q)) (< (second p) (second q))))))))
    (if (< (length sorted) 3)
        sorted
        (flet ((half (points)
                 (let ((chain '()))
                   (dolist (p points)
                     (loop while (and (rest chain) (<= (g-cross (second chain) (first chain) p) 0))
                           do (pop chain))
                     (push p chain))
                   (rest chain))))
          (append (reverse (half sorted)) (reverse (half (reverse sorted))))))))

(defun g-gen-convex-polygon (&key (points 6) (size 8))
  "A generator of convex polygons (counter-clockwise rational vertices, at least three)
as hulls of random integer points."
  (lambda ()
    (loop
      (let ((hull (g-convex-hull
                   (loop repeat (+ 3 (random (- points 2)))
                         collect (list (- (random (1+ (* 2 size))) size)
                                       (- (random (1+ (* 2 size))) size))))))
        (when (>= (length hull) 3) (return hull))))))

(defun g-vertex-differences (b a)
  (loop for p in b nconc (loop for q in a collect (list (- (first p) (first q)) (- (second p) (second q))))))

(defun g-polygon-form (vertices) (cons 'polygon vertices))

(defun g-sum-pair (a b)
  "The contact pair of the polygon A observing the polygon B."
  (ames.geometry:make-contact-pair-with-observer
   'a (g-shape (g-polygon-form a)) 'b (g-shape (g-polygon-form b))))

(defun g-same-point-set-p (ps qs)
  (and (= (length ps) (length qs))
       (every (lambda (p) (member p qs :test #'equal)) ps)))

(defun g-strictly-inside-hull-p (q hull)
  (loop for (a b) on (append hull (list (first hull))) while b
        always (plusp (g-cross a b q))))

(defun g-on-hull-boundary-p (q hull)
  (and (loop for (a b) on (append hull (list (first hull))) while b
             always (>= (g-cross a b q) 0))
       (loop for (a b) on (append hull (list (first hull))) while b
             thereis (zerop (g-cross a b q)))))

(test geometry-obstacle-vertices-are-the-hull-of-differences
  (for-all ((a (g-gen-convex-polygon)) (b (g-gen-convex-polygon)))
    (let* ((pair (g-sum-pair a b))
           (starts (mapcar (lambda (c) (mapcar #'g-exact (ames.geometry:contact-start c)))
                           (ames.geometry:pair-contacts pair))))
      (is (g-same-point-set-p (g-convex-hull (g-vertex-differences b a)) starts)
          "A ~S observing B ~S: contact starts ~S" a b starts)
      (is (every (lambda (c) (eq :segment (ames.geometry:contact-kind c)))
                 (ames.geometry:pair-contacts pair))))))

(defun g-support-value (direction points)
  "max over POINTS of DIRECTION . point, numerically (DIRECTION expressions)."
  (loop for p in points
        maximize (+ (* (g-value (first direction)) (first p))
                    (* (g-value (second direction)) (second p)))))

(test geometry-contact-points-lie-on-the-boundary-with-the-stated-normal
  (for-all ((a (g-gen-convex-polygon)) (b (g-gen-convex-polygon)))
    (let* ((pair (g-sum-pair a b))
           (differences (g-vertex-differences b a))
           (hull (g-convex-hull differences)))
      (dolist (c (ames.geometry:pair-contacts pair))
        (dolist (fraction '(0 1/3 1/2 7/9 1))
          (let* ((s (ames.geometry::e* fraction (ames.geometry:contact-length c)))
                 (point (ames.geometry:contact-point c s))
                 (normal (ames.geometry:contact-outward-normal c s))
                 (exact (mapcar #'g-exact point)))
            ;; the point is exact, on the hull's boundary
            (is (g-on-hull-boundary-p exact hull) "~S not on the boundary of ~S" exact hull)
            ;; the normal is a unit vector supporting the hull at the point
            (is (g-close-p (ames.geometry::norm-squared normal) 1))
            (is (< (abs (- (g-support-value normal differences)
                           (+ (* (g-value (first normal)) (first exact))
                              (* (g-value (second normal)) (second exact)))))
                   1d-9))))))))

(test geometry-penetration-and-contact-agree-with-the-hull
  (for-all ((a (g-gen-convex-polygon)) (b (g-gen-convex-polygon))
            (x (gen-integer :min -24 :max 24)) (y (gen-integer :min -24 :max 24)))
    (let* ((pair (g-sum-pair a b))
           (hull (g-convex-hull (g-vertex-differences b a)))
           (q (list (/ x 2) (/ y 2))))
      (is (eq (g-strictly-inside-hull-p q hull) (ames.geometry:penetrates-p pair q)))
      (is (eq (g-on-hull-boundary-p q hull) (not (null (ames.geometry:contacts-at pair q)))))
      ;; every hull vertex touches two contacts and penetrates nothing
      (let ((corner (first hull)))
        (is (not (ames.geometry:penetrates-p pair corner)))
        (is (= 2 (length (ames.geometry:contacts-at pair corner))))))))

(test geometry-disc-obstacle-is-the-polygon-pushed-out-by-the-radius
  (for-all ((b (g-gen-convex-polygon)) (radius (gen-integer :min 1 :max 5)))
    (let* ((rho (/ radius 2))
           (pair (ames.geometry:make-contact-pair-with-observer
                  'disc (g-shape (list 'circle rho)) 'b (g-shape (g-polygon-form b))))
           (contacts (ames.geometry:pair-contacts pair)))
      (is (= (* 2 (length b)) (length contacts)))
      (is (g-close-p (reduce #'+ (mapcar (lambda (c) (g-value (ames.geometry:contact-length c)))
                                         (remove :segment contacts :key #'ames.geometry:contact-kind)))
                     (* 2 pi rho)))
      (dolist (c contacts)
        (dolist (fraction '(0 1/4 1/2 1))
          (let* ((s (ames.geometry::e* fraction (ames.geometry:contact-length c)))
                 (point (ames.geometry:contact-point c s))
                 (normal (ames.geometry:contact-outward-normal c s)))
            (is (g-close-p (ames.geometry::norm-squared normal) 1))
            ;; h(n) of B (+) disc = h_B(n) + rho, reached at the point
            (is (< (abs (- (+ (g-support-value normal b) rho)
                           (g-value (ames.geometry::dot normal point))))
                   1d-9))))))))

(test geometry-polygon-observing-a-disc
  ;; the disc as obstacle: B (+) (-A) has h(n) = rho + max(-a . n)
  (for-all ((a (g-gen-convex-polygon)) (radius (gen-integer :min 1 :max 5)))
    (let* ((rho (/ radius 2))
           (pair (ames.geometry:make-contact-pair-with-observer
                  'a (g-shape (g-polygon-form a)) 'disc (g-shape (list 'circle rho))))
           (negated (mapcar (lambda (p) (mapcar #'- p)) a)))
      (is (= (* 2 (length a)) (length (ames.geometry:pair-contacts pair))))
      (dolist (c (ames.geometry:pair-contacts pair))
        (let* ((s (ames.geometry::e* 1/2 (ames.geometry:contact-length c)))
               (normal (ames.geometry:contact-outward-normal c s)))
          (is (< (abs (- (+ (g-support-value normal negated) rho)
                         (g-value (ames.geometry::dot normal (ames.geometry:contact-point c s)))))
                 1d-9)))))))

;;; Random non-convex (star-shaped) polygons

(defun g-gen-star-polygon (&key (points 8) (size 9))
  "A generator of simple counter-clockwise polygons, star-shaped about the origin and
usually not convex: random integer points sorted by angle."
  (lambda ()
    (loop
      (let* ((candidates (loop repeat (+ 4 (random (- points 3)))
                               collect (list (- (random (1+ (* 2 size))) size)
                                             (- (random (1+ (* 2 size))) size))))
             (points (remove-duplicates
                      (remove '(0 0) candidates :test #'equal)
                      :test (lambda (p q) (and (zerop (g-cross '(0 0) p q))
                                               (plusp (+ (* (first p) (first q))
                                                         (* (second p) (second q))))))))
             (sorted (sort (copy-list points) #'<
                           :key (lambda (p) (atan (float (second p) 1d0) (float (first p) 1d0))))))
        (when (and (>= (length sorted) 4)
                   (loop for (p q) on (append sorted (list (first sorted))) while q
                         always (plusp (g-cross '(0 0) p q))))
          (return sorted))))))

(defun g-point-in-polygon-p (q polygon)
  "True when Q lies strictly inside POLYGON (exact crossing number, boundary excluded)."
  (let ((inside nil))
    (loop for (a b) on (append polygon (list (first polygon))) while b
          do (when (and (zerop (g-cross a b q))
                        (<= (min (first a) (first b)) (first q) (max (first a) (first b)))
                        (<= (min (second a) (second b)) (second q) (max (second a) (second b))))
               (return-from g-point-in-polygon-p nil))
             (when (and (not (eq (> (second a) (second q)) (> (second b) (second q))))
                        (< (first q) (+ (first a) (/ (* (- (second q) (second a)) (- (first b) (first a)))
                                                     (- (second b) (second a))))))
               (setf inside (not inside))))
    inside))

(test geometry-point-in-random-star-polygons
  (for-all ((b (g-gen-star-polygon))
            (x (gen-integer :min -20 :max 20)) (y (gen-integer :min -20 :max 20)))
    (let ((pair (ames.geometry:make-contact-pair 'p (g-shape 'point) 'b (g-shape (g-polygon-form b))))
          (q (list (/ x 2) (/ y 2))))
      ;; one contact per edge (edges that continue straight on stay apart)
      (is (= (length b) (length (ames.geometry:pair-contacts pair))))
      (is (eq (g-point-in-polygon-p q b) (ames.geometry:penetrates-p pair q))
          "~S in ~S" q b))))

(test geometry-block-contacts-bound-the-penetration-region
  ;; just outside a contact the block is free, just inside it penetrates
  (for-all ((b (g-gen-star-polygon)))
    (let ((pair (ames.geometry:make-contact-pair-with-observer
                 'block (g-shape '(polygon (0 0) (1 0) (1 1) (0 1))) 'b (g-shape (g-polygon-form b)))))
      (dolist (c (ames.geometry:pair-contacts pair))
        (let* ((start (mapcar #'g-exact (ames.geometry:contact-start c)))
               (end (mapcar #'g-exact (ames.geometry:contact-end c)))
               (middle (mapcar (lambda (u v) (/ (+ u v) 2)) start end))
               (normal (list (- (second end) (second start)) (- (first start) (first end))))
               (step (/ 1 (* 1000000 (max (abs (first normal)) (abs (second normal)))))))
          (is (not (ames.geometry:penetrates-p pair middle)))
          (is (not (ames.geometry:penetrates-p
                    pair (mapcar (lambda (m n) (+ m (* step n))) middle normal))))
          (is (ames.geometry:penetrates-p
               pair (mapcar (lambda (m n) (- m (* step n))) middle normal))
              "~S: inside ~S is free" c middle))))))
