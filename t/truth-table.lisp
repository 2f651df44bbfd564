;;;; t/truth-table.lisp -- textbook facts with the verdicts a physicist gives them, decided by the bridge.
;;;;
;;;; Each row is (FACTS RELATION VERDICT NOTE): under FACTS, DECIDE must answer VERDICT.
;;;; :TRUE and :FALSE rows are facts a physicist reads off (signs of angles' functions,
;;;; orderings of times, monotonicity, signed factors); :UNKNOWN rows are facts that are
;;;; false at some admissible point, which no sound procedure may prove. Every verdict is
;;;; also checked against numbers: a :TRUE row holds (a :FALSE row fails) at every random
;;;; admissible point where it can be evaluated, and an :UNKNOWN row is seen to hold at
;;;; one admissible point and fail at another.

(in-package #:ames.tests)

(def-suite truth-table :in all-tests
  :description "Textbook facts against the bridge's DECIDE, verdict by verdict.")

(in-suite truth-table)

(defparameter *acute* '((> a 0) (< a (/ pi 2))))
(defparameter *two-acute* '((> a 0) (< a (/ pi 2)) (> b 0) (< b (/ pi 2))))

(defparameter *truth-table*
  `(;; signs of sin, cos and tan, from the angles' ranges
    (,*acute* (> (sin a) 0) :true "sin of an acute angle")
    (,*acute* (> (cos a) 0) :true "cos of an acute angle")
    (,*acute* (> (tan a) 0) :true "tan of an acute angle")
    (,*acute* (> (cos (- (/ pi 2) a)) 0) :true "cos(pi/2 - a) is sin a")
    (,*acute* (> (cos (* -1/2 (- (* 2 a) pi))) 0) :true "the disc on the wedge (issue 9)")
    (,*acute* (> (sin (- (/ pi 2) a)) 0) :true "sin(pi/2 - a) is cos a")
    (,*acute* (< (sin (- (* 3/2 pi) a)) 0) :true "sin(3 pi/2 - a) is -cos a")
    (,*acute* (< (cos (+ pi a)) 0) :true "cos(pi + a) is -cos a")
    (,*acute* (> (tan (- (/ pi 2) a)) 0) :true "tan(pi/2 - a) is cot a")
    (,*acute* (> (sin (* 2 a)) 0) :true "a doubled acute angle stays below pi")
    (,*acute* (> (cos (/ a 2)) 0) :true "half an acute angle")
    (,*acute* (> (tan (/ a 2)) 0) :true "tan of half an acute angle")
    (,*acute* (> (+ 1 (* 3 (sin (* 2 a)))) 0) :true "a sum with sin 2a")
    (,*two-acute* (> (sin (+ a b)) 0) :true "the sum of two acute angles is below pi")
    ((,@*two-acute* (> b a)) (> (sin (- b a)) 0) :true "b - a in (0, pi/2)")
    (((> g 0) ,@*acute*) (< (* g (sin a)) g) :true "sliding is slower than falling: sin a < 1")
    (((> r 0) ,@*acute*) (< (/ (* (- (cos a) 1) r) (sin a)) 0) :true "cos a < 1 away from 0")
    (,*acute* (> (cos (* 2 a)) 0) :unknown "cos 2a is negative for a > pi/4")
    (,*two-acute* (> (cos (+ a b)) 0) :unknown "a + b may exceed pi/2")
    (,*two-acute* (> (sin (- a b)) 0) :unknown "a - b has either sign")
    ;; monotonicity of the angles' functions
    ((,@*acute* (> b a) (< b (/ pi 2))) (< (sin a) (sin b)) :true "sin increases on (0, pi/2)")
    ((,@*acute* (> b a) (< b (/ pi 2))) (< (cos a) (cos b)) :false "cos decreases on (0, pi/2)")
    (,*acute* (> (cos (/ a 2)) (cos a)) :true "a/2 < a and cos decreases")
    (((> a 0) (< a (/ pi 4))) (< (sin a) (cos a)) :true "below pi/4, sin a < cos a")
    (,*acute* (< (sin a) (cos a)) :unknown "above pi/4 it is the other way")
    ;; signed factors: products, quotients, orderings inside sums
    (((> mp 0) (> mw 0) (> g 0) ,@*acute*)
     (> (/ (* mp mw g (cos a)) (+ mw (* mp (expt (sin a) 2)))) 0) :true "the wedge's normal force")
    (((> mw 0) (> mp 0) ,@*acute*) (> (+ mw (* mp (expt (sin a) 2))) mw) :true "mw + mp sin^2 a > mw")
    (,*acute* (> (* (sin a) (cos a)) 0) :true "sin a cos a")
    (((> r 0) (> h r) (> l2 0) (> l1 l2)) (> (* (- h r) (- l1 l2)) 0) :true "two orderings, one product")
    (((> r 0) (> h r) (> l2 0) (> l1 l2)) (> (/ (- h r) (- l1 l2)) 0) :true "two orderings, one quotient")
    (((> r 0) (> h r) (> l2 0) (> l1 l2)) (< (* (- h r) (- l2 l1)) 0) :true "a negative factor")
    (((> r 0) (> h r) (> k 0)) (> (* (- h r) (- k r)) 0) :unknown "k - r has either sign")
    (((> m 0) (> g 0) (> f 0)) (> (- (* m g) f) 0) :unknown "weight against push")
    (((> mb 0) (> g 0) (> l2 0) (> l1 l2) (> l3 0) (> f (/ (* mb g (- l1 l2)) l3)))
     (> (- (* f l3) (* mb g (- l1 l2))) 0) :true "the push beats the weight (two blocks in a corner)")
    ;; orderings of times: squares, arguments, monotonicity of sqrt
    (((> g 0) (> h1 0) (> h2 h1)) (< (sqrt (/ (* 2 h1) g)) (sqrt (/ (* 2 h2) g))) :true
     "the lower drop lands first")
    (((> h1 0) (> h2 h1)) (< (sqrt h1) (sqrt h2)) :true "sqrt increases")
    (((> g 0) (> h 0) (> k 0)) (< (sqrt (/ (* 2 h) g)) (sqrt (/ (* 2 k) g))) :unknown
     "unordered heights")
    (((> g 0) (> h 0) (> d 0)) (< (sqrt (/ (* 2 h) g)) (sqrt (/ (* 2 (+ h d)) g))) :true
     "a higher drop takes longer")
    (((> g 0) (> k 0) (> h 0) (< h k) (> r 0) (< r h))
     (<= (/ (* 2 (sqrt (+ h (* (- (sqrt 3) 2) r)))) (sqrt g)) (/ (* 2 (sqrt h)) (sqrt g))) :true
     "the disc at 30 degrees meets the floor first (issue 9)")
    (((> g 0) (> h0 0) (> l 0) ,@*acute*)
     (<= (/ (sqrt (+ (* 2 h0) (* (tan a) l))) (* (sin a) (sqrt g)))
         (/ (sqrt l) (* (sqrt (cos a)) (sqrt (sin a)) (sqrt g)))) :false
     "the particle leaves the raised ramp first (issue 9)")
    (((> g 0) (> h 0) ,@*acute*) (<= (sqrt (/ (* 2 h) g)) (sqrt (/ (* 2 h) (* g (expt (sin a) 2))))) :true
     "falling beats sliding down the same height")
    (((> g 0) (> h 0) (> k h)) (> (sqrt (* 2 g h)) (sqrt (* 2 g k))) :false "speeds at landing")
    (((> h 0) (> r 0)) (> (expt (+ h r) 2) (expt h 2)) :true "squares of positives")
    (((> r 0) (> h r)) (> (expt (- h r) 3) 0) :true "an odd power keeps the sign")
    (((> r 0) (> h r)) (> (log (/ h r)) 0) :true "log of a ratio above 1")
    (((> h 0)) (> (atan h) 0) :true "atan keeps the sign")
    (((> h1 0) (> h2 h1)) (< (atan h1) (atan h2)) :true "atan increases")
    (((> m 0) (> v 0) (> g 0) (> h 0)) (> (+ (* 1/2 m (expt v 2)) (* m g h)) 0) :true "energy")
    (((> g 0) (> h 0)) (> (sqrt (/ (* 2 h) g)) 0) :true "a fall takes time")
    ;; abs, which Maxima writes for sqrt(l^2)
    (((> l -1)) (>= (sqrt (expt l 2)) 0) :true "sqrt(l^2) is abs(l) (issue 9)")
    (((> l 0)) (= (abs l) l) :true "abs of a positive")
    (((> l -1)) (> (abs l) 1) :unknown "l may lie in (-1, 1)")
    (((> l -1)) (>= (+ (abs l) 1) 1) :true "abs is never negative")
    ;; equations
    (,*acute* (= (+ (expt (sin a) 2) (expt (cos a) 2)) 1) :true "Pythagoras")
    (,*acute* (= (sin a) (cos a)) :unknown "equal only at pi/4"))
  "Textbook facts: (FACTS RELATION VERDICT NOTE).")

(defun table-point-truth (relation facts point)
  "RELATION's truth (:TRUE, :FALSE or NIL when unsure) at POINT, when every fact of FACTS
surely holds there; :INADMISSIBLE otherwise."
  (let ((values (mapcar (lambda (entry) (cons (car entry) (rational (cdr entry)))) point)))
    (if (every (lambda (fact) (eq (ames.algebra:value-truth fact values) :true)) facts)
        (ames.algebra:value-truth relation values)
        :inadmissible)))

(defun random-table-points (facts relation count)
  "COUNT random points over the variables of FACTS and RELATION (values in (-3, 3),
as alists), from a fixed seed."
  (let ((variables (remove-duplicates (append (expression-variables relation)
                                              (mapcan #'expression-variables facts))))
        (state (sb-ext:seed-random-state 9)))
    (loop repeat count
          collect (mapcar (lambda (v) (cons v (- (random 6d0 state) 3d0))) variables))))

(test truth-table-has-enough-rows
  (is (>= (length *truth-table*) 40))
  (is (>= (count :unknown *truth-table* :key #'third) 8))
  (is (>= (count :false *truth-table* :key #'third) 3)))

(test textbook-facts-get-a-physicist-s-verdict
  (call-with-bridge
   (lambda (bridge)
     (loop for (facts relation verdict note) in *truth-table*
           do (ames.maxima:with-assumptions (bridge facts)
                (is (eq verdict (ames.algebra:decide bridge relation))
                    "~A: ~S under ~S should be ~S" note relation facts verdict))))))

(test textbook-verdicts-agree-with-numbers
  "A proven verdict is never contradicted at an admissible point; an :UNKNOWN one is
really false somewhere (and true somewhere else)."
  (call-with-bridge
   (lambda (bridge)
     (loop for (facts relation verdict note) in *truth-table*
           for truths = (loop for point in (random-table-points facts relation 3000)
                              for truth = (table-point-truth relation facts point)
                              unless (eq truth :inadmissible) collect truth)
           do (ecase verdict
                (:true (is (not (member :false truths)) "~A: fails at an admissible point" note))
                (:false (is (not (member :true truths)) "~A: holds at an admissible point" note))
                (:unknown
                 (ames.maxima:with-assumptions (bridge facts)
                   (is (or (and (member :true truths) (member :false truths))
                           (ames.algebra:undecided-witnesses bridge relation))
                       "~A: not seen to hold at one point and fail at another" note))))))))
