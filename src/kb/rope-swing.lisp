;;;; src/kb/rope-swing.lisp -- a body swinging on a taut rope from a fixed point turns back at the
;;;; top of its swing (the language's "Oscillation and turning points").
;;;;
;;;; A taut straight piece of rope from a point of a fixed body to a point of a free body keeps
;;;; the free point on a circle about the fixed one while the piece turns (a pendulum: the
;;;; span's turning mode, spans.lisp). Its angle's rate, (B - A) x (B' - A') / |B - A|^2,
;;;; changes sign where the swing stops and comes back: the event (:turns BODY), BODY the
;;;; free body, and the next state swings the other way. The modes are the two ways of
;;;; swinging, with no equations of their own; a body released at rest starts in the one its
;;;; angular acceleration is consistent with (the other's exit holds at once). The rate is
;;;; written without the positive |B - A|^2.

(in-package #:ames.kb)

(register-template *mechanics* 'swing-rate
                   (lambda (situation a b)
                     (ames.geometry:cross (span-difference situation a b 'pos)
                                          (span-difference situation a b 'vel)))
                   :documentation "(B - A) x (B' - A'): the rate of the angle of the span from A to B, times its length squared.")

(defmacro define-rope-swing (name fixed-end documentation)
  "A turning point of the swing of a taut rope piece whose end FIXED-END (:FROM or :TO)
is on a fixed body and whose other end is on a free body."
  (let ((fixed-body (if (eq fixed-end :from) '?body1 '?body2))
        (free-body (if (eq fixed-end :from) '?body2 '?body1)))
    `(defcomponent ,name (:knowledge-base *mechanics*)
       ,documentation
       (:arguments (?segment :entity rope-segment
                             :where (:rope ?rope :from (?body1 ?p1) :to (?body2 ?p2) :within-one-body nil))
                   (,fixed-body :entity body :where (:fixed t))
                   (,free-body :entity body :where (:fixed nil :driven nil)))
       ;; a piece closed at its pulley has no span (closed-rope-pieces.lisp): no swing
       (:activation (:believes (taut ?rope)) (:believes (span ?segment :from ?_ :to ?_)))
       (:mode :counter-clockwise
        (:entry (> (swing-rate (?body1 ?p1) (?body2 ?p2)) 0))
        (:transition :to :clockwise :when (< (swing-rate (?body1 ?p1) (?body2 ?p2)) 0)
                     :event (:turns ,free-body)))
       (:mode :clockwise
        (:entry (< (swing-rate (?body1 ?p1) (?body2 ?p2)) 0))
        (:transition :to :counter-clockwise :when (> (swing-rate (?body1 ?p1) (?body2 ?p2)) 0)
                     :event (:turns ,free-body))))))

(define-rope-swing swing-from-the-first-end :from
  "A body hanging on a taut rope piece whose first end is on a fixed body swings back
where the piece's angular rate changes sign: event (:turns BODY), the next state swings
the other way.")

(define-rope-swing swing-from-the-last-end :to
  "As SWING-FROM-THE-FIRST-END, for a piece whose last end is on the fixed body.")
