;;;; src/report/numbers.lisp -- the reports' floating-point numbers, which never overflow.
;;;;
;;;; A report prints a number beside each closed form when the run has values; it is a
;;;; double-float. A value beyond double precision (a default of 10^400, a coefficient of
;;;; 1d308 squared) has no such number: REPORT-FLOAT gives NIL and the closed form stands
;;;; alone, in every format, instead of a FLOATING-POINT-OVERFLOW ending the report.

(in-package #:ames.report)

(defun report-float (x)
  "The real X as a finite double-float, or NIL when it has none (beyond the range of
double precision, or not a finite real). Signals nothing."
  (and (realp x)
       (let ((value (handler-case (float x 1d0) (arithmetic-error () nil))))
         (and value (finite-real-p value) value))))

(defun report-floats (alist)
  "The entries (KEY . REAL) of ALIST with their numbers as REPORT-FLOATs, those without
one left out."
  (loop for (key . value) in alist
        for number = (report-float value)
        when number collect (cons key number)))
