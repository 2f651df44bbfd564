;;;; bench/wedge-demo.lisp -- `make demo` until the simulator exists: the particle on a wedge (thesis section 2.6.1) solved through the Maxima bridge.
;;;;
;;;; Run as `sbcl --load bench/wedge-demo.lisp` from anywhere: it loads the checkout's
;;;; ames.asd, solves Newton's second law for the wedge and the particle together with the
;;;; reference-frame conversion for the normal force N and the accelerations, shows that
;;;; N > 0 (the particle never leaves the wedge), prints everything, and exits 0.

(require :asdf)
(asdf:load-asd (merge-pathnames "../ames.asd" *load-truename*))
(asdf:load-system "ames")

(defpackage #:ames.wedge-demo
  (:use #:cl #:ames.base)
  (:import-from #:ames.maxima #:make-bridge #:close-bridge #:solve-equations #:simplify
                #:decide #:equivalent-p #:with-assumptions #:latex #:bridge-statistics))

(in-package #:ames.wedge-demo)

(defparameter *equations*
  '((= (* mw awx) (- (* n (sin a))))            ; wedge, horizontal
    (= (* mp apx) (* n (sin a)))                ; particle, horizontal
    (= (* mp apy) (- (* n (cos a)) (* mp g)))   ; particle, vertical
    (= apx (+ awx (* arel (cos a))))            ; A(particle) = A(particle<-wedge) + A(wedge),
    (= apy (- (* arel (sin a)))))               ;   AREL down the slope, direction (cos a, -sin a)
  "The five equations of section 2.6.1: N is the normal force between particle and
wedge, AWX the wedge's acceleration, APX and APY the particle's, AREL the particle's
acceleration relative to the wedge, down the slope of angle A.")

(defparameter *unknowns* '(n apx apy awx arel))

(defparameter *facts* '((> mp 0) (> mw 0) (> g 0) (> a 0) (< a (/ pi 2)))
  "The declared assumptions: positive masses and gravity, an acute slope.")

(defparameter *thesis-normal-force* '(/ (* mp mw g (cos a)) (+ mw (* mp (expt (sin a) 2)))))

;;; A small infix printer, for display only.

(defun infix (expression)
  "EXPRESSION (prefix algebra) as readable infix text."
  (labels ((level (x)
             (cond ((and (realp x) (minusp x)) 1)
                   ((typep x 'ratio) 2)
                   ((atom x) 5)
                   ((quantity-term-p x) 5)
                   (t (case (car x)
                        ((+ -) 1)
                        ((* /) 2)
                        (expt 3)
                        (t 5)))))
           (wrap (x least)
             (if (< (level x) least) (format nil "(~A)" (text x)) (text x)))
           (text (x)
             (cond ((integerp x) (princ-to-string x))
                   ((rationalp x) (format nil "~D/~D" (numerator x) (denominator x)))
                   ((floatp x) (format nil "~,6G" x))
                   ((eq x 'pi) "pi")
                   ((symbolp x) (string-downcase (symbol-name x)))
                   ((quantity-term-p x)
                    (format nil "~(~A~)(~{~(~A~)~^, ~})" (car x) (cdr x)))
                   (t (let ((args (cdr x)))
                        (case (car x)
                          (+ (format nil "~{~A~^ + ~}" (mapcar (lambda (a) (wrap a 1)) args)))
                          (- (if (rest args)
                                 (format nil "~A~{ - ~A~}" (wrap (first args) 1)
                                         (mapcar (lambda (a) (wrap a 2)) (rest args)))
                                 (format nil "-~A" (wrap (first args) 2))))
                          (* (format nil "~{~A~^*~}" (mapcar (lambda (a) (wrap a 2)) args)))
                          (/ (format nil "~A~{/~A~}" (wrap (first args) 2)
                                     (mapcar (lambda (a) (wrap a 3)) (rest args))))
                          (expt (format nil "~A^~A" (wrap (first args) 4) (wrap (second args) 4)))
                          ((= /= < > <= >=)
                           (format nil "~A ~(~A~) ~A" (text (first args)) (car x) (text (second args))))
                          (t (format nil "~(~A~)(~{~A~^, ~})" (car x) (mapcar #'text args)))))))))
    (text expression)))

(defun main ()
  (let ((bridge (make-bridge)))
    (unwind-protect
         (let ((start (get-internal-real-time)))
           (format t "~&AMES -- particle on a wedge (Wong 1994, section 2.6.1), through the Maxima bridge~2%")
           (format t "Equations (frictionless; the wedge slides on the ground):~%")
           (dolist (equation *equations*)
             (format t "    ~A~%" (infix equation)))
           (let* ((solutions (solve-equations bridge *equations* *unknowns*))
                  (solution (first solutions)))
             (unless (= 1 (length solutions))
               (error "Expected exactly one solution, got ~D." (length solutions)))
             (with-assumptions (bridge *facts*)
               (format t "~%Solution, under ~{~A~^, ~}:~%" (mapcar #'infix *facts*))
               (dolist (binding solution)
                 (format t "    ~4A = ~A~%" (string-downcase (symbol-name (car binding)))
                         (infix (simplify bridge (cdr binding) :strategy :full))))
               (let ((n (cdr (assoc 'n solution))))
                 (format t "~%Normal force N = ~A~%" (infix (simplify bridge n :strategy :full)))
                 (format t "    as LaTeX: ~A~%" (remove #\Newline (latex bridge (simplify bridge n :strategy :full))))
                 (format t "    equal to the thesis's m_p m_w g cos a / (m_w + m_p sin^2 a): ~:[NO~;yes~] (checked by Maxima)~%"
                         (equivalent-p bridge n *thesis-normal-force*))
                 (let ((verdict (decide bridge `(> ,n 0))))
                   (format t "    N > 0 is ~A: ~:[the particle may leave the wedge~;the particle stays on the wedge~]~%"
                           verdict (eq verdict :true))
                   (unless (eq verdict :true)
                     (error "N > 0 was not decided true (~S)." verdict)))))
             (let ((statistics (bridge-statistics bridge)))
               (format t "~%Bridge: ~D requests (~D answered from the cache), ~D Maxima round trips, ~,1F ms in all.~%"
                       (getf statistics :calls) (getf statistics :cache-hits)
                       (getf statistics :maxima-calls)
                       (/ (* 1000 (- (get-internal-real-time) start))
                          internal-time-units-per-second)))))
      (close-bridge bridge))))

(main)
(uiop:quit 0)
