;;;; t/deferred-pairs.lisp -- issue 24: pairs of bodies proven apart are left out of the
;;;; world (src/scenario/deferred-pairings.lisp, src/simulator/deferred-pairs.lisp), and
;;;; the shortcuts that keep a state's cost growing with its structure.
;;;;
;;;; The chain's forces are the textbook's (t/scale.lisp checks them with the pairs
;;;; deferred, as every run now does); here: which pairs are left out, that a run with
;;;; them left out prints what a run with every pair prints, that a pair left out which
;;;; comes to touch is built and its impact found at the textbook's time, and the
;;;; algebra's shortcuts against the slow way.

(in-package #:ames.tests)

(def-suite deferred-pairs :in all-tests
  :description "Contact pairs proven apart are deferred, built when they may touch, and
change no result; polynomial identities without Maxima; many bindings in a table.")

(in-suite deferred-pairs)

(defun screened-world (scenario bridge)
  "The WORLD of SCENARIO's checks with the simulator's pair screen in force."
  (let ((ames.scenario:*pair-screen* (ames.simulator::make-pair-screen)))
    (nth-value 1 (ames:check-scenario scenario bridge))))

(defun pair-names (world)
  "The (OBSERVER OBSTACLE) names of WORLD's built pairs, as sorted name lists."
  (mapcar (lambda (pair)
            (sort (list (symbol-name (ames.geometry:pair-observer pair))
                        (symbol-name (ames.geometry:pair-obstacle pair)))
                  #'string<))
          (ames:world-pairs world)))

(defun history-printed (scenario bridge &key (defer t))
  "The s-expression output of SCENARIO's run, with the pairs deferred or (DEFER NIL)
every pair built."
  (let ((ames.simulator::*defer-pairs* defer))
    (ames:history-sexp (simulate-stopping-when-ambiguous scenario bridge))))

(test a-chain-defers-the-pairs-of-blocks-apart
  "A chain of six blocks on a floor against a wall: of the 6 x 5 / 2 pairs of blocks,
only the 5 neighbours' are built (the others are strictly apart along x); the floor's
and the wall's (half-planes, unbounded) are all built: 6 + 6 + 5 pairs. The run prints
what it prints with every pair built."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scale-form :chain 6))
           (world (screened-world scenario bridge))
           (names (pair-names world)))
      (is (= 17 (length (ames:world-pairs world))))
      (is (= 10 (length (ames.scenario:world-deferred-pairings world))))
      (loop for k from 1 below 6
            do (is (member (sort (list (format nil "B~D" k) (format nil "B~D" (1+ k))) #'string<)
                           names :test #'equal)))
      (is (not (member (list "B1" "B3") names :test #'equal)))
      (is (equal (history-printed scenario bridge :defer nil)
                 (history-printed scenario bridge))))))

(test a-stack-defers-the-pairs-of-blocks-apart-along-y
  "A stack of five blocks: the pairs of blocks not one on the other are apart along y
and left out (4 x 3 / 2 of them); the result is the one with every pair built."
  (with-fixture simulator-bridge ()
    (let* ((scenario (scale-form :stack 5))
           (world (screened-world scenario bridge)))
      (is (= 6 (length (ames.scenario:world-deferred-pairings world))))
      (is (equal (history-printed scenario bridge :defer nil)
                 (history-printed scenario bridge))))))

(test a-deferred-pair-that-comes-to-touch-is-built
  "Block A slides at v toward block B at rest, a gap d between them: apart at the start
(their pair is deferred), they cannot be proven apart over the state, so the pair is
built and the run starts again: the impact comes at d / v, as with every pair built,
and the whole history is the same."
  (with-fixture simulator-bridge ()
    (let* ((scenario (ames:parse-scenario (with-restitution "blocks-colliding" 1)))
           (world (screened-world scenario bridge)))
      (is (member '("BLOCK-A" "BLOCK-B")
                  (mapcar #'rest (ames.scenario:world-deferred-pairings world))
                  :test (lambda (a b) (equal a (mapcar #'symbol-name b)))))
      (let* ((history (simulate-stopping-when-ambiguous scenario bridge))
             (before (first (ames::history-states history))))
        (is (equal '(:collision "BLOCK-A" "BLOCK-B")
                   (event-names (subseq (ames::state-end-event before) 0 3))))
        (call-with-scenario-facts
         bridge scenario
         (lambda ()
           (is-same bridge "time to the impact" (ames::state-duration before)
                    (in-scenario-terms scenario '(/ d v))))))
      (is (equal (history-printed scenario bridge :defer nil)
                 (history-printed scenario bridge))))))

(test the-pair-screen-proves-only-what-holds
  "The screen leaves a pair out only when its bounds are strictly apart along an axis:
a disc of radius r at (0, 0) and a unit block at (r + 1, 0) (apart along x); not the
block at (r, 0) (touching); not a disc that rotates; not a half-plane."
  (with-fixture simulator-bridge ()
    (flet ((screened-p (block-x &key rotating half-plane)
             (let* ((form `(scenario "SCREEN" "Two bodies."
                             (parameters ("R" :positive) ("G" :positive))
                             (gravity "G")
                             (body "DISC" :mass 1 :position (0 0) :velocity (0 0)
                                   ,@(and rotating '(:inertia :uniform))
                                   :shape (circle "R"))
                             ,(if half-plane
                                  `(body "WALL" :fixed t :shape (half-plane (,block-x 1) (,block-x 0)))
                                  `(body "BLOCK" :mass 1 :position (,block-x 0) :velocity (0 0)
                                         :shape (polygon (0 0) (1 0) (1 1) (0 1))))
                             (simulate :states 1)))
                    (scenario (ames:parse-scenario
                               (labels ((walk (x)
                                          (cond ((and (stringp x) (string/= x "Two bodies."))
                                                 (intern x '#:ames-scenario))
                                                ((consp x) (cons (walk (car x)) (walk (cdr x))))
                                                (t x))))
                                 (walk form))))
                    (bodies (ames:scenario-bodies scenario)))
               (funcall (ames.simulator::make-pair-screen) scenario (first bodies) (second bodies)))))
      (is-true (screened-p '(+ "R" 1)))
      (is-false (screened-p "R"))
      (is-false (screened-p '(+ "R" 1) :rotating t))
      (is-false (screened-p '(+ "R" 1) :half-plane t)))))

(test polynomial-identities-are-settled-as-ratsimp-settles-them
  "POLYNOMIAL-IDENTITY-VERDICT: a difference that cancels is :ZERO, one that does not is
:NONZERO (quantity terms are indeterminates), and anything but a polynomial is left to
Maxima (NIL); where it answers, ratsimp() agrees."
  (with-fixture simulator-bridge ()
    (let ((cases '(((- (* 2 (+ a (acc b :x))) (+ (acc b :x) a (acc b :x) a)) :zero)
                   ((- (* (+ a b) (- a b)) (- (expt a 2) (expt b 2))) :zero)
                   ((- (/ (acc b :x) 2) (* 1/2 (acc b :y))) :nonzero)
                   ((+ (* m (acc b :x)) (- f)) :nonzero)
                   ((- (sin a) (sin a)) nil)
                   ((/ 1 a) nil))))
      (loop for (expression verdict) in cases
            do (is (eq verdict (ames.simulator::polynomial-identity-verdict expression))
                   "~S" expression)
               (when verdict
                 (is (eq (eq verdict :zero)
                         (eql 0 (ames.maxima:simplify bridge expression)))
                     "ratsimp disagrees on ~S" expression))))))

(defun substituted-by-assoc (bindings expression)
  "EXPRESSION with its variables and terms replaced as by ASSOC over the alist BINDINGS
(the walk of SUBSTITUTE-EXPRESSIONS before its table: the reference)."
  (labels ((walk (x)
             (let ((entry (and (or (ames.base:variable-symbol-p x) (ames.base:quantity-term-p x))
                               (assoc x bindings :test #'equal))))
               (cond (entry (cdr entry))
                     ((and (consp x) (not (ames.base:quantity-term-p x)))
                      (cons (car x) (mapcar #'walk (cdr x))))
                     (t x)))))
    (walk expression)))

(test many-bindings-substitute-as-an-alist-does
  "SUBSTITUTE-EXPRESSIONS with more bindings than its table threshold: the first
binding of a term wins, as with ASSOC, inside functions too, and a term bound to
nothing stays; on random sums and products of positions it gives what ASSOC over the alist gives."
  (let* ((bindings (append (list (cons '(acc b1 :x) 'first) (cons 'w1 '(+ a 1)))
                           (loop for k from 0 below 40
                                 collect (cons (list 'pos (intern (format nil "B~D" k)) :x) k))
                           (list (cons '(acc b1 :x) 'second))))
         (expression '(+ (acc b1 :x) (* w1 (pos b3 :x)) (sin (pos b3 :x)) (pos b99 :x)))
         (random (sb-ext:seed-random-state 24)))
    (is (equal '(+ first (* (+ a 1) 3) (sin 3) (pos b99 :x))
               (ames.base:substitute-expressions bindings expression)))
    (dotimes (i 50)
      (let ((expression (cons (if (zerop (random 2 random)) '+ '*)
                              (loop repeat (1+ (random 6 random))
                                    collect (list 'pos (intern (format nil "B~D" (random 60 random))) :x)))))
        (is (equal (substituted-by-assoc bindings expression)
                   (ames.base:substitute-expressions bindings expression)))))))
