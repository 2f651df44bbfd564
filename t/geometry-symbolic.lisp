;;;; t/geometry-symbolic.lisp -- geometry on symbolic shapes, decided through the Maxima bridge.
;;;;
;;;; Every test starts its own bridge under the scenario's assumptions and closes it.
;;;; Expressions are compared by meaning (ames.maxima:equivalent-p), never by print form.

(in-package #:ames.tests)

(def-suite geometry-symbolic :in geometry
  :description "Contacts of shapes with parameters (the scenario language's wedge, ...).")

(in-suite geometry-symbolic)

(defun g-call-with-bridge (facts function)
  "Call FUNCTION with a fresh bridge, under the assumptions FACTS; close it afterwards."
  (let ((bridge (ames.maxima:make-bridge)))
    (unwind-protect
         (ames.maxima:with-assumptions (bridge facts)
           (funcall function bridge))
      (ames.maxima:close-bridge bridge))))

(defun g-same-meaning-p (bridge a b &key samples)
  "True when the expressions (or lists of expressions) A and B are equal: by Maxima, or,
when Maxima finds no proof and SAMPLES (binding alists satisfying the assumptions) are
given, by their values agreeing at every sample."
  (if (and (consp a) (consp b) (not (symbolp (car a))) (not (symbolp (car b))))
      (and (= (length a) (length b))
           (every (lambda (x y) (g-same-meaning-p bridge x y :samples samples)) a b))
      (or (ames.maxima:equivalent-p bridge a b)
          (and samples
               (every (lambda (bindings) (g-close-p a b bindings 1d-9)) samples)))))

(defparameter *g-wedge-facts* '((> h 0) (> a 0) (< a (/ pi 2)))
  "The wedge parameters' assumptions in the scenario language's example.")

(defparameter *g-wedge-form* '(polygon (0 0) ((/ h (tan a)) 0) (0 h))
  "The wedge of the scenario language's example (thesis section 2.6.1).")

(test geometry-point-against-symbolic-wedge
  (g-call-with-bridge
   *g-wedge-facts*
   (lambda (bridge)
     (let* ((pair (g-pair 'particle 'point 'wedge *g-wedge-form* bridge))
            (slope (g-contact pair '(:edge 1)))
            (base (g-contact pair '(:edge 0)))
            (back (g-contact pair '(:edge 2)))
            (start '((/ h (* 2 (tan a))) (/ h 2))))
       (is (= 3 (length (ames.geometry:pair-contacts pair))))
       (is (g-same-meaning-p bridge (ames.geometry:contact-start slope) '((/ h (tan a)) 0)))
       (is (g-same-meaning-p bridge (ames.geometry:contact-end slope) '(0 h)))
       (is (g-same-meaning-p bridge (ames.geometry:contact-length slope) '(/ h (sin a))))
       (is (g-same-meaning-p bridge (ames.geometry:contact-unit-tangent slope 's) '((- (cos a)) (sin a))))
       (is (g-same-meaning-p bridge (ames.geometry:contact-outward-normal slope 's) '((sin a) (cos a))))
       (is (g-same-meaning-p bridge (ames.geometry:contact-tangent-angle slope 's) '(- pi a)))
       (is (g-same-meaning-p bridge (ames.geometry:contact-normal-angle slope 's) '(- (/ pi 2) a)))
       (is (g-same-meaning-p bridge (ames.geometry:contact-outward-normal base 's) '(0 -1)))
       (is (g-same-meaning-p bridge (ames.geometry:contact-outward-normal back 's) '(-1 0)))
       (is (g-same-meaning-p bridge (ames.geometry:contact-length back) 'h))
       ;; the particle starts halfway down the slope, on it and on nothing else
       (let ((at (ames.geometry:contacts-at pair start)))
         (is (= 1 (length at)))
         (is (eq slope (car (first at))))
         (is (g-same-meaning-p bridge (cdr (first at)) '(/ h (* 2 (sin a)))))
         (is (g-same-meaning-p bridge (ames.geometry:contact-point slope (cdr (first at))) start)))
       (is (not (ames.geometry:penetrates-p pair start)))
       (is (ames.geometry:penetrates-p pair '((/ h (* 4 (tan a))) (/ h 4))))
       (is (not (ames.geometry:penetrates-p pair '((/ h (tan a)) h))))
       ;; dropped from (h/(2 tan a), h), it meets the slope when g tau^2 / 2 = h / 2
       (let* ((meeting (ames.geometry:contact-meeting slope '((/ h (* 2 (tan a))) (- h (* 1/2 g tau tau)))))
              (at-meeting (list (cons 'tau '(sqrt (/ h g))))))
         (ames.maxima:with-assumptions (bridge '((> g 0)))
           (is (g-same-meaning-p bridge (substitute-expressions at-meeting (ames.geometry:meeting-gap meeting)) 0))
           (dolist (relation (rest (ames.geometry:meeting-conditions meeting)))
             (is (eq :true (ames.algebra:decide bridge (substitute-expressions at-meeting relation)))
                 "~S" relation))))))))

(test geometry-symbolic-wedge-on-the-ground
  (g-call-with-bridge
   *g-wedge-facts*
   (lambda (bridge)
     (let* ((pair (g-pair 'wedge *g-wedge-form* 'ground '(half-plane (1 0) (0 0)) bridge))
            (floor (first (ames.geometry:pair-contacts pair))))
       (is (eq 'wedge (ames.geometry:pair-observer pair)))
       (is (= 1 (length (ames.geometry:pair-contacts pair))))
       (is (equal '(:edge 0 :of wedge) (ames.geometry:contact-observer-feature floor)))
       (is (equal '(:edge 0 :of ground) (ames.geometry:contact-obstacle-feature floor)))
       (is (= 1 (length (ames.geometry:contacts-at pair '(0 0)))))
       (is (= 1 (length (ames.geometry:contacts-at pair '((- h) 0)))))
       (is (null (ames.geometry:contacts-at pair '(0 h))))
       (is (ames.geometry:penetrates-p pair '(0 (- h))))))))

(test geometry-disc-against-symbolic-wedge
  ;; the corner arcs turn pi/2, pi - a and pi/2 + a: 2 pi in all
  (g-call-with-bridge
   (cons '(> rho 0) *g-wedge-facts*)
   (lambda (bridge)
     (let ((pair (ames.geometry:make-contact-pair-with-observer
                  'disc (g-shape '(circle rho) bridge) 'wedge (g-shape *g-wedge-form* bridge)
                  :bridge bridge)))
       (is (= 6 (length (ames.geometry:pair-contacts pair))))
       (loop for (vertex length) in '((0 (* rho (/ pi 2))) (1 (* rho (- pi a))) (2 (* rho (+ (/ pi 2) a))))
             do (let ((arc (g-contact pair (list :vertex vertex))))
                  (is (eq :arc (ames.geometry:contact-kind arc)))
                  ;; atan(1/tan a) = pi/2 - a escapes Maxima: checked at sample values
                  (is (g-same-meaning-p bridge (ames.geometry:contact-length arc) length
                                      :samples '(((h . 2) (a . 0.3d0) (rho . 0.5d0))
                                                 ((h . 1) (a . 1.2d0) (rho . 3))
                                                 ((h . 5) (a . 0.7d0) (rho . 1))))
                      "vertex ~D: ~S" vertex (ames.geometry:contact-length arc))))
       (let ((slope (g-contact pair '(:edge 1))))
         (is (g-same-meaning-p bridge (ames.geometry:contact-start slope)
                             '((+ (/ h (tan a)) (* rho (sin a))) (* rho (cos a))))))))))

(test geometry-symbolic-blocks
  ;; two blocks with symbolic sides, as in the thesis's blocks in a corner
  (g-call-with-bridge
   '((> w 0) (> d 0) (> l 0))
   (lambda (bridge)
     (let ((pair (ames.geometry:make-contact-pair-with-observer
                  'a (g-shape '(polygon (0 0) (w 0) (w d) (0 d)) bridge)
                  'b (g-shape '(polygon (0 0) (l 0) (l l) (0 l)) bridge)
                  :bridge bridge)))
       (is (= 4 (length (ames.geometry:pair-contacts pair))))
       (let ((top (g-contact pair '(:edge 2) '(:edge 0))))
         (is (not (null top)))
         (when top
           (is (g-same-meaning-p bridge (ames.geometry:contact-start top) '(l l)))
           (is (g-same-meaning-p bridge (ames.geometry:contact-end top) '((- w) l)))
           (is (g-same-meaning-p bridge (ames.geometry:contact-length top) '(+ l w)))))
       (is (ames.geometry:penetrates-p pair '((/ l 2) (/ l 2))))
       (is (not (ames.geometry:penetrates-p pair '((+ l 1) 0))))))))

(test geometry-symbolic-path-coordinates-give-v2-over-r
  (g-call-with-bridge
   '((> r 0))
   (lambda (bridge)
     (let* ((circle (first (ames.geometry:pair-contacts (g-pair 'particle 'point 'sphere '(circle r) bridge))))
            (a (ames.geometry:path-acceleration circle 's 'sdot 'sddot)))
       (is (g-same-meaning-p bridge (ames.geometry::dot a (ames.geometry:contact-inward-normal circle 's))
                           '(/ (expt sdot 2) r)))
       (is (g-same-meaning-p bridge (ames.geometry::dot a (ames.geometry:contact-unit-tangent circle 's))
                           'sddot))
       (is (g-same-meaning-p bridge (ames.geometry:contact-curvature circle) '(/ 1 r)))
       ;; the second time derivative of the position along the circle is the path acceleration
       (dolist (s-of-tau '((* w tau) (+ (* 1/2 k (expt tau 2)) (* v tau) s0)))
         (let* ((sdot (ames.geometry::differentiate s-of-tau 'tau))
                (sddot (ames.geometry::differentiate sdot 'tau))
                (q (ames.geometry:contact-point circle s-of-tau))
                (acceleration (mapcar (lambda (x) (ames.geometry::differentiate
                                                   (ames.geometry::differentiate x 'tau) 'tau))
                                      q)))
           (is (g-same-meaning-p bridge acceleration
                               (ames.geometry:path-acceleration circle s-of-tau sdot sddot)))))))))

(test geometry-symbolic-facts-that-cannot-be-decided
  (g-call-with-bridge
   '()
   (lambda (bridge)
     (let ((condition (handler-case (progn (g-shape '(polygon (0 0) (x 0) (0 1)) bridge) nil)
                        (ames.geometry:undecidable-geometric-fact (c) c))))
       (is (typep condition 'ames.geometry:undecidable-geometric-fact))
       (is (member 'x (alexandria:flatten (ames.geometry:undecidable-fact condition)))))))
  (g-call-with-bridge
   '((> l 0) (> r 0))
   (lambda (bridge)
     ;; sizes that cannot be compared leave the first body observing, without error
     (is (eq 'block (ames.geometry:choose-observer
                     'block (g-shape '(polygon (0 0) (l 0) (l l) (0 l)) bridge)
                     'ball (g-shape '(circle r) bridge) :bridge bridge)))
     (is (eq 'ball (ames.geometry:choose-observer
                    'block (g-shape '(polygon (0 0) (l 0) (l l) (0 l)) bridge)
                    'ball (g-shape '(circle (/ l 4)) bridge) :bridge bridge)))))
  (g-call-with-bridge
   '((> x 0))
   (lambda (bridge)
     (is (ames.geometry:shape-convex-p (g-shape '(polygon (0 0) (x 0) (0 1)) bridge)))
     (signals ames.geometry:invalid-shape (g-shape '(polygon (0 0) (0 1) (x 0)) bridge)))))

(test geometry-meeting-and-leaving-conditions
  "The meeting and leaving conditions the simulator solves: a drop onto the slope's
middle meets it (gap 0, approaching, within its ends) at sqrt(h/g); the base's line is
crossed at sqrt(2 h / g) only from inside, with the drop outside the base's extent; the
slope's start leads on to the base."
  (g-call-with-bridge
   (list* '(> g 0) *g-wedge-facts*)
   (lambda (bridge)
     (let* ((pair (g-pair 'particle 'point 'wedge *g-wedge-form* bridge))
            (slope (g-contact pair '(:edge 1)))
            (base (g-contact pair '(:edge 0)))
            (fall '((/ h (* 2 (tan a))) (- h (* 1/2 g tau tau))))
            (meeting (ames.geometry:contact-meeting slope fall)))
       (multiple-value-bind (time status)
           (ames.algebra:earliest-root bridge (ames.geometry:meeting-gap meeting) 'tau)
         (is (eq :found status))
         (is (g-same-meaning-p bridge time '(sqrt (/ h g))))
         (when (eq status :found)
           (is (eq :true (ames.algebra:decide
                          bridge (substitute-expressions (list (cons 'tau time))
                                                         `(< ,(ames.geometry:meeting-rate meeting) 0)))))
           (dolist (relation (ames.geometry:meeting-extent meeting))
             (is (eq :true (ames.algebra:decide
                            bridge (substitute-expressions (list (cons 'tau time)) relation)))))))
       (let ((below (ames.geometry:contact-meeting base fall)))
         (is (eq :true (ames.algebra:decide
                        bridge (substitute-expressions (list (cons 'tau '(sqrt (/ (* 2 h) g))))
                                                       `(> ,(ames.geometry:meeting-rate below) 0))))))
       (let ((leavings (ames.geometry:contact-leavings slope 's 'sdot)))
         (is (= 2 (length leavings)))
         (is (eq base (ames.geometry:leaving-neighbour
                       (find :start leavings :key #'ames.geometry:leaving-endpoint)))))))))

(defparameter *g-tilted-block*
  '(polygon ((- (* (/ b 2) (cos a))) (* (/ b 2) (sin a)))
            ((* (/ b 2) (cos a)) (- (* (/ b 2) (sin a))))
            ((+ (* (/ b 2) (cos a)) (* b (sin a))) (+ (- (* (/ b 2) (sin a))) (* b (cos a))))
            ((+ (- (* (/ b 2) (cos a))) (* b (sin a))) (+ (* (/ b 2) (sin a)) (* b (cos a)))))
  "scenarios/block-on-incline.lisp: a square of side b tilted to sit on the slope.")

(test geometry-tilted-block-on-symbolic-incline
  ;; the square sits face on face on the slope's middle; the flat contact runs the
  ;; slope's length plus the block's side, h / sin a + b
  (g-call-with-bridge
   (list* '(> b 0) '(< b h) *g-wedge-facts*)
   (lambda (bridge)
     (let* ((pair (ames.geometry:make-contact-pair
                   'incline (g-shape *g-wedge-form* bridge) 'block (g-shape *g-tilted-block* bridge)
                   :bridge bridge :fixed '(incline)))
            (face (g-contact pair '(:edge 1) '(:edge 0)))
            (start '((/ h (* 2 (tan a))) (/ h 2))))
       (is (eq 'block (ames.geometry:pair-observer pair)))
       (is (= 6 (length (ames.geometry:pair-contacts pair))))
       (is (not (null face)))
       (when face
         (is (g-same-meaning-p bridge (ames.geometry:contact-length face) '(+ (/ h (sin a)) b)))
         (is (g-same-meaning-p bridge (ames.geometry:contact-outward-normal face 's) '((sin a) (cos a))))
         (let ((at (ames.geometry:contacts-at pair start)))
           (is (equal (list face) (mapcar #'car at)))
           (is (g-same-meaning-p bridge (cdr (first at)) '(/ (+ (/ h (sin a)) b) 2)
                                 :samples '(((h . 2) (a . 0.4d0) (b . 1))
                                            ((h . 3) (a . 1.2d0) (b . 1/2)))))))
       (is (not (ames.geometry:penetrates-p pair start)))
       (is (ames.geometry:penetrates-p pair '((/ h (* 2 (tan a))) (/ h 4))))))))
