;;;; t/settled-signs.lisp -- the earliest-root search asks only the sign proofs that can
;;;; change what it reads of a form's signs (src/algebra/roots.lisp, SETTLED-SIGNS).

(in-package #:ames.tests)

(def-suite settled-signs :in all-tests
  :description "DECIDED-SIGNS with the caller's tests reads as it does with every proof
asked, and leaves out proofs that cannot change that reading.")

(in-suite settled-signs)

(defparameter *root-search-tests*
  (list (ames.algebra::verdict-tests t) (ames.algebra::verdict-tests nil)
        '((:positive :negative) (:zero)) '((:positive :negative)) '((:negative))
        '((:negative) (:zero) (:positive)) '((:negative :zero) (:positive))
        '((:negative) (:positive :zero)) '((:positive :zero)))
  "Every set of tests src/algebra/roots.lisp reads signs through.")

(defun decision-steps (signs)
  "The proofs DECIDED-SIGNS tries for SIGNS, in its order."
  (append (list (cons '> '(:positive)) (cons '< '(:negative)))
          (and (member :zero signs)
               (list (cons '>= '(:positive :zero)) (cons '<= '(:negative :zero))))))

(defun signs-reading (signs tests)
  "Whether SIGNS lie within each set of TESTS."
  (mapcar (lambda (set) (subsetp signs set)) tests))

(test settled-signs-read-as-every-proof-asked
  "For every pattern of Maxima's undecided signs, every combination of proofs that hold
and every caller's tests: the settled answer lies within the same tests as the answer
with every proof tried in order, and no proof is asked that the search in order would
not ask."
  (dolist (signs '((:positive :negative :zero) (:positive :zero) (:negative :zero)
                   (:positive :negative)))
    (let ((steps (decision-steps signs)))
      (dotimes (provable (expt 2 (length steps)))
        (flet ((proven-p (step) (logbitp (position step steps) provable)))
          (let ((full (or (loop for step in steps
                                when (proven-p step) return (cdr step))
                          signs))
                (full-asked (1+ (or (position-if #'proven-p steps) (1- (length steps))))))
            (dolist (tests *root-search-tests*)
              (let* ((asked 0)
                     (settled (ames.algebra::settled-signs
                               steps signs tests
                               (lambda (step) (incf asked) (proven-p step)))))
                (is (equal (signs-reading full tests) (signs-reading settled tests))
                    "~S, proofs ~B, tests ~S: ~S read otherwise than ~S"
                    signs provable tests settled full)
                (is (<= asked full-asked) "~S, proofs ~B, tests ~S: ~D asked, ~D in order"
                    signs provable tests asked full-asked)))))))))

(test settled-signs-leave-out-what-cannot-matter
  "Nothing proven: the product of Vieta's roots asks 2 of the 4 proofs (>= 0 and <= 0
would read as undecided), a comparison of two roots (is the difference >= 0?) 3 (<= 0
would read as undecided), a strict root verdict all 4 (<= 0 would read as no root)."
  (flet ((asked (tests)
           (let ((asked '()))
             (ames.algebra::settled-signs (decision-steps '(:positive :negative :zero))
                                          '(:positive :negative :zero) tests
                                          (lambda (step) (push (car step) asked) nil))
             (reverse asked))))
    (is (equal '(> <) (asked '((:negative) (:zero) (:positive)))))
    (is (equal '(> < >=) (asked '((:positive :zero)))))
    (is (equal '(> < >= <=) (asked (ames.algebra::verdict-tests t))))))
