;;;; src/geometry/pieces.lisp -- boundary pieces: directed line segments and circular arcs.
;;;;
;;;; A shape's boundary and an obstacle's contact locus are both made of pieces,
;;;; directed so that the solid lies on the LEFT and the exterior on the right (a
;;;; counter-clockwise outline). A LINE-PIECE runs from START to END (or, when INFINITE,
;;;; along the whole line through them). An ARC-PIECE lies on the circle (CENTER, RADIUS)
;;;; and runs from the point at angle FROM to the point at angle TO, counter-clockwise
;;;; when SENSE is :CCW (a convex piece: the solid inside the circle) or clockwise when
;;;; :CW (a concave piece: the solid outside). The outward normal points to the right of
;;;; the direction of travel: radially outward on a :CCW arc, toward the centre on :CW.
;;;; Also here: which point of a piece is nearest what, and piece-piece intersections,
;;;; all decided through a DECIDER.

(in-package #:ames.geometry)

(defstruct (line-piece (:constructor make-line-piece (start end &key name infinite)))
  "A directed straight piece from START to END, solid on its left; INFINITE when it is
the whole line through them (a half-plane's boundary). NAME is the feature it is."
  start end name infinite)

(defstruct (arc-piece (:constructor make-arc-piece (center radius from to sense &key name full)))
  "A directed circular piece on the circle (CENTER, RADIUS) from angle FROM to angle TO,
turning counter-clockwise (SENSE :CCW, convex) or clockwise (:CW, concave); FULL when it
is the whole circle. NAME is the feature it is."
  center radius from to sense name full)

(defun piece-name (piece)
  (etypecase piece (line-piece (line-piece-name piece)) (arc-piece (arc-piece-name piece))))

(defun line-direction (piece)
  "END - START of the line PIECE."
  (v- (line-piece-end piece) (line-piece-start piece)))

(defun line-normal (piece)
  "The outward (right-hand) normal of the line PIECE, not normalized."
  (rot-cw (line-direction piece)))

(defun arc-point (piece angle)
  "The point of the circle of the arc PIECE at ANGLE."
  (v+ (arc-piece-center piece) (vscale (arc-piece-radius piece) (polar angle))))

(defun piece-start (piece)
  "The first point of PIECE."
  (etypecase piece
    (line-piece (line-piece-start piece))
    (arc-piece (arc-point piece (arc-piece-from piece)))))

(defun piece-end (piece)
  "The last point of PIECE."
  (etypecase piece
    (line-piece (line-piece-end piece))
    (arc-piece (arc-point piece (arc-piece-to piece)))))

(defun arc-normal-direction (piece angle)
  "The outward normal direction of the arc PIECE at the point at ANGLE."
  (if (eq (arc-piece-sense piece) :ccw)
      (direction-at-angle angle)
      (opposite-direction (direction-at-angle angle))))

(defun piece-start-normal (piece)
  "The outward normal direction at the start of PIECE."
  (etypecase piece
    (line-piece (make-direction (line-normal piece)))
    (arc-piece (arc-normal-direction piece (arc-piece-from piece)))))

(defun piece-end-normal (piece)
  "The outward normal direction at the end of PIECE."
  (etypecase piece
    (line-piece (make-direction (line-normal piece)))
    (arc-piece (arc-normal-direction piece (arc-piece-to piece)))))

(defun piece-start-tangent (piece)
  "The direction of travel at the start of PIECE (a vector)."
  (rot-ccw (direction-vector (piece-start-normal piece))))

(defun piece-end-tangent (piece)
  "The direction of travel at the end of PIECE (a vector)."
  (rot-ccw (direction-vector (piece-end-normal piece))))

(defun arc-signed-sweep (piece)
  "TO - FROM of the arc PIECE: positive for :CCW, negative for :CW."
  (e- (arc-piece-to piece) (arc-piece-from piece)))

(defun arc-normal-range (piece)
  "The counter-clockwise range of the outward normals of the arc PIECE."
  (if (arc-piece-full piece)
      (full-angular-range (arc-normal-direction piece (arc-piece-from piece)))
      (let ((a (arc-normal-direction piece (arc-piece-from piece)))
            (b (arc-normal-direction piece (arc-piece-to piece))))
        (if (eq (arc-piece-sense piece) :ccw)
            (make-angular-range a b)
            (make-angular-range b a)))))

(defun arc-position-range (piece)
  "The counter-clockwise range of the directions from the centre to the points of the
arc PIECE."
  (if (arc-piece-full piece)
      (full-angular-range (direction-at-angle (arc-piece-from piece)))
      (let ((a (direction-at-angle (arc-piece-from piece)))
            (b (direction-at-angle (arc-piece-to piece))))
        (if (eq (arc-piece-sense piece) :ccw)
            (make-angular-range a b)
            (make-angular-range b a)))))

;;; Where a point lies relative to a piece.

(defun point-on-piece-p (decider q piece)
  "True when the point Q lies on PIECE (endpoints included). Asks only the facts that
change the answer (see CALL-DECIDING-WHAT-MATTERS)."
  (deciding-what-matters (decider)
    (point-on-piece-p-deciding-all decider q piece)))

(defun point-on-piece-p-deciding-all (decider q piece)
  "POINT-ON-PIECE-P's test, each fact asked as it comes."
  (etypecase piece
    (line-piece
     (let* ((p (line-piece-start piece)) (d (line-direction piece)) (w (v- q p)))
       (and (zero-p decider (cross d w))
            (or (line-piece-infinite piece)
                (let ((along (dot w d)))
                  (and (nonnegative-p decider along)
                       (fact-holds-p decider (list '<= along (norm-squared d)))))))))
    (arc-piece
     (let ((w (v- q (arc-piece-center piece))))
       (and (zero-p decider (e- (norm-squared w) (esquare (arc-piece-radius piece))))
            (direction-in-range-p decider w (arc-position-range piece) :closed t))))))

(defun piece-outward-normal-at (piece q)
  "The outward normal (not normalized) of PIECE at its point Q."
  (etypecase piece
    (line-piece (line-normal piece))
    (arc-piece (let ((w (v- q (arc-piece-center piece))))
                 (if (eq (arc-piece-sense piece) :ccw) w (vneg w))))))

;;; Piece parameters: a monotone position along a piece, used to order cut points.
;;; A line's parameter is t in [0, 1] (q = start + t d); an arc's is the angle turned
;;; from its start, in its own sense.

(defun piece-parameter (decider piece q)
  "The parameter of the point Q (on PIECE's carrier) along PIECE."
  (etypecase piece
    (line-piece (let ((d (line-direction piece)))
                  (e/ (dot (v- q (line-piece-start piece)) d) (norm-squared d))))
    (arc-piece (angle-from-direction decider (polar (arc-piece-from piece))
                                     (v- q (arc-piece-center piece))
                                     :sense (arc-piece-sense piece)))))

(defun piece-point-at-parameter (piece parameter)
  "The point of PIECE at PARAMETER."
  (etypecase piece
    (line-piece (v+ (line-piece-start piece) (vscale parameter (line-direction piece))))
    (arc-piece (arc-point piece (if (eq (arc-piece-sense piece) :ccw)
                                    (e+ (arc-piece-from piece) parameter)
                                    (e- (arc-piece-from piece) parameter))))))

(defun piece-end-parameter (decider piece)
  "The parameter of PIECE's end point."
  (declare (ignorable decider))
  (etypecase piece
    (line-piece 1)
    (arc-piece (if (arc-piece-full piece)
                   (e* 2 'pi)
                   (let ((sweep (arc-signed-sweep piece)))
                     (if (eq (arc-piece-sense piece) :ccw) sweep (e- sweep)))))))

(defun sub-piece (piece from-parameter to-parameter)
  "The part of PIECE between two parameters (FROM before TO)."
  (etypecase piece
    (line-piece (make-line-piece (piece-point-at-parameter piece from-parameter)
                                 (piece-point-at-parameter piece to-parameter)
                                 :name (line-piece-name piece)))
    (arc-piece (let ((sign (if (eq (arc-piece-sense piece) :ccw) 1 -1)))
                 (make-arc-piece (arc-piece-center piece) (arc-piece-radius piece)
                                 (e+ (arc-piece-from piece) (e* sign from-parameter))
                                 (e+ (arc-piece-from piece) (e* sign to-parameter))
                                 (arc-piece-sense piece)
                                 :name (arc-piece-name piece))))))

(defun piece-midpoint (decider piece)
  "A point in the middle of PIECE."
  (declare (ignorable decider))
  (etypecase piece
    (line-piece (vmid (line-piece-start piece) (line-piece-end piece)))
    (arc-piece (arc-point piece (e* 1/2 (e+ (arc-piece-from piece)
                                             (if (arc-piece-full piece)
                                                 (e+ (arc-piece-from piece) (e* 2 'pi))
                                                 (arc-piece-to piece))))))))

;;; Intersections of the carriers of two pieces, restricted to both pieces.

(defun within-piece-p (decider piece q)
  "True when Q, known to lie on PIECE's carrier, lies on PIECE."
  (etypecase piece
    (line-piece (or (line-piece-infinite piece)
                    (let ((along (dot (v- q (line-piece-start piece)) (line-direction piece))))
                      (and (nonnegative-p decider along)
                           (fact-holds-p decider (list '<= along (norm-squared (line-direction piece))))))))
    (arc-piece (direction-in-range-p decider (v- q (arc-piece-center piece))
                                     (arc-position-range piece) :closed t))))

(defun carrier-intersections (decider a b)
  "The points where the carriers (line or circle) of the pieces A and B cross or touch,
as a list; :SAME when the carriers coincide."
  (cond ((and (line-piece-p a) (line-piece-p b))
         (let* ((p (line-piece-start a)) (d (line-direction a))
                (q (line-piece-start b)) (e (line-direction b))
                (denominator (cross d e)))
           (if (zero-p decider denominator)
               (if (zero-p decider (cross d (v- q p))) :same '())
               (let ((s (e/ (cross (v- q p) e) denominator)))
                 (list (v+ p (vscale s d)))))))
        ((and (arc-piece-p a) (line-piece-p b)) (carrier-intersections decider b a))
        ((line-piece-p a)
         ;; |p + s d - c|^2 = r^2
         (let* ((p (line-piece-start a)) (d (line-direction a))
                (c (arc-piece-center b)) (r (arc-piece-radius b))
                (f (v- p c))
                (qa (norm-squared d)) (qb (e* 2 (dot d f)))
                (qc (e- (norm-squared f) (esquare r)))
                (discriminant (e- (esquare qb) (e* 4 qa qc))))
           (ecase (sign-of decider discriminant)
             (:negative '())
             (:zero (list (v+ p (vscale (e/ (e- qb) (e* 2 qa)) d))))
             (:positive (let ((root (esqrt discriminant)))
                          (list (v+ p (vscale (e/ (e- (e- qb) root) (e* 2 qa)) d))
                                (v+ p (vscale (e/ (e+ (e- qb) root) (e* 2 qa)) d))))))))
        (t
         (let* ((c1 (arc-piece-center a)) (r1 (arc-piece-radius a))
                (c2 (arc-piece-center b)) (r2 (arc-piece-radius b))
                (between (v- c2 c1)) (d2 (norm-squared between)))
           (if (zero-p decider d2)
               (if (zero-p decider (e- r1 r2)) :same '())
               ;; the radical line: points at distance k along c1->c2, offset h
               (let* ((k (e/ (e+ d2 (esquare r1) (e- (esquare r2))) (e* 2 d2)))
                      (h2 (e- (e/ (esquare r1) d2) (esquare k)))
                      (foot (v+ c1 (vscale k between))))
                 (ecase (sign-of decider h2)
                   (:negative '())
                   (:zero (list foot))
                   (:positive (let ((h (esqrt h2)))
                                (list (v+ foot (vscale h (rot-ccw between)))
                                      (v- foot (vscale h (rot-ccw between)))))))))))))

(defun piece-intersections (decider a b)
  "The points lying on both pieces A and B. For pieces on the same carrier, the
endpoints of each that lie on the other."
  (let ((crossings (carrier-intersections decider a b)))
    (if (eq crossings :same)
        (remove-duplicates
         (remove-if-not (lambda (q) (and (within-piece-p decider a q) (within-piece-p decider b q)))
                        (append (piece-endpoints b) (piece-endpoints a)))
         :test #'equal)
        (remove-if-not (lambda (q) (and (within-piece-p decider a q) (within-piece-p decider b q)))
                       crossings))))

(defun piece-endpoints (piece)
  "The endpoints of PIECE (none for an infinite line or a full circle)."
  (cond ((and (line-piece-p piece) (line-piece-infinite piece)) '())
        ((and (arc-piece-p piece) (arc-piece-full piece)) '())
        (t (list (piece-start piece) (piece-end piece)))))

(defun pieces-cross-p (decider a b)
  "True when the pieces A and B have a point in common."
  (not (null (piece-intersections decider a b))))
