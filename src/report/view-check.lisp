;;;; src/report/view-check.lisp -- what a report says of the self-check (AMES.CHECK's result in
;;;; a history's notes): the states checked, those not checked and why, the printed numbers
;;;; checked against their formulas, and each claim that failed.

(in-package #:ames.report)

(defun self-check-lines (history)
  "The lines a report prints about HISTORY's self-check (its notes' :SELF-CHECK, see
AMES.CHECK): which states were checked against a numeric integration and an event
search, which were not and why, how many printed numbers match their formulas, and each
claim that failed with how far off it was. NIL when the run had no values to check with."
  (let ((check (getf (history-notes history) :self-check)))
    (cond ((null check) '())
          ((getf check :skipped) (list "Self-check: skipped (--no-check); nothing here was checked."))
          ((getf check :not-made)
           (list (format nil "Self-check: not made (~A); nothing here was checked." (getf check :not-made))))
          (t (append
              (list (format nil "Self-check~@[ (with ~{~A~^, ~} chosen for it: the claims hold for every value)~]: ~:[no state~*~;~:*state~P ~{~D~^, ~}~] checked against a numeric integration and an event search~@[; ~{~A~^; ~}~]; ~@[~{~D of ~D model equations satisfied by the solution along it~}; ~]~D of ~D printed numbers checked against their formulas."
                            (loop for (name . value) in (getf check :chosen)
                                  collect (format nil "~A = ~A" (name-text name) (number-text value)))
                            (and (getf check :checked) (length (getf check :checked))) (getf check :checked)
                            (loop for entry in (getf check :unchecked)
                                  collect (format nil "state ~D not checked (~A)" (getf entry :state) (getf entry :reason)))
                            (let ((equations (getf check :equations)))
                              (and equations (plusp (second equations)) equations))
                            (first (getf check :numbers)) (second (getf check :numbers))))
              (loop for failure in (getf check :failures)
                    collect (format nil "SELF-CHECK FAILED~@[ at state ~D~]: ~A (off by ~A): ~A"
                                    (getf failure :state) (getf failure :claim)
                                    (let ((d (getf failure :discrepancy)))
                                      (if (realp d) (format nil "~,3,,,,,'eG" d) (datum-text d)))
                                    (getf failure :detail))))))))
