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
.state-label{font-size:10px;fill:#444}
.plot-title{font-size:12px;font-weight:bold}
.tick{font-size:9px;fill:#555}
.legend{font-size:10px}
.branch-label{font-size:11px;fill:#333}
.axis{stroke:#444;stroke-width:1}
.event-time{stroke:#999;stroke-width:1;stroke-dasharray:4 3}
.curve{fill:none;stroke-width:1.6}"
  "The picture's style sheet.")

(defun event-short (event)
  "A short label for an end EVENT: \"hits ground\", \"lifts off sphere\": the :SHORT words
its phenomenon gives (AMES.KB:EVENT-DESCRIPTION) over its second name, else the kind's
words and that name."
  (let* ((kind (first event))
         (other (and (third event) (symbolp (third event)) (name-text (third event))))
         (short (getf (ames.kb:event-description kind) :short)))
    (cond (short (format nil short other))
          ((eq kind :time-limit) "time limit")
          (t (format nil "~A~@[ ~A~]" (keyword-words kind) other)))))

(defun state-events (state)
  "The events that end STATE (several when simultaneous), none for :NONE or :UNDECIDED."
  (let ((end (state-end-event state)))
    (if (consp end) (or (state-simultaneous-events state) (list end)) '())))

(defun picture-path (history bindings)
  "The states the picture follows: HISTORY's states (a fork, which has no period of
motion, left out) and, at each fork, the branch the given values select, else the first whose fact holds at the picture's BINDINGS, else
none (the path stops at the fork). Returns a second value: the branch labels taken."
  (let ((taken '()))
    (labels ((follow (states prefix)
               (loop for state in states
                     ;; a fork is no period of motion: its selected branch is drawn instead
                     append (append
                             (unless (state-fork-p state) (list state))
                                  (let* ((branches (state-branches state))
                                         (k (or (position-if (lambda (b) (getf b :selected)) branches)
                                                (position-if (lambda (b)
                                                               (let ((fact (getf b :assume)))
                                                                 (and (consp fact) (relation-holds-p fact bindings))))
                                                             branches))))
                                    (when k
                                      (let ((label (format nil "~@[~A.~]~D" prefix (1+ k))))
                                        (push label taken)
                                        (follow (getf (nth k branches) :states) label))))))))
      (values (follow (history-states history) nil) (reverse taken)))))

(defun branch-lines (history drawn)
  "One (DEPTH TEXT) per branch of HISTORY's forks, DEPTH its level in the tree: its label,
fact, whether it was selected, is the one DRAWN (a list of labels), or was not simulated."
  (labels ((walk (states prefix depth)
             (loop for state in states
                   append (loop for branch in (state-branches state)
                                for k from 1
                                for label = (format nil "~@[~A.~]~D" prefix k)
                                append (cons (list depth
                                                   (format nil "branch ~A~:[~; (selected)~]~:[~; (drawn)~]: ~A~:[ (not simulated)~;~]"
                                                           label (getf branch :selected)
                                                           (member label drawn :test #'string=)
                                                           (let ((fact (getf branch :assume)))
                                                             (if (consp fact) (text-form fact) "?"))
                                                           (getf branch :states)))
                                             (walk (getf branch :states) label (1+ depth)))))))
    (walk (history-states history) nil 0)))

(defun layout-trajectories (states bindings moving outlines)
  "Per state of STATES, an alist body -> points of its trajectory."
  (let* ((finite (loop for state in states
                       collect (loop for body in moving
                                     collect (cons body (and (state-duration-number state bindings)
                                                             (trajectory state body bindings 0d0))))))
         (points (append (loop for (nil . outline) in outlines append (outline-points outline))
                         (loop for alist in finite append (loop for (nil . ps) in alist append ps))))
         (size (scene-size points)))
    (loop for state in states
          for known in finite
          collect (if (state-duration-number state bindings)
                      known
                      (let ((horizon (forever-horizon state bindings (* 0.6d0 size))))
                        (loop for body in moving
                              collect (cons body (trajectory state body bindings horizon))))))))

(defun scene-size (points)
  "The larger extent of POINTS, at least 1."
  (let ((xs (mapcar #'first points)) (ys (mapcar #'second points)))
    (max 1d0 (- (reduce #'max xs) (reduce #'min xs)) (- (reduce #'max ys) (reduce #'min ys)))))

(defun scaled-arrows (scenario state bindings size)
  "The force arrows of STATE at the start, scaled so the largest is 0.22 SIZE."
  (let* ((arrows (and state (force-arrows scenario state bindings)))
         (largest (reduce #'max (mapcar (lambda (a) (vlength (second a))) arrows) :initial-value 0d0)))
    (and (plusp largest)
         (let ((symbols (mapcar (lambda (a) (list :symbol (third a) :word (third a))) arrows)))
           ;; two forces with one symbol are told apart as in the reports: N_1, N_2
           (loop for (from vector) in arrows
                 for numbered in (numbered-symbols symbols)
                 when (> (vlength vector) (* 1d-9 largest))
                   collect (list from (vscale (/ (* 0.22d0 size) largest) vector)
                                 (if (= 1 (length (getf numbered :word))) (getf numbered :symbol) (getf numbered :word))))))))

(defun draw-trajectories (out frame scenario path paths moving colours bindings)
  "One path per moving body per state of PATH, each numbered \"state N\" where it has room."
  (loop for state in path
        for alist in paths
        do (dolist (body moving)
             (let ((points (or (cdr (assoc body alist))
                               (list (body-origin (find-scenario-body body scenario) bindings)))))
               (format out "<path class=\"trajectory state-~:[even~;odd~]\" data-body=\"~A\" data-state=\"~D\" style=\"stroke:~A\" d=\"~A\"/>~%"
                       (oddp (state-index state)) (xml-escape (name-text body)) (state-index state)
                       (cdr (assoc body colours)) (path-data frame points))
               (when (and (rest points) (> (vlength (v- (first points) (car (last points)))) 1d-9))
                 (draw-label out frame (nth (floor (length points) 2) points)
                             (format nil "state ~D" (state-index state)) :class "state-label"
                             :dx 6 :dy 12 :priority 6))))))

(defun draw-events (out frame path moving bindings)
  "Every event of PATH marked where it happens, labelled with what and when."
  (let ((clock 0d0))
    (dolist (state path)
      (let ((duration (state-duration-number state bindings))
            (start (number-at (state-start state) bindings)))
        ;; the time of the state's end is its start's value plus its duration: after
        ;; impacts that accumulate, not the durations before it summed
        (setf clock (and (or start clock) duration (+ (or start clock) duration)))
        (loop for event in (state-events state)
              for k from 0
              for body = (find-if (lambda (b) (member b moving)) (rest event))
              for point = (and body (point-at (body-entry (state-final-positions state) body) bindings))
              when point
                do (destructuring-bind (x y) (to-picture frame point)
                     (when (zerop k)
                       (format out "<circle class=\"event\" cx=\"~,2F\" cy=\"~,2F\" r=\"6\"/>~%" x y))
                     (request-label (+ x 10) (- y 8) (format nil "~A~@[ (t = ~A)~]" (event-short event)
                                                             (and clock (number-text clock)))
                                    "event-label" :priority 2)))))))

(defun history-svg (history)
  "The picture of HISTORY as an SVG document (a string): see svg.lisp's header, and under
it the plots over time of plots.lisp. Numbers come from ILLUSTRATION-VALUES; at a fork
the picture follows the selected branch (else the one the numbers satisfy), and lists
every branch. Every moving body has one <path class=\"trajectory\"> per state of that
path (a zero-length one where its trajectory cannot be drawn). No label overlaps another
(see labels.lisp)."
  (multiple-value-bind (bindings chosen) (illustration-values history)
    (let* ((scenario (history-scenario history))
           (bindings (report-floats bindings))
           (path-and-drawn (multiple-value-list (picture-path history bindings)))
           (path (first path-and-drawn))
           (bodies (scenario-bodies scenario))
           (moving (mapcar #'scenario-body-name (remove-if #'scenario-body-fixed-p bodies)))
           (colours (loop for body in moving for i from 0
                          collect (cons body (nth (mod i (length *body-colours*)) *body-colours*))))
           (outlines (loop for body in bodies
                           for outline = (shape-outline (scenario-body-shape body) (body-origin body bindings) bindings)
                           when outline collect (cons (scenario-body-name body) outline)))
           (paths (layout-trajectories path bindings moving outlines))
           (scene (append (loop for (nil . o) in outlines append (outline-points o))
                          (loop for alist in paths append (loop for (nil . ps) in alist append ps))
                          (list (list 0d0 0d0))))
           (size (let ((bare (frame-for scene)))
                   (/ (max (- (frame-xmax bare) (frame-xmin bare)) (- (frame-ymax bare) (frame-ymin bare)))
                      1.24d0)))
           (arrows (scaled-arrows scenario (first path) bindings size))
           (frame (frame-for (append scene (loop for (from vector) in arrows collect (v+ from vector)))))
           (branch-lines (branch-lines history (second path-and-drawn)))
           (scene-bottom (+ (frame-height frame) 10))
           (branches-top (+ scene-bottom 4))
           (plots-top (+ branches-top (* 14 (length branch-lines)) 10)))
      (multiple-value-bind (plots event-times)
          (time-plots path bindings moving colours)
        (let* ((height (round (+ plots-top (plots-height plots) 44)))
               (*label-requests* '()))
          (with-output-to-string (out)
            (write-svg-start out scenario frame height)
            (draw-bodies out frame scenario path outlines moving colours bindings)
            (draw-trajectories out frame scenario path paths moving colours bindings)
            (draw-first-contacts-and-forces out frame (first path) arrows bindings)
            (draw-events out frame path moving bindings)
            (loop for (depth line) in branch-lines
                  for y from (+ branches-top 11) by 14
                  do (request-label (+ 10 (* 16 depth)) y line "branch-label" :priority 0 :required t))
            (draw-time-plots out plots event-times plots-top)
            (request-captions height bindings chosen)
            (write-labels out (place-labels *label-requests* *picture-width* height))
            (format out "</svg>~%")))))))

(defun write-svg-start (out scenario frame height)
  "Write the start of the picture of SCENARIO on OUT: the <svg> element HEIGHT pixels high,
its title, description and style, the arrow marker and the scene's clip (FRAME's
height), the white background; and request the title's label."
  (format out "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"ames-picture\" width=\"~D\" height=\"~D\" viewBox=\"0 0 ~D ~D\">~%"
          *picture-width* height *picture-width* height)
  (format out "<title>~A</title>~%<desc>~A</desc>~%<style>~A</style>~%"
          (xml-escape (format nil "AMES: ~A" (name-text (scenario-name scenario))))
          (xml-escape (or (scenario-description scenario) "")) *svg-style*)
  (format out "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" orient=\"auto-start-reverse\"><path d=\"M 0 0 L 10 5 L 0 10 z\" fill=\"#000\"/></marker>~%<clipPath id=\"view\"><rect x=\"0\" y=\"0\" width=\"~D\" height=\"~D\"/></clipPath></defs>~%"
          *picture-width* (round (frame-height frame)))
  (format out "<rect x=\"0\" y=\"0\" width=\"100%\" height=\"100%\" fill=\"#fff\"/>~%")
  (request-label 10 20 (name-text (scenario-name scenario)) "title" :priority 0 :required t))

(defun draw-bodies (out frame scenario path outlines moving colours bindings)
  "Draw the bodies' OUTLINES on OUT: the fixed bodies, then the MOVING ones at the end of
each state of PATH (ghosts), then the moving ones at the start, in their COLOURS and
labelled with their names."
  (loop for (name . outline) in outlines
        unless (member name moving) do (draw-outline out frame outline "fixed" :colour "#c8c8c8"))
  (loop for state in path
        do (loop for (body position) in (state-final-positions state)
                 for end = (point-at position bindings)
                 for outline = (cdr (assoc body outlines))
                 for start = (let ((b (find-scenario-body body scenario))) (and b (body-origin b bindings)))
                 when (and end outline start (member body moving) (not (eq (first outline) :point)))
                   do (draw-outline out frame (moved-outline outline (v- end start)) "ghost")))
  (loop for (name . outline) in outlines
        when (member name moving)
          do (draw-outline out frame outline "body" :colour (cdr (assoc name colours)))
             (draw-label out frame (outline-anchor outline) (name-text name) :dx 8 :dy 14 :priority 1)))

(defun draw-first-contacts-and-forces (out frame first-state arrows bindings)
  "Draw on OUT the contacts of FIRST-STATE (the path's first state, or NIL) as small
diamonds at their touching points, and its forces' ARROWS (see SCALED-ARROWS)."
  (when first-state
    (dolist (contact (state-contacts first-state))
      (let ((geometry (contact-point-and-normal first-state contact bindings)))
        (when geometry
          (destructuring-bind (x y) (to-picture frame (first geometry))
            (format out "<rect class=\"contact\" x=\"~,2F\" y=\"~,2F\" width=\"7\" height=\"7\" transform=\"rotate(45 ~,2F ~,2F)\"/>~%"
                    (- x 3.5) (- y 3.5) x y)))))
    (loop for (from vector label) in arrows
          do (draw-arrow out frame from vector label "#000"))))

(defun request-captions (height bindings chosen)
  "Request the picture's two captions at the foot of its HEIGHT: the values drawn with
(BINDINGS, those CHOSEN for the illustration marked), and how to read the picture."
  (request-label 10 (- height 24)
                 (format nil "~:[values~;illustrative values~]: ~{~A~^, ~}" chosen
                         (loop for (name . value) in bindings
                               collect (format nil "~A = ~A~:[~; (chosen)~]" (name-text name)
                                               (number-text value) (member name chosen))))
                 "caption" :priority 0 :required t)
  (request-label 10 (- height 8)
                 "arrows: forces at the start, to scale; paths: states, solid and dashed in turn; rings: events"
                 "caption" :priority 0 :required t))

(defun print-history-svg (history stream)
  "Write HISTORY-SVG of HISTORY on STREAM as a standalone SVG file (with its XML declaration)."
  (format stream "<?xml version=\"1.0\" encoding=\"UTF-8\"?>~%~A" (history-svg history)))
