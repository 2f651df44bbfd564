;;;; src/simulator/exponential-floors.lisp -- a sum of two decaying exponentials that never
;;;; turns negative: the overdamped oscillator.
;;;;
;;;; An overdamped spring's length is G = A + exp(P tau) (B cosh(K tau) + C sinh(K tau)),
;;;; that is A + C1 exp(S1 tau) + C2 exp(S2 tau) with S = P +- K < 0. Its root search does
;;;; not decide (the rates' ratio is irrational), but G' = C1 S1 exp(S1 tau) + C2 S2
;;;; exp(S2 tau) vanishes at most once, at tau* = log(Q) / (S1 - S2), Q = -(C2 S2) / (C1 S1),
;;;; when Q > 0. So G is monotone on each side of tau*, and tends to A: after a start where
;;;; it is not negative, G never turns negative when A >= 0 and G(tau*) > 0 (or tau* is no
;;;; time after the start). Sound: it answers only what it proves (FIRST-TIME-NEGATIVE,
;;;; termination.lisp).

(in-package #:ames.simulator)

(defun hyperbolic-rate (g)
  "K of the first sinh(K tau) or cosh(K tau) in G, as an expression (/ X tau), or NIL."
  (labels ((walk (x)
             (when (consp x)
               (if (and (member (first x) '(sinh cosh)) (not (free-of-p 'tau (second x))))
                   (return-from hyperbolic-rate `(/ ,(second x) tau))
                   (mapc #'walk (rest x))))))
    (walk g)
    nil))

(defun two-exponentials (run g)
  "(A C1 S1 C2 S2) with G = A + C1 exp(S1 tau) + C2 exp(S2 tau), from G = A + exp(P tau)
\(B cosh(K tau) + C sinh(K tau)) (S = P +- K, C1,2 = (B +- C) / 2), checked by
simplification; or NIL."
  (let* ((decay (decaying-exponential run g))
         (k (and decay (hyperbolic-rate g)))
         (k (and k (tidy run k))))
    (when (and k (free-of-p 'tau k) (not (holds run `(= ,k 0))))
      (let* ((u (gensym "DECAY"))
             (linear (tidy run (exponentials-as-powers run decay u g)))
             (a (tidy run (substitute-expressions (list (cons u 0)) linear)))
             (wave (tidy run `(- ,(substitute-expressions (list (cons u 1)) linear) ,a)))
             (b (tidy run (at-time wave 0)))
             (c (tidy run `(/ ,(at-time (time-derivative wave) 0) ,k)))
             (p (tidy run `(/ ,(second decay) tau))))
        (when (and (free-of-p 'tau a) (free-of-p u a) (free-of-p 'tau p)
                   (holds run `(= (- ,wave (+ (* ,b (cosh (* ,k tau))) (* ,c (sinh (* ,k tau))))) 0))
                   (holds run `(= (- ,g (+ ,a (* ,decay ,wave))) 0)))
          (list a (tidy run `(/ (+ ,b ,c) 2)) (tidy run `(+ ,p ,k))
                (tidy run `(/ (- ,b ,c) 2)) (tidy run `(- ,p ,k))))))))

(defun overdamped-never-negative-p (run g)
  "True when G, a sum A + C1 exp(S1 tau) + C2 exp(S2 tau) with S1, S2 < 0 (TWO-EXPONENTIALS),
is proven never to turn negative after a start where it is not negative (see the file
header)."
  (let ((parts (and (not (trigonometric-in-time-p g)) (two-exponentials run g))))
    (when parts
      (destructuring-bind (a c1 s1 c2 s2) parts
        (and (holds run `(< ,s1 0)) (holds run `(< ,s2 0)) (holds run `(>= ,a 0))
             (not (holds run `(= ,c1 0)))
             (let ((q (tidy run `(- (/ (* ,c2 ,s2) (* ,c1 ,s1))))))
               (case (decide run `(> ,q 0))
                 (:false t)
                 (:true (let ((critical (tidy run `(/ (log ,q) (- ,s1 ,s2)))))
                          (case (decide run `(> ,critical 0))
                            (:false t)
                            (:true (holds run `(> ,(at-time g critical) 0)))
                            (t nil))))
                 (t nil))))))))
