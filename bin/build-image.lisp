;;;; bin/build-image.lisp -- saves the executable image that bin/ames runs.
;;;; Usage: sbcl --non-interactive --load bin/build-image.lisp OUTPUT-PATH

(require :asdf)
(asdf:load-asd (merge-pathnames "../ames.asd" *load-truename*))
(asdf:load-system "ames")

;;; The request server compiled by Maxima's GCL into build/gcl/ (see the bridge's
;;; compiled-server.lisp): every Maxima a run starts loads it compiled. Without gcc the
;;; sources are loaded, as before.
(unless (ignore-errors (ames.maxima::compile-server-files))
  (format *error-output* "~&the request server could not be compiled: Maxima loads its sources~%"))

;;; A warm-up before saving: one run of a small scenario with its text report, so that
;;; what the first run in a process pays once (the generic functions' dispatch caches
;;; filled on first call, the rule engine's first matches, the first garbage collections
;;; of the loaded code) is paid here, not by every cold bin/ames run. Its bridge and Maxima
;;; process are discarded, so the image keeps no state of the run (each run starts from a
;;; reset bridge anyway, see RUN-SCENARIO). A warm-up that fails is only reported.
(let ((scenario (merge-pathnames "../scenarios/particle-on-wedge.lisp" *load-truename*)))
  (when (probe-file scenario)
    (let ((bridge (ames.maxima:make-bridge)))
      (handler-case
          (let ((ames.simulator:*bridge* bridge))
            (ames::run-files (list scenario) :stream (make-broadcast-stream)))
        (error (condition) (format *error-output* "~&warm-up skipped: ~A~%" condition)))
      (ames.maxima:close-bridge bridge)
      (setf ames.maxima::*assumption-key-memo* nil))))

(let ((output (car (last sb-ext:*posix-argv*))))
  (sb-ext:save-lisp-and-die output
                            :executable t
                            :save-runtime-options t
                            :toplevel (lambda ()
                                        (uiop:symbol-call :ames :main
                                                          (rest sb-ext:*posix-argv*)))))
