;;;; bench/profile-requests.lisp -- where a run's Maxima time goes: its requests, by the code that asked.
;;;;
;;;; Runs one scenario file in this process on a fresh bridge (with its values when
;;;; AMES_NUMERIC is set, as bin/ames run --numeric), then its text report, logging every
;;;; round trip through the bridge's *REQUEST-LOG*: the seconds Maxima spent on it
;;;; (measured inside Maxima), the kind of request, and who asked (the innermost
;;;; function on the stack outside the bridge and the algebra, and the algebra function
;;;; it called). Prints the totals of the run and of the report, then the costliest
;;;; askers and request kinds, and how many requests were asked again with the same
;;;; text (under other facts: the cache keys requests by the facts in force). Prints
;;;; numbers; asserts nothing; not one of `make bench`'s files (its name does not start
;;;; with bench-). Run:
;;;;   AMES_NUMERIC=1 AMES_SCENARIO=scenarios/two-blocks-in-corner.lisp \
;;;;     sbcl --non-interactive --eval '(require :asdf)' \
;;;;     --eval '(asdf:load-asd (truename "ames.asd"))' --eval '(asdf:load-system "ames")' \
;;;;     --load bench/profile-requests.lisp
;;;;
;;;; What it found for issue 24 (2026-11-26, the corner under --numeric, a loaded machine:
;;;; the seconds are Maxima's own and scale with the load, the shares do not):
;;;;   run 2,882 trips, report 1,031; 65 % of Maxima's time in outermost DECIDE calls that
;;;;   end :UNKNOWN (every strategy tried and failed), most of them on relations with a
;;;;   square root whose radicand is negative at admissible points (the candidates of the
;;;;   fork at t = 0, before the branch's fact is known);
;;;;   the fork state's candidates (13 termination conditions worked out in full, then
;;;;   branched on f l3 - mb g (l1 - l2)): about 60 % of the run;
;;;;   the report: 80 % presenting the six facts "assumed from the given values" (huge
;;;;   relations whose terms' sign proofs fail); requests repeated with the same text:
;;;;   12 %, nearly all under other facts.

(defpackage #:ames.bench.profile-requests
  (:use #:cl)
  (:documentation "Where a run's Maxima time goes, by the code that asked."))

(in-package #:ames.bench.profile-requests)

(defvar *records* '()
  "One (PHASE SECONDS ASKER KIND TEXT) per round trip, newest first.")

(defvar *phase* :run "The phase being logged: :RUN or :REPORT.")

(defun ames-frame-name (frame)
  "The name of FRAME's function as PACKAGE:NAME (the package without its AMES. prefix)
when it is a function of an AMES package other than the bridge's (and this file's),
else NIL."
  (let* ((name (sb-di:debug-fun-name (sb-di:frame-debug-fun frame)))
         (symbol (cond ((symbolp name) name)
                       ((and (consp name) (symbolp (second name))) (second name)))))
    (when (and symbol (symbol-package symbol))
      (let ((package (package-name (symbol-package symbol))))
        (when (and (> (length package) 5) (string= "AMES." package :end2 5)
                   (not (string= package "AMES.MAXIMA"))
                   (not (uiop:string-prefix-p "AMES.BENCH" package)))
          (format nil "~(~A:~A~)" (subseq package 5) symbol))))))

(defun asker ()
  "Who asked the request being logged: the innermost AMES function outside the bridge and
the algebra, after the algebra function it called (when one was called)."
  (let ((names '()))
    (sb-debug::map-backtrace (lambda (frame)
                               (let ((name (ames-frame-name frame)))
                                 (when name (push name names))))
                             :count 80)
    (setf names (nreverse names))
    (let ((outside (position-if-not (lambda (n) (uiop:string-prefix-p "algebra:" n)) names)))
      (cond ((null names) "(none)")
            ((null outside) (first names))
            ((zerop outside) (nth 0 names))
            (t (format nil "~A < ~A" (nth (1- outside) names) (nth outside names)))))))

(defun request-kind (request)
  "The head of the Maxima form of REQUEST (:EVAL FORM), or its kind."
  (let ((form (second request)))
    (if (and (consp form) (consp (first form)))
        (string-downcase (symbol-name (first (first form))))
        (string-downcase (princ-to-string (first request))))))

(defun log-request (bridge request seconds wall)
  "The bridge's *REQUEST-LOG* hook: record one round trip."
  (declare (ignore bridge wall))
  (push (list *phase* (or seconds 0) (asker) (request-kind request)
              (let ((*print-pretty* nil)) (prin1-to-string request)))
        *records*))

(defun totals (records key)
  "((KEY-VALUE SECONDS COUNT) ...) of RECORDS grouped by KEY, costliest first."
  (let ((table (make-hash-table :test 'equal)))
    (dolist (r records)
      (let ((entry (or (gethash (funcall key r) table)
                       (setf (gethash (funcall key r) table) (list 0 0)))))
        (incf (first entry) (second r))
        (incf (second entry))))
    (sort (loop for k being the hash-keys of table using (hash-value v) collect (cons k v))
          #'> :key #'second)))

(defun print-totals (title rows limit)
  "Print TITLE and the first LIMIT ROWS of TOTALS."
  (format t "~&~A~%" title)
  (loop for (k seconds count) in rows
        repeat limit
        do (format t "  ~7,2F s ~6D  ~A~%" seconds count k)))

(let* ((file (or (uiop:getenv "AMES_SCENARIO") "scenarios/two-blocks-in-corner.lisp"))
       (numeric (plusp (length (or (uiop:getenv "AMES_NUMERIC") ""))))
       (bridge (ames.maxima:make-bridge))
       (ames.maxima::*request-log* #'log-request))
  (unwind-protect
       (let ((histories (ames::run-file (truename file) :numeric numeric :bridge bridge)))
         (setf *phase* :report)
         (ames.report:report-history (ames.report:make-report-output
                                      :text (make-broadcast-stream) :bridge bridge)
                                     (first histories)))
    (ames.maxima:close-bridge bridge))
  (let ((records (reverse *records*)))
    (format t "~&~A~:[~; --numeric~]: Maxima's own seconds and round trips~%" file numeric)
    (print-totals "by phase:" (totals records #'first) 2)
    (print-totals "by asker (phase, the algebra function < its caller):"
                  (totals records (lambda (r) (format nil "~(~A~) ~A" (first r) (third r)))) 25)
    (print-totals "by request kind:" (totals records #'fourth) 12)
    (let ((seen (make-hash-table :test 'equal)) (again 0) (seconds 0))
      (dolist (r records)
        (when (gethash (fifth r) seen) (incf again) (incf seconds (second r)))
        (setf (gethash (fifth r) seen) t))
      (format t "~&requests asked again with the same text: ~D, ~,2F s~%" again seconds))))
