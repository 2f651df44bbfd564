;;;; src/simulator/abs-signs.lisp -- abs() of a function of TAU whose sign is known over a
;;;; state, written without abs() before a root search.
;;;;
;;;; Quadratic drag -c |v| v puts |v| into a state's closed forms; a block sliding alone
;;;; has v = 9 / (9 + 2 tau) and its "turns" candidate asks for the earliest root of
;;;; (81 + 18 tau + 9 |9 + 2 tau|) / ((9 + 2 tau) |9 + 2 tau|), which the root search
;;;; cannot take (abs is no polynomial) although 9 + 2 tau > 0 for every tau >= 0. A
;;;; linear U = U(AFTER) + U' (TAU - AFTER) keeps the sign of U(AFTER) for TAU >= AFTER
;;;; when U' has that sign too: abs(U) is U there, or -U.

(in-package #:ames.simulator)

(defun mentions-abs-p (g)
  "True when G has an abs()."
  (and (consp g) (or (eq (first g) 'abs) (some #'mentions-abs-p (rest g)))))

(defun abs-of-known-sign (run u after)
  "U or (- U) when the linear function U of TAU is proven >= 0, or <= 0, for every
TAU >= AFTER; NIL when U is not linear in TAU or its sign is not proven."
  (let ((slope (tidy run (time-derivative u))))
    (when (free-of-p 'tau slope)
      (let ((start (tidy run (at-time u after))))
        (flet ((proven (operator) (and (eq (decide run (list operator start 0)) :true)
                                       (eq (decide run (list operator slope 0)) :true))))
          (cond ((proven '>=) u)
                ((proven '<=) `(- ,u))))))))

(defun without-abs-of-known-sign (run g after)
  "G with each abs(U), U linear in TAU of a sign proven over TAU >= AFTER, written U or
-U (ABS-OF-KNOWN-SIGN); the other abs() left as they are."
  (if (atom g)
      g
      (let ((g (cons (first g) (mapcar (lambda (x) (without-abs-of-known-sign run x after)) (rest g)))))
        (or (and (eq (first g) 'abs) (= (length g) 2) (not (free-of-p 'tau (second g)))
                 (abs-of-known-sign run (second g) after))
            g))))

(defun numerator-without-root-p (run g after)
  "True when G is a quotient N / D whose numerator N (a polynomial in TAU, or a constant)
is proven to have no root after AFTER: then G has none either (the root search takes no
quotient)."
  (and (consp g) (eq (first g) '/) (= (length g) 3)
       (not (mentions-abs-p (second g)))
       (eq :none (ames.algebra:earliest-root (run-bridge run) (second g) 'tau
                                             :after after :strictly t :candidates nil))))
