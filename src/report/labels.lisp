;;;; src/report/labels.lisp -- the labels of a picture, placed so that none overlaps another.
;;;;
;;;; A picture asks for its labels (LABEL-REQUEST) while it draws; PLACE-LABELS then takes them
;;;; in order of priority and puts each at the first of its candidate positions (where asked,
;;;; then a line below, a line above, two lines below ...) whose box meets no box placed
;;;; before and lies inside the picture. A label with no free position is left out, unless it
;;;; is required (the title, the captions: laid out apart by construction). A box is measured
;;;; from the label's font size and length (LABEL-BOX): sans-serif glyphs are narrower than
;;;; 0.62 of the size on average, so the estimate is generous.

(in-package #:ames.report)

(defparameter *label-font-sizes*
  '(("title" . 15) ("caption" . 11) ("label" . 13) ("event-label" . 12) ("force-label" . 12)
    ("state-label" . 10) ("plot-title" . 12) ("tick" . 9) ("legend" . 10) ("branch-label" . 11))
  "The font size, in pixels, of each class of label (the picture's style sheet says the same).")

(defun label-font-size (class)
  "The font size of a label of CLASS."
  (or (cdr (assoc class *label-font-sizes* :test #'string=)) 13))

(defun label-box (x y text class &key (anchor :start))
  "The box (LEFT TOP RIGHT BOTTOM) a label of CLASS writing TEXT at X, Y (the baseline)
covers, for ANCHOR :START, :MIDDLE or :END."
  (let* ((size (label-font-size class))
         (width (* 0.62d0 size (length text)))
         (left (ecase anchor (:start x) (:middle (- x (/ width 2))) (:end (- x width)))))
    (list left (- y size) (+ left width) (+ y (* 0.3d0 size)))))

(defun boxes-overlap-p (a b)
  "True when the boxes A and B (LEFT TOP RIGHT BOTTOM) share more than a point."
  (destructuring-bind (l1 t1 r1 b1) a
    (destructuring-bind (l2 t2 r2 b2) b
      (and (< l1 r2) (< l2 r1) (< t1 b2) (< t2 b1)))))

(defstruct (label-request (:constructor make-label-request
                              (x y text class &key (anchor :start) (priority 5) required colour)))
  "A label asked for at X, Y (picture pixels, baseline) of CLASS; lower PRIORITY is
placed first."
  x y text class anchor priority required colour)

(defvar *label-requests* :none
  "While a picture is drawn: the labels asked for so far, or :NONE outside a picture
(then labels are written at once).")

(defun request-label (x y text class &rest options)
  "Ask for a label (see MAKE-LABEL-REQUEST's options); returns the request."
  (let ((request (apply #'make-label-request x y text class options)))
    (push request *label-requests*)
    request))

(defun candidate-offsets (class)
  "The (DX DY) tried in turn for a label of CLASS: where asked, then lines below and above."
  (let ((line (* 1.4d0 (label-font-size class))))
    (cons '(0 0)
          (loop for k from 1 to 5
                append (list (list 0 (* k line)) (list 0 (- (* k line))))))))

(defun place-labels (requests width height)
  "The labels of REQUESTS placed (see the file header) inside WIDTH by HEIGHT: a list of
(X Y TEXT CLASS ANCHOR BOX)."
  (let ((placed '()))
    (dolist (request (stable-sort (reverse requests) #'< :key #'label-request-priority)
                     (nreverse placed))
      (let ((class (label-request-class request)) (anchor (label-request-anchor request))
            (text (label-request-text request)))
        (loop for (dx dy) in (if (label-request-required request) '((0 0)) (candidate-offsets class))
              for x = (+ (label-request-x request) dx)
              for y = (+ (label-request-y request) dy)
              for box = (label-box x y text class :anchor anchor)
              when (or (label-request-required request)
                       (and (>= (first box) 0) (<= (third box) width)
                            (>= (second box) 0) (<= (fourth box) height)
                            (notany (lambda (p) (boxes-overlap-p box (sixth p))) placed)))
                do (push (list x y text class anchor box (label-request-colour request)) placed)
                   (return))))))

(defun write-labels (stream placed)
  "Write the PLACED labels (see PLACE-LABELS) as SVG text elements."
  (loop for (x y text class anchor nil colour) in placed
        do (format stream "<text class=\"~A\" x=\"~,2F\" y=\"~,2F\"~@[ text-anchor=\"~A\"~]~@[ style=\"fill:~A\"~]>~A</text>~%"
                   class x y (case anchor (:middle "middle") (:end "end")) colour (xml-escape text))))
