;;;; t/tipping-criterion.lisp -- a pushed block that tips or slides (issue 23): the textbook's criterion.
;;;;
;;;; The block (width w, height k, mass m, uniform) on a rough floor (mu), pushed by P > mu m g
;;;; at height y above its centre on its back face. Sliding flat, its back corner's normal
;;;; force is (w/2) m g - y P - (k/2) mu m g over w: it stays flat while
;;;; T: y P + (k/2) mu m g <= (w/2) m g, and tips about its front edge otherwise. With
;;;; W: 3 mu w k < 4 w^2 + k^2 (no Painleve paradox), the front edge cannot stick while it
;;;; tips where T holds: sticking needs 2 (w^2 + k^2) (P - mu m g) <= 3 (k + mu w) tau, tau =
;;;; P (y + k/2) - m g w/2 the tipping torque about the edge, and under T tau <= (k/2) (P -
;;;; mu m g), so 4 w^2 + k^2 <= 3 mu w k would follow. DECIDE proves that by combining T and
;;;; P > mu m g (src/algebra/combined-bounds.lisp), and the choice search branches on T first
;;;; (src/simulator/choice.lisp). A block at rest in its angle slides with a constant
;;;; acceleration (src/simulator/frozen-rotation.lisp).

(in-package #:ames.tests)

(def-suite tipping-criterion :in all-tests
  :description "The pushed block that tips or slides: the textbook's criterion as the run's
branch, the static pivot ruled out where it slides, two bounds combined by DECIDE.")

(in-suite tipping-criterion)

(defparameter *pushed-block-facts*
  '((> m 0) (> g 0) (> w 0) (> k 0) (> mu 0) (> p 0) (> y (* -1/2 k)) (< y (* 1/2 k))
    (> p (* mu m g)) (< (* 3 mu w k) (+ (* 4 w w) (* k k))))
  "The pushed block's assumptions: the push beats friction, and no Painleve paradox.")

(defparameter *slides-flat*
  '(<= (+ (* y p) (* 1/2 k mu m g)) (* 1/2 w m g))
  "T, the textbook's criterion: the block pushed at height y stays flat.")

(defparameter *front-edge-sticks*
  ;; 2 (w^2 + k^2) (P - mu m g) <= 3 (k + mu w) (P (y + k/2) - m g w / 2)
  '(<= (* 2 (+ (* w w) (* k k)) (- p (* mu m g)))
       (* 3 (+ k (* mu w)) (- (* p (+ y (* 1/2 k))) (* 1/2 m g w))))
  "The static friction limit of the front edge while the block tips about it from rest.")

(defun pushed-block-file ()
  "The file of the block pushed low (y = -9k/20)."
  (merge-pathnames "scenarios/awaiting-rotation/pushed-block-slides.lisp"
                   (asdf:system-source-directory "ames")))

(test sticking-front-edge-is-ruled-out-where-the-block-slides-flat
  "Under T and W, the front edge's static friction limit fails: DECIDE proves it by
combining T with P > mu m g (Farkas in P); without W (the Painleve case) it proves
nothing, and the limit does hold at a point where W fails."
  (call-with-bridge
   (lambda (b)
     (is (eq :false (decided b (cons *slides-flat* *pushed-block-facts*) *front-edge-sticks*)))
     ;; and the other way round: where the edge can stick, the block does not slide flat
     (is (eq :false (decided b (cons *front-edge-sticks* *pushed-block-facts*) *slides-flat*)))
     (let ((without-w (cons *slides-flat* (butlast *pushed-block-facts*))))
       (is (not (eq :false (decided b without-w *front-edge-sticks*))))
       ;; w = k = 1, mu = 3, y = -1/4, m g = 1, P = 4: T holds (as an equality), W fails
       ;; (9 >= 5) and the edge can stick (4 <= 6): a :FALSE above would have been wrong
       (flet ((at (expression)
                (ames.maxima:simplify
                 b (sublis '((w . 1) (k . 1) (mu . 3) (y . -1/4) (m . 1) (g . 1) (p . 4))
                           `(- ,(third expression) ,(second expression))))))
         (is (>= (at *slides-flat*) 0))
         (is (>= (at *front-edge-sticks*) 0)))))))

(test combined-bounds-prove-only-what-holds
  "Two lower bounds on p combined: a p - d >= 0 and p - c > 0 give 2 a p - d - a c > 0
(their sum with multipliers 1 and a), but not 2 a p - d - 2 a c > 0, which fails at an
admissible point."
  (call-with-bridge
   (lambda (b)
     ;; a p - d >= 0 and p - c > 0 with a > 0 bound p below; 2 a p - d - a c > 0 follows
     (is (eq :true (decided b '((> a 0) (> c 0) (>= (- (* a p) d) 0) (> (- p c) 0))
                            '(> (- (* 2 a p) d (* a c)) 0))))
     ;; but not 2 a p - d - 2 a c > 0 (-1/2 at a = c = 1, p = d = 3/2)
     (is (not (eq :true (decided b '((> a 0) (> c 0) (>= (- (* a p) d) 0) (> (- p c) 0))
                                 '(> (- (* 2 a p) d (* 2 a c)) 0))))))))

(test pushed-block-branches-on-the-textbook-criterion-first
  "The pushed block (y = -9k/20, symbolic): the first fact the run branches on is T,
y P + (k/2) mu m g against (w/2) m g, up to a factor of one sign (the back corner's
normal force, the criterion over w)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (unbranched (first (ames:read-scenario-file (pushed-block-file)))))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (condition (getf (ames::history-notes history) :stopped-by)))
      (is (eq :ambiguous (ames::history-outcome history)))
      (when (typep condition 'ames::ambiguous-transition)
        (let* ((fact (ames::ambiguous-transition-missing-fact condition))
               (criterion (in-scenario-terms
                           scenario '(- (+ (* -9/20 k p) (* 1/2 k mu m g)) (* 1/2 w m g))))
               (ratio (ames.maxima:simplify
                       bridge `(/ (- ,(second fact) ,(third fact)) ,criterion) :strategy :ratsimp)))
          ;; a factor of one sign, free of the push and of friction (the back normal
          ;; force is the criterion over w)
          (is (and (free-of-p (in-scenario-terms scenario 'p) ratio)
                   (free-of-p (in-scenario-terms scenario 'mu) ratio)
                   (call-with-scenario-facts
                    bridge scenario
                    (lambda ()
                      (or (eq :true (ames.algebra:decide bridge `(> ,ratio 0)))
                          (eq :true (ames.algebra:decide bridge `(< ,ratio 0)))))))
              "the fork's fact ~S is not the textbook's criterion (ratio ~S)" fact ratio))))))

(defparameter *pushed-flat-block-form*
  '(scenario pushed-flat-block "A block pushed at its centre along a smooth floor."
    (parameters (m :positive) (g :positive) (w :positive) (k :positive) (f :positive))
    (gravity g)
    (body floor :fixed t :shape (half-plane (1 0) (0 0)))
    (body block :mass m :inertia :uniform :position (0 (/ k 2)) :velocity (0 0)
     :shape (polygon ((- (/ w 2)) (- (/ k 2))) ((/ w 2) (- (/ k 2)))
                     ((/ w 2) (/ k 2)) ((- (/ w 2)) (/ k 2))))
    (force push :on block :value (f 0))
    (simulate :states 1 :until 1))
  "A rotating block on two corners, held flat: its angle stays 0.")

(test block-held-flat-on-two-corners-slides-in-closed-form
  "A uniform block pushed by f at its centre along a smooth floor rests on two corners,
its angle held at 0: its model's angular acceleration depends on the angle and omega, but
vanishes at 0 and 0, so it slides with the constant acceleration f/m, x = f tau^2 / (2 m),
each corner carrying m g / 2 (src/simulator/frozen-rotation.lisp), not integrated
numerically."
  (with-fixture simulator-bridge ()
    (let ((scenario (ames:parse-scenario *pushed-flat-block-form*)))
      (multiple-value-bind (history states) (run-of scenario bridge)
        (declare (ignore history))
        (is (= 1 (length states)))
        (let ((state (first states)))
          (when state
            (flet ((x (form) (in-scenario-terms scenario form)))
              (call-with-scenario-facts
               bridge scenario
               (lambda ()
                 (is-same-vector bridge "sliding flat" (per-body (ames::state-accelerations state) "BLOCK")
                                 (x '((/ f m) 0)))
                 (is-same-vector bridge "where it is at t = 1"
                                 (per-body (ames::state-final-positions state) "BLOCK")
                                 (x '((/ f (* 2 m)) (/ k 2))))
                 (is-same bridge "its angle at t = 1"
                          (rotation-entry (ames.simulator:state-final-angles state) "BLOCK") 0)
                 (let ((normals (loop for force in (ames::state-forces-of state)
                                      when (eq (first force) :normal) collect (fourth force))))
                   (is (= 2 (length normals)))
                   (dolist (n normals)
                     (is-same bridge "a corner's share" n (x '(/ (* m g) 2))))))))))))))
