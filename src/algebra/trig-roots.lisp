;;;; src/algebra/trig-roots.lisp -- the earliest root of A + B cos(w t) + C sin(w t), proven earliest.
;;;;
;;;; Springs make termination conditions sinusoidal in time: a bumper's compression
;;;; (v0/w) sin(w t) returns to 0 at t = pi/w. With x = w t and the half angle
;;;; u = tan(x/2) (cos x = (1 - u^2)/(1 + u^2), sin x = 2u/(1 + u^2)), a root x in (0, pi)
;;;; of g(x) = A + B cos x + C sin x is a root u > 0 of the quadratic
;;;;   P(u) = (A - B) u^2 + 2 C u + (A + B)
;;;; (x = 2 atan u); x = pi is a root exactly when A = B; a root in (pi, 2 pi) is
;;;; pi + 2 atan u' for a root u' > 0 of g(pi + x') in the same way,
;;;;   P'(u') = (A + B) u'^2 - 2 C u' + (A - B);
;;;; and x = 2 pi when A + B = 0. g has period 2 pi, so if none of these is a root there is
;;;; none at all. EARLIEST-ROOT (roots.lisp) proves which root of a quadratic is earliest
;;;; from the signs of their product and sum, so the earliest x is proven in the same
;;;; way. A root exists at all only when A^2 <= B^2 + C^2: when that is not decided, the
;;;; answer is :UNKNOWN with that fact.

(in-package #:ames.algebra)

(defun earliest-trigonometric-root (bridge expression variable &key (after 0) (strictly t))
  "The earliest real root of EXPRESSION = 0 in VARIABLE greater than AFTER (or equal to
it, when STRICTLY is false), proven earliest under the current assumptions, where
EXPRESSION is A + B cos(w VARIABLE + c) + C sin(w VARIABLE + c') with A, B, C, w, c,
c' free of VARIABLE (one frequency). Returns, like EARLIEST-ROOT,
  (values ROOT :FOUND)      the proven earliest root (prefix algebra);
  (values :NONE NIL)        proven: no root after AFTER (A^2 > B^2 + C^2);
  (values :UNKNOWN FACT)    not decided; FACT is the relation whose truth is missing
                            (the amplitude condition (<= (expt A 2) (+ (expt B 2)
                            (expt C 2))), or whether a special point is a root), or NIL
                            (several frequencies, or signs the assumptions leave open).
An EXPRESSION without sine or cosine of VARIABLE goes to EARLIEST-ROOT (whose :UNKNOWN
carries candidates instead). Every root returned is substituted back: it must make
EXPRESSION simplify to 0 (or vanish numerically at admissible points); else :UNKNOWN.
Signals UNTRANSLATABLE-EXPRESSION, INVALID-BRIDGE-ARGUMENT (VARIABLE not a name, AFTER
depending on VARIABLE), MAXIMA-ERROR, MAXIMA-TIMEOUT."
  (check-root-search-arguments expression variable after)
  (unless (trigonometric-arguments expression variable)
    (return-from earliest-trigonometric-root
      (earliest-root bridge expression variable :after after :strictly strictly :candidates nil)))
  (let* ((shifted (if (eql after 0)
                      expression
                      (substitute-expressions (list (cons variable `(+ ,after ,variable))) expression)))
         (parts (call-or-nil (lambda () (sinusoid-coefficients bridge shifted variable)))))
    (if (null parts)
        (values :unknown nil)
        (destructuring-bind (a b c w) parts
          (case (decided-sign bridge w)
            (:positive)
            (:negative (setf c (simplified bridge `(- ,c)) w (simplified bridge `(- ,w))))
            (t (return-from earliest-trigonometric-root (values :unknown nil))))
          (multiple-value-bind (angle status) (earliest-angle bridge a b c strictly)
            (case status
              (:found
               (let ((root (simplified bridge `(+ ,after (/ ,angle ,w)))))
                 (if (root-checked-p bridge expression variable root (list a b c))
                     (values root :found)
                     (values :unknown nil))))
              (:none (values :none nil))
              (t (values :unknown angle))))))))

(defun earliest-angle (bridge a b c strictly)
  "The earliest x > 0 (x >= 0 unless STRICTLY) with A + B cos x + C sin x = 0, as
(values X :FOUND), (values NIL :NONE), or (values FACT :UNKNOWN), FACT the missing
relation or NIL (see the file header)."
  (let ((amplitude (amplitude-relation bridge a b c))
        (u (auxiliary-variable bridge *half-angle-variable*)))
    (flet ((settled (relation)
             (let ((verdict (decide bridge relation)))
               (when (eq verdict :unknown)
                 (return-from earliest-angle (values relation :unknown)))
               (eq verdict :true)))
           (first-positive-root (polynomial)
             (multiple-value-bind (root status)
                 (earliest-root bridge polynomial u :after 0 :strictly t :candidates nil)
               (case status
                 (:found root)
                 (t (if (eq root :none)
                        nil
                        (return-from earliest-angle
                          (values (undecided-quadratic-fact bridge polynomial u) :unknown))))))))
      (unless (settled amplitude)
        (return-from earliest-angle (values nil :none)))
      (when (and (not strictly) (settled `(= (+ ,a ,b) 0)))
        (return-from earliest-angle (values 0 :found)))
      (let ((first (first-positive-root `(+ (* (- ,a ,b) (expt ,u 2)) (* 2 ,c ,u) (+ ,a ,b))))
            (even (eq (decide bridge `(= ,c 0)) :true)))
        (when first
          ;; without a sine term, the only root in (0, pi) is acos(-A/B): cos is one-to-one
          ;; there; without a cosine term, the earliest is asin(-A/C) (see ODD-ANGLE)
          (return-from earliest-angle
            (values (cond (even `(acos (/ (- ,a) ,b)))
                          ((odd-angle bridge a b c nil))
                          (t `(* 2 (atan ,first))))
                    :found))))
      (when (settled `(= ,a ,b))
        (return-from earliest-angle (values 'pi :found)))
      (let ((second (first-positive-root `(- (+ (* (+ ,a ,b) (expt ,u 2)) (- ,a ,b)) (* 2 ,c ,u)))))
        (when second
          (return-from earliest-angle
            (values (cond ((eq (decide bridge `(= ,c 0)) :true)
                           `(- (* 2 pi) (acos (/ (- ,a) ,b))))
                          ((odd-angle bridge a b c t))
                          (t `(+ pi (* 2 (atan ,second)))))
                    :found))))
      (if (settled `(= (+ ,a ,b) 0))
          (values '(* 2 pi) :found)
          (values nil :none)))))

(defun amplitude-relation (bridge a b c)
  "The relation under which A + B cos x + C sin x has a root: A^2 <= B^2 + C^2; with one of
B, C proven 0 and the signs of A and the other K decided, the same written |A| <= |K|
(l w^2 - 3 g <= 0, not l^2 w^4 - 9 g^2 <= 0: a fact linear where its sides are, whose
boundary a parameter solves)."
  (let ((k (cond ((eq (decide bridge `(= ,b 0)) :true) c)
                 ((eq (decide bridge `(= ,c 0)) :true) b))))
    (flet ((sign-factor (x)
             (case (decided-sign bridge x) (:positive 1) (:negative -1))))
      (let ((sa (and k (sign-factor a))) (sk (and k (sign-factor k))))
        (if (and sa sk)
            `(<= ,(simplified bridge `(- (* ,sa ,a) (* ,sk ,k))) 0)
            `(<= ,(simplified bridge `(expt ,a 2))
                 ,(simplified bridge `(+ (expt ,b 2) (expt ,c 2)))))))))

(defun undecided-quadratic-fact (bridge polynomial u)
  "For the half-angle POLYNOMIAL in U (degree at most 2) whose earliest positive root is
not decided: the relation X > 0 on the first of its coefficients (highest degree
first) or its discriminant whose sign the assumptions leave open, the readable fact
that would settle it (the rod swinging back below its hinge or past it: the sign of A -
B); NIL when each sign is decided."
  (let ((coefficients (call-or-nil (lambda () (polynomial-coefficients-in bridge polynomial u)))))
    (when (and coefficients (<= (length coefficients) 3))
      (destructuring-bind (&optional (c0 0) (c1 0) (c2 0)) coefficients
        (find-if (lambda (fact)
                   (and (not (realp (second fact)))
                        (eq (decide bridge fact) :unknown)
                        (eq (decide bridge (list '< (second fact) 0)) :unknown)))
                 (mapcar (lambda (c) (list '> (simplified bridge c) 0))
                         (list c2 c1 c0 `(- (expt ,c1 2) (* 4 ,c2 ,c0)))))))))

(defun odd-angle (bridge a b c past-pi)
  "The earliest root of A + C sin x in (0, pi) (in (pi, 2 pi) when PAST-PI) written
asin(-A/C) (pi + asin(A/C)) when B is proven 0, else NIL. Called once the half-angle
quadratic has proven that root: its u = tan(x/2) is the smaller positive root of
A u^2 + 2 C u + A, of product 1, so u <= 1 and x <= pi/2 (past pi, likewise for x - pi),
where asin is the inverse of sin. The same angle as 2 atan(u), but u = (-C - sqrt(C^2 -
A^2))/A loses its digits where A is small beside C, and sin, cos of asin are algebraic
(a later state's initial values, the facts about the root stay short)."
  (when (eq (decide bridge `(= ,b 0)) :true)
    (if past-pi
        `(+ pi (asin (/ ,a ,c)))
        `(asin (/ (- ,a) ,c)))))

(defun root-checked-p (bridge expression variable root coefficients)
  "True when EXPRESSION vanishes at VARIABLE = ROOT: by simplification (the sines of
sums expanded: a phase asin(q) plus the root), else at
admissible points within 1e-9 of the size of COEFFICIENTS (A, B and C)."
  (let ((value (substitute-expressions (list (cons variable root)) expression)))
    (or (call-or-nil (lambda () (zero-expression-p bridge value)))
        (call-or-nil (lambda () (trigonometric-identity-p bridge value 0)))
        (let ((size `(+ ,@(mapcar (lambda (c) `(sqrt (expt ,c 2))) coefficients)))
              (checked 0) (failed nil))
          (call-with-admissible-points
           bridge `(> (+ ,value ,size) 0)
           (lambda (point)
             (let ((residual (expression-value value point))
                   (scale (expression-value size point)))
               (cond ((null scale))
                     ((and residual (<= (abs residual) (* 1d-9 (max scale 1d-300)))) (incf checked))
                     (t (setf failed t))))
             failed))
          (and (not failed) (>= checked *verification-points*))))))
