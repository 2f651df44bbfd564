;;;; src/report/svg.lisp -- the picture of a run: one SVG per scenario.
;;;;
;;;; The scenario at its start (fixed bodies grey, moving bodies coloured and named, the first
;;;; state's contacts marked, its forces as arrows scaled to their sizes and labelled), then
;;;; each moving body's trajectory state by state (one <path> per body per state, solid and
;;;; dashed in turn, numbered by state), the bodies' outlines where each state ends, and every
;;;; event marked where it happens, labelled with what happens and when. Numbers come from
;;;; scene.lisp; the caption says which values were used.

(in-package #:ames.report)

(defparameter *body-colours* '("#1f5fa8" "#c0392b" "#2e8b57" "#8e44ad" "#d35400" "#7f6000")
  "The colours of the moving bodies, in the order of declaration.")

(defparameter *picture-width* 720 "The width of a picture in pixels.")

(defun xml-escape (text)
  "TEXT with & < > \" escaped for XML, and its control characters but tab and line
breaks written visibly (VISIBLE-TEXT): XML 1.0 allows no other."
  (with-output-to-string (out)
    (loop for c across (visible-text text :keep '(#\Tab #\Newline #\Return))
          do (case c (#\& (write-string "&amp;" out)) (#\< (write-string "&lt;" out))
                   (#\> (write-string "&gt;" out)) (#\" (write-string "&quot;" out))
                   (t (write-char c out))))))

(defstruct (frame (:constructor make-frame (xmin ymin xmax ymax scale margin)))
  "The map from the plane (y up) to the picture (y down)."
  xmin ymin xmax ymax scale margin)

(defun to-picture (frame point)
  "POINT in picture coordinates, as (X Y)."
  (list (+ (frame-margin frame) (* (frame-scale frame) (- (first point) (frame-xmin frame))))
        (+ (frame-margin frame) (* (frame-scale frame) (- (frame-ymax frame) (second point))))))

(defun frame-for (points)
  "The frame that shows POINTS with a margin, *PICTURE-WIDTH* wide."
  (let* ((xs (mapcar #'first points)) (ys (mapcar #'second points))
         (xmin (reduce #'min xs)) (xmax (reduce #'max xs))
         (ymin (reduce #'min ys)) (ymax (reduce #'max ys))
         (size (max (- xmax xmin) (- ymax ymin) 1d-6))
         (pad (* 0.12d0 size)))
    (make-frame (- xmin pad) (- ymin pad) (+ xmax pad) (+ ymax pad)
                (/ (- *picture-width* 80) (+ (- xmax xmin) (* 2 pad)))
                40)))

(defun frame-height (frame)
  "The height of FRAME's drawing area in pixels."
  (+ (* 2 (frame-margin frame)) (* (frame-scale frame) (- (frame-ymax frame) (frame-ymin frame)))))

(defun points-attribute (frame points)
  "POINTS as the points attribute of a polygon or polyline."
  (format nil "~{~{~,2F,~,2F~}~^ ~}" (mapcar (lambda (p) (to-picture frame p)) points)))

(defun path-data (frame points)
  "The d attribute of a path through POINTS (a single point gives a zero-length path)."
  (let ((shown (mapcar (lambda (p) (to-picture frame p)) points)))
    (format nil "M ~{~,2F ~,2F~}~{ L ~{~,2F ~,2F~}~}" (first shown) (or (rest shown) (list (first shown))))))

(defun draw-outline (stream frame outline class &key (colour "none") (extra ""))
  "Write OUTLINE as an SVG element of CLASS."
  (ecase (first outline)
    (:polygon (format stream "<polygon class=\"~A\" points=\"~A\" style=\"fill:~A\"~A/>~%" class
                      (points-attribute frame (second outline)) colour extra))
    (:polyline (format stream "<polyline class=\"~A\" points=\"~A\" style=\"stroke:~A;stroke-width:3;fill:none\"~A/>~%"
                       class (points-attribute frame (second outline))
                       (if (member class '("fixed" "ghost") :test #'string=) "#555" colour) extra))
    (:circle (destructuring-bind (x y) (to-picture frame (second outline))
               (format stream "<circle class=\"~A\" cx=\"~,2F\" cy=\"~,2F\" r=\"~,2F\" style=\"fill:~A\"~A/>~%"
                       class x y (* (frame-scale frame) (third outline)) colour extra)))
    (:point (destructuring-bind (x y) (to-picture frame (second outline))
              (format stream "<circle class=\"~A point\" cx=\"~,2F\" cy=\"~,2F\" r=\"5\" style=\"fill:~A\"~A/>~%"
                      class x y (if (string= colour "none") "#333" colour) extra)))
    (:half-plane
     ;; the solid lies left of P1 -> P2: a large quadrilateral on that side, clipped
     (destructuring-bind (p1 p2) (rest outline)
       (let* ((direction (vunit (v- p2 p1)))
              (inward (list (- (second direction)) (first direction)))
              (reach (* 4 (max (- (frame-xmax frame) (frame-xmin frame)) (- (frame-ymax frame) (frame-ymin frame)))))
              (a (v- p1 (vscale reach direction))) (b (v+ p1 (vscale reach direction))))
         (format stream "<polygon class=\"~A\" points=\"~A\" clip-path=\"url(#view)\"~A/>~%" class
                 (points-attribute frame (list a b (v+ b (vscale reach inward)) (v+ a (vscale reach inward))))
                 extra)
         (format stream "<line class=\"surface\" x1=\"~,2F\" y1=\"~,2F\" x2=\"~,2F\" y2=\"~,2F\" clip-path=\"url(#view)\"/>~%"
                 (first (to-picture frame a)) (second (to-picture frame a))
                 (first (to-picture frame b)) (second (to-picture frame b))))))))

(defun draw-label (stream frame point text &key (class "label") (dx 6) (dy -6) (priority 5))
  "Ask for TEXT at POINT, offset by DX and DY pixels, with PRIORITY (see REQUEST-LABEL);
write it at once outside a picture's label placement."
  (destructuring-bind (x y) (to-picture frame point)
    (if (listp *label-requests*)
        (request-label (+ x dx) (+ y dy) text class :priority priority)
        (format stream "<text class=\"~A\" x=\"~,2F\" y=\"~,2F\">~A</text>~%" class (+ x dx) (+ y dy)
                (xml-escape text)))))

(defun draw-arrow (stream frame from vector label colour)
  "An arrow from FROM along VECTOR (plane units), labelled."
  (let ((to (v+ from vector)))
    (destructuring-bind ((x1 y1) (x2 y2)) (list (to-picture frame from) (to-picture frame to))
      (format stream "<line class=\"force\" x1=\"~,2F\" y1=\"~,2F\" x2=\"~,2F\" y2=\"~,2F\" style=\"stroke:~A\" marker-end=\"url(#arrow)\"/>~%"
              x1 y1 x2 y2 colour)
      (draw-label stream frame to label :class "force-label" :dx 4 :dy 4 :priority 3))))

;;; Contacts and forces at the start

(defun contact-point-and-normal (state contact bindings)
  "Where the bodies of CONTACT, one of STATE's contacts, touch at the start and the unit
normal from its obstacle (the second body) into its observer (the first), as numbers
under BINDINGS: (POINT NORMAL), or NIL. The simulator found them (STATE-CONTACT-POINTS):
the report derives no geometry."
  (let* ((index (position contact (state-contacts state)))
         (entry (and index (nth index (state-contact-points state))))
         (point (and entry (point-at (getf entry :point) bindings)))
         (normal (and entry (point-at (getf entry :normal) bindings))))
    (and point normal (> (vlength normal) 0.5d0) (list point (vunit normal)))))

(defun arrow-label (entry)
  "The picture's label of the force ENTRY's arrow: the :LABEL its phenomenon gives
(AMES.KB:FORCE-DESCRIPTION), a string or (:NAME I) the entry's Ith name, else the
kind's words."
  (let ((label (getf (ames.kb:force-description (first entry)) :label)))
    (cond ((stringp label) label)
          ((and (consp label) (eq (first label) :name)) (name-text (nth (1+ (second label)) entry)))
          (t (keyword-words (first entry))))))

(defun force-arrows (scenario state bindings)
  "The arrows of STATE's forces at the start: (FROM VECTOR LABEL) in the plane."
  (let ((s0 (number-at (getf (state-path-coordinates state) :arc-length-from) bindings))
        (arrows '()))
    (dolist (entry (state-forces state) (nreverse arrows))
      (let ((point (if s0 (acons +arc-length+ s0 bindings) bindings)))
        (multiple-value-bind (label symbol value) (force-entry entry)
          (declare (ignore label))
          (cond ((eq (getf (ames.kb:force-description (first entry)) :arrow) :along-contact-normal)
                 (let* ((contact (contact-of state (second entry) (third entry)))
                        (geometry (and contact (contact-point-and-normal state contact bindings)))
                        (size (number-at value point)))
                   (when (and geometry size)
                     (push (list (first geometry)
                                 (vscale (if (eq (first contact) (second entry)) size (- size)) (second geometry))
                                 (or symbol (keyword-words (first entry))))
                           arrows))))
                ((vector-value-p value)
                 (let* ((body-name (find-if (lambda (x) (and (symbolp x) (find-scenario-body x scenario)))
                                            (reverse (rest entry))))
                        (body (and body-name (find-scenario-body body-name scenario)))
                        (vector (point-at value point))
                        (outline (and body (shape-outline (scenario-body-shape body)
                                                          (body-origin body bindings) bindings))))
                   (when (and vector outline)
                     (push (list (outline-anchor outline) vector
                                 (arrow-label entry))
                           arrows))))))))))
