;;;; t/pushed-block.lisp -- the pushed block that tips or slides (issue 23): its two textbook
;;;; states, each at its start, and the fork between them.
;;;;
;;;; scenarios/pushed-block-tips-or-slides.lisp: a uniform block (width w, height k, mass m)
;;;; on a rough floor (mu), pushed by P > mu m g on its back face at height y = 9k/20 above
;;;; its centre (PUSHED-BLOCK-TIPS; the block pushed low, y = -9k/20, is
;;;; awaiting-rotation/pushed-block-slides.lisp, t/tipping-criterion.lisp). The
;;;; textbook (e.g. Meriam and Kraige, "sliding or tipping"): sliding flat, the floor's
;;;; resultant acts at x_N = (y P + (k/2) mu m g) / (m g) ahead of the centre; the block
;;;; stays flat while x_N <= w/2 and slides at (P - mu m g) / m; it tips about its front
;;;; edge when y P + (k/2) mu m g > (w/2) m g, at the start with
;;;; alpha = (m g w/2 - (y + k/2) P) / I_edge, I_edge = m (w^2 + k^2) / 3, its centre
;;;; accelerating at alpha x r (r from the edge to the centre), so that the edge's normal
;;;; force is N = m g - m alpha w/2 and its friction F = -m alpha k/2 - P (static where
;;;; -mu N < F < mu N: the tipping branch's two friction limits). Each test settles the
;;;; first state under its branch's facts (the choice search, the model solved and
;;;; integrated, no end sought) and compares with these by Maxima equivalence; the fork's
;;;; fact is the criterion (its ratio to it a factor of one sign).

(in-package #:ames.tests)

(def-suite pushed-block :in all-tests
  :description "The pushed block that tips or slides: the sliding state's acceleration,
the tipping state's start, and the fork on the textbook's criterion.")

(in-suite pushed-block)

(defun pushed-block-scenario (name)
  "The scenario NAME (a string) of scenarios/pushed-block-tips-or-slides.lisp."
  (named-scenario "pushed-block-tips-or-slides" name))

(defun push-height (scenario)
  "The height y of SCENARIO's push above the block's centre, over the parameters."
  (second (ames.scenario:scenario-force-point (first (ames:scenario-forces scenario)))))

(defun call-with-first-state (scenario bridge facts function)
  "Call FUNCTION with the RUN, the SOLVED model and the integrated GROUPS of SCENARIO's
first state, settled by the choice search under its assumptions and FACTS (relations in
the scenario's own parameter symbols)."
  (let ((world (nth-value 1 (ames:check-scenario scenario bridge))))
    (ames.maxima:with-assumptions (bridge (append (ames:scenario-assumption-relations scenario)
                                                  facts))
      (let* ((run (ames.simulator::make-run world bridge))
             (solved (ames.simulator::trial-solved (ames.simulator::settle-choices run))))
        (funcall function run solved (ames.simulator::integrate-groups run solved))))))

(defun criterion-gap (bridge scenario)
  "20 (y P + (k/2) mu m g - (w/2) m g) for SCENARIO's push, expanded (as the run's fork
writes its fact): positive where the block tips."
  (ames.maxima:simplify
   bridge (in-scenario-terms scenario `(* 20 (- (+ (* ,(push-height scenario) p) (* 1/2 k mu m g))
                                                (* 1/2 w m g))))
   :strategy :ratsimp))

(test pushed-block-slides-flat-at-the-textbook-acceleration
  "Where the criterion keeps it flat (the run's branch 2), the block pushed at y = 9k/20
slides without turning at (P - mu m g) / m."
  (with-fixture simulator-bridge ()
    (let ((scenario (pushed-block-scenario "pushed-block-tips-or-slides")))
      (call-with-first-state
       scenario bridge (list `(< ,(criterion-gap bridge scenario) 0))
       (lambda (run solved groups)
         (flet ((x (form) (in-scenario-terms scenario form)))
           (is-same-vector bridge "the sliding block's acceleration"
                           (per-body (ames.simulator::solved-accelerations run solved groups) "BLOCK")
                           (x '((/ (- p (* mu m g)) m) 0)))
           (is-same bridge "its angular acceleration"
                    (per-body (ames.simulator::solved-angular-accelerations run solved groups) "BLOCK")
                    0)))))))

(defun edge-static-limits (scenario)
  "The tipping block's front edge's lower and upper static friction limits at the start,
F + mu N > 0 and mu N - F > 0, from the textbook's alpha (see the file header)."
  (let* ((y (push-height scenario))
         (alpha (in-scenario-terms scenario `(/ (- (* m g (/ w 2)) (* (+ ,y (/ k 2)) p))
                                                (/ (* m (+ (* w w) (* k k))) 3))))
         (normal (in-scenario-terms scenario `(- (* m g) (* m ,alpha (/ w 2)))))
         (friction (in-scenario-terms scenario `(- (* -1 m ,alpha (/ k 2)) p)))
         (mu (in-scenario-terms scenario 'mu)))
    (values `(> (+ ,friction (* ,mu ,normal)) 0) `(> (- (* ,mu ,normal) ,friction) 0)
            alpha normal)))

(test pushed-high-block-tips-about-its-front-edge-at-the-textbook-rate
  "Pushed at y = 9k/20 where the criterion says it tips, and its front edge sticks (both
static friction limits), the block turns about that edge: one rotation path, with
alpha = (m g w/2 - (y + k/2) P) / I_edge at the start (half the slope of omega^2 along
the angle there)."
  (with-fixture simulator-bridge ()
    (let ((scenario (pushed-block-scenario "pushed-block-tips-or-slides")))
      (multiple-value-bind (lower upper alpha) (edge-static-limits scenario)
        (call-with-first-state
         scenario bridge (list `(> ,(criterion-gap bridge scenario) 0) lower upper)
         (lambda (run solved groups)
           (declare (ignore run solved))
           (let ((path (find :rotation-path groups :key #'ames.simulator::group-kind))
                 (s 'ames.simulator::arc-length))
             (is (= 1 (length groups)))
             (is (not (null path)) "no rotation path: ~S" (mapcar #'ames.simulator::group-kind groups))
             (when path
               (is-same bridge "the angular acceleration at the start"
                        (ames.maxima:simplify
                         bridge (substitute-expressions
                                 (list (cons s 0))
                                 `(/ ,(ames.geometry:differentiate
                                       (ames.simulator::group-speed-squared path) s)
                                     2)))
                        alpha)))))))))

(test pushed-high-block-branches-on-the-textbook-criterion-first
  "The block pushed at y = 9k/20, symbolic: the first fact the run branches on is the
criterion y P + (k/2) mu m g against (w/2) m g, up to a factor of one sign free of the
push and of friction."
  (with-fixture simulator-bridge ()
    (let* ((scenario (unbranched (pushed-block-scenario "pushed-block-tips-or-slides")))
           (history (simulate-stopping-when-ambiguous scenario bridge))
           (condition (getf (ames::history-notes history) :stopped-by)))
      (is (eq :ambiguous (ames::history-outcome history)))
      (is (typep condition 'ames::ambiguous-transition))
      (when (typep condition 'ames::ambiguous-transition)
        (let* ((fact (ames::ambiguous-transition-missing-fact condition))
               (ratio (ames.maxima:simplify
                       bridge `(/ (- ,(second fact) ,(third fact)) ,(criterion-gap bridge scenario))
                       :strategy :ratsimp)))
          (is (and (free-of-p (in-scenario-terms scenario 'p) ratio)
                   (free-of-p (in-scenario-terms scenario 'mu) ratio)
                   (call-with-scenario-facts
                    bridge scenario
                    (lambda ()
                      (or (eq :true (ames.algebra:decide bridge `(> ,ratio 0)))
                          (eq :true (ames.algebra:decide bridge `(< ,ratio 0)))))))
              "the fork's fact ~S is not the textbook's criterion (ratio ~S)" fact ratio))))))
