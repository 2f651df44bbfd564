;;;; t/compiled-server.lisp -- the request server compiled by GCL answers as its sources do.
;;;;
;;;; bin/ames compiles the request server into build/gcl/ when it builds its image
;;;; (src/maxima-bridge/compiled-server.lisp); a bridge loads it only while it is newer
;;;; than both sources. Here it is compiled into a scratch directory, and a bridge on the
;;;; compiled server and one on the sources are asked the same requests: the shortcuts
;;;; and presorting of sums of many variables (a chain's widths, given in shuffled
;;;; order), their full simplification and presentation, a wedge's solve and a
;;;; trigonometric simplification. Their answers must be EQUAL; a compiled server older
;;;; than a source is not loaded.

(in-package #:ames.tests)

(def-suite compiled-server :in all-tests
  :description "The compiled request server answers as its sources do.")

(in-suite compiled-server)

(defun compiled-server-requests (bridge)
  "The answers of BRIDGE to a fixed list of requests, in order."
  (let* ((widths (loop for k from 1 to 40 collect (intern (format nil "W~D" k) '#:ames.tests)))
         (shuffled (alexandria:shuffle (copy-list widths)))
         (sum (cons '+ shuffled))
         (multiples `(+ 3 ,@(mapcar (lambda (w) `(* 2 ,w)) (subseq shuffled 0 20)))))
    (list (ames.maxima:simplify bridge sum)
          (ames.maxima:simplify bridge sum :strategy :full)
          (ames.maxima:simplify bridge multiples :strategy :full)
          (ames.maxima:simplify bridge `(- ,sum ,(cons '+ (reverse widths))))
          (ames.maxima:presentation-candidates bridge multiples)
          (ames.maxima:simplify bridge '(+ (expt (sin a) 2) (expt (cos a) 2) (tan a))
                                :strategy :trigsimp)
          (ames.maxima:solve-equations bridge *wedge-equations* '(awx apx apy n arel)))))

(defun gcc-available-p ()
  "True when a C compiler, which GCL's compile-file calls, is on the PATH."
  (ignore-errors
   (zerop (nth-value 2 (uiop:run-program '("sh" "-c" "command -v gcc")
                                         :ignore-error-status t :output nil)))))

(test the-compiled-server-answers-as-its-sources-do
  (if (not (gcc-available-p))
      (skip "gcc is absent: GCL cannot compile the request server, and bridges load its sources")
      (compiled-server-comparison)))

(defun compiled-server-comparison ()
  "The body of THE-COMPILED-SERVER-ANSWERS-AS-ITS-SOURCES-DO."
  (let ((directory (uiop:ensure-directory-pathname
                    (merge-pathnames (format nil "ames-gcl-~36R/" (random (expt 36 8) (make-random-state t)))
                                     (uiop:temporary-directory))))
        (*random-state* (sb-ext:seed-random-state 24)))
    (unwind-protect
         (progn
           (is-true (ames.maxima::compile-server-files :directory directory))
           (is (equal (namestring (merge-pathnames "maxima-server.o" directory))
                      (namestring (ames.maxima::compiled-server-file directory))))
           (let* ((state (make-random-state *random-state*))
                  (compiled (let ((ames.maxima::*compiled-server-directory* directory)
                                  (*random-state* (make-random-state state)))
                              (call-with-bridge #'compiled-server-requests)))
                  (source (let ((ames.maxima::*compiled-server-directory*
                                  (merge-pathnames "none/" directory))
                                (*random-state* (make-random-state state)))
                            (call-with-bridge #'compiled-server-requests))))
             (is (= 7 (length compiled)))
             (is (equal source compiled))
             ;; the sum of the widths simplifies to itself, whatever their order
             (is (and (consp (first compiled)) (eq '+ (first (first compiled)))
                      (null (set-exclusive-or (rest (first compiled))
                                              (loop for k from 1 to 40
                                                    collect (intern (format nil "W~D" k) '#:ames.tests))))))
             ;; so does its difference with the same sum in another order: 0
             (is (eql 0 (fourth compiled))))
           (let ((ames.maxima::*compiled-server-directory* directory))
             (is (equal (namestring (merge-pathnames "maxima-server.o" directory))
                        (namestring (ames.maxima::server-file-to-load)))))
           ;; compiled before its sources were last written: not loaded
           (uiop:run-program (list "touch" "-d" "2000-01-01"
                                   (namestring (merge-pathnames "maxima-server-functions.o" directory))))
           (is (null (ames.maxima::compiled-server-file directory)))
           (let ((ames.maxima::*compiled-server-directory* directory))
             (is (equal (namestring ames.maxima::*server-file*)
                        (namestring (ames.maxima::server-file-to-load))))))
      (uiop:delete-directory-tree directory :validate t :if-does-not-exist :ignore))))
