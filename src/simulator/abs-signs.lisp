;;;; src/simulator/abs-signs.lisp -- abs() of a function of TAU whose sign is known over a
;;;; state, written without abs() before a root search.
;;;;
;;;; Quadratic drag -c |v| v puts |v| into a state's closed forms; a block sliding alone
;;;; has v = 9 / (9 + 2 tau) and its "turns" candidate asks for the earliest root of
;;;; (81 + 18 tau + 9 |9 + 2 tau|) / ((9 + 2 tau) |9 + 2 tau|), which the root search
;;;; cannot take (abs is no polynomial) although 9 + 2 tau > 0 for every tau >= 0. A
;;;; linear U = U(AFTER) + U' (TAU - AFTER) keeps the sign of U(AFTER) for TAU >= AFTER
;;;; when U' has that sign too: abs(U) is U there, or -U. So does a U whose derivative has
;;;; a sign for every TAU (a sliding block's speed under drag and a push,
;;;; c1 exp(k tau) - c0 with c1 > 0).

(in-package #:ames.simulator)

(defun mentions-abs-p (g)
  "True when G has an abs()."
  (and (consp g) (or (eq (first g) 'abs) (some #'mentions-abs-p (rest g)))))

(defun abs-of-known-sign (run u after)
  "U or (- U) when the function U of TAU is proven >= 0, or <= 0, for every TAU >= AFTER:
U(AFTER) has that sign and so has dU/dTAU (proven for every TAU: a constant, or such as
c exp(k TAU) with c of known sign); NIL when not proven."
  (let ((slope (tidy run (time-derivative u)))
        (start (tidy run (at-time u after))))
    (flet ((proven (operator) (and (eq (decide run (list operator start 0)) :true)
                                   (eq (decide run (list operator slope 0)) :true))))
      (cond ((proven '>=) u)
            ((proven '<=) `(- ,u))))))

(defun without-abs-of-known-sign (run g after)
  "G with each abs(U), U linear in TAU of a sign proven over TAU >= AFTER, written U or
-U (ABS-OF-KNOWN-SIGN); the other abs() left as they are."
  (if (atom g)
      g
      (let ((g (cons (first g) (mapcar (lambda (x) (without-abs-of-known-sign run x after)) (rest g)))))
        (or (and (eq (first g) 'abs) (= (length g) 2) (not (free-of-p 'tau (second g)))
                 (abs-of-known-sign run (second g) after))
            g))))

(defun keeps-sign-p (run u after)
  "True when U, a function of TAU, is proven nonzero for every TAU >= AFTER: U(AFTER) > 0
and dU/dTAU >= 0 (for every TAU), or U(AFTER) < 0 and dU/dTAU <= 0."
  (let ((slope (tidy run (time-derivative u)))
        (start (tidy run (at-time u after))))
    (flet ((proven (strict loose) (and (eq (decide run (list strict start 0)) :true)
                                       (eq (decide run (list loose slope 0)) :true))))
      (or (proven '> '>=) (proven '< '<=)))))

(defun numerator-without-root-p (run g after)
  "True when G, or its numerator N when G is a quotient N / D, is proven to have no root
after AFTER (by the root search, or KEEPS-SIGN-P: a sum of exponentials in TAU): then G
has none either (the root search takes no quotient and no exponential)."
  (let ((n (if (and (consp g) (eq (first g) '/) (= (length g) 3)) (second g) g)))
    (and (not (mentions-abs-p n))
         (if (free-of-p 'tau n)
             (eq :true (decide run `(/= ,n 0)))
             (or (keeps-sign-p run n after)
                 (and (not (eq n g))
                      (eq :none (ames.algebra:earliest-root (run-bridge run) n 'tau
                                                            :after after :strictly t :candidates nil))))))))
