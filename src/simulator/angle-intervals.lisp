;;;; src/simulator/angle-intervals.lisp -- a condition proven not to fire before a rotating
;;;; body turns back, under numbers, by interval arithmetic.
;;;;
;;;; Along a :ROTATION-PATH motion (rotation-path.lisp) the body goes no further than the
;;;; turning point of its energy integral E(theta) = omega^2 (where E turns negative it
;;;; turns back). A condition whose root along the angle has no closed form (a pivot's
;;;; normal force, quadratic in sin and cos) is searched with numbers
;;;; (numeric-angle-roots.lisp); when the search finds no crossing, that is no proof. Here,
;;;; when every parameter has a number, the condition's function f(theta) is bounded
;;;; below over the whole stretch from the start to just past the turning point by
;;;; interval arithmetic: the stretch is cut into pieces, f evaluated over each piece with
;;;; intervals (sin and cos over an interval, +, -, *, /, integer powers, square roots,
;;;; each result widened by a relative 1e-12 for the rounding of double precision), and a
;;;; piece whose lower bound is not positive is halved, down to a 2^-16th of the first
;;;; pieces (ames.algebra's intervals.lisp). f > 0 on every piece proves that the condition never fires before the body
;;;; turns back; anything else (a bound that stays non-positive, a form not evaluated) is
;;;; no proof, and the condition stays undecided. Without numbers, a function quadratic in
;;;; one sinusoid of the angle (a normal force) may be proven positive at every angle
;;;; (ames.algebra's sinusoid-quadratics.lisp).

(in-package #:ames.simulator)

(defun positive-before-turning-p (run group function)
  "True when, under the run's numbers, FUNCTION (of the angle) is proven positive from
GROUP's start to just past the angle where its body turns back (its energy integral
turns negative, within a full turn): the condition it stands for never fires within the
state's motion along the angle. NIL when not proven (no numbers, no turning point found,
or the bound fails). Without numbers: FUNCTION proven positive at every angle, a
quadratic in one sinusoid of it (AMES.ALGEBRA:SIGN-AT-EVERY-ANGLE)."
  (unless (run-numbers-known-p run)
    (return-from positive-before-turning-p
      (eq :positive (ames.algebra:sign-at-every-angle (run-bridge run) (tidy run function)
                                                      +arc-length+))))
  (progn
    (let ((reach (numeric-turning-reach run group))
          (bindings (numeric-bindings run)))
      (when (and reach (< reach (* 2 pi)))
        (let ((start (expression-value (group-s0 group) bindings))
              (beyond (+ reach (* 1d-9 (max 1d0 reach)))))
          (when (realp start)
            (let ((start (coerce start 'double-float)))
              (ames.algebra:positive-over-interval-p (tidy run function) +arc-length+
                                      start (+ start (* (group-direction group) beyond))
                                      bindings))))))))
