;;;; t/exact-radicals.lisp -- constants of numbers and radicals whose terms cancel far
;;;; beyond a double's digits (issue 21, crosscheck terrain 2028 #70): their signs and
;;;; values from exact interval arithmetic (src/base/exact-intervals.lisp), never from
;;;; Maxima's sign() (a float's sign), and the root of a quadratic with such coefficients.
;;;;
;;;; The quadratic is the meeting time of a particle, after three bounces over terrain,
;;;; with a terrain piece: c0 + c1 s + c2 s^2 with coefficients near 1e76 written with
;;;; sqrt(7) sqrt(1003) and the square roots of two constants R1, R2 near 5e48 and 1e49
;;;; that are themselves differences of terms near 5e56. Its reduced discriminant, in
;;;; rational form N/D, has N near -1.06e181 and D near -1.30e182, each a sum of terms
;;;; near 1e213: Maxima's sign() called both "pos", and the square root AMES built of the
;;;; radicand came back as %i sqrt(...), a refusal. The reference values below are
;;;; Maxima's bfloat() at fpprec 600 of the forms as written (computed apart, once).

(in-package #:ames.tests)

(def-suite exact-radicals :in all-tests
  :description "Signs and values of constants of cancelling radicals, proven exactly.")

(in-suite exact-radicals)

(defparameter *radicand-1*
  '(- 539876575537379055372383284551433301335074852287875954115
      (* 920443115811987544401036311192448581420977273869896370 (expt 7 3/2) (sqrt 1003))))

(defparameter *radicand-2*
  '(- (* 53717591672250055206847059642374006983749740629745862 (expt 7 5/2) (sqrt 1003))
      220552547768059874354714428080688911564046046685744114093))

(defun terrain-coefficient (a b c d)
  "(b - a sqrt(7) sqrt(1003)) sqrt(R1) sqrt(R2) + c sqrt(7) sqrt(1003) - d."
  `(- (+ (* (- ,b (* ,a (sqrt 7) (sqrt 1003))) (sqrt ,*radicand-1*) (sqrt ,*radicand-2*))
         (* ,c (sqrt 7) (sqrt 1003)))
      ,d))

(defparameter *terrain-quadratic*
  (let ((c0 (terrain-coefficient
             1770868702560925656 148651350340408544666
             428421639123709375647439534569451185651824929223469512215427671619218204362
             35898052222524503490473165878129735280526545057497326125935604425809710645382))
        (c1 (terrain-coefficient
             824595229628881830 68694351271560269255
             781844038529148886257172480994166140553977853532573957043900962741682802516
             65511812567045023498612948181929720470191379152713064578255585247680106374626))
        (c2 '(- 30389571578032846784472828854804758477654915746341028702301833130185961487055
                (* 362681239250031770440126991267070242677910309220534908578727971479696197880
                   (sqrt 7) (sqrt 1003)))))
    (list c0 c1 c2))
  "The coefficients (c0 c1 c2) of the quadratic of terrain 2028 #70's state 3.")

(defparameter *terrain-numerator*
  '(- (* 539878440050839653906378616180767516889381369103205380861220339538841882110202368900391060118589824805937873318590407728267255073967986443853453299108367219958908533603503404058650573899141488388494570379723628
       (expt 7 3/2) (sqrt 1003))
    316660221253136521658359822704598752867092466589594586375174854693450486887015666756695421746100219592735785850242319650610405383226691278687149089504872760833299643072682130689583842366652777749453171346899795431
    (* (- (* 16003543963808432317133862063573726535892325086514856428683829795882787715071278174738345967952607227695669822351583324781547900995555549337136076179857680
             (sqrt 7) (sqrt 1003))
          1340959476501164707320230511569317134063340541647327167489218168495615101626426211270701203569780220528055096686714923357259680936240681605770507971356907980)
       (sqrt (- 539876575537379055372383284551433301335074852287875954115
                (* 920443115811987544401036311192448581420977273869896370 (expt 7 3/2) (sqrt 1003))))
       (sqrt (- (* 53717591672250055206847059642374006983749740629745862 (expt 7 5/2) (sqrt 1003))
                220552547768059874354714428080688911564046046685744114093))))
  "The numerator of the quadratic's reduced discriminant in rational form (Maxima's
num(ratsimp(S^2/4 - P))): -1.0597699469961728566e181 (bfloat, fpprec 600), terms near
3e213; Maxima's sign() says pos.")

(defparameter *terrain-root*
  292790270048828180171616960043827570587313411521602015857964668670813038274248/1000000000000000000000000000000000000000000000000000000000000000000000000000000
  "The larger root S/2 + sqrt(S^2/4 - P) of the quadratic: 0.292790270048828180171616960043827570587313411521602015857964668670813038274248
(bfloat at fpprec 600 of the root as written; ratsimp and factor of it agree, radcan's
form is 0.5298, with %i).")

(defun within-p (expression reference tolerance)
  "True when the constant EXPRESSION's exact interval (1024 bits) lies within TOLERANCE
of the rational REFERENCE."
  (let ((interval (exact-interval expression 1024)))
    (and interval
         (<= (- reference tolerance) (car interval))
         (<= (cdr interval) (+ reference tolerance)))))

(test exact-signs-of-radical-constants
  "Exact interval arithmetic decides a sign where the terms cancel (the terrain
numerator, 32 digits of cancellation), never calls a constant equal to 0 zero unless it
is exactly rational zero (sqrt(2) sqrt(11) - sqrt(22) stays :NEAR-ZERO), takes exact
roots exactly (8^(2/3) = 4), and has no answer for names, functions or a root of a
negative."
  (is (eq :negative (exact-constant-sign *terrain-numerator*)))
  (is (within-p *terrain-numerator* (* -10597699469961728566010026559877911657 (expt 10 144)) (expt 10 145)))
  (is (eq :near-zero (exact-constant-sign '(- (* (sqrt 2) (sqrt 11)) (sqrt 22)))))
  (is (eq :zero (exact-constant-sign '(- (expt 8 2/3) 4))))
  (is (eq :positive (exact-constant-sign '(- (sqrt 2) 14142135623730950/10000000000000000))))
  (is (eq :negative (exact-constant-sign '(- (sqrt 2) 14142135623730951/10000000000000000))))
  (is (eq :negative (exact-constant-sign '(/ 1 (- (expt 2 1/3) 2)))))
  (is (null (exact-constant-sign '(+ x (sqrt 2)))))
  (is (null (exact-constant-sign '(sin 1))))
  (is (null (exact-constant-sign '(sqrt (- 1 (sqrt 3)))))))

(test accurate-doubles-of-cancelling-constants
  "EXPRESSION-VALUE of the terrain numerator is its value to a double's precision (a
plain double evaluation of its terms near 3e213 is noise: 3.7e196 with the wrong sign)."
  (let ((value (expression-value *terrain-numerator*)))
    (is (and (realp value)
             (< (abs (- (/ value -1.0597699469961728566d181) 1)) 1d-14))
        "~S" value)))

(test signs-of-cancelling-constants-never-by-float
  "The bridge's signs and DECIDE's verdicts of the terrain numerator are exact (Maxima's
sign() of it, a float's sign, is pos)."
  (with-fixture simulator-bridge ()
    (is (equal '(:negative) (ames.maxima:maxima-signs bridge *terrain-numerator*)))
    (is (eq :true (ames.algebra:decide bridge (list '< *terrain-numerator* 0))))
    (is (eq :false (ames.algebra:decide bridge (list '> *terrain-numerator* 0))))))

(test simplest-form-checked-exactly
  "A simplification of a constant of radicals is kept only when exact intervals cannot
tell it from the original: a sign-flipped or non-real one is dropped."
  (is (ames.maxima::exactly-same-number-p '(sqrt 6) '(* (sqrt 2) (sqrt 3))))
  (is (not (ames.maxima::exactly-same-number-p '(sqrt 6) '(- (* (sqrt 2) (sqrt 3))))))
  (is (not (ames.maxima::exactly-same-number-p '(sqrt 6) '(sqrt (- 1 (sqrt 37)))))))

(test root-of-a-quadratic-with-cancelling-radical-coefficients
  "The earliest root after 0 of the terrain quadratic (its roots' product is negative)
is the larger root, real: 0.29279027004882818 (Maxima's bfloat at fpprec 600); it
substitutes to zero in c0 + c1 s + c2 s^2. Once refused: the radicand's numerator and
denominator, both negative, were taken for positive (Maxima's sign() of constants near
1e213 that cancel), and Maxima wrote their quotient's square root with %i."
  (with-fixture simulator-bridge ()
    (destructuring-bind (c0 c1 c2) *terrain-quadratic*
      (multiple-value-bind (root status)
          (ames.algebra:earliest-root bridge `(+ ,c0 (* ,c1 s) (* ,c2 (expt s 2))) 's)
        (is (eq :found status) "~S ~S" root status)
        (when (eq status :found)
          (is (within-p root *terrain-root* (expt 10 -60)) "~S" root)
          (is (member (exact-constant-sign `(+ ,c0 (* ,c1 ,root) (* ,c2 (expt ,root 2))))
                      '(:zero :near-zero))))))))
