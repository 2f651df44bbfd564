;;;; t/weaker-assumptions.lisp -- a verdict (or a definite sign() or is() answer) proven under some facts is taken over under more
;;;; facts (a branch does not prove again what its parent proved before the fork), and only
;;;; then: never from a sibling's facts, never an undecided one.

(in-package #:ames.tests)

(def-suite weaker-assumptions :in all-tests
  :description "DECIDE takes over the proofs made under facts that the facts in force
include (src/maxima-bridge/weaker-assumptions.lisp), and nothing else.")

(in-suite weaker-assumptions)

(defun maxima-round-trips (bridge)
  "The round trips BRIDGE has made to Maxima so far."
  (getf (ames.maxima:bridge-statistics bridge) :maxima-calls))

(defparameter *square-plus-one* '(> (+ (- (expt (+ m g) 2) (* 4 m g)) 1) 0)
  "(m - g)^2 + 1 > 0 written so that the rules of signs do not see it: Maxima proves it.")

(test a-proof-holds-under-more-facts
  "(m + g)^2 - 4 m g + 1 > 0 (a square plus one), proven by Maxima under m, g > 0, is :TRUE
under f > m g too, without asking Maxima again; f > 0,
undecided under m, g > 0 alone, is proven under f > m g (not taken over as undecided)."
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> m 0) (> g 0)))
       (is (eq :true (ames.algebra:decide b *square-plus-one*)))
       (is (eq :unknown (ames.algebra:decide b '(> f 0))))
       (let ((outer (ames.maxima:assumption-key b)))
         (ames.maxima:with-assumptions (b '((> f (* m g))))
           (is (member outer (ames.maxima:weaker-assumption-keys b)))
           (let ((trips (maxima-round-trips b)))
             (is (eq :true (ames.algebra:decide b *square-plus-one*)))
             (is (= trips (maxima-round-trips b))))
           (is (eq :true (ames.algebra:decide b '(> f 0))))))))))

(test a-sibling-branch-lends-no-proof
  "The two sides of a fork, f < m g and f > m g: what one proves about f - m g is not taken
over by the other, whose facts do not include it; each gets its own, opposite verdict."
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> m 0) (> g 0)))
       (let ((relation '(> (- (* m g) f) 0)))
         (ames.maxima:with-assumptions (b '((< f (* m g))))
           (is (eq :true (ames.algebra:decide b relation))))
         (ames.maxima:with-assumptions (b '((> f (* m g))))
           (is (eq :false (ames.algebra:decide b relation)))
           (is (eq :true (ames.algebra:decide b '(> f (* m g)))))))))))

(test a-definite-sign-holds-under-more-facts
  "Maxima's sign() of m g + 1, pos under m, g > 0, is pos under f > m g too, without a
round trip (the request's definite answer is taken over); sign() of
f - m g, any sign under m, g > 0 alone, is asked again under f > m g, and is pos there."
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> m 0) (> g 0)))
       (let ((product '(+ (* m g) 1)))
         (is (equal '(:positive) (ames.maxima:maxima-signs b product)))
         (is (equal '(:negative :positive :zero)
                    (sort (copy-list (ames.maxima:maxima-signs b '(- f (* m g)))) #'string<)))
         (ames.maxima:with-assumptions (b '((> f (* m g))))
           (let ((trips (maxima-round-trips b)))
             (is (equal '(:positive) (ames.maxima:maxima-signs b product)))
             (is (= trips (maxima-round-trips b)))
             (is (equal '(:positive) (ames.maxima:maxima-signs b '(- f (* m g)))))
             (is (< trips (maxima-round-trips b))))))))))

(test a-sibling-branch-lends-no-sign
  "sign() of m g - f is neg under f > m g and pos under its sibling f < m g: a definite
answer is taken over from fewer facts only, never from a sibling's."
  (call-with-bridge
   (lambda (b)
     (ames.maxima:with-assumptions (b '((> m 0) (> g 0)))
       (let ((difference '(- (* m g) f)))
         (ames.maxima:with-assumptions (b '((> f (* m g))))
           (is (equal '(:negative) (ames.maxima:maxima-signs b difference))))
         (ames.maxima:with-assumptions (b '((< f (* m g))))
           (is (equal '(:positive) (ames.maxima:maxima-signs b difference)))
           (is (eq :true (ames.maxima:maxima-is b '(> (* m g) f))))))))))
