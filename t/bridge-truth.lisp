;;;; t/bridge-truth.lisp -- the truth interface: what a physicist knows, abs, names, values, and deciding only what matters.
;;;;
;;;; The facts of issue 9 are asserted here as relations, so that the truth work is
;;;; verified apart from the simulator; t/truth-table.lisp holds the wider table and
;;;; t/truth-scenarios.lisp the scenarios. Soundness is checked against numbers: a verdict
;;;; DECIDE proves is never contradicted at an admissible point.

(in-package #:ames.tests)

(def-suite bridge-truth :in all-tests
  :description "DECIDE as a physicist: angles, signed factors, monotonicity, squares;
abs; order-preserving names; parameter values; geometry asking only what matters.")

(in-suite bridge-truth)

(defun decided (bridge facts relation)
  "DECIDE's verdict on RELATION under FACTS."
  (ames.maxima:with-assumptions (bridge facts)
    (ames.algebra:decide bridge relation)))

;;; The facts of issue 9

(test issue-9-facts-are-decided-as-a-physicist-would
  (call-with-bridge
   (lambda (b)
     ;; the disc down the wedge: cos(-(2a - pi)/2) = sin a > 0 (and the variant met with
     ;; the wedge's other corner, -cos(-(2a - 3 pi)/2) = sin a)
     (is (eq :true (decided b '((> a 0) (< a (/ pi 2))) '(> (cos (* -1/2 (- (* 2 a) pi))) 0))))
     (is (eq :true (decided b '((> a 0) (< a (/ pi 2)))
                            '(> (- (cos (* -1/2 (- (* 2 a) (* 3 pi))))) 0))))
     ;; the raised ramp: false for every h0 > 0, the particle leaves the ramp first
     (is (eq :false (decided b '((> g 0) (> h0 0) (> l 0) (> a 0) (< a (/ pi 2)))
                             '(<= (/ (sqrt (+ (* 2 h0) (* (tan a) l))) (* (sin a) (sqrt g)))
                                  (/ (sqrt l) (* (sqrt (cos a)) (sqrt (sin a)) (sqrt g)))))))
     ;; the disc at 30 degrees: monotonicity of sqrt
     (is (eq :true (decided b '((> g 0) (> k 0) (> h 0) (< h k) (> r 0) (< r h))
                            '(<= (/ (* 2 (sqrt (+ h (* (- (sqrt 3) 2) r)))) (sqrt g))
                                 (/ (* 2 (sqrt h)) (sqrt g)))))))))

(test quarter-turns-are-shifted-out-exactly
  "Every rewriting of REDUCE-QUARTER-TURNS has the value of what it rewrites."
  (let ((state (sb-ext:seed-random-state 7)))
    (dolist (function '(sin cos tan))
      (dolist (angle '((- (/ pi 2) a) (+ a pi) (* -1/2 (- (* 2 a) (* 3 pi))) (- a)
                       (+ (* 3/2 pi) (* -1 a) b) (- (* 5/2 pi) (* 2 a)) (/ (- pi (* 2 a)) 2)))
        (let* ((original (list function angle))
               (reduced (ames.algebra::reduce-quarter-turns original)))
          (is (not (equal reduced original)) "~S was left as it is" original)
          (dotimes (i 5)
            (let* ((values `((a . ,(+ 0.1d0 (random 1.3d0 state))) (b . ,(random 1d0 state))))
                   (x (expression-value original values))
                   (y (expression-value reduced values)))
              (is (and x y (< (abs (- x y)) 1d-9)) "~S = ~S at ~S: ~S against ~S"
                  original reduced values x y))))))))

(test angle-ranges-are-exact
  (flet ((sign-of (function angle facts)
           (ames.algebra::range-trigonometric-sign
            function (ames.algebra::expression-range
                      angle (ames.algebra::subject-ranges (ames.maxima::flatten-facts facts))))))
    ;; open and closed ends at a zero or a pole
    (is (eq :positive (sign-of 'sin 'a '((> a 0) (< a pi)))))
    (is (eq :nonnegative (sign-of 'sin 'a '((>= a 0) (<= a pi)))))
    (is (null (sign-of 'sin 'a '((> a 0) (< a 3.2)))))
    (is (eq :positive (sign-of 'tan 'a '((> a 0) (< a (/ pi 2))))))
    (is (null (sign-of 'tan 'a '((> a 0) (<= a (/ pi 2))))))
    (is (eq :negative (sign-of 'cos 'a '((> a (/ pi 2)) (< a pi)))))
    ;; shifted and scaled angles, and a range passed on through b > a
    (is (eq :positive (sign-of 'cos '(- (/ pi 2) a) '((> a 0) (< a (/ pi 2))))))
    (is (eq :positive (sign-of 'sin '(* 2 a) '((> a 0) (< a (/ pi 2))))))
    (is (null (sign-of 'cos '(* 2 a) '((> a 0) (< a (/ pi 2))))))
    (is (eq :positive (sign-of 'sin '(+ a b) '((> a 0) (< a (/ pi 2)) (> b 0) (< b (/ pi 2))))))
    (is (eq :positive (sign-of 'sin 'b '((> a 0) (> b a) (< b 1)))))
    ;; a bound that is no multiple of pi is widened, soundly
    (is (eq :positive (sign-of 'cos 'a '((> a 0) (< a (sqrt 2))))))
    (is (null (sign-of 'cos 'a '((> a 0) (< a (sqrt 3))))))
    ;; the derived facts Maxima is given
    (is (equal '((> (sin a) 0) (> (cos a) 0) (> (tan a) 0)
                 (< (sin a) 1) (> (sin a) -1) (< (cos a) 1) (> (cos a) -1))
               (ames.algebra::derived-sign-facts '((> a 0) (< a (/ pi 2))))))
    (is (equal '((>= (sin a) 0) (> (cos a) 0) (>= (tan a) 0) (< (sin a) 1) (> (sin a) -1)
                 (> (cos a) -1))
               (ames.algebra::derived-sign-facts '((>= a 0) (< a (/ pi 2)))))
        "cos a reaches 1 at a = 0")))

(test signed-factors-and-orderings-inside-them
  (call-with-bridge
   (lambda (b)
     (let ((facts '((> r 0) (> h r) (> l2 0) (> l1 l2))))
       (is (eq :true (decided b facts '(> (* (- h r) (- l1 l2)) 0))))
       (is (eq :true (decided b facts '(< (/ (- h r) (- l2 l1)) 0))))
       (is (eq :unknown (decided b facts '(> (* (- h r) (- l1 h)) 0)))))
     ;; is() proves X <= 0 from the fact X <= 0, not that X > 0 fails: DECIDE asks both
     (let ((x '(- (* a b c) (* d (sqrt (+ a b))))))
       (is (eq :false (decided b `((> a 0) (> b 0) (> c 0) (> d 0) (<= ,x 0)) `(> ,x 0))))))))

(test facts-linear-in-a-parameter-order-it
  "A fact linear in a parameter orders it even where the parameter is not alone on a
side: w < h - g d^2/(2 v0^2) with w > 0 says h > w + g d^2/(2 v0^2), so the ball thrown
from height h at speed v0 is above 0 at the wall's distance d and lands beyond it; a
coefficient of proven sign (2 v0^2) and an equation (h = g d^2/(2 v0^2) exactly) serve
too. Verdicts are checked against admissible random points."
  (call-with-bridge
   (lambda (b)
     (let ((over '((> g 0) (> h 0) (> d 0) (> v0 0) (> w 0)
                   (< w (- h (/ (* g (expt d 2)) (* 2 (expt v0 2)))))))
           (landing '(- (* v0 (sqrt (/ (* 2 h) g))) d)))
       (is (eq :true (decided b over '(> (- h (/ (* g (expt d 2)) (* 2 (expt v0 2)))) 0))))
       (is (eq :true (decided b over `(> ,landing 0))))
       (is (eq :false (decided b over `(= (* w ,landing) 0))))
       (is (eq :unknown (decided b over '(> (- h (* 2 w)) 0))))
       (dolist (relation (list `(> ,landing 0) '(> (- h w) 0) '(> (- h (* 2 w)) 0)))
         (let ((verdict (decided b over relation)))
           (unless (eq verdict :unknown)
             (dolist (point (random-table-points over relation 3000))
               (let ((truth (table-point-truth relation over point)))
                 (unless (member truth '(:inadmissible nil))
                   (is (eq truth verdict) "~S decided ~S, but ~S at ~S" relation verdict truth point))))))))
     (is (eq :true (decided b '((> g 0) (> h 0) (> d 0) (> v0 0) (> w 0)
                                (> (- (* 2 (expt v0 2) (- h w)) (* g (expt d 2))) 0))
                            '(> (- h w) 0)))
         "2 v0^2 (h - w) > g d^2 orders h above w")
     (let ((grazing '((> g 0) (> d 0) (> v0 0) (= (- (* 2 h (expt v0 2)) (* g (expt d 2))) 0))))
       (is (eq :true (decided b grazing '(> h 0))))
       (is (eq :true (decided b grazing '(= (- (* v0 (sqrt (/ (* 2 h) g))) d) 0))))))))

(test inverse-trigonometric-values-lie-in-their-principal-ranges
  "atan u lies in (-pi/2, pi/2) and asin u in [-pi/2, pi/2] whatever u is, so pi - atan u
is positive (the arc length of a particle in a bowl, r (pi - atan(cos t / sin t))) and
asin u + pi/2 is never negative; what the ranges leave open stays open."
  (call-with-bridge
   (lambda (b)
     (let ((facts '((> r 0) (> theta0 0) (< theta0 (/ pi 2)) (> u 0))))
       (is (eq :true (decided b facts '(> (* (- pi (atan (/ (cos theta0) (sin theta0)))) r) 0))))
       (is (eq :false (decided b facts '(< (+ (asin (- u 1)) (/ pi 2)) 0))))
       (is (eq :true (decided b facts '(> (- (* 2 pi) (acos (- u 3)) (atan u)) 0))))
       (is (eq :unknown (decided b facts '(> (- (atan (- u 1)) theta0) 0))))))))

(test square-roots-of-negatives-in-a-product
  "Maxima writes some times as sqrt(A) sqrt(B) with A, B < 0 (both radicands negative
under the facts, though sign() cannot see it): that is -sqrt(A B)."
  (call-with-bridge
   (lambda (b)
     (let ((facts '((> m 0) (> n 0) (> w 0) (> z 0) (> g 0) (> l 0) (> f 0) (< f (/ (* m g) l))))
           (product '(* (sqrt (- (* 2 m p q) (* m (expt p 2)) (* m (expt q 2)) (* n (expt w 2))))
                        (sqrt (- (* f l) (* m g))))))
       (is (eq :true (decided b facts `(< ,product 0))))
       (is (eq :true (decided b facts `(> (/ (- z) ,product) 0))) "z > 0 over a negative product")))))

(test soundness-on-random-relations
  "DECIDE's :TRUE and :FALSE on random relations of angles, lengths and square roots
are never contradicted at a random admissible point."
  (let ((state (sb-ext:seed-random-state 1994))
        (facts '((> a 0) (< a (/ pi 2)) (> h 0) (> r 0) (< r h) (> g 0))))
    (labels ((pick (list) (nth (random (length list) state) list))
             (term (depth)
               (if (zerop depth)
                   (pick '(a h r g 1 2 1/2 pi))
                   (let ((x (term (1- depth))) (y (term (1- depth))))
                     (ecase (random 8 state)
                       (0 `(+ ,x ,y)) (1 `(- ,x ,y)) (2 `(* ,x ,y)) (3 `(/ ,x (+ 1 (expt ,y 2))))
                       (4 `(sqrt (+ ,x (* ,y ,y)))) (5 `(,(pick '(sin cos)) ,(pick '(a (- (/ pi 2) a) (* 2 a) (/ a 2)))))
                       (6 `(* ,(pick '(h r g)) ,x)) (7 x))))))
      (call-with-bridge
       (lambda (b)
         (ames.maxima:with-assumptions (b facts)
           (dotimes (i 40)
             (let* ((relation (list (pick '(> < >= <=)) (term 2) (term 2)))
                    (verdict (ames.algebra:decide b relation)))
               (unless (eq verdict :unknown)
                 (dolist (point (random-table-points facts relation 400))
                   (let ((truth (table-point-truth relation facts point)))
                     (unless (member truth '(:inadmissible nil))
                       (is (eq truth verdict) "~S decided ~S, but ~S at ~S"
                           relation verdict truth point)))))))))))))

;;; abs belongs in the algebra

(test abs-comes-back-from-maxima-and-goes-back-to-it
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> l -1)))
       (let ((root (ames.maxima:simplify b '(sqrt (expt l 2)))))
         (is (equal '(abs l) root))
         ;; sent back to Maxima inside other requests: no "operator MABS is not allowed"
         (is (eq :true (ames.algebra:decide b `(>= ,root 0))))
         (is (eq :true (ames.algebra:decide b `(>= (+ (* 2 ,root) (expt l 2)) 0))))
         (is (ames.maxima:equivalent-p b `(* ,root ,root) '(expt l 2)))
         (is (= 3/2 (ames.maxima:numeric-value b `(+ 1 ,root) '((l . -1/2)))))))
     (ames.maxima:with-assumptions (b '((> l 0)))
       (is (eq :true (ames.algebra:decide b '(= (abs l) l))))))))

(test abs-in-the-algebra-and-in-scenarios
  (is (valid-expression-p '(abs (- x 1)) :kind :arithmetic))
  (is (eql 3 (expression-value '(abs (- 1 x)) '((x . 4)))))
  (let ((scenario (ames:parse-scenario
                   '(scenario with-abs "A mass given by an absolute value."
                     (parameters (m :nonnegative) (g :positive))
                     (gravity g)
                     (body b :mass (+ 1 (abs m)) :position (0 0) :velocity (0 0) :shape point)))))
    (is (equal '(+ 1 (abs m))
               (ames:scenario-body-mass (first (ames:scenario-bodies scenario)))))))

;;; Names must not change what Maxima can decide

(test mangled-names-sort-in-the-order-they-are-made
  (let ((names (loop for i below 20000 collect (ames.maxima::letters-for-index i))))
    (is (every #'string< names (rest names)))
    (is (= 20000 (length (remove-duplicates names :test #'string=))))
    (is (equal '("A" "Y" "ZAA" "ZYZ" "ZZAAA") (mapcar #'ames.maxima::letters-for-index
                                                       '(0 24 25 674 675))))))

(test thirty-ordered-variables-stay-ordered-for-maxima
  "With 30 names (once $AMESVAA sorted before $AMESVB), the chain h1 < ... < h30 and the
times of drops from those heights are ordered."
  (call-with-bridge
   (lambda (b)
     (let* ((heights (loop for i from 1 to 30 collect (intern (format nil "H~D" i) '#:ames.tests)))
            (facts (list* '(> g 0) `(> ,(first heights) 0)
                          (loop for (lower higher) on heights while higher
                                collect `(> ,higher ,lower)))))
       (ames.maxima:with-assumptions (b facts)
         (is (eq :true (ames.algebra:decide b `(< ,(first heights) ,(car (last heights))))))
         (loop for (lower higher) on heights while higher
               do (is (eq :true (ames.algebra:decide b `(<= (sqrt (/ (* 2 ,lower) g))
                                                           (sqrt (/ (* 2 ,higher) g)))))
                      "~A lands before ~A" lower higher)))))))

;;; Numbers before proofs: the values of a run

(test values-decide-what-the-assumptions-leave-open
  (let ((values '((m . 2) (g . 981/100) (f . 20))))
    (is (eq :true (ames.algebra:value-truth '(> f (* m g)) values)))
    (is (eq :false (ames.algebra:value-truth '(> (* m g) f) values)))
    (is (eq :true (ames.algebra:value-truth '(= (* 2 f) 40) values)) "exact where rational")
    (is (eq :true (ames.algebra:value-truth '(< (sin 1) (* m g)) values)))
    (is (null (ames.algebra:value-truth '(> h 0) values)) "no value for h")
    (is (null (ames.algebra:value-truth '(< x (/ pi 2)) '((x . 7853981633974483/5000000000000000))))
        "too close to call"))
  (ames.algebra:with-parameter-values ('((m . 2) (g . 981/100) (f . 20)))
    (is (eq :true (ames.algebra:decide-by-values '(> f (* m g)))))
    (is (eq :false (ames.algebra:decide-by-values '(< f (* m g)))))
    (is (equal '((> f (* m g)) (>= f (* m g))) (ames.algebra:facts-from-values))
        "each fact recorded as it holds"))
  (signals ames.maxima:invalid-bridge-argument
    (ames.algebra:call-with-parameter-values '((m . "two")) (lambda () nil))))

(test an-undecided-fact-says-which-values-give-which-outcome
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> m 0) (> g 0) (> f 0)))
       (let ((text (ames.algebra:explain-undecided b '(> f (* m g)))))
         (is (stringp text))
         (is (search "holds at" text))
         (is (search "fails at" text)))
       (multiple-value-bind (holds fails) (ames.algebra:undecided-witnesses b '(> f (* m g)))
         (is (eq :true (ames.algebra:value-truth '(> f (* m g)) holds)))
         (is (eq :false (ames.algebra:value-truth '(> f (* m g)) fails))))
       (is (null (ames.algebra:explain-undecided b '(> (* m g) 0))) "a fact that always holds")))))

;;; Geometry asks only the facts that change its answer

(defun obstacle-pair (bridge observer-shape obstacle-shape)
  "The contact pair of the observer O with the fixed obstacle W (shape forms)."
  (ames.geometry:make-contact-pair 'o (ames.geometry:parse-shape observer-shape :bridge bridge)
                                   'w (ames.geometry:parse-shape obstacle-shape :bridge bridge)
                                   :bridge bridge :fixed '(w)))

(test an-overlap-check-asks-only-the-facts-that-matter
  "A point left of a triangle is outside it, whatever the sign of its height: the
undecided fact about the height is not asked."
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> h 0) (> k 0)))
       (let ((pair (obstacle-pair b 'point '(polygon (0 0) (1 0) (0 h)))))
         (is (not (ames.geometry:penetrates-p pair '(-1 (- k 1)))))
         ;; asked fact by fact, the same test stops on that fact
         (is (typep (handler-case (let ((ames.geometry::*fact-choices* '()))
                                    (funcall (ames.geometry::pair-inside-test pair)
                                             (ames.geometry::pair-decider pair) '(-1 (- k 1))))
                      (ames.geometry:undecidable-geometric-fact (c) c))
                    'ames.geometry:undecidable-geometric-fact))
         ;; a fact that matters is still asked, and says which values decide it
         (let ((condition (handler-case (ames.geometry:penetrates-p pair '(1/4 (- k 1)))
                            (ames.geometry:undecidable-geometric-fact (c) c))))
           (is (typep condition 'ames.geometry:undecidable-geometric-fact))
           (is (search "holds at" (princ-to-string condition))))
         ;; ... unless the run's values decide it, and then it is recorded
         (ames.algebra:with-parameter-values ('((h . 1) (k . 3/2)))
           (is (ames.geometry:penetrates-p pair '(1/4 (- k 1))))
           (let ((facts (ames.algebra:facts-from-values)))
             (is (consp facts))
             (dolist (fact facts)
               (is (eq :true (ames.algebra:value-truth fact '((h . 1) (k . 3/2)))))))))))))

(test a-point-outside-a-segment-s-span-is-not-on-it
  "Whether the point lies on the segment's line is undecided, and does not matter."
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> l3 0) (> l2 0) (> l1 l2)))
       (let ((decider (ames.geometry::ensure-decider b))
             (piece (ames.geometry::make-line-piece '(l3 (- l2)) '((* 2 l3) (- l1)))))
         (is (not (ames.geometry::point-on-piece-p decider '((- (/ l3 2)) 0) piece))))))))

(test polynomials-in-one-bounded-quantity-are-decided-by-their-roots
  "A polynomial in one quantity bounded on both sides (a parameter, or sin or cos of an
angle with a range) has one sign where Sturm's count finds no root in the interval; a
root inside, or a root at a closed end, leaves the strict relation open. The verdicts
hold at sample points."
  (call-with-bridge
   (lambda (b)
     (let ((angle '((> th 0) (< th (/ pi 2))))
           (bounded '((> x 1) (< x 3))))
       ;; met landing from the sphere: 32 c^4 - 96 c^3 + 108 c - 81 < 0 on c = cos th in (0, 1)
       (is (eq :true (decided b angle '(< (- (+ (* 32 (expt (cos th) 4)) (* 108 (cos th)))
                                            81 (* 96 (expt (cos th) 3)))
                                         0))))
       (is (eq :false (decided b angle '(> (- (* 2 (expt (sin th) 2)) 3) 0))))
       ;; x^2 - 4 x + 5 = (x - 2)^2 + 1 > 0; (x - 2)^2 > 0 fails at x = 2, inside (1, 3)
       (is (eq :true (decided b bounded '(> (- (expt x 2) (* 4 x)) -5))))
       (is (eq :unknown (decided b bounded '(> (- (expt x 2) (* 4 x)) -4))))
       ;; (x - 1)(3 - x) > 0 on the open interval, its roots at the open ends
       (is (eq :true (decided b bounded '(> (* (- x 1) (- 3 x)) 0))))
       ;; and not on a closed one
       (is (eq :unknown (decided b '((>= x 1) (<= x 3)) '(> (* (- x 1) (- 3 x)) 0))))
       ;; soundness at sample points
       (dolist (c '(1/100 1/4 1/2 3/4 99/100))
         (is (minusp (+ (* 32 (expt c 4)) (* 108 c) -81 (* -96 (expt c 3))))))))))

(test a-relation-dividing-by-zero-is-unknown-not-an-error
  "A relation that divides by a literal 0 is undefined: DECIDE answers :UNKNOWN (it once
signalled DIVISION-BY-ZERO from its own reasoning, which ended the run)."
  (call-with-bridge
   (lambda (b)
     (is (eq :unknown (decided b '((> d 0) (> g 0))
                               '(< (- (/ (+ (* -2 g d) (* 2 g 0)) (* d 0))) 0)))))))

(test a-root-split-gives-its-numerator-back
  "Clearing a square root writes the numerator n = a + b sqrt(A) only where a + b sqrt(A)
gives n back: in sqrt(sin c) sqrt(g) (m cos c - sin c), expanded, sin(c)^(3/2) is free of
sqrt(sin c) for hipow() but its cube for ratcoef(), which dropped that term (b = m cos c
sqrt(g), a = 0) and proved the negative form positive."
  (call-with-bridge
   (lambda (b)
     (let ((facts '((> c 0) (< c (/ pi 2)) (> m 0) (> g 0) (< (- (* (cos c) m) (sin c)) 0)))
           (x '(/ (* (sqrt (sin c)) (sqrt g) (- (* (cos c) m) (sin c)))
                (* (tan c) (sqrt (- (sin c) (* (cos c) m)))))))
       (is (eq :true (decided b facts `(< ,x 0))))
       (is (eq :false (decided b facts `(> ,x 0))))
       (is (eq :false (decided b facts `(>= ,x 0))))
       ;; and at numbers that satisfy the facts, the form is negative
       (is (minusp (ames.base:expression-value (sublis '((c . 1/2) (m . 1/4) (g . 10)) x))))))))

(test half-angles-place-sums-of-sines-and-cosines
  "1 + sin a - cos a > 0 for 0 < a < pi/2 (t = tan(a/2): 2t (1 + t)/(1 + t^2)), the
factor of the disc down the wedge's fork; sin a + cos a > 1 there too (2t (1 - t) > 0 over
1 + t^2); 1 - sin a - cos a is left open for 0 < a < pi (its sign changes at pi/2)."
  (call-with-bridge
   (lambda (b)
     (let ((quarter '((> a 0) (< a (/ pi 2)))))
       (is (eq :true (decided b quarter '(> (- (+ 1 (sin a)) (cos a)) 0))))
       (is (eq :true (decided b quarter '(> (+ (sin a) (cos a)) 1))))
       (is (eq :false (decided b (list* '(> h 0) '(> r 0) quarter)
                               '(< (+ (* (cos a) (expt h 2)) (* (- (+ 1 (sin a)) (cos a)) h r)) 0))))
       (is (eq :unknown (decided b '((> a 0) (< a pi)) '(> (- 1 (sin a) (cos a)) 0))))))))
