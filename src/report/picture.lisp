;;;; src/report/picture.lisp -- HISTORY-SVG: the whole picture of a run, laid out from scene.lisp and drawn by svg.lisp.

(in-package #:ames.report)

(defparameter *svg-style*
  "text{font-family:sans-serif;font-size:13px;fill:#222}
.title{font-size:15px;font-weight:bold}
.caption{font-size:11px;fill:#555}
.fixed{fill:#c8c8c8;stroke:#777;stroke-width:1}
.body{fill-opacity:0.35;stroke:#222;stroke-width:1.2}
.ghost{fill:none;stroke:#888;stroke-width:1;stroke-dasharray:3 3}
.surface{stroke:#555;stroke-width:1.5}
.trajectory{fill:none;stroke-width:2}
.state-odd{stroke-dasharray:7 4}
.contact{fill:#fff;stroke:#000;stroke-width:1.5}
.force{stroke-width:2}
.force-label{font-size:12px;font-style:italic}
.event{fill:#fff;stroke:#000;stroke-width:2}
.event-label{font-size:12px;font-weight:bold}
.state-label{font-size:10px;fill:#444}"
  "The picture's style sheet.")

(defun event-short (event)
  "A short label for an end EVENT: \"hits ground\", \"lifts off sphere\"."
  (let ((kind (first event)) (other (and (third event) (symbolp (third event)) (name-text (third event)))))
    (case kind
      (:collision (format nil "hits ~A" other))
      (:contact (format nil "touches ~A" other))
      (:lift-off (format nil "lifts off ~A" other))
      (:leaves (format nil "leaves ~A" other))
      (:time-limit "time limit")
      (t (format nil "~A~@[ ~A~]" (keyword-words kind) other)))))

(defun state-events (state)
  "The events that end STATE (several when simultaneous), none for :NONE or :UNDECIDED."
  (let ((end (state-end-event state)))
    (if (consp end) (or (getf (state-notes state) :events) (list end)) '())))

(defun layout-trajectories (history bindings moving outlines)
  "Per state, an alist body -> points of its trajectory, and the durations as numbers
(NIL where unknown)."
  (let* ((states (history-states history))
         (finite (loop for state in states
                       collect (loop for body in moving
                                     collect (cons body (and (state-duration-number state bindings)
                                                             (trajectory state body bindings 0d0))))))
         (points (append (loop for (nil . outline) in outlines append (outline-points outline))
                         (loop for alist in finite append (loop for (nil . ps) in alist append ps))))
         (size (let ((xs (mapcar #'first points)) (ys (mapcar #'second points)))
                 (max 1d0 (- (reduce #'max xs) (reduce #'min xs)) (- (reduce #'max ys) (reduce #'min ys))))))
    (loop for state in states
          for known in finite
          collect (if (state-duration-number state bindings)
                      known
                      (let ((horizon (forever-horizon state bindings (* 0.6d0 size))))
                        (loop for body in moving
                              collect (cons body (trajectory state body bindings horizon))))))))

(defun history-svg (history)
  "The picture of HISTORY as an SVG document (a string): see svg.lisp's header. Numbers
come from ILLUSTRATION-VALUES. Every moving body has one <path class=\"trajectory\">
per state (a zero-length one where its trajectory cannot be drawn)."
  (multiple-value-bind (bindings chosen) (illustration-values history)
    (let* ((scenario (history-scenario history))
           (bindings (report-floats bindings))
           (bodies (scenario-bodies scenario))
           (moving (mapcar #'scenario-body-name (remove-if #'scenario-body-fixed-p bodies)))
           (colours (loop for body in moving for i from 0
                          collect (cons body (nth (mod i (length *body-colours*)) *body-colours*))))
           (outlines (loop for body in bodies
                           for outline = (shape-outline (scenario-body-shape body) (body-origin body bindings) bindings)
                           when outline collect (cons (scenario-body-name body) outline)))
           (paths (layout-trajectories history bindings moving outlines))
           (scene (append (loop for (nil . o) in outlines append (outline-points o))
                          (loop for alist in paths append (loop for (nil . ps) in alist append ps))
                          (list (list 0d0 0d0))))
           (size (let ((bare (frame-for scene)))
                   (/ (max (- (frame-xmax bare) (frame-xmin bare)) (- (frame-ymax bare) (frame-ymin bare)))
                      1.24d0)))
           (arrows (let* ((first-state (first (history-states history)))
                          (arrows (and first-state (force-arrows scenario first-state bindings)))
                          (largest (reduce #'max (mapcar (lambda (a) (vlength (second a))) arrows)
                                           :initial-value 0d0)))
                     (and (plusp largest)
                          (loop for (from vector label) in arrows
                                when (> (vlength vector) (* 1d-9 largest))
                                  collect (list from (v* (/ (* 0.22d0 size) largest) vector) label)))))
           (frame (frame-for (append scene (loop for (from vector) in arrows collect (v+ from vector)))))
           (height (round (+ (frame-height frame) 44))))
      (with-output-to-string (out)
        (format out "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"ames-picture\" width=\"~D\" height=\"~D\" viewBox=\"0 0 ~D ~D\">~%"
                *picture-width* height *picture-width* height)
        (format out "<title>~A</title>~%<desc>~A</desc>~%<style>~A</style>~%"
                (xml-escape (format nil "AMES: ~A" (name-text (scenario-name scenario))))
                (xml-escape (or (scenario-description scenario) "")) *svg-style*)
        (format out "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" orient=\"auto-start-reverse\"><path d=\"M 0 0 L 10 5 L 0 10 z\" fill=\"#000\"/></marker>~%<clipPath id=\"view\"><rect x=\"0\" y=\"0\" width=\"~D\" height=\"~D\"/></clipPath></defs>~%"
                *picture-width* (round (frame-height frame)))
        (format out "<rect x=\"0\" y=\"0\" width=\"100%\" height=\"100%\" fill=\"#fff\"/>~%")
        (format out "<text class=\"title\" x=\"10\" y=\"20\">~A</text>~%" (xml-escape (name-text (scenario-name scenario))))
        ;; fixed bodies, then the moving ones at the end of each state (ghosts), at the start
        (loop for (name . outline) in outlines
              unless (member name moving) do (draw-outline out frame outline "fixed" :colour "#c8c8c8"))
        (loop for state in (history-states history)
              do (loop for (body position) in (state-final-positions state)
                       for end = (point-at position bindings)
                       for outline = (cdr (assoc body outlines))
                       for start = (let ((b (find-scenario-body body scenario))) (and b (body-origin b bindings)))
                       when (and end outline start (member body moving) (not (eq (first outline) :point)))
                         do (draw-outline out frame (moved-outline outline (v- end start)) "ghost")))
        (loop for (name . outline) in outlines
              when (member name moving)
                do (draw-outline out frame outline "body" :colour (cdr (assoc name colours)))
                   (draw-label out frame (outline-anchor outline) (name-text name) :dx 8 :dy 14))
        ;; trajectories: one path per moving body per state
        (loop for state in (history-states history)
              for alist in paths
              do (dolist (body moving)
                   (let ((points (or (cdr (assoc body alist))
                                     (let* ((b (find-scenario-body body scenario)) (o (body-origin b bindings)))
                                       (list o)))))
                     (format out "<path class=\"trajectory state-~:[even~;odd~]\" data-body=\"~A\" data-state=\"~D\" style=\"stroke:~A\" d=\"~A\"/>~%"
                             (oddp (state-index state)) (xml-escape (name-text body)) (state-index state)
                             (cdr (assoc body colours)) (path-data frame points))
                     (when (rest points)
                       (draw-label out frame (nth (floor (length points) 2) points)
                                   (format nil "~D" (state-index state)) :class "state-label" :dx 4 :dy 12)))))
        ;; contacts and forces of the first state
        (let ((first-state (first (history-states history))))
          (when first-state
            (dolist (contact (state-contacts first-state))
              (let ((geometry (contact-point-and-normal scenario contact bindings)))
                (when geometry
                  (destructuring-bind (x y) (to-picture frame (first geometry))
                    (format out "<rect class=\"contact\" x=\"~,2F\" y=\"~,2F\" width=\"7\" height=\"7\" transform=\"rotate(45 ~,2F ~,2F)\"/>~%"
                            (- x 3.5) (- y 3.5) x y)))))
            (loop for (from vector label) in arrows
                  do (draw-arrow out frame from vector label "#000"))))
        ;; events, where and when they happen
        (let ((clock 0d0))
          (dolist (state (history-states history))
            (let ((duration (state-duration-number state bindings)))
              (setf clock (and clock duration (+ clock duration)))
              (loop for event in (state-events state)
                    for k from 0
                    for body = (find-if (lambda (b) (member b moving)) (rest event))
                    for point = (and body (point-at (body-entry (state-final-positions state) body) bindings))
                    when point
                      do (destructuring-bind (x y) (to-picture frame point)
                           (when (zerop k)
                             (format out "<circle class=\"event\" cx=\"~,2F\" cy=\"~,2F\" r=\"6\"/>~%" x y))
                           (format out "<text class=\"event-label\" x=\"~,2F\" y=\"~,2F\">~A</text>~%"
                                   (+ x 10) (- y 8 (* 15 k))
                                   (xml-escape (format nil "~A~@[ (t = ~A)~]" (event-short event)
                                                       (and clock (number-text clock))))))))))
        (format out "<text class=\"caption\" x=\"10\" y=\"~D\">~A</text>~%" (- height 24)
                (xml-escape (format nil "~:[values~;illustrative values~]: ~{~A~^, ~}" chosen
                                    (loop for (name . value) in bindings
                                          collect (format nil "~A = ~A~:[~; (chosen)~]" (name-text name)
                                                          (number-text value) (member name chosen))))))
        (format out "<text class=\"caption\" x=\"10\" y=\"~D\">~A</text>~%" (- height 8)
                "arrows: the forces at the start, to scale; paths: the states 0, 1, 2 ... solid and dashed in turn; rings: events")
        (format out "</svg>~%")))))

(defun print-history-svg (history stream)
  "Write HISTORY-SVG of HISTORY on STREAM as a standalone SVG file (with its XML declaration)."
  (format stream "<?xml version=\"1.0\" encoding=\"UTF-8\"?>~%~A" (history-svg history)))
