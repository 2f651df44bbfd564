;;;; src/simulator/reaches-at.lisp -- the WHEN (reaches QUANTITY VALUE) of a value query
;;;; (scenario-language.md, "Queries"): the first point of the run where QUANTITY takes
;;;; VALUE, in time or along a state's coordinate.
;;;;
;;;; The states are searched in order. In a state over time the point is the earliest root
;;;; tau of QUANTITY - VALUE before the state ends (as REACHES-TIME finds it). In a state
;;;; along a coordinate s (a curve's arc length, a rotating body's angle) it is the earliest
;;;; root of QUANTITY - VALUE from the state's start s0 toward its end s1 (the arc length
;;;; where it ends, or the far turning point of a periodic swing), proven to lie between
;;;; them (the algebra's COORDINATE-ROOT-AHEAD, every turn considered): the point is then
;;;; (:ARC S), where the state's quantities are read with no time needed. Where the
;;;; history does not decide it, UNANSWERABLE says why.

(in-package #:ames.simulator)

(defun rotation-arc-start (scenario previous state)
  "Where STATE's motion along a rotating body's angle starts (the body whose angle over
STATE is the coordinate itself): its angle at the end of the PREVIOUS state, or the
scenario's initial angle when STATE comes first; NIL for no such motion."
  (let ((body (first (find +arc-length+ (state-angles state) :key #'second))))
    (when body
      (if previous
          (second (assoc body (state-final-angles previous)))
          (ames.scenario:scenario-body-angle (ames.scenario:find-scenario-body body scenario))))))

(defun state-arc-span (scenario previous state)
  "(S0 S1), where STATE's motion along its coordinate starts and ends (the far turning
point of a periodic swing), or NIL when either is not known; PREVIOUS is the state
before it (NIL for the first)."
  (let ((between (getf (state-periodic state) :between))
        (start (or (arc-length-start state) (rotation-arc-start scenario previous state)))
        (end (arc-length-end state)))
    (cond ((and between (not (getf (state-periodic state) :coordinate))) between)
          ((and start end) (list start end))
          ;; a motion along the coordinate that never ends nor turns (a rod turning over
          ;; and over): its far end is NIL
          ((and start (eq (state-duration state) :forever) (not between)) (list start nil)))))

(defun endless-motion-direction (state)
  "The direction (1 or -1) of STATE's one motion along its coordinate, or NIL."
  (let ((notes (state-line-coordinates state)))
    (and notes (null (rest notes)) (member (getf (first notes) :direction) '(1 -1))
         (getf (first notes) :direction))))

(defun reached-with-speed-p (bridge state root)
  "True when the motion along STATE's coordinate reaches ROOT moving: its energy integral
(the squared speed along the coordinate) is proven positive there, so that it is not
only approached for ever (an unstable equilibrium reached with exactly its energy)."
  (let ((integral (getf (first (state-line-coordinates state)) :energy-integral)))
    (and integral
         (eq :true (ames.algebra:decide
                    bridge `(> ,(substitute-expressions (list (cons +arc-length+ root)) (third integral)) 0))))))

(defun first-root-ahead (bridge state difference s0 direction)
  "The first arc length ahead of S0 (along DIRECTION, +1 or -1) where DIFFERENCE vanishes
in STATE, or NIL when there is none; signals UNANSWERABLE when that is not decided."
  (multiple-value-bind (root status)
      (ames.algebra:coordinate-root-ahead bridge difference +arc-length+ s0 direction)
    (case root
      (:none nil)
      (:unknown (unanswerable "where it is reached in state ~D is not decided~@[ (~S)~]"
                              (state-index state) status))
      (t root))))

(defun reaches-along-endless-arc (bridge state difference s0)
  "The arc length S where DIFFERENCE first vanishes ahead of S0 in STATE, whose motion along
its coordinate never ends nor turns, or NIL; signals UNANSWERABLE when not decided."
  (let ((direction (or (endless-motion-direction state)
                       (unanswerable "which way state ~D runs along its coordinate is not known"
                                     (state-index state)))))
    (let ((root (first-root-ahead bridge state difference s0 direction)))
      (cond ((null root) nil)
            ((reached-with-speed-p bridge state root) root)
            (t (unanswerable "whether state ~D reaches it moving is not decided"
                             (state-index state)))))))

(defun reaches-along-arc (bridge scenario previous state difference)
  "The arc length S where DIFFERENCE (over the arc length) first vanishes in STATE, or NIL
when it does not in STATE (PREVIOUS the state before it); signals UNANSWERABLE when that
is not decided."
  (let ((span (or (state-arc-span scenario previous state)
                  (unanswerable "where state ~D starts and ends along its coordinate is not known"
                                (state-index state)))))
    (destructuring-bind (s0 s1) span
      (flet ((at (s) (substitute-expressions (list (cons +arc-length+ s)) difference))
             (decided (fact) (ames.algebra:decide bridge fact)))
        (case (decided `(= ,(at s0) 0))
          (:true (return-from reaches-along-arc s0))
          (:unknown (unanswerable "whether it holds at the start of state ~D is not decided"
                                  (state-index state))))
        (unless s1
          (return-from reaches-along-arc (reaches-along-endless-arc bridge state difference s0)))
        (let ((direction (case (decided `(> ,s1 ,s0)) (:true 1)
                           (t (if (eq (decided `(< ,s1 ,s0)) :true) -1
                                  (return-from reaches-along-arc nil))))))
          (let ((root (first-root-ahead bridge state difference s0 direction)))
            (when root
              (case (decided `(<= (* ,direction (- ,root ,s1)) 0))
                (:true root)
                (:false nil)
                (t (unanswerable "whether it is reached before state ~D ends is not decided"
                                 (state-index state)))))))))))

(defun reaches-in-time (bridge state difference)
  "The local time where DIFFERENCE (over TAU) first vanishes in STATE, or NIL; signals
UNANSWERABLE when that is not decided."
  (case (ames.algebra:decide bridge `(= ,(substitute-expressions '((tau . 0)) difference) 0))
    (:true (return-from reaches-in-time 0))
    (:unknown (unanswerable "whether it holds at the start of state ~D is not decided"
                            (state-index state))))
  (unless (free-of-p 'tau difference)
    (let ((root (query-root bridge difference 'tau 0))
          (duration (state-duration state)))
      (when (eq root :unknown)
        (unanswerable "where it is reached in state ~D is not decided" (state-index state)))
      (unless (eq root :none)
        (case (if (eq duration :forever)
                  :true
                  (progn (unless (closed-form-p duration)
                           (unanswerable "state ~D's end has no closed form" (state-index state)))
                         (ames.algebra:decide bridge `(<= ,root ,duration))))
          (:true root)
          (:false nil)
          (t (unanswerable "whether it is reached before state ~D ends is not decided"
                           (state-index state))))))))

(defun reaches-point (bridge scenario states quantity value)
  "The STATE and point (a local time, or (:ARC S)) where QUANTITY first takes VALUE among
STATES (see the file header); signals UNANSWERABLE when the run never reaches it or it
is not decided."
  (loop for previous = nil then state
        for state in (motion-states states)
        for difference = (quantity-in scenario state `(- ,quantity ,value))
        for point = (cond ((free-of-p +arc-length+ difference)
                           (reaches-in-time bridge state difference))
                          ((not (free-of-p 'tau difference))
                           (unanswerable "in state ~D it varies both in time and along the path"
                                         (state-index state)))
                          (t (let ((s (reaches-along-arc bridge scenario previous state difference)))
                               (and s (list :arc s)))))
        when point
          do (return-from reaches-point (values state point)))
  (unanswerable "~(~S~) never reaches ~(~S~) in this run" quantity value))
