;;;; bench/bench-tms.lisp -- JTMS propagation speed: 10,000 nodes and 30,000 justifications,
;;;; retracting and re-enabling one assumption. Prints numbers; asserts nothing.

(defpackage #:ames.bench.tms
  (:use #:cl)
  (:documentation "The JTMS benchmark."))

(in-package #:ames.bench.tms)

(defun seconds-since (start)
  "Seconds of real time since the internal time START."
  (/ (- (get-internal-real-time) start) internal-time-units-per-second))

(defun random-network (node-count justification-count assumption-count random-state)
  "A JTMS of NODE-COUNT nodes, the first ASSUMPTION-COUNT of them assumptions, and
JUSTIFICATION-COUNT justifications (spread evenly over the other nodes). Each node
has a home assumption; each of its justifications has one antecedent in its home's
cone (the home itself or an earlier node of the same home) and, often, one or two
antecedents anywhere earlier. Retracting an assumption thus takes out its cone and
whatever leans on it, while alternative justifications keep some of it IN.
Returns the JTMS and the node vector."
  (let* ((jtms (ames.tms:make-jtms :title "bench"))
         (nodes (coerce (loop for i below node-count
                              collect (ames.tms:make-node jtms i :assumption (< i assumption-count)))
                        'vector))
         (home (make-array node-count))
         (members (make-array assumption-count :initial-element '())))
    (loop for i below node-count
          do (let ((h (if (< i assumption-count) i (random assumption-count random-state))))
               (setf (aref home i) h)
               (push i (aref members h))))
    (flet ((earlier-in-home (i)
             ;; the home assumption or a node of the same home with a lower index
             (let ((candidates (remove-if-not (lambda (j) (< j i)) (aref members (aref home i)))))
               (nth (random (length candidates) random-state) candidates))))
      (loop for k below justification-count
            for consequence = (+ assumption-count (mod k (- node-count assumption-count)))
            do (ames.tms:justify-node
                :bench (aref nodes consequence)
                (cons (aref nodes (earlier-in-home consequence))
                      (loop repeat (if (< (random 1.0 random-state) 0.6) (1+ (random 2 random-state)) 0)
                            collect (aref nodes (random consequence random-state)))))))
    (values jtms nodes)))

(defun in-count (nodes)
  "How many of NODES are IN."
  (count-if #'ames.tms:node-in-p nodes))

(defun run-tms-benchmark (&key (nodes 10000) (justifications 30000) (assumptions 100)
                            (trials 200))
  "Build the network, enable every assumption, then for a sample of assumptions time
a retraction followed by a re-enabling; print the figures."
  (let ((random-state (sb-ext:seed-random-state 1994)) (start (get-internal-real-time)))
    (multiple-value-bind (jtms vector)
        (random-network nodes justifications assumptions random-state)
      (format t "~&Network: ~D nodes, ~D justifications, ~D assumptions (built in ~,3F s)~%"
              (ames.tms:jtms-node-count jtms) (ames.tms:jtms-justification-count jtms)
              assumptions (seconds-since start))
      (setf start (get-internal-real-time))
      (loop for i below assumptions do (ames.tms:enable-assumption (aref vector i)))
      (format t "Enabling all ~D assumptions: ~,3F s; ~D nodes IN~%"
              assumptions (seconds-since start) (in-count vector))
      ;; each assumption: retract and re-enable it TRIALS times
      (let ((results '()))
        (dotimes (i assumptions)
          (let ((node (aref vector i)) (start (get-internal-real-time)) (out 0))
            (dotimes (k trials)
              (setf out (length (nth-value 1 (ames.tms:retract-assumption node))))
              (ames.tms:enable-assumption node))
            (push (list (/ (* 1000 (seconds-since start)) trials) out i) results)))
        (setf results (sort results #'< :key #'first))
        (let ((mean (/ (reduce #'+ results :key #'first) assumptions))
              (median (nth (floor assumptions 2) results))
              (slowest (car (last results)))
              (widest (first (sort (copy-list results) #'> :key #'second))))
          (format t "Retract + re-enable one assumption (~D trials each, ms): ~
                     mean ~,3F, median ~,3F, slowest ~,3F (assumption #~D, ~D nodes OUT)~%"
                  trials mean (first median) (first slowest) (third slowest) (second slowest))
          (format t "The assumption that takes most OUT (#~D): ~D nodes, ~,3F ms~%"
                  (third widest) (second widest) (first widest)))))))

(defun run-worst-case (&key (nodes 10000) (justifications 30000) (trials 20))
  "One assumption under every node: retracting it takes the whole network OUT."
  (let ((random-state (sb-ext:seed-random-state 1994)))
    (multiple-value-bind (jtms vector) (random-network nodes justifications 1 random-state)
      (declare (ignore jtms))
      (ames.tms:enable-assumption (aref vector 0))
      (let ((start (get-internal-real-time)) (out 0))
        (dotimes (k trials)
          (setf out (length (nth-value 1 (ames.tms:retract-assumption (aref vector 0)))))
          (ames.tms:enable-assumption (aref vector 0)))
        (format t "Worst case, one assumption under all ~D nodes: retract + re-enable ~,2F ms ~
                   (~D nodes OUT and back IN)~%"
                nodes (/ (* 1000 (seconds-since start)) trials) out)))))

(run-tms-benchmark)
(run-worst-case)
