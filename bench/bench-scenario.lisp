;;;; bench/bench-scenario.lisp -- how fast scenarios are read, validated and checked through Maxima.

(in-package #:cl-user)

(let* ((directory (merge-pathnames "../scenarios/" *load-truename*))
       (files (sort (directory (merge-pathnames "*.lisp" directory)) #'string<
                    :key #'pathname-name))
       (texts (mapcar #'uiop:read-file-string files))
       (forms (mapcan #'ames:read-scenario-forms texts)))
  (flet ((per-call (n thunk)
           (let ((start (get-internal-real-time)))
             (dotimes (i n) (funcall thunk))
             (/ (- (get-internal-real-time) start) (float internal-time-units-per-second) n))))
    (format t "read + validate all ~D scenario files: ~,1F us~%" (length files)
            (* 1d6 (per-call 200 (lambda ()
                                   (dolist (text texts)
                                     (ames:read-scenarios-from-string text))))))
    (format t "read only (restricted reader):        ~,1F us~%"
            (* 1d6 (per-call 200 (lambda () (mapc #'ames:read-scenario-forms texts)))))
    (format t "validate only (PARSE-SCENARIO):       ~,1F us~%"
            (* 1d6 (per-call 200 (lambda () (mapc #'ames:parse-scenario forms)))))
    (let ((bridge (ames.maxima:make-bridge)))
      (unwind-protect
           (dolist (file files)
             (let ((scenario (first (ames:read-scenario-file file))))
               (ames.maxima:reset-bridge-statistics bridge)
               (let* ((start (get-internal-real-time))
                      (outcome (handler-case (progn (ames:check-scenario scenario bridge) "ok")
                                 (ames:ames-error (condition)
                                   (format nil "~A" (type-of condition)))))
                      (seconds (/ (- (get-internal-real-time) start)
                                  (float internal-time-units-per-second)))
                      (statistics (ames.maxima:bridge-statistics bridge)))
                 (format t "CHECK-SCENARIO ~22A ~6,3F s  ~3D Maxima calls ~3D cache hits  ~A~%"
                         (pathname-name file) seconds (getf statistics :calls)
                         (getf statistics :cache-hits) outcome))))
        (ames.maxima:close-bridge bridge)))))
