;;;; src/report/scene.lisp -- numbers for a picture: illustration values, shapes in the plane, sampled trajectories.
;;;;
;;;; The picture of a run is drawn from its closed forms evaluated at numbers: the run's
;;;; parameter values (--set), else the scenario's (:value N) defaults, else illustrative
;;;; values chosen to satisfy the assumptions (and said so in the picture). Everything here is
;;;; numeric (double floats), by EXPRESSION-VALUE in Lisp: no Maxima.

(in-package #:ames.report)

(defun relation-holds-p (relation point)
  "True when RELATION surely holds at POINT (an alist name -> number)."
  (let ((difference (expression-value (list '- (relation-lhs relation) (relation-rhs relation)) point)))
    (and (realp difference)
         (ecase (first relation)
           (> (> difference 0)) (>= (>= difference 0)) (< (< difference 0)) (<= (<= difference 0))
           (= (zerop difference)) (/= (/= difference 0))))))

(defun illustration-values (history)
  "An alist (PARAMETER . NUMBER) for every parameter of HISTORY's scenario, and a second
value: the parameters whose number was chosen here for illustration (no --set value and
no (:value N) default). A chosen value satisfies every assumption over the parameters
valued so far (see ADMISSIBLE-PARAMETER-VALUES)."
  (admissible-parameter-values (history-scenario history) (history-parameter-values history)))

(defun number-at (expression bindings)
  "The double-float value of EXPRESSION under BINDINGS, or NIL."
  (let ((value (and (valid-expression-p expression :kind :arithmetic)
                    (expression-value expression bindings))))
    (report-float value)))

(defun point-at (pair bindings)
  "The point (X Y) of the expressions PAIR under BINDINGS, or NIL."
  (let ((x (number-at (first pair) bindings)) (y (number-at (second pair) bindings)))
    (and x y (list x y))))

;; Points of the drawing are vectors of numbers: the vector toolkit's V+, V- and VSCALE
;; (ames.geometry, imported) fold numbers as CL does; lengths are taken in floating point.
(defun vlength (a) "The length of the numeric vector A, a float." (sqrt (norm-squared a)))
(defun vunit (a)
  "The numeric vector A scaled to length 1 (the zero vector stays zero)."
  (let ((l (vlength a))) (if (> l 1d-12) (vscale (/ 1 l) a) (list 0d0 0d0))))

;;; Shapes in the plane

(defun body-origin (body bindings)
  "The reference point of the scenario BODY at the start, (0 0) when it has none."
  (or (and (scenario-body-position body) (point-at (scenario-body-position body) bindings))
      (list 0d0 0d0)))

(defun arc-points (center radius from to)
  "Points along the arc of RADIUS about CENTER from angle FROM to TO (radians)."
  (let ((n (max 8 (ceiling (* 24 (abs (- to from)))))))
    (loop for i from 0 to n
          for angle = (+ from (* (- to from) (/ i n)))
          collect (v+ center (list (* radius (cos angle)) (* radius (sin angle)))))))

(defun shape-outline (shape origin bindings)
  "The numeric outline of the shape form SHAPE placed at ORIGIN: (:POLYGON POINTS),
(:POLYLINE POINTS), (:CIRCLE CENTER RADIUS), (:HALF-PLANE P1 P2) or (:POINT P); NIL
where a number is missing."
  (flet ((at (pair) (let ((p (point-at pair bindings))) (and p (v+ origin p))))
         (num (x) (number-at x bindings)))
    (case (shape-kind shape)
      (:point (list :point origin))
      (:circle (let ((r (num (second shape)))) (and r (list :circle origin r))))
      (:polygon (let ((points (mapcar #'at (rest shape))))
                  (and (every #'identity points) (list :polygon points))))
      (:segment (let ((a (at (second shape))) (b (at (third shape))))
                  (and a b (list :polyline (list a b)))))
      (:half-plane (let ((a (at (second shape))) (b (at (third shape))))
                     (and a b (list :half-plane a b))))
      (:arc (let ((center (at (getf (rest shape) :center)))
                  (radius (num (getf (rest shape) :radius)))
                  (from (num (getf (rest shape) :from)))
                  (to (num (getf (rest shape) :to))))
              (and center radius from to (list :polyline (arc-points center radius from to)))))
      (:outline (let ((points '()))
                  (dolist (piece (rest shape) (and points (list :polygon (nreverse points))))
                    (cond ((string-equal (symbol-name (first piece)) "LINE")
                           (let ((a (at (second piece))))
                             (unless a (return nil))
                             (push a points)))
                          (t (let ((center (at (getf (rest piece) :center)))
                                   (radius (num (getf (rest piece) :radius)))
                                   (from (num (getf (rest piece) :from)))
                                   (to (num (getf (rest piece) :to))))
                               (unless (and center radius from to) (return nil))
                               (dolist (p (arc-points center radius from to)) (push p points)))))))))))

(defun outline-points (outline)
  "The points that bound OUTLINE (a half-plane's two points, a circle's box)."
  (ecase (first outline)
    ((:polygon :polyline) (second outline))
    (:circle (destructuring-bind (center radius) (rest outline)
               (list (v- center (list radius radius)) (v+ center (list radius radius)))))
    (:half-plane (list (second outline) (third outline)))
    (:point (list (second outline)))))

(defun moved-outline (outline offset)
  "OUTLINE translated by OFFSET."
  (ecase (first outline)
    ((:polygon :polyline) (list (first outline) (mapcar (lambda (p) (v+ p offset)) (second outline))))
    (:circle (list :circle (v+ (second outline) offset) (third outline)))
    (:half-plane (list :half-plane (v+ (second outline) offset) (v+ (third outline) offset)))
    (:point (list :point (v+ (second outline) offset)))))

(defun outline-anchor (outline)
  "A point inside OUTLINE where its label and weight go: a polygon's vertex mean."
  (ecase (first outline)
    ((:polygon :polyline) (vscale (/ 1d0 (length (second outline))) (reduce #'v+ (second outline))))
    (:circle (second outline))
    (:half-plane (vscale 0.5d0 (v+ (second outline) (third outline))))
    (:point (second outline))))

;;; Trajectories

(defparameter *samples-per-state* 48 "Points per trajectory of a state.")

(defun numeric-samples (state body)
  "The points of BODY's numerically integrated trajectory in STATE's notes, or NIL."
  (loop for group in (state-numeric-trajectory state)
        for terms = (getf group :terms)
        for x = (position-if (lambda (term) (and (consp term) (string= (symbol-name (first term)) "POS")
                                                 (eq (second term) body) (eq (third term) :x)))
                             terms)
        for y = (position-if (lambda (term) (and (consp term) (string= (symbol-name (first term)) "POS")
                                                 (eq (second term) body) (eq (third term) :y)))
                             terms)
        when (and x y)
          return (loop for (nil . values) in (getf group :samples)
                       collect (list (float (nth x values) 1d0) (float (nth y values) 1d0)))))

(defun sample-between (function from to)
  "Points of FUNCTION (a number -> point or NIL) at *SAMPLES-PER-STATE* + 1 parameters
from FROM to TO, those where it is undefined left out."
  (loop for i from 0 to *samples-per-state*
        for point = (funcall function (+ from (* (- to from) (/ i *samples-per-state*))))
        when point collect point))

(defun state-duration-number (state bindings)
  "STATE's duration as a number under BINDINGS: a closed form's value, the numeric note,
or NIL (:FOREVER, undecided, no closed form)."
  (let ((duration (state-duration state)))
    (or (and (not (keywordp duration)) (not (and (consp duration) (keywordp (first duration))))
             (number-at duration bindings))
        (let ((note (getf (state-numbers state) :duration)))
          (report-float note)))))

(defun trajectory (state body bindings horizon)
  "The points of BODY's reference point over STATE under BINDINGS: by tau up to the
state's duration (or HORIZON when it has none), by arc length along a curve, or from
the numeric integration's samples; at least its start point when known."
  (let* ((position (body-entry (state-positions state) body))
         (duration (or (state-duration-number state bindings) horizon))
         (arc-length +arc-length+))
    (cond ((and (consp position) (eq (first position) :on-path))
           (let* ((from (number-at (getf (state-path-coordinates state) :arc-length-from) bindings))
                  (to (or (number-at (state-end-arc-length state) bindings)
                          (let ((d (state-duration state)))
                            (and (consp d) (number-at (getf (rest d) :to-arc-length) bindings)))
                          from)))
             (and from
                  (sample-between (lambda (s) (point-at (second position) (acons arc-length s bindings)))
                                  from to))))
          ((equal position '(:no-closed-form)) (numeric-samples state body))
          ;; an undecided end: the closed forms hold until a time nobody knows
          ((eq (state-duration state) :undecided) (let ((p (and (vector-value-p position)
                                                                 (point-at position (acons 'tau 0d0 bindings)))))
                                                     (and p (list p))))
          ((vector-value-p position)
           (sample-between (lambda (time) (point-at position (acons 'tau time bindings))) 0d0 duration)))))

(defun forever-horizon (state bindings size)
  "A time over which the motions of a state that lasts forever are drawn: long enough
for some body to move about SIZE (the scene's extent), at most 2^10 time units."
  (let ((time 0.125d0))
    (loop repeat 14
          while (every (lambda (entry)
                         (let ((position (second entry)))
                           (or (not (vector-value-p position))
                               (let ((a (point-at position (acons 'tau 0d0 bindings)))
                                     (b (point-at position (acons 'tau time bindings))))
                                 (or (null a) (null b) (< (vlength (v- b a)) size))))))
                       (state-positions state))
          do (setf time (* 2 time)))
    time))
