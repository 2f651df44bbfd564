;;;; src/report/plots.lisp -- plots over time under a run's picture: each moving body's x(t),
;;;; y(t) and speed, and the energies, with the events marked.
;;;;
;;;; The curves are the closed forms of the states along the picture's path (see
;;;; PICTURE-PATH) evaluated at the picture's numbers; t runs from the start of the run, each
;;;; state's tau = t - t0. A state whose motion has no closed form in time (along a curve by
;;;; arc length, integrated numerically) leaves a gap. The speed is |v| from the state's
;;;; velocities, the energies the kinetic, potential and total energy the knowledge base
;;;; reports in each state's notes. Every end of a state is a dashed vertical line.

(in-package #:ames.report)

(defparameter *plot-height* 150 "The height of one plot's drawing area in pixels.")

(defun time-samples (path bindings)
  "For each state of PATH with a known extent in time, (STATE START DURATION): its start
and duration as numbers (a third of the time before it, at least 1/4 of a time unit, for
a state that lasts forever). Stops at the first state whose start is not known."
  (let* ((clock 0d0) (samples '())
         (finite (loop for state in path
                       for d = (state-duration-number state bindings)
                       while d sum d))
         (horizon (max 0.25d0 (/ finite 3))))
    (dolist (state path (nreverse samples))
      (let ((duration (or (state-duration-number state bindings)
                          (and (eq (state-duration state) :forever) horizon))))
        (unless duration (return (nreverse samples)))
        ;; a state starts at its start formula's value where it has one (after impacts
        ;; that accumulate, the durations before it summed fall short)
        (let ((start (or (number-at (state-start state) bindings) clock)))
          (push (list state start duration) samples)
          (setf clock (+ start duration)))))))

(defun state-series (state start duration bindings function)
  "Points (T VALUE) of FUNCTION (of tau, a number or NIL) over STATE, from START."
  (loop for i from 0 to *samples-per-state*
        for time = (* duration (/ i *samples-per-state*))
        ;; a value beyond double precision (an overflow) is a point not drawn
        for value = (handler-case (funcall function time) (arithmetic-error () nil))
        when (and (realp value) (< (abs value) 1d12))
          collect (list (+ start time) value)))

(defun closed-form-in-tau-p (expression)
  "True when EXPRESSION is arithmetic (a closed form in tau)."
  (and (not (keywordp expression)) (valid-expression-p expression :kind :arithmetic)))

(defun body-series (spans body bindings)
  "Per quantity of BODY (:X :Y :SPEED), a list of series (one per state, lists of (T V))."
  (flet ((series (selector)
           (loop for (state start duration) in spans
                 for position = (body-entry (state-positions state) body)
                 for velocity = (body-entry (state-velocities state) body)
                 for values = (and (vector-value-p position)
                                   (state-series state start duration bindings
                                                 (lambda (time) (funcall selector position velocity
                                                                        (acons 'tau time bindings)))))
                 when values collect values)))
    (list :x (series (lambda (p v b) (declare (ignore v)) (number-at (first p) b)))
          :y (series (lambda (p v b) (declare (ignore v)) (number-at (second p) b)))
          :speed (series (lambda (p v b) (declare (ignore p))
                           (let ((point (and (vector-value-p v) (point-at v b))))
                             (and point (vlength point))))))))

(defun energy-series (spans bindings)
  "The series of each kind of energy term the knowledge base declares and of their total:
a list of (LABEL SERIES), the total last (labelled with the kinds' symbols, K + U)."
  (flet ((series (kinds)
           (loop for (state start duration) in spans
                 for entries = (remove-if-not (lambda (e) (member (first e) kinds))
                                              (getf (state-reported-sections state) :energy))
                 for values = (and entries (every (lambda (e) (closed-form-in-tau-p (third e))) entries)
                                   (state-series state start duration bindings
                                                 (lambda (time)
                                                   (let ((b (acons 'tau time bindings)) (sum 0d0))
                                                     (dolist (e entries sum)
                                                       (let ((v (number-at (third e) b)))
                                                         (unless v (return nil))
                                                         (incf sum v)))))))
                 when values collect values)))
    (let ((terms (ames.kb:reported-terms :energy)))
      (append (loop for term in terms
                    collect (list (ames.kb:term-label term) (series (list (ames.kb:term-kind term)))))
              (list (list (format nil "total ~{~A~^ + ~}" (mapcar #'ames.kb:term-symbol terms))
                          (series (mapcar #'ames.kb:term-kind terms))))))))

(defparameter *energy-curve-styles*
  '(("#c0392b" nil) ("#1f5fa8" "5 3") ("#8e44ad" "1 3") ("#27ae60" "8 3"))
  "Colour and dash of the energy plot's curves, one per kind of term in turn; the total
is drawn in *ENERGY-TOTAL-STYLE*.")

(defparameter *energy-total-style* '("#222" "2 2")
  "Colour and dash of the energy plot's total.")

(defun energy-curves (energy)
  "The energy plot's curves (LABEL COLOUR DASH . SERIES) of ENERGY (see ENERGY-SERIES),
those with points."
  (loop for (label series) in energy
        for k from 0
        for (colour dash) = (if (= k (1- (length energy)))
                                *energy-total-style*
                                (nth (mod k (length *energy-curve-styles*)) *energy-curve-styles*))
        when series
          collect (list* label colour dash series)))

(defun nice-ticks (low high)
  "About four round numbers from LOW to HIGH for an axis."
  (let* ((span (max (- high low) 1d-9))
         (raw (/ span 4))
         (magnitude (expt 10d0 (floor (log raw 10))))
         (step (* magnitude (find-if (lambda (k) (>= (* k magnitude) raw)) '(1 2 2.5d0 5 10)))))
    (loop for tick = (* step (ceiling low step)) then (+ tick step)
          while (<= tick (+ high (* 1d-9 span)))
          collect tick)))

(defun draw-plot (stream left top width title curves event-times)
  "Draw one plot at LEFT, TOP (pixels) WIDTH wide: its TITLE, axes with ticks, CURVES
((LABEL COLOUR DASH SERIES...) ...) over time, and a dashed line at each of EVENT-TIMES.
Returns nothing; its labels are requested (see REQUEST-LABEL)."
  (let* ((points (loop for (nil nil nil . series) in curves append (apply #'append series)))
         (tmax (max 1d-9 (reduce #'max (mapcar #'first points) :initial-value 0d0)
                    (reduce #'max event-times :initial-value 0d0)))
         (vmin (reduce #'min (mapcar #'second points) :initial-value 0d0))
         (vmax (reduce #'max (mapcar #'second points) :initial-value 0d0))
         (vmax (if (< (- vmax vmin) 1d-9) (+ vmin 1) vmax))
         (inner-left (+ left 44)) (inner-right (- (+ left width) 10))
         (inner-top (+ top 22)) (inner-bottom (+ top *plot-height*)))
    (flet ((px (time) (+ inner-left (* (- inner-right inner-left) (/ time tmax))))
           (py (value) (- inner-bottom (* (- inner-bottom inner-top) (/ (- value vmin) (- vmax vmin))))))
      (request-label left (+ top 12) title "plot-title" :priority 1)
      (format stream "<g class=\"plot\" data-title=\"~A\">~%" (xml-escape title))
      (format stream "<line class=\"axis\" x1=\"~,2F\" y1=\"~,2F\" x2=\"~,2F\" y2=\"~,2F\"/>~%"
              inner-left inner-bottom inner-right inner-bottom)
      (format stream "<line class=\"axis\" x1=\"~,2F\" y1=\"~,2F\" x2=\"~,2F\" y2=\"~,2F\"/>~%"
              inner-left inner-top inner-left inner-bottom)
      (dolist (tick (nice-ticks vmin vmax))
        (request-label (- inner-left 4) (+ (py tick) 3) (number-text tick 3) "tick" :anchor :end :priority 3))
      (dolist (tick (nice-ticks 0 tmax))
        (request-label (px tick) (+ inner-bottom 11) (number-text tick 3) "tick" :anchor :middle :priority 3))
      (dolist (time event-times)
        (format stream "<line class=\"event-time\" x1=\"~,2F\" y1=\"~,2F\" x2=\"~,2F\" y2=\"~,2F\"/>~%"
                (px time) inner-top (px time) inner-bottom))
      (loop for (label colour dash . series) in curves
            for k from 0
            do (dolist (one series)
                 (format stream "<polyline class=\"curve\" data-curve=\"~A\" style=\"stroke:~A~@[;stroke-dasharray:~A~]\" points=\"~{~{~,2F,~,2F~}~^ ~}\"/>~%"
                         (xml-escape label) colour dash
                         (mapcar (lambda (p) (list (px (first p)) (py (second p)))) one)))
               ;; a legend only while the colours tell the curves apart
               (when (and label series (<= (length curves) (length *body-colours*)))
                 (request-label (- inner-right 2) (+ inner-top 10 (* 14 k)) label "legend"
                                :anchor :end :priority 2 :colour colour)))
      (format stream "</g>~%"))))

(defun plots-height (plots)
  "The height in pixels of PLOTS laid out two to a row."
  (* (ceiling (length plots) 2) (+ *plot-height* 30)))

(defun time-plots (path bindings moving colours)
  "The plots of PATH over time: (TITLE CURVES) for x(t), y(t), speed and energy, those
with nothing to draw left out; and the times of the events (the ends of the states)."
  (let* ((spans (time-samples path bindings))
         (series (mapcar (lambda (body) (cons body (body-series spans body bindings))) moving))
         (energy (energy-series spans bindings))
         (plots (remove-if-not
                 #'second
                 (append
                  (loop for (key title) in '((:x "x(t)") (:y "y(t)") (:speed "speed |v|"))
                        collect (list title
                                      (loop for (body . quantities) in series
                                            when (getf quantities key)
                                              collect (list* (name-text body) (cdr (assoc body colours)) nil
                                                             (getf quantities key)))))
                  (list (list "energy" (energy-curves energy)))))))
    (values plots
            (loop for (state start duration) in spans
                  when (consp (state-end-event state)) collect (+ start duration)))))

(defun draw-time-plots (stream plots event-times top)
  "Draw PLOTS (see TIME-PLOTS) two to a row from TOP down."
  (loop for (title curves) in plots
        for k from 0
        do (draw-plot stream (+ 10 (* (mod k 2) (/ *picture-width* 2))) (+ top (* (floor k 2) (+ *plot-height* 30)))
                      (- (/ *picture-width* 2) 20) title curves event-times)))
