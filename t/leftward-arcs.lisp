;;;; t/leftward-arcs.lisp -- events on a circle for a body moving toward -x (issue 20, class
;;;; 1): relations between constants that agree to round-off decided exactly, never by
;;;; Maxima's float sign(); a turning point, a lift-off and a plastic landing after it,
;;;; on fresh scenarios, against the textbook's closed forms.

(in-package #:ames.tests)

(def-suite leftward-arcs :in all-tests
  :description "Events on arcs for motion toward -x: exact zeros of constants (issue 20).")

(in-suite leftward-arcs)

(test constants-equal-to-round-off-are-decided-exactly
  "sin(pi/2 + acos c) = c, asin c + acos c = pi/2, and cos(a + pi/2 + 2 atan w) = 2 cos(a)/3
for the dome's lift-off root w: Maxima's sign() takes each difference for its float
(about -1e-15) and calls it negative; DECIDE proves it zero."
  (call-with-bridge
   (lambda (b)
     (let* ((c 407/1032)
            (energy `(/ (- (* 1032 (sin (/ (* 4 (/ (+ (* 3 pi) (* 6 (acos ,c))) 8)) 3))) 407) 64))
            (w '(/ (- (sqrt (+ 5 (* 4 (expt (sin 17/20) 2)))) (* 3 (sin 17/20))) (* 5 (cos 17/20))))
            (normal `(- (* 24 (sin (/ (+ 17 (* 10 pi) (* 40 (atan ,w))) 20))) (* 16 (cos 17/20)))))
       (is (eq :true (ames.algebra:decide b `(>= ,energy 0))))
       (is (eq :false (ames.algebra:decide b `(< ,energy 0))))
       (is (eq :true (ames.algebra:decide b `(= (- (/ (- (* 3 (asin ,c)) (* 3 pi)) 4))
                                                (/ (+ (* 3 pi) (* 6 (acos ,c))) 8)))))
       (is (eq :true (ames.algebra:decide b `(= (+ (asin ,c) (acos ,c)) (/ pi 2)))))
       (is (eq :true (ames.algebra:decide b `(= ,normal 0))))
       (is (eq :false (ames.algebra:decide b `(> ,normal 0))))
       (is (eq :true (ames.algebra:decide
                      b '(= (- (* 1032 (sin (+ (atan (/ 407 (* 25 (sqrt 1439)))) (* 2 (atan (/ (* 25 (sqrt 1439)) 407))))))
                               407)
                            0))))
       ;; a difference of 1e-12 is not round-off to be proven away: never :TRUE
       (is (not (eq :true (ames.algebra:decide b `(= (asin ,c) (+ (asin ,c) (expt 10 -12)))))))
       ;; sides that differ plainly are decided as before
       (is (eq :true (ames.algebra:decide b `(> (acos ,c) 1))))))))

(defun leftward-history (text bridge)
  (ames:run-scenario (first (ames:read-scenarios-from-string text)) :bridge bridge))

(defun entry-named (alist name)
  (second (find name alist :key (lambda (entry) (symbol-name (first entry))) :test #'string-equal)))

(defun numbers-of (expressions)
  (mapcar (lambda (x) (float (ames.base:expression-value x) 1d0)) expressions))

(test leftward-loop-turns-below-the-centre
  "Launched toward -x at v0 = 4 in a loop of radius 1 under g = 10 (v0^2 < 2 g r), the
particle turns at the height v0^2 / (2 g) = 4/5, at x = -sqrt(1 - (1 - 4/5)^2), at rest,
and swings back (a periodic state)."
  (call-with-bridge
   (lambda (b)
     (let* ((history (leftward-history "(scenario l \"\" (gravity 10) (restitution 1)
                 (body loop :fixed t :shape (arc :center (0 1) :radius 1 :from 0 :to (* 2 pi) :solid :outside))
                 (body particle :mass 1 :position (0 0) :velocity (-4 0) :shape point) (simulate :states 2))" b))
            (states (ames::history-states history))
            (turn (first states)))
       (is (eq :turns (first (ames::state-end-event turn))))
       (destructuring-bind (x y) (numbers-of (entry-named (ames::state-final-positions turn) "PARTICLE"))
         (is (near (- (sqrt 0.96d0)) x 1d-9))
         (is (near 4/5 y 1d-9)))
       (is (ames::state-periodic (second states)))))))

(test leftward-dome-lift-off-and-plastic-landing
  "Released at rest at the angle 1/2 left of a dome's top (r = 1, g = 10), the particle
leaves the dome where cos = (2/3) cos(1/2) (thesis 2.6.3), flies free (no contact), lands
on the floor and, with e = 0, slides on it with the horizontal velocity of the lift-off,
-v cos with v^2 = 2 g r cos(1/2) / 3."
  (call-with-bridge
   (lambda (b)
     (let* ((history (leftward-history "(scenario d \"\" (gravity 10) (restitution 0)
                 (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                 (body dome :fixed t :shape (arc :center (0 0) :radius 1 :from 0 :to pi :solid :inside))
                 (body particle :mass 1 :position ((- (sin 1/2)) (cos 1/2)) :velocity (0 0) :shape point)
                 (simulate :states 3))" b))
            (states (ames::history-states history))
            (cos-lift (* 2/3 (cos 0.5d0)))
            (v (sqrt (/ (* 20 (cos 0.5d0)) 3))))
       (is (= 3 (length states)))
       (is (eq :lift-off (first (ames::state-end-event (first states)))))
       (destructuring-bind (x y) (numbers-of (entry-named (ames::state-final-positions (first states)) "PARTICLE"))
         (is (near (- (sqrt (- 1 (* cos-lift cos-lift)))) x 1d-9))
         (is (near cos-lift y 1d-9)))
       (is (null (ames::state-contacts (second states))))
       (is (eq :collision (first (ames::state-end-event (second states)))))
       (is (ames::state-contacts (third states)))
       (destructuring-bind (vx vy) (numbers-of (entry-named (ames::state-initial-velocities (third states)) "PARTICLE"))
         (is (near (- (* v cos-lift)) vx 1d-9))
         (is (near 0 vy 1d-12)))))))
