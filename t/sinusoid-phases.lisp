;;;; t/sinusoid-phases.lisp -- sinusoids written with a phase (issue 23): a hinged rod launched
;;;; from hanging, whose speed after its turning point is A + B sin(x - asin q), and a gap
;;;; closed along a tangent of a circle (a square: its root a double one).
;;;;
;;;; Expected results:
;;;;   3 g - l w^2 - 3 g sin(x - asin q), q = (l w^2 - 3 g)/(3 g), is A + B cos x + C sin x with
;;;;     A = 3 g - l w^2, B = 3 g q = l w^2 - 3 g, C = -3 g sqrt(1 - q^2) (sin of a sum);
;;;;   its first root after 0 is x = pi + 2 asin q (sin(x - asin q) = q again): past pi when
;;;;     q > 0, before it when q < 0 (the sign of l w^2 - 3 g, a readable fact);
;;;;   a uniform rod of length l hanging from a hinge, launched at w: omega^2 = w^2 - (3 g / l)
;;;;     (1 + sin s) (s its angle, -pi/2 hanging), so it goes over the top exactly when
;;;;     l w^2 > 6 g, and otherwise turns back where sin s = (l w^2 - 3 g)/(3 g);
;;;;   (a s^2 + b s + c)^2 k has the roots of a s^2 + b s + c.
;;;; Compared by Maxima-checked equivalence.

(in-package #:ames.tests)

(def-suite sinusoid-phases :in all-tests
  :description "Sinusoids with an asin/acos phase, and polynomials with a repeated factor, in root searches.")

(in-suite sinusoid-phases)

(defparameter *launched-rod-facts* '((> g 0) (> l 0) (> w 0) (< (* l (expt w 2)) (* 6 g))))

(test sinusoid-with-an-asin-phase-is-read
  "3 g - l w^2 - 3 g sin(x - asin q) is read as A + B cos x + C sin x (the textbook's sine of
a sum), and its first root ahead makes it vanish."
  (with-fixture simulator-bridge ()
    (ames.maxima:with-assumptions (bridge *launched-rod-facts*)
      (let* ((q '(/ (- (* l (expt w 2)) (* 3 g)) (* 3 g)))
             (expression `(- (* 3 g) (* l (expt w 2)) (* 3 g (sin (- x (asin ,q))))))
             (parts (ames.algebra:sinusoid-coefficients bridge expression 'x)))
        (is (= 4 (length parts)) "read: ~S" parts)
        (when (= 4 (length parts))
          (destructuring-bind (a b c k) parts
            (is-same bridge "the mean" a '(- (* 3 g) (* l (expt w 2))))
            (is-same bridge "the cosine's coefficient" b `(* 3 g ,q))
            (is (ames.maxima:equivalent-p bridge c `(- (* 3 g (sqrt (- 1 (expt ,q 2))))))
                "the sine's coefficient: ~S" c)
            (is-same bridge "the frequency" k 1)))
        ;; before pi or past it by the sign of q: the readable fact on l w^2 - 3 g
        (multiple-value-bind (root fact)
            (ames.algebra:earliest-trigonometric-root bridge expression 'x)
          (is (eq :unknown root))
          (is (and (consp fact) (member (first fact) '(< > <= >=))
                   (realp (ames.maxima:simplify
                           bridge `(/ (- ,(second fact) ,(third fact)) (- (* l (expt w 2)) (* 3 g)))
                           :strategy :ratsimp)))
              "the fact is on l w^2 - 3 g: ~S" fact))
        (ames.maxima:with-assumptions (bridge '((> (* l (expt w 2)) (* 3 g))))
          (multiple-value-bind (root status)
              (ames.algebra:earliest-trigonometric-root bridge expression 'x)
            (is (eq :found status) "the root: ~S ~S" root status)
            (when (eq status :found)
              (is (ames.maxima:zero-after-trigexpand-p
                   bridge (substitute-expressions (list (cons 'x root)) expression) 0)
                  "the root makes it vanish: ~S" root)
              (is (eq :true (ames.algebra:decide bridge `(> ,root pi))) "past pi: ~S" root)
              (is (eq :true (ames.algebra:decide bridge `(< ,root (* 2 pi)))) "before 2 pi: ~S" root))))))))

(test sinusoid-with-an-acos-phase-is-read
  "a + b cos(x + acos p) + c sin(x + asin p): each phase taken apart."
  (with-fixture simulator-bridge ()
    (ames.maxima:with-assumptions (bridge '((> p 0) (< p 1) (> a 0) (> b 0) (> c 0)))
      (let* ((expression '(+ a (* b (cos (+ x (acos p)))) (* c (sin (+ x (asin p))))))
             (parts (ames.algebra:sinusoid-coefficients bridge expression 'x)))
        (is (= 4 (length parts)) "read: ~S" parts)
        (when (= 4 (length parts))
          (destructuring-bind (a0 b0 c0 k) parts
            (is-same bridge "the mean" a0 'a)
            (is (ames.maxima:equivalent-p bridge b0 '(+ (* b p) (* c p))) "cos: ~S" b0)
            (is (ames.maxima:equivalent-p bridge c0 '(* (- c b) (sqrt (- 1 (expt p 2)))))
                "sin: ~S" c0)
            (is-same bridge "the frequency" k 1)))))))

(test a-square-has-the-roots-of-its-square-root
  "k (a s^2 + b s + c)^2 with radicals in its coefficients (which hide the square from
gcd()): its square-free part is a s^2 + b s + c up to a factor free of s."
  (with-fixture simulator-bridge ()
    (ames.maxima:with-assumptions (bridge '((> k 0) (> a 0) (> c 0) (> h 0) (> g 0)))
      (let* ((quadratic '(+ (* a (expt s 2)) (* (sqrt (* 2 g h)) s) (- c)))
             (square `(* k (expt ,quadratic 2)))
             (reduced (ames.algebra:square-free-part bridge square 's)))
        (is (not (null reduced)) "a square is found")
        (when reduced
          (let ((ratio (ames.maxima:simplify bridge `(/ ,reduced ,quadratic) :strategy :ratsimp)))
            (is (free-of-p 's ratio) "the square root up to a constant: ~S" reduced)))
        (is (null (ames.algebra:square-free-part bridge `(* ,quadratic (- s 3) (+ s 1)) 's))
            "no repeated factor, nothing reduced")))))

(defparameter *launched-hanging-rod*
  "(scenario rod-hinged-launched-hanging
     \"A uniform rod hanging from a hinge at its top end, launched sideways.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1))
                 (w :positive (:value 2)))
     (gravity g)
     (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
               :position (0 (- (/ l 2))) :angle (- (/ pi 2)) :velocity ((/ (* w l) 2) 0)
               :angular-velocity w)
     (hinge pin :body rod :at ((- (/ l 2)) 0))
     (simulate :states 3))"
  "A hinged rod launched from hanging at a symbolic angular speed w.")

(defparameter *launched-horizontal-rod*
  "(scenario rod-hinged-launched
     \"A uniform rod hinged at one end, launched upward from the horizontal.\"
     (parameters (m :positive (:value 1)) (g :positive (:value 981/100)) (l :positive (:value 1))
                 (w :positive (:value 2)))
     (gravity g)
     (body rod :mass m :inertia :uniform :shape (segment ((- (/ l 2)) 0) ((/ l 2) 0))
               :position ((/ l 2) 0) :velocity (0 (/ (* w l) 2)) :angular-velocity w)
     (hinge pin :body rod :at ((- (/ l 2)) 0))
     (simulate :states 1))"
  "A hinged rod launched upward from the horizontal at a symbolic angular speed w.")

(test launched-hinged-rod-branches-on-going-over-the-top
  "The rod launched from hanging at w: the run branches on l w^2 - 6 g (over the top or
not, the boundary its own branch), and every branch ends without an ambiguity (the
speed after the turning point, a sinusoid with an asin phase, is read). Launched from
the horizontal, on l w^2 - 3 g (omega^2 = w^2 - 3 g sin(theta) / l)."
  (check-launched-rod *launched-hanging-rod* '(- (* l (expt w 2)) (* 6 g)))
  (check-launched-rod *launched-horizontal-rod* '(- (* l (expt w 2)) (* 3 g))))

(defun check-launched-rod (text boundary)
  "Run the scenario TEXT: it forks first on a multiple of BOUNDARY, and no branch ends
ambiguous or failed."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario (first (ames:read-scenario-forms text))))
           (history (ames:run-scenario scenario :bridge bridge))
           (fork (first (ames::history-states history)))
           (fact (and fork (ames::state-missing-fact fork))))
      (is (eq :branched (ames::history-outcome history)))
      (is (member (first fact) '(< > <= >=)) "a readable fact: ~S" fact)
      (when (member (first fact) '(< > <= >=))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (let ((difference `(- ,(second fact) ,(third fact)))
                 (top (in-scenario-terms scenario boundary)))
             (is (realp (ames.maxima:simplify bridge `(/ ,difference ,top) :strategy :ratsimp))
                 "a multiple of ~S: ~S" boundary fact)))))
      (labels ((leaves (states)
                 (loop for state in states
                       append (if (ames::state-branches state)
                                  (loop for branch in (ames::state-branches state)
                                        collect (getf branch :outcome)
                                        append (leaves (getf branch :states)))
                                  '()))))
        (let ((outcomes (leaves (ames::history-states history))))
          (is (not (null outcomes)))
          (is (notany (lambda (o) (member o '(:ambiguous :failed))) outcomes)
              "every branch ends: ~S" outcomes))))))
