;;;; t/crosscheck.lisp -- `make crosscheck`: N random scenarios (environment N, default
;;;; 1000; SEED, default 1; FAMILIES, default all, e.g. FAMILIES=loop,bowl) through AMES
;;;; and the witness (Siconos); prints a line per
;;;; scenario and the counts per family and verdict; writes every disagreement, crash and
;;;; witness failure under witness/disagreements/. Exits 1 when AMES was wrong or crashed.

(require :asdf)
(asdf:load-asd (merge-pathnames "../ames.asd" *load-truename*))
(asdf:load-system "ames")
(unless (ames.witness:siconos-available-p)
  (format t "~&crosscheck: ~A cannot import siconos (install Debian's python3-siconos)~%"
          ames.witness:*python*)
  (uiop:quit 1))
(let* ((n (parse-integer (or (uiop:getenv "N") "1000")))
       (seed (parse-integer (or (uiop:getenv "SEED") "1")))
       ;; FAMILIES: names separated by commas or spaces (default: every family)
       (names (remove "" (uiop:split-string (or (uiop:getenv "FAMILIES") "") :separator ", ")
                      :test #'string=))
       (families (if names
                     (mapcar (lambda (name)
                               (let ((family (find name (ames.witness:generator-families) :test #'string-equal)))
                                 (or family
                                     (progn (format t "~&crosscheck: no family ~A (families: ~(~{~A~^ ~}~))~%"
                                                    name (ames.witness:generator-families))
                                            (uiop:quit 2)))))
                             names)
                     (ames.witness:generator-families)))
       (counts (ames::crosscheck :n n :seed seed :families families
                                 :directory (merge-pathnames "../witness/disagreements/"
                                                             *load-truename*))))
  (uiop:quit (if (loop for (nil . verdicts) in counts
                       thereis (loop for (verdict . count) in verdicts
                                     thereis (and (member verdict '(:ames-wrong :crash))
                                                  (plusp count))))
                 1 0)))
