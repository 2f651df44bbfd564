;;;; t/crosscheck.lisp -- `make crosscheck`: N random scenarios (environment N, default
;;;; 1000; SEED, default 1; FAMILIES, default all, e.g. FAMILIES=loop,bowl) through AMES
;;;; and the witness (Siconos). Three uses:
;;;;   RESULTS=F SHARD=K SHARDS=J  run shard K of J (witness/crosscheck-shard runs it),
;;;;                               its records appended to F; a line per scenario printed
;;;;   SUMMARY=DIR                 print the counts per family and verdict, the refusal
;;;;                               rate and the time per scenario of DIR's shard files;
;;;;                               exit 1 when AMES was wrong or crashed
;;;;   neither                     run every scenario in this process, then the summary
;;;; Every disagreement, crash and witness failure is written under witness/disagreements/.

(require :asdf)
(asdf:load-asd (merge-pathnames "../ames.asd" *load-truename*))
(asdf:load-system "ames")

(defun crosscheck-families ()
  "The families FAMILIES names (separated by commas or spaces), every family by default."
  (let ((names (remove "" (uiop:split-string (or (uiop:getenv "FAMILIES") "") :separator ", ")
                       :test #'string=)))
    (if names
        (mapcar (lambda (name)
                  (or (find name (ames.witness:generator-families) :test #'string-equal)
                      (progn (format t "~&crosscheck: no family ~A (families: ~(~{~A~^ ~}~))~%"
                                     name (ames.witness:generator-families))
                             (uiop:quit 2))))
                names)
        (ames.witness:generator-families))))

(defun wrong-p (records)
  (some (lambda (r) (member (getf r :verdict) '(:ames-wrong :crash))) records))

(defun env-integer (name default)
  (parse-integer (or (uiop:getenv name) default)))

(let ((summary (uiop:getenv "SUMMARY")))
  (when summary
    (let ((records (loop for file in (directory (merge-pathnames "shard-*.sexp" (uiop:ensure-directory-pathname summary)))
                         append (remove-if-not (lambda (f) (getf f :verdict))
                                               (ames::read-crosscheck-records file)))))
      (ames::print-crosscheck-summary records *standard-output* :seed (uiop:getenv "SEED"))
      (uiop:quit (if (wrong-p records) 1 0)))))

(unless (ames.witness:siconos-available-p)
  (format t "~&crosscheck: ~A cannot import siconos (install Debian's python3-siconos)~%"
          ames.witness:*python*)
  (uiop:quit 1))

(let* ((results (uiop:getenv "RESULTS"))
       (counts (ames::crosscheck :n (env-integer "N" "1000") :seed (env-integer "SEED" "1")
                                 :families (crosscheck-families)
                                 :shard (env-integer "SHARD" "0") :shards (env-integer "SHARDS" "1")
                                 :results results
                                 :summary (not results)
                                 :directory (merge-pathnames "../witness/disagreements/"
                                                             *load-truename*))))
  (declare (ignorable counts))
  (uiop:quit (if (and (not results)
                      (loop for (nil . verdicts) in counts
                              thereis (loop for (verdict . count) in verdicts
                                              thereis (and (member verdict '(:ames-wrong :crash))
                                                           (plusp count)))))
                 1 0)))
