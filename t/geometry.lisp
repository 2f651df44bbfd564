;;;; t/geometry.lisp -- tests of the geometry layer on exact numeric shapes (no Maxima needed).
;;;;
;;;; Shapes with rational coordinates are decided by exact arithmetic, so these tests
;;;; check exact results (rationals compared with =, points with exact equality); where
;;;; square roots or angles make a value irrational, it is compared by its floating value.

(in-package #:ames.tests)

(def-suite geometry :in all-tests
  :description "The geometry layer (src/geometry/): shapes, C-space contacts, path coordinates.")

(in-suite geometry)

;;; Helpers

(defparameter *g-bitten-square*
  '(outline (line (0 0) (4 0)) (line (4 0) (4 4)) (line (4 4) (3 4))
            (arc :center (2 4) :radius 1 :from 0 :to (- pi))
            (line (1 4) (0 4)) (line (0 4) (0 0)))
  "A 4 x 4 square with a half-disc bite out of its top: a concave arc.")

(defun g-shape (form &optional bridge)
  "FORM parsed as a shape."
  (ames.geometry:parse-shape form :bridge bridge))

(defun g-pair (name-1 form-1 name-2 form-2 &optional bridge)
  "The contact pair of two bodies given by their shape forms."
  (ames.geometry:make-contact-pair name-1 (g-shape form-1 bridge) name-2 (g-shape form-2 bridge)
                                   :bridge bridge))

(defun g-value (expression &optional bindings)
  "The floating value of EXPRESSION (an error when it has none)."
  (let ((value (expression-value expression bindings)))
    (assert value () "~S has no numeric value under ~S" expression bindings)
    (float value 1d0)))

(defun g-close-p (a b &optional bindings (tolerance 1d-9))
  "True when the expressions (or lists of expressions) A and B agree numerically."
  (if (consp a)
      (if (and (consp b) (= (length a) (length b)) (not (symbolp (car a))))
          (every (lambda (x y) (g-close-p x y bindings tolerance)) a b)
          (< (abs (- (g-value a bindings) (g-value b bindings))) tolerance))
      (< (abs (- (g-value a bindings) (g-value b bindings))) tolerance)))

(defun g-exact (x)
  "The exact rational value of the expression X, or :NOT-RATIONAL."
  (or (ames.geometry::rational-value x) :not-rational))

(defun g-point= (p q)
  "True when the points P and Q are exactly equal (rational coordinates)."
  (and (eql (g-exact (first p)) (g-exact (first q)))
       (eql (g-exact (second p)) (g-exact (second q)))
       (not (eq (g-exact (first p)) :not-rational))))

(defun g-contact (pair obstacle-feature &optional observer-feature)
  "The contact of PAIR whose obstacle feature (without :of) is OBSTACLE-FEATURE."
  (find-if (lambda (c)
             (and (equal (butlast (ames.geometry:contact-obstacle-feature c) 2) obstacle-feature)
                  (or (null observer-feature)
                      (equal (butlast (ames.geometry:contact-observer-feature c) 2) observer-feature))))
           (ames.geometry:pair-contacts pair)))

(defun g-contacts-chain-p (pair &key open)
  "True when each contact of PAIR ends where another starts (numerically): all of them
for a closed boundary, all but one when OPEN (a thin surface's contacts)."
  (let* ((contacts (ames.geometry:pair-contacts pair))
         (unmatched (count-if-not
                     (lambda (c)
                       (let ((end (ames.geometry:contact-end c)))
                         (or (null end)
                             (some (lambda (d) (and (not (eq c d))
                                                    (g-close-p end (ames.geometry:contact-start d))))
                                   contacts))))
                     contacts)))
    (= unmatched (if open 1 0))))

(defun g-holds-numerically-p (relation bindings)
  "The truth of RELATION (a relation, AND, OR) with BINDINGS, by floating evaluation."
  (ecase (car relation)
    (and (every (lambda (r) (g-holds-numerically-p r bindings)) (cdr relation)))
    (or (some (lambda (r) (g-holds-numerically-p r bindings)) (cdr relation)))
    ((= < > <= >=)
     (let ((a (g-value (second relation) bindings)) (b (g-value (third relation) bindings)))
       (ecase (car relation)
         (= (< (abs (- a b)) 1d-9)) (< (< a b)) (> (> a b))
         (<= (<= a (+ b 1d-9))) (>= (>= a (- b 1d-9))))))))

;;; Shapes

(test geometry-parses-every-shape-kind
  (is (eq :point (ames.geometry:shape-kind (g-shape 'point))))
  (is (eq :circle (ames.geometry:shape-kind (g-shape '(circle 2)))))
  (is (eq :polygon (ames.geometry:shape-kind (g-shape '(polygon (0 0) (4 0) (0 3))))))
  (is (eq :segment (ames.geometry:shape-kind (g-shape '(segment (4 0) (0 0))))))
  (is (eq :arc (ames.geometry:shape-kind (g-shape '(arc :center (0 0) :radius 1 :from 0 :to pi)))))
  (is (eq :half-plane (ames.geometry:shape-kind (g-shape '(half-plane (1 0) (0 0))))))
  (let ((d (g-shape '(outline (line (0 0) (2 0))
                              (arc :center (2 1) :radius 1 :from (- (/ pi 2)) :to (/ pi 2))
                              (line (2 2) (0 2)) (line (0 2) (0 0))))))
    (is (eq :outline (ames.geometry:shape-kind d)))
    (is (ames.geometry:shape-convex-p d))
    ;; a 2 x 2 square plus a half disc of radius 1
    (is (g-close-p (ames.geometry:shape-area d) (+ 4 (/ pi 2)))))
  (is (ames.geometry:shape-convex-p (g-shape '(polygon (0 0) (4 0) (0 3)))))
  (is (not (ames.geometry:shape-convex-p
            (g-shape '(polygon (0 0) (2 0) (2 1) (1 1) (1 2) (0 2))))))
  (is (eql 6 (ames.geometry:shape-area (g-shape '(polygon (0 0) (4 0) (0 3))))))
  (is (eql 3 (ames.geometry:shape-area (g-shape '(polygon (0 0) (2 0) (2 1) (1 1) (1 2) (0 2))))))
  (is (eq :infinite (ames.geometry:shape-area (g-shape '(half-plane (1 0) (0 0))))))
  (is (g-close-p (ames.geometry:shape-area (g-shape '(circle 2))) (* 4 pi))))

(defparameter *g-invalid-shapes*
  '((polygon (0 0) (0 1) (1 0))                          ; clockwise
    (polygon (0 0) (1 0))                                ; too few vertices
    (polygon (0 0) (1 0) (2 0))                          ; no area
    (polygon (0 0) (6 0) (6 6) (3 6) (3 -2) (2 -2) (2 6) (0 6)) ; crosses itself
    (polygon (0 0) (1 0) (1 0) (0 1))                    ; repeated vertex
    (polygon (0 0) (2 0) (2 2) (1 2) (1 4) (1 2) (0 2))  ; folds back on itself
    (polygon (0 0) (1 0 5) (0 1))                        ; not a point
    (polygon (0 0) ("x" 0) (0 1))                        ; not an expression
    (circle 0)                                           ; zero radius
    (circle -1)                                          ; negative radius
    (circle)                                             ; no radius
    (segment (1 1) (1 1))                                ; degenerate segment
    (half-plane (0 0) (0 0))                             ; degenerate half-plane
    (outline (line (0 0) (1 0)) (line (1 1) (0 1)))      ; pieces do not join
    (outline (line (0 0) (0 1)) (line (0 1) (1 0)) (line (1 0) (0 0))) ; clockwise
    (outline (arc :center (0 0) :radius 1 :from 0 :to 0)) ; zero-length arc
    (outline (line (0 0) (1 0)) (circle 1))              ; not an outline piece
    (outline)                                            ; no pieces
    (arc :center (0 0) :radius 1 :from 1 :to 0)          ; clockwise track
    (arc :center (0 0) :radius 1 :from 0 :to 7)          ; more than a full turn
    (arc :center (0 0) :radius 0 :from 0 :to 1)          ; zero radius
    (arc :center (0 0) :radius 1 :from 0 :to 1 :solid :sideways)
    (arc :radius 1 :from 0 :to 1)                        ; no centre
    (arc :center (0 0) :radius 1 :from 0 :to 1 :colour red)
    (triangle (0 0) (1 0) (0 1))                         ; unknown shape
    42
    "point")
  "Shape forms that each must signal INVALID-SHAPE.")

(test geometry-invalid-shapes-signal-their-condition
  (dolist (form *g-invalid-shapes*)
    (let ((condition (handler-case (progn (g-shape form) nil)
                       (ames.geometry:invalid-shape (c) c))))
      (is (typep condition 'ames.geometry:invalid-shape) "~S was accepted" form)
      (when condition
        (is (typep condition 'ames-error))
        (is (equal form (ames.geometry:invalid-shape-form condition)))
        (is (plusp (length (princ-to-string condition))))))))

(test geometry-invalid-shape-reports-name-the-fault
  (flet ((report (form) (handler-case (progn (g-shape form) "")
                          (ames.geometry:invalid-shape (c) (princ-to-string c)))))
    (is (search "clockwise" (report '(polygon (0 0) (0 1) (1 0)))))
    (is (search "zero radius" (report '(circle 0))))
    (is (search "degenerate segment" (report '(segment (1 1) (1 1)))))
    (is (search "do not join" (report '(outline (line (0 0) (1 0)) (line (1 1) (0 1))))))
    (is (search "crosses itself" (report '(polygon (0 0) (6 0) (6 6) (3 6) (3 -2) (2 -2) (2 6) (0 6)))))))

(test geometry-undecidable-fact-names-the-fact-and-offers-restarts
  (let ((condition (handler-case (progn (g-shape '(polygon (0 0) (x 0) (0 1))) nil)
                     (ames.geometry:undecidable-geometric-fact (c) c))))
    (is (typep condition 'ames.geometry:undecidable-geometric-fact))
    (is (member 'x (alexandria:flatten (ames.geometry:undecidable-fact condition))))
    (is (equal '(polygon (0 0) (x 0) (0 1)) (ames.geometry:undecidable-subject condition))))
  ;; choosing the answer through the restart lets parsing go on
  (let ((shape (handler-bind ((ames.geometry:undecidable-geometric-fact
                                (lambda (c) (declare (ignore c))
                                  (invoke-restart 'ames.geometry:assume-true))))
                 (g-shape '(polygon (0 0) (x 0) (0 1))))))
    (is (eq :polygon (ames.geometry:shape-kind shape)))))

;;; Configuration-space obstacles

(test geometry-rectangle-plus-rectangle
  ;; A = [0,2]x[0,1] observes B = [0,4]x[0,3]: B (+) (-A) = [-2,4]x[-1,3]
  (let* ((pair (g-pair 'a '(polygon (0 0) (2 0) (2 1) (0 1)) 'b '(polygon (0 0) (4 0) (4 3) (0 3))))
         (contacts (ames.geometry:pair-contacts pair)))
    (is (eq 'a (ames.geometry:pair-observer pair)))
    (is (= 4 (length contacts)))
    (is (every (lambda (c) (eq :segment (ames.geometry:contact-kind c))) contacts))
    (loop for (obstacle-edge observer-edge start end normal length)
            in '(((:edge 0) (:edge 2) (-2 -1) (4 -1) (0 -1) 6)
                 ((:edge 1) (:edge 3) (4 -1) (4 3) (1 0) 4)
                 ((:edge 2) (:edge 0) (4 3) (-2 3) (0 1) 6)
                 ((:edge 3) (:edge 1) (-2 3) (-2 -1) (-1 0) 4))
          do (let ((c (g-contact pair obstacle-edge observer-edge)))
               (is (not (null c)) "no contact ~S of b against ~S of a" obstacle-edge observer-edge)
               (when c
                 (is (g-point= start (ames.geometry:contact-start c)))
                 (is (g-point= end (ames.geometry:contact-end c)))
                 (is (g-point= normal (ames.geometry:contact-outward-normal c 1)))
                 (is (eql length (ames.geometry:contact-length c)))
                 (is (eql 0 (ames.geometry:contact-curvature c)))
                 (is (equal (append observer-edge '(:of a)) (ames.geometry:contact-observer-feature c)))
                 (is (equal (append obstacle-edge '(:of b)) (ames.geometry:contact-obstacle-feature c))))))
    ;; the corner (4 3) lies on two contacts: at the end of one, the start of the next
    (let ((at (ames.geometry:contacts-at pair '(4 3))))
      (is (= 2 (length at)))
      (is (equal '(0 4) (sort (mapcar (lambda (entry) (g-exact (cdr entry))) at) #'<))))
    (is (ames.geometry:penetrates-p pair '(1 1)))
    (is (not (ames.geometry:penetrates-p pair '(4 3))))
    (is (not (ames.geometry:penetrates-p pair '(4 1))))
    (is (ames.geometry:penetrates-p pair '(3999/1000 1)))
    (is (not (ames.geometry:penetrates-p pair '(5 5))))))

(test geometry-diamond-plus-square-pairs-corners-with-faces
  ;; a diamond of area 2 observes a 4 x 4 square: the obstacle is an octagon whose
  ;; axis-aligned sides are the square's faces against the diamond's corners and whose
  ;; slanted sides are the square's corners against the diamond's faces
  (let* ((pair (g-pair 'diamond '(polygon (1 0) (0 1) (-1 0) (0 -1))
                       'square '(polygon (0 0) (4 0) (4 4) (0 4))))
         (contacts (ames.geometry:pair-contacts pair)))
    (is (= 8 (length contacts)))
    (is (g-contacts-chain-p pair))
    (let ((bottom (g-contact pair '(:edge 0))))
      (is (equal '(:vertex 1 :of diamond) (ames.geometry:contact-observer-feature bottom)))
      (is (g-point= '(0 -1) (ames.geometry:contact-start bottom)))
      (is (g-point= '(4 -1) (ames.geometry:contact-end bottom))))
    (let ((corner (g-contact pair '(:vertex 1))))
      (is (equal '(:edge 1 :of diamond) (ames.geometry:contact-observer-feature corner)))
      (is (g-point= '(4 -1) (ames.geometry:contact-start corner)))
      (is (g-point= '(5 0) (ames.geometry:contact-end corner))))
    (is (equal '((-1 0) (-1 4) (0 -1) (0 5) (4 -1) (4 5) (5 0) (5 4))
               (sort (mapcar (lambda (c) (mapcar #'g-exact (ames.geometry:contact-start c))) contacts)
                     (lambda (p q) (or (< (first p) (first q))
                                       (and (= (first p) (first q)) (< (second p) (second q))))))))))

(test geometry-point-against-numeric-wedge
  (let* ((pair (g-pair 'particle 'point 'wedge '(polygon (0 0) (4 0) (0 3))))
         (slope (g-contact pair '(:edge 1))))
    (is (eq 'particle (ames.geometry:pair-observer pair)))
    (is (g-point= '(2 3/2) (ames.geometry:relative-position pair '(7 5/2) '(5 1))))
    (is (= 3 (length (ames.geometry:pair-contacts pair))))
    (is (equal '(:point :of particle) (ames.geometry:contact-observer-feature slope)))
    (is (eql 5 (ames.geometry:contact-length slope)))
    (is (g-point= '(-4/5 3/5) (ames.geometry:contact-unit-tangent slope 0)))
    (is (g-point= '(3/5 4/5) (ames.geometry:contact-outward-normal slope 0)))
    (is (g-point= '(-3/5 -4/5) (ames.geometry:contact-inward-normal slope 0)))
    (is (g-close-p (ames.geometry:contact-tangent-angle slope 0) (atan 3d0 -4d0)))
    (is (g-close-p (ames.geometry:contact-normal-angle slope 0) (atan 4d0 3d0)))
    (is (g-point= '(2 3/2) (ames.geometry:contact-point slope 5/2)))
    (let ((at (ames.geometry:contacts-at pair '(2 3/2))))
      (is (= 1 (length at)))
      (is (eq slope (car (first at))))
      (is (eql 5/2 (cdr (first at)))))
    (is (null (ames.geometry:contacts-at pair '(1 1))))
    (is (ames.geometry:penetrates-p pair '(1 1)))
    (is (not (ames.geometry:penetrates-p pair '(2 3/2))))
    (is (not (ames.geometry:penetrates-p pair '(3 3))))
    (signals ames.geometry:position-not-on-contact (ames.geometry:contact-parameter slope '(1 1)))))

(test geometry-disc-against-polygon-rounds-the-corners
  ;; a disc of radius 1 against the 3-4-5 wedge: every edge pushed out by 1 along its
  ;; normal, every corner an arc of radius 1 centred on it, the arcs turning 2 pi in all
  (let* ((pair (g-pair 'disc '(circle 1) 'wedge '(polygon (0 0) (4 0) (0 3))))
         (contacts (ames.geometry:pair-contacts pair))
         (arcs (remove :segment contacts :key #'ames.geometry:contact-kind))
         (segments (remove :arc contacts :key #'ames.geometry:contact-kind)))
    (is (eq 'disc (ames.geometry:pair-observer pair)))
    (is (= 6 (length contacts)))
    (is (= 3 (length arcs)))
    (is (g-contacts-chain-p pair))
    (loop for (vertex center) in '((0 (0 0)) (1 (4 0)) (2 (0 3)))
          do (let ((arc (g-contact pair (list :vertex vertex))))
               (is (eq :arc (ames.geometry:contact-kind arc)))
               (is (equal '(:circle :of disc) (ames.geometry:contact-observer-feature arc)))
               (is (g-point= center (ames.geometry:contact-center arc)))
               (is (eql 1 (ames.geometry:contact-radius arc)))
               (is (eql 1 (g-exact (ames.geometry:contact-curvature arc))))))
    (is (g-close-p (reduce #'+ (mapcar (lambda (c) (g-value (ames.geometry:contact-length c))) arcs))
                   (* 2 pi)))
    (is (g-close-p (ames.geometry:contact-length (g-contact pair '(:vertex 0))) (/ pi 2)))
    (is (equal '(3 4 5) (sort (mapcar (lambda (c) (g-exact (ames.geometry:contact-length c))) segments) #'<)))
    (let ((slope (g-contact pair '(:edge 1))))
      (is (g-point= '(23/5 4/5) (ames.geometry:contact-start slope)))
      (is (g-point= '(3/5 19/5) (ames.geometry:contact-end slope))))
    ;; the arc around the right-angle corner: from the left face's normal to the bottom's
    (let ((corner (g-contact pair '(:vertex 0))))
      (is (g-point= '(-1 0) (ames.geometry:contact-start corner)))
      (is (g-point= '(0 -1) (ames.geometry:contact-end corner)))
      (is (g-close-p (ames.geometry:contact-outward-normal corner (/ pi 4))
                     (list (- (sqrt 0.5d0)) (- (sqrt 0.5d0))))))
    (is (ames.geometry:penetrates-p pair '(-1/2 -1/2)))
    (is (not (ames.geometry:penetrates-p pair '(-1 -1))))
    (is (ames.geometry:penetrates-p pair '(2 -1/2)))))

(test geometry-point-against-fixed-circle
  ;; the thesis's particle on a sphere: one contact, the whole circle
  (let* ((pair (g-pair 'particle 'point 'sphere '(circle 5)))
         (circle (first (ames.geometry:pair-contacts pair))))
    (is (= 1 (length (ames.geometry:pair-contacts pair))))
    (is (eq :circle (ames.geometry:contact-kind circle)))
    (is (g-point= '(0 0) (ames.geometry:contact-center circle)))
    (is (eql 5 (ames.geometry:contact-radius circle)))
    (is (eql 1/5 (g-exact (ames.geometry:contact-curvature circle))))
    (is (g-close-p (ames.geometry:contact-length circle) (* 10 pi)))
    (is (null (ames.geometry:contact-end circle)))
    (is (null (ames.geometry:contact-leavings circle 's 'sdot)))
    (is (equal '(:circle :of sphere) (ames.geometry:contact-obstacle-feature circle)))
    ;; s runs counter-clockwise from the point at angle 0
    (is (g-point= '(5 0) (ames.geometry:contact-point circle 0)))
    (is (g-close-p (cdr (first (ames.geometry:contacts-at pair '(0 5)))) (* 5/2 pi)))
    (is (g-close-p (cdr (first (ames.geometry:contacts-at pair '(3 4)))) (* 5 (atan 4d0 3d0))))
    (is (g-close-p (cdr (first (ames.geometry:contacts-at pair '(3 -4)))) (* 5 (- (* 2 pi) (atan 4d0 3d0)))))
    (is (g-close-p (ames.geometry:contact-outward-normal circle '(* 5/2 pi)) '(0 1)))
    (is (null (ames.geometry:contacts-at pair '(1 1))))
    (is (ames.geometry:penetrates-p pair '(1 1)))
    (is (not (ames.geometry:penetrates-p pair '(3 4))))
    (is (not (ames.geometry:penetrates-p pair '(6 0))))))

;;; Path coordinates

(test geometry-path-coordinates-on-a-circle-give-v2-over-r
  (let* ((circle (first (ames.geometry:pair-contacts (g-pair 'particle 'point 'sphere '(circle 5)))))
         (bindings '((s . 1.3d0) (sdot . 2.0d0) (sddot . 0.7d0))))
    (let ((a (ames.geometry:path-acceleration circle 's 'sdot 'sddot))
          (inward (ames.geometry:contact-inward-normal circle 's))
          (tangent (ames.geometry:contact-unit-tangent circle 's)))
      ;; normal component sdot^2 / R toward the centre, tangential component sddot
      (is (g-close-p (ames.geometry::dot a inward) (/ (* 2 2) 5) bindings))
      (is (g-close-p (ames.geometry::dot a tangent) 0.7d0 bindings))
      ;; the inward normal points at the centre
      (is (g-close-p (ames.geometry::v+ (ames.geometry:contact-point circle 's)
                                        (ames.geometry::vscale 5 inward))
                     '(0 0) bindings)))
    (is (g-close-p (ames.geometry:path-velocity circle 's 'sdot)
                   (ames.geometry::vscale 'sdot (ames.geometry:contact-unit-tangent circle 's))
                   '((s . 0.4d0) (sdot . 3d0))))))

(defun g-path-kinematics-agree-p (contact s-of-tau sample-times)
  "True when the second time derivative of CONTACT's point at S-OF-TAU equals
PATH-ACCELERATION with the derivatives of S-OF-TAU, at the SAMPLE-TIMES (numerically)."
  (let* ((sdot (ames.geometry::differentiate s-of-tau 'tau))
         (sddot (ames.geometry::differentiate sdot 'tau))
         (q (ames.geometry:contact-point contact s-of-tau))
         (velocity (mapcar (lambda (x) (ames.geometry::differentiate x 'tau)) q))
         (acceleration (mapcar (lambda (x) (ames.geometry::differentiate x 'tau)) velocity)))
    (every (lambda (time)
             (let ((bindings (list (cons 'tau time))))
               (and (g-close-p velocity (ames.geometry:path-velocity contact s-of-tau sdot) bindings 1d-8)
                    (g-close-p acceleration
                               (ames.geometry:path-acceleration contact s-of-tau sdot sddot)
                               bindings 1d-8))))
           sample-times)))

(test geometry-path-acceleration-is-the-second-derivative-of-position
  ;; on a convex arc, a concave arc (inside a bowl) and a segment
  (let ((circle (first (ames.geometry:pair-contacts (g-pair 'p 'point 'sphere '(circle 5)))))
        (bowl (first (ames.geometry:pair-contacts
                      (g-pair 'p 'point 'bowl '(arc :center (0 0) :radius 2 :from pi :to (* 2 pi)
                                                :solid :outside)))))
        (slope (g-contact (g-pair 'p 'point 'wedge '(polygon (0 0) (4 0) (0 3))) '(:edge 1))))
    (dolist (contact (list circle bowl slope))
      (is (g-path-kinematics-agree-p contact '(+ (* 1/3 (expt tau 3)) (* 2 tau) 1/2) '(0 0.3d0 1.1d0))
          "~A" contact))))

;;; Meeting and leaving contacts

(test geometry-meeting-a-segment-from-outside
  ;; a particle dropped at (1, 3) falls onto the slope 3x + 4y = 12 at y = 9/4,
  ;; when 3 - tau^2/2 = 9/4, i.e. tau^2 = 3/2
  (let* ((pair (g-pair 'particle 'point 'wedge '(polygon (0 0) (4 0) (0 3))))
         (slope (g-contact pair '(:edge 1)))
         (meeting (ames.geometry:contact-meeting slope '(1 (- 3 (* 1/2 tau tau)))))
         (at-meeting (list (cons 'tau (sqrt 1.5d0)))))
    (is (g-close-p (ames.geometry:meeting-gap meeting) 0 at-meeting))
    (is (plusp (g-value (ames.geometry:meeting-gap meeting) '((tau . 0)))))
    (is (every (lambda (r) (g-holds-numerically-p r at-meeting))
               (ames.geometry:meeting-conditions meeting)))
    ;; straight down at x = 5, the slope's line is reached (at y = -3/4, tau^2 = 15/2)
    ;; but not the slope
    (let ((miss (ames.geometry:contact-meeting slope '(5 (- 3 (* 1/2 tau tau)))))
          (at-line (list (cons 'tau (sqrt 7.5d0)))))
      (is (g-close-p (ames.geometry:meeting-gap miss) 0 at-line))
      (is (notevery (lambda (r) (g-holds-numerically-p r at-line))
                    (ames.geometry:meeting-extent miss))))
    ;; moving away from the line: the rate is positive when the gap vanishes
    (let ((leaving (ames.geometry:contact-meeting slope '((+ 8/5 tau) (+ 9/5 tau)))))
      (is (g-close-p (ames.geometry:meeting-gap leaving) 0 '((tau . 0))))
      (is (not (g-holds-numerically-p (list '<= (ames.geometry:meeting-rate leaving) 0) '((tau . 0))))))))

(test geometry-meeting-an-arc
  ;; the disc's contact with the wedge's right-angle corner is the arc of radius 1
  ;; around (0 0) between angles pi and 3 pi/2; a disc moving along y = -x/2 - ... meets it
  (let* ((pair (g-pair 'disc '(circle 1) 'wedge '(polygon (0 0) (4 0) (0 3))))
         (corner (g-contact pair '(:vertex 0)))
         (meeting (ames.geometry:contact-meeting corner '((- tau 3) (- tau 3))))
         (time (- 3 (sqrt 0.5d0))))
    (is (g-close-p (ames.geometry:meeting-gap meeting) 0 (list (cons 'tau time))))
    (is (every (lambda (r) (g-holds-numerically-p r (list (cons 'tau time))))
               (ames.geometry:meeting-conditions meeting)))
    ;; the same circle met on its far side (angle pi/4) is outside the arc
    (is (notevery (lambda (r) (g-holds-numerically-p r (list (cons 'tau (+ 3 (sqrt 0.5d0))))))
                  (ames.geometry:meeting-extent meeting)))))

(test geometry-leaving-a-contact-past-its-ends
  (let* ((pair (g-pair 'particle 'point 'wedge '(polygon (0 0) (4 0) (0 3))))
         (slope (g-contact pair '(:edge 1)))
         (leavings (ames.geometry:contact-leavings slope 's 'sdot)))
    (is (equal '(:start :end) (mapcar #'ames.geometry:leaving-endpoint leavings)))
    (is (equal '((= s 0) (= s 5)) (mapcar #'ames.geometry:leaving-equation leavings)))
    (is (equal '((< sdot 0) (> sdot 0)) (mapcar #'ames.geometry:leaving-direction leavings)))
    (is (g-point= '(4 0) (ames.geometry:leaving-point (first leavings))))
    (is (eq (g-contact pair '(:edge 0)) (ames.geometry:leaving-neighbour (first leavings))))
    (is (eq (g-contact pair '(:edge 2)) (ames.geometry:leaving-neighbour (second leavings)))))
  ;; an unbounded line has no ends
  (let ((ground (first (ames.geometry:pair-contacts
                        (g-pair 'wedge '(polygon (0 0) (4 0) (0 3)) 'ground '(half-plane (1 0) (0 0)))))))
    (is (eq :line (ames.geometry:contact-kind ground)))
    (is (eq :infinite (ames.geometry:contact-length ground)))
    (is (null (ames.geometry:contact-leavings ground 's 'sdot)))))

;;; Observers

(test geometry-observer-choice
  (flet ((observer (a form-a b form-b)
           (values (ames.geometry:choose-observer a (g-shape form-a) b (g-shape form-b)))))
    (is (eq 'p (observer 'p 'point 'w '(polygon (0 0) (4 0) (0 3)))))
    (is (eq 'p (observer 'w '(polygon (0 0) (4 0) (0 3)) 'p 'point)))
    (is (eq 'w (observer 'ground '(half-plane (1 0) (0 0)) 'w '(polygon (0 0) (4 0) (0 3)))))
    (is (eq 'w (observer 'table '(segment (4 0) (0 0)) 'w '(polygon (0 0) (4 0) (0 3)))))
    (is (eq 'small (observer 'big '(polygon (0 0) (4 0) (4 4) (0 4)) 'small '(circle 1))))
    (is (eq 'small (observer 'small '(circle 1) 'big '(polygon (0 0) (4 0) (4 4) (0 4)))))
    ;; a fixed body does not observe a moving one, however small
    (is (eq 'big (nth-value 0 (ames.geometry:choose-observer
                               'big (g-shape '(polygon (0 0) (4 0) (4 4) (0 4)))
                               'small (g-shape '(circle 1)) :fixed '(small)))))
    ;; equal sizes: the first body observes
    (is (eq 'a (observer 'a '(polygon (0 0) (1 0) (1 1) (0 1)) 'b '(polygon (0 0) (1 0) (1 1) (0 1)))))
    (is (eq 'p (observer 'p 'point 'bowl '(arc :center (0 0) :radius 1 :from pi :to (* 2 pi)
                                           :solid :outside))))))

(test geometry-unsupported-pairs-signal
  (signals ames.geometry:unsupported-shape-pair
    (g-pair 'floor '(half-plane (1 0) (0 0)) 'wall '(half-plane (0 0) (0 1))))
  (signals ames.geometry:unsupported-shape-pair
    (g-pair 'block '(polygon (0 0) (1 0) (1 1) (0 1))
            'bowl '(arc :center (0 0) :radius 5 :from pi :to (* 2 pi) :solid :outside)))
  (signals ames.geometry:unsupported-shape-pair
    (g-pair 'disc '(circle 3)
            'bowl '(arc :center (0 0) :radius 2 :from pi :to (* 2 pi) :solid :outside)))
  (let ((condition (handler-case (g-pair 'disc '(circle 1/4) 'bitten *g-bitten-square*)
                     (ames.geometry:unsupported-shape-pair (c) c))))
    (is (typep condition 'ames-error))
    (is (eq 'bitten (ames.geometry:unsupported-obstacle condition)))
    (is (eq 'disc (ames.geometry:unsupported-observer condition)))))
