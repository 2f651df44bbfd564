;;;; src/interface/crosscheck.lisp -- make crosscheck: random scenarios through AMES and the witness.
;;;;
;;;; CROSSCHECK runs N random scenarios (the families in turn, from a seed) in this Lisp
;;;; (AMES and its Maxima warm) with one warm witness server (src/witness/server.lisp),
;;;; each scenario under its own time limit. A large run is split into SHARDS processes
;;;; (make crosscheck runs them with GNU parallel): shard K takes the indices equal to K
;;;; modulo SHARDS and appends a record per scenario to its RESULTS file, so that a Lisp
;;;; that dies is started again and goes on after the scenario it died on (recorded as a
;;;; crash). PRINT-CROSSCHECK-SUMMARY prints the counts per family and verdict, the refusal
;;;; rate and the time per scenario from the records of all shards.

(in-package #:ames)

(defun crosscheck-scenario-text (family seed index)
  "The text of the INDEXth random scenario of FAMILY for SEED (the same each time)."
  (let ((ames.witness:*random* (sb-ext:seed-random-state (+ (* 1000003 seed) index))))
    (ames.witness:random-scenario family index)))

(defun crosscheck-one (family seed index &key limits directory)
  "Run the INDEXth random scenario of FAMILY for SEED through AMES and the witness; its
record: (:INDEX :FAMILY :VERDICT :REASON :SECONDS :WITNESS-SECONDS). A disagreement, a
crash and a witness failure are written under DIRECTORY."
  (let* ((*package* (find-package '#:ames-scenario))
         (text (crosscheck-scenario-text family seed index))
         (start (get-internal-real-time))
         (ames.witness:*witness-seconds* 0d0)
         (result (handler-case
                     (witness-check (first (read-scenarios-from-string text)) :numeric t
                                                                              :limits limits)
                   (ames-error (condition) (list :verdict :refused :reason (princ-to-string condition)))
                   (error (condition) (list :verdict :crash :reason (princ-to-string condition)))))
         (verdict (getf result :verdict)))
    (when (member verdict '(:ames-wrong :crash :witness-failed))
      (ames.witness:write-disagreement directory (format nil "~(~A-~A-~D-~D~)" verdict family seed index)
                                       text result))
    (list :index index :family family :verdict verdict
          :reason (let ((reason (getf result :reason)))
                    ;; an agreement has a reason only when the witness's step was refined (records are
                    ;; read in the keyword package: a NIL written reads back as :NIL)
                    (and reason
                         (let ((line (substitute #\Space #\Newline (princ-to-string reason))))
                           (subseq line 0 (min 160 (length line))))))
          :seconds (float (seconds-since start) 1d0) :witness-seconds ames.witness:*witness-seconds*)))

;;; The records file of a shard

(defun read-crosscheck-records (path)
  "The forms of the records file PATH (none when it does not exist), read as data."
  (with-open-file (in path :if-does-not-exist nil)
    (and in
         (with-standard-io-syntax
           (let ((*read-eval* nil) (*package* (find-package :keyword)))
             (loop for form = (handler-case (read in nil :eof) (error () :eof))
                   until (eq form :eof) collect form))))))

(defun append-crosscheck-record (path form)
  "Append FORM to the records file PATH (when there is one) and flush it."
  (when path
    (with-open-file (out path :direction :output :if-exists :append :if-does-not-exist :create)
      (with-standard-io-syntax
        (let ((*print-readably* nil) (*print-pretty* nil))
          (format out "~S~%" form))))))

(defun resumed-records (path seed directory)
  "The scenario records of PATH from an earlier run of the shard, with a crash record
for a scenario that was started and never finished (the Lisp died)."
  (let* ((forms (read-crosscheck-records path))
         (records (remove-if-not (lambda (form) (getf form :verdict)) forms)))
    (dolist (form forms records)
      (let ((index (getf form :started)))
        (when (and index (not (find index records :key (lambda (r) (getf r :index)))))
          (let ((record (list :index index :family (getf form :family) :verdict :crash
                              :reason "the Lisp process died in this scenario" :seconds 0d0
                              :witness-seconds 0d0)))
            (ames.witness:write-disagreement
             directory (format nil "crash-~(~A~)-~D-~D" (getf form :family) seed index)
             (crosscheck-scenario-text (getf form :family) seed index)
             (list :verdict :crash :reason (getf record :reason)))
            (append-crosscheck-record path record)
            (push record records)))))))

(defun print-crosscheck-line (record stream)
  "One line of the verbose crosscheck: index, family, verdict, seconds, reason."
  (format stream "~&~5D ~14A ~14A ~6,2Fs ~@[~A~]~%" (getf record :index)
          (string-downcase (getf record :family)) (string-downcase (getf record :verdict))
          (getf record :seconds) (getf record :reason))
  (finish-output stream))

(defun crosscheck (&key (n 1000) (seed 1) (families (ames.witness:generator-families))
                     (directory "witness/disagreements/") (stream *standard-output*)
                     (limits (change-limits *limits* :time-limit 120)) (verbose t)
                     (shard 0) (shards 1) results (summary t))
  "Run the random scenarios of indices below N equal to SHARD modulo SHARDS (the families
in turn, from SEED) through AMES and the witness, print a line per scenario when VERBOSE
and, when SUMMARY, the summary (PRINT-CROSSCHECK-SUMMARY) at the end. With RESULTS (a file), every
scenario's record is appended to it and the scenarios it already records are not run
again. Every disagreement, crash and witness failure is written under DIRECTORY (see
WRITE-DISAGREEMENT). Returns the counts: an alist ((FAMILY . ((VERDICT . COUNT) ...)) ...)."
  (let ((records (and results (resumed-records results seed directory))))
    (ames.witness:with-witness-server ()
      (loop for index from shard below n by shards
            for family = (nth (mod index (length families)) families)
            unless (find index records :key (lambda (r) (getf r :index)))
              do (append-crosscheck-record results (list :started index :family family))
                 (let ((record (crosscheck-one family seed index :limits limits :directory directory)))
                   (append-crosscheck-record results record)
                   (push record records)
                   (when verbose (print-crosscheck-line record stream)))))
    (append-crosscheck-record results (list :finished shard))
    (when summary (print-crosscheck-summary records stream :seed seed))
    (crosscheck-counts records)))

;;; The figures

(defun crosscheck-counts (records)
  "The counts of RECORDS per family and verdict: ((FAMILY . ((VERDICT . COUNT) ...)) ...),
families and verdicts in the order they first come."
  (let ((counts '()))
    (dolist (record (sort (copy-list records) #'< :key (lambda (r) (getf r :index))))
      (let ((entry (or (assoc (getf record :family) counts)
                       (first (push (list (getf record :family)) counts)))))
        (incf (cdr (or (assoc (getf record :verdict) (cdr entry))
                       (first (push (cons (getf record :verdict) 0) (cdr entry))))))))
    (reverse (mapcar (lambda (entry) (cons (car entry) (reverse (cdr entry)))) counts))))

(defun mean-of (numbers) (if numbers (/ (reduce #'+ numbers) (length numbers)) 0))

(defun median-of (sorted)
  "The median of the SORTED numbers (not empty)."
  (let ((n (length sorted)))
    (if (oddp n)
        (nth (floor n 2) sorted)
        (/ (+ (nth (1- (floor n 2)) sorted) (nth (floor n 2) sorted)) 2))))

(defun print-time-figures (records stream)
  "The time per scenario of RECORDS: mean, median and largest, and the witness's share."
  (let ((seconds (sort (mapcar (lambda (r) (getf r :seconds)) records) #'<)))
    (when seconds
      (format stream "  time per scenario: mean ~,2F s, median ~,2F s, largest ~,1F s (witness ~,2F s of the mean); ~,1F s in all~%"
              (mean-of seconds) (median-of seconds) (car (last seconds))
              (mean-of (mapcar (lambda (r) (getf r :witness-seconds)) records))
              (reduce #'+ seconds)))))

(defun print-crosscheck-summary (records stream &key seed)
  "Print the counts of RECORDS per family and verdict (with each family's mean time), the
counts per verdict with the refusal rate, and the time per scenario."
  (format stream "~&~%Crosscheck of ~D random scenarios~@[ (seed ~A)~]:~%" (length records) seed)
  (dolist (entry (crosscheck-counts records))
    (let ((own (remove (car entry) records :key (lambda (r) (getf r :family)) :test-not #'eq)))
      (format stream "  ~16A~{ ~(~A~) ~D~^,~}  (~,2F s each)~%" (string-downcase (car entry))
              (loop for (verdict . count) in (cdr entry) append (list verdict count))
              (mean-of (mapcar (lambda (r) (getf r :seconds)) own)))))
  (let ((verdicts '()))
    (dolist (record records)
      (incf (getf verdicts (getf record :verdict) 0)))
    (format stream "  verdicts:~{ ~(~A~) ~D~^,~}~%" verdicts)
    (let ((refined (count-if (lambda (r) (and (eq (getf r :verdict) :agree) (stringp (getf r :reason)))) records)))
      (when (plusp refined)
        (format stream "  agreed at a finer witness step (src/witness/refine.lisp): ~D~%" refined)))
    (when records
      (format stream "  refused: ~,1F %~%" (* 100 (/ (getf verdicts :refused 0) (length records))))))
  (print-time-figures records stream))
