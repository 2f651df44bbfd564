;;;; t/linear-sums.lisp -- the request server's shortcuts for sums of variables give Maxima's own answers.
;;;;
;;;; A linear form in distinct variables with integer coefficients (a chain's sum of
;;;; widths) is ratsimp'd and factored in Lisp inside Maxima (AMES-LINEAR-RATSIMP,
;;;; AMES-LINEAR-FACTOR), and its terms are handed to the simplifier in the order it
;;;; inserts fastest (AMES-PRESORT-SUMS), in maxima-server-functions.lisp. Each must give
;;;; exactly the form Maxima's own ratsimp() and factor() give: the simplification and
;;;; presentation candidates of such forms are compared, structure and flags, with plain
;;;; ratsimp() and factor() requests of the same sum written so that no shortcut applies
;;;; (one term a product of a product).

(in-package #:ames.tests)

(def-suite linear-sums :in bridge-shortcuts
  :description "Sums of variables: the server's shortcuts give ratsimp()'s and factor()'s forms.")

(in-suite linear-sums)

(defun random-linear-sum (state)
  "A pseudo-random linear form drawn with the random STATE, as (VALUES SUM UNSHORTENED):
integer coefficients (some 1 or -1, some sharing a factor) on 1 to 14 distinct
variables in a shuffled order, sometimes an integer constant; UNSHORTENED is the same
sum with its first term written (* 1 (* c x)), which no shortcut of the server takes."
  (let* ((pool '(w1 w2 w3 w4 w5 w6 w7 w8 w9 w10 w11 w12 w13 w14 m1 m2 xa xb))
         (count (1+ (random 14 state)))
         (variables (subseq (alexandria:shuffle (copy-list pool)) 0 count))
         (scale (nth (random 4 state) '(1 2 -1 -3)))
         (terms (mapcar (lambda (v)
                          (let ((c (* scale (nth (random 6 state) '(1 1 -1 2 -2 3)))))
                            (if (eql c 1) v (list '* c v))))
                        variables))
         (constant (and (zerop (random 3 state)) (* scale (- (random 9 state) 4)))))
    (flet ((sum (terms) (cons '+ (if (and constant (not (zerop constant))) (cons constant terms) terms))))
      (values (sum terms)
              (sum (cons (let ((first (first terms)))
                           (list '* 1 (if (consp first) first (list '* 1 first))))
                         (rest terms)))))))

(test linear-sums-simplify-as-ratsimp-and-factor-do
  (call-with-bridge
   (lambda (b)
     (let ((state (sb-ext:seed-random-state 24))
           (*random-state* (sb-ext:seed-random-state 24)))
       (dotimes (i 40)
         (multiple-value-bind (sum unshortened) (random-linear-sum state)
           (let* ((form (ames.maxima::to-mx b sum))
                  (long (ames.maxima::to-mx b unshortened))
                  (ratsimped (ames.maxima::mcall "$RATSIMP" long))
                  (answers (ames.maxima::request-list
                            b (list (ames.maxima::simplest-form-request form)
                                    (ames.maxima::mcall "$AMES_PRESENTATION_CANDIDATES" form
                                                        ames.maxima::+false+)
                                    ratsimped
                                    (ames.maxima::mcall "$FACTOR" ratsimped))
                            :cache nil)))
             (destructuring-bind (candidates presentation ratsimp factor) answers
               (is (equal (list ratsimp factor) (ames.maxima::mlist-items candidates))
                   "~S: the candidates ~S, ratsimp() and factor() ~S" sum candidates (list ratsimp factor))
               (is (equal (list ratsimp factor)
                          (subseq (ames.maxima::mlist-items presentation) 0 2))
                   "~S: the presentation's forms ~S, ratsimp() and factor() ~S"
                   sum presentation (list ratsimp factor))
               ;; and the simplest form is the sum itself
               (is (ames.maxima:equivalent-p b (ames.maxima:simplify b sum :strategy :full) sum))))))))))

(test exact-constants-are-maxima-s-rationals
  "SIMPLIFY answers an expression whose arithmetic on rationals gives a rational without
Maxima (exact-constants.lisp): that rational is what Maxima's ratsimp() gives; what
has no such value (a variable left, a float, a division by zero, 0^0, a function) is
left to Maxima."
  (dolist (expression '((* m (+ (expt 0 2) (expt 0 2)) 1/2) (* (+ 0 (- 0)) (expt 2 -1))
                        (* (- (* m 0) 0) (expt 1 -1)) (+ 1/2 (* 3 (- 2 5)) (/ 7 3))
                        (* 0 (expt (+ x (* y 0)) 3)) (- 4) (/ 6) (expt -2/3 -3)))
    (is (rationalp (ames.maxima::exact-constant-value expression)) "~S" expression))
  (dolist (expression '((* 0 (/ 1 x)) (* 0 (expt 0 -1)) (/ 1 0) (/ 0) (expt 0 0) (+ 1 0.5)
                        (* 0 (sin x)) (+ x 0) (* 0 (expt x 1/2)) x 0.0))
    (is (null (ames.maxima::exact-constant-value expression)) "~S" expression))
  (call-with-bridge
   (lambda (b)
     (dolist (expression '((* m (+ (expt 0 2) (expt 0 2)) 1/2) (* (+ 0 (- 0)) (expt 2 -1))
                           (+ 1/2 (* 3 (- 2 5)) (/ 7 3)) (* 0 (expt (+ x (* y 0)) 3))
                           (expt -2/3 -3) (- 4)))
       (is (eql (ames.maxima::exact-constant-value expression)
                (ames.maxima::from-mx b (ames.maxima::maxima-request
                                         b (ames.maxima::mcall "$RATSIMP" (ames.maxima::to-mx b expression)))))
           "~S" expression)
       (is (eql (ames.maxima::exact-constant-value expression)
                (ames.maxima:simplify b expression :strategy :full)))))))
