;;;; t/real-roots.lisp -- a root of undecided realness is no event time (src/algebra/real-roots.lisp).
;;;;
;;;; A body thrown up at v under gravity g reaches the height TOP above its start when
;;;; v tau - g tau^2 / 2 = TOP, at tau = (v -+ sqrt(v^2 - 2 g TOP)) / g: real only when
;;;; v^2 >= 2 g TOP. A point meeting a circle's rim along the tangent of a rope closes a
;;;; squared gap, (v tau - g tau^2 / 2 - TOP)^2, whose roots solve() writes with that square
;;;; root (without %i when the discriminant's sign is open): a negative discriminant means
;;;; no meeting, a positive one the smaller root, an undecided one no answer.
;;;;
;;;; The Atwood machine over a massive pulley (scenarios/atwood-massive-pulley.lisp) with
;;;; restitution 1/2 between the heavy mass and the floor: heavy lands at
;;;; v = R sqrt(2 (m1 - m2) g h / K), K = I + (m1 + m2) R^2, bounces up at v / 2 (its rope
;;;; slack: the pulley turns on, paying rope out) and, in free flight, lands again after
;;;; 2 (v / 2) / g = v / g. It rises (v/2)^2 / (2 g) < h, far below the pulley (top > 2 h):
;;;; the contact with the pulley's rim, a complex time, must not end that state.

(in-package #:ames.tests)

(def-suite real-roots :in all-tests
  :description "Roots of undecided realness are not event times: squared gaps, the bouncing Atwood machine.")

(in-suite real-roots)

(defparameter *squared-rise-gap* '(expt (- (* v tm) (/ (* g (expt tm 2)) 2) top) 2)
  "The squared gap of a body thrown up at V under G to the height TOP, at time TM.")

(defparameter *rise-facts* '((> v 0) (> g 0) (> top 0)))

(test squared-gap-with-a-negative-discriminant-has-no-root
  "v^2 < 2 g top: the body never reaches top; the roots are complex, and no root is found.
Asked after the same search under fewer facts, as a run does (the bridge's forms of the
roots are then those without %i, which sign() took for positive reals)."
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b *rise-facts*)
       (is (eq :unknown (ames.algebra:earliest-root b *squared-rise-gap* 'tm)))
       (ames.maxima:with-assumptions (b '((> (* 2 g top) (expt v 2))))
         (is (eq :none (ames.algebra:earliest-root b *squared-rise-gap* 'tm))))))))

(test squared-gap-with-a-positive-discriminant-has-the-smaller-root
  "v^2 > 2 g top: the body reaches top first at (v - sqrt(v^2 - 2 g top)) / g."
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b (append *rise-facts* '((< (* 2 g top) (expt v 2)))))
       (multiple-value-bind (root status) (ames.algebra:earliest-root b *squared-rise-gap* 'tm)
         (is (eq :found status))
         (when (eq status :found)
           (is (ames.maxima:equivalent-p
                b root '(/ (- v (sqrt (- (expt v 2) (* 2 g top)))) g)))
           (is (ames.maxima:equivalent-p
                b (substitute-expressions (list (cons 'tm root)) *squared-rise-gap*) 0))))))))

(test squared-gap-with-an-undecided-discriminant-is-unknown
  "The sign of v^2 - 2 g top open: no root is claimed, with or without the run's values
(which settle it for the caller, not inside the proof)."
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b *rise-facts*)
       (is (eq :unknown (ames.algebra:earliest-root b *squared-rise-gap* 'tm)))
       (ames.algebra:call-with-parameter-values
        '((v . 7/5) (g . 981/100) (top . 3))
        (lambda ()
          (is (eq :unknown (ames.algebra:earliest-root b *squared-rise-gap* 'tm)))))))))

(test cubic-with-a-complex-pair-of-undecided-realness
  "(tm - 1)(tm^2 - 2 a tm + b), a, b > 0: solve() writes the pair a -+ sqrt(a^2 - b), both
positive when real. Not a proven root under a^2 < b (then only tm = 1); 1 or
a - sqrt(a^2 - b), whichever is earlier, only when a^2 >= b is known."
  (call-with-bridge
   (lambda (b)
     (let ((cubic '(* (- tm 1) (+ (expt tm 2) (* -2 a tm) bb))))
       ;; undecided first, then under a^2 < b (see the test of the negative discriminant)
       (ames.maxima:with-assumptions (b '((> a 2) (> bb 0)))
         (multiple-value-bind (root status) (ames.algebra:earliest-root b cubic 'tm)
           (is (not (eq :found status)) "a root claimed, ~S" root))
         (ames.maxima:with-assumptions (b '((> bb (expt a 2))))
           (multiple-value-bind (root status) (ames.algebra:earliest-root b cubic 'tm)
             (is (eq :found status))
             (is (eql 1 root)))))))))

(defun bouncing-atwood-scenario ()
  "scenarios/atwood-massive-pulley.lisp with restitution 1/2 between heavy and the
floor, its main line (:branch nil) over two states."
  (let* ((file (find "atwood-massive-pulley" (scenario-files) :key #'pathname-name :test #'string=))
         (form (first (ames:read-scenario-forms (uiop:read-file-string file))))
         (simulate-p (lambda (clause)
                       (and (consp clause) (symbolp (first clause))
                            (string= (symbol-name (first clause)) "SIMULATE")))))
    (ames:parse-scenario
     (append (remove-if simulate-p form)
             (list (read-from-string "(restitution heavy floor 1/2)")
                   (list (first (find-if simulate-p form)) :states 2 :branch nil))))))

(test bouncing-atwood-lands-again
  "After the bounce heavy, in free flight, lands again after v / g (the file header), not
at a complex time of contact with the pulley's rim. The run is stopped once state 1 is
analysed (the second landing's impact is not this test's)."
  (with-fixture simulator-bridge ()
    (let* ((scenario (bouncing-atwood-scenario))
           (state (catch 'state-1
                    (let ((ames.simulator:*state-hook*
                            (lambda (history state)
                              (declare (ignore history))
                              (when (= 1 (ames::state-index state)) (throw 'state-1 state)))))
                      (ames:run-scenario scenario :bridge bridge :numeric t)
                      nil)))
           (v (in-scenario-terms
               scenario '(* big-r (sqrt (/ (* 2 (- m1 m2) g h) (+ i (* (+ m1 m2) (expt big-r 2)))))))))
      (is (not (null state)) "the run reached state 1")
      (when state
        (is (equal '(:collision "HEAVY" "FLOOR") (event-names (ames::state-end-event state)))
            "state 1 ends: ~S" (ames::state-end-event state))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same bridge "the flight after the bounce" (ames::state-duration state)
                    `(/ ,v ,(in-scenario-terms scenario 'g)))))))))
