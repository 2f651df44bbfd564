;;;; src/algebra/sine-roots.lisp -- the first root ahead of A + C sin q (or A + B cos q) in the
;;;; form a textbook writes: pi - asin(2 sin(a)/3), not a half-angle arc tangent.
;;;;
;;;; sin is monotonic on each piece [k pi - pi/2, k pi + pi/2], where sin q = c has the one
;;;; solution q = k pi + (-1)^k asin(c). From a start q0 in piece k, moving in the direction
;;;; d (1 or -1), sin runs monotonically to its value d (-1)^k at the piece's end
;;;; k pi + d pi/2: the root is in that stretch when c lies strictly past sin(q0) and up to
;;;; that end value; else, when -1 <= c <= 1, it is in the next piece, k + d. Every choice
;;;; is decided under the assumptions (or, under parameter values, by them, recorded as
;;;; DECIDE-BY-VALUES does); cos q = sin(q + pi/2) shifts into the same. The half-angle
;;;; method (trig-roots.lisp) proves the earliest root of any sinusoid, in arc tangents
;;;; whose comparisons Maxima rarely decides; this one covers the single-function factors
;;;; (a ladder's wall push, its top's height) in the forms that compare.

(in-package #:ames.algebra)

(defun decided-or-by-values (bridge relation)
  "RELATION's truth under the assumptions (:TRUE, :FALSE or :UNKNOWN), or, when they
leave it open, at the run's parameter values (recorded, see DECIDE-BY-VALUES); while
the values decide first (values-first.lisp), after only a cheap proof."
  (let ((truth (decide-first-cheaply bridge relation)))
    (if (eq truth :unknown) (or (decide-by-values relation) :unknown) truth)))

(defvar *sine-variable* (make-symbol "SINE")
  "The variable standing for sin q or cos q in SINE-FACTOR-PARTS.")

(defun sine-factor-parts (bridge factor coordinate)
  "(values HEAD C) when FACTOR is A + K HEAD(q), HEAD sin or cos of the name COORDINATE q,
A and K free of q and K /= 0 decided: the root condition HEAD(q) = C, C = -A/K. NIL
otherwise."
  (let ((v (auxiliary-variable bridge *sine-variable*)))
    (dolist (head '(sin cos) nil)
      (let* ((linear (subst v (list head coordinate) factor :test #'equal))
             (coefficients (and (free-of-p coordinate linear) (not (free-of-p v linear))
                                (call-or-nil (lambda () (polynomial-coefficients-in bridge linear v))))))
        (when (and (= (length coefficients) 2)
                   (member (decided-sign bridge (second coefficients)) '(:positive :negative)))
          (return (values head (simplified bridge `(- (/ ,(first coefficients) ,(second coefficients)))))))))))

(defun sine-piece (bridge q0)
  "The integer k in -3..4 with k pi - pi/2 <= Q0 < k pi + pi/2 decided, or NIL."
  (loop for k from -3 to 4
        when (eq :true (decided-or-by-values
                        bridge `(and (>= ,q0 (- (* ,k pi) (/ pi 2))) (< ,q0 (+ (* ,k pi) (/ pi 2))))))
          return k))

(defun sine-root-ahead (bridge c q0 direction)
  "The first q strictly ahead of Q0 in DIRECTION with sin q = C (see the file header):
(values Q :FOUND), (values :NONE NIL), or NIL when a needed fact is not decided."
  (let ((k (sine-piece bridge q0)))
    (when k
      (flet ((solution (piece) (simplified bridge `(+ (* ,piece pi) (* ,(expt -1 piece) (asin ,c)))))
             (truth (relation) (decided-or-by-values bridge relation)))
        (let* ((start (simplified bridge `(sin ,q0)))
               (end-value (* direction (expt -1 k)))
               ;; the stretch from sin(q0) (excluded) to END-VALUE (included)
               (within (if (plusp end-value)
                           `(and (> ,c ,start) (<= ,c 1))
                           `(and (< ,c ,start) (>= ,c -1)))))
          (case (truth within)
            (:true (values (solution k) :found))
            (:false (case (truth `(and (>= ,c -1) (<= ,c 1)))
                      (:true (values (solution (+ k direction)) :found))
                      (:false (values :none nil))))))))))

(defun single-function-root-ahead (bridge factor coordinate start direction)
  "The first root of FACTOR strictly ahead of START in DIRECTION when FACTOR is
A + K sin q or A + K cos q (SINE-FACTOR-PARTS): (values Q :FOUND) or (values :NONE NIL);
NIL when FACTOR has another form or a needed fact is not decided."
  (multiple-value-bind (head c) (sine-factor-parts bridge factor coordinate)
    (case head
      (sin (sine-root-ahead bridge c start direction))
      ;; cos q = sin(q + pi/2)
      (cos (multiple-value-bind (root status)
               (sine-root-ahead bridge c (simplified bridge `(+ ,start (/ pi 2))) direction)
             (case status
               (:found (values (simplified bridge `(- ,root (/ pi 2))) :found))
               (t (values root status))))))))
