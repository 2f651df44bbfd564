;;;; src/maxima-bridge/compiled-server.lisp -- the request server compiled by GCL once,
;;;; loaded compiled by every Maxima the bridge starts.
;;;;
;;;; Maxima loads the request server (maxima-server.lisp and the functions it loads,
;;;; maxima-server-functions.lisp) as source: GCL interprets it. Interpreted, the server's
;;;; own Lisp is slow: checking, presorting and answering one request of a chain of 64
;;;; blocks took 0.2 s, most of it in the server's code rather than Maxima's. Compiled by
;;;; GCL (compile-file: C through gcc, 3 s, once per change of the sources, when bin/ames
;;;; builds its image) the same requests cost a third. The compiled files live in
;;;; build/gcl/; the bridge loads them only while they are newer than both sources, and
;;;; the sources otherwise (tests run from the sources, a machine without gcc): the same
;;;; code either way.

(in-package #:ames.maxima)

(defparameter *compiled-server-directory*
  (asdf:system-relative-pathname "ames" "build/gcl/")
  "Where COMPILE-SERVER-FILES writes the compiled request server.")

(defun server-sources ()
  "The source files of the request server: the server and the functions it loads."
  (list *server-file* (merge-pathnames "maxima-server-functions.lisp" *server-file*)))

(defun compiled-server-file (&optional (directory *compiled-server-directory*))
  "The compiled request server in DIRECTORY when it and its compiled functions exist
and are newer than both sources; else NIL."
  (let ((server (merge-pathnames "maxima-server.o" directory))
        (functions (merge-pathnames "maxima-server-functions.o" directory)))
    (flet ((date (file) (and (probe-file file) (file-write-date file))))
      (let ((newest-source (reduce #'max (mapcar (lambda (file) (or (date file) 0))
                                                 (server-sources))))
            (compiled (list (date server) (date functions))))
        (when (and (every #'identity compiled)
                   (every (lambda (date) (> date newest-source)) compiled))
          server)))))

(defun server-file-to-load ()
  "The file a new Maxima loads (with -p): the compiled server when it is up to date
(COMPILED-SERVER-FILE), else the source, *SERVER-FILE*."
  (or (ignore-errors (compiled-server-file)) *server-file*))

(defun compile-server-files (&key (directory *compiled-server-directory*) (program "maxima"))
  "Compile the request server's two source files with Maxima's GCL into DIRECTORY
(compiled in a scratch directory beside it, then renamed into place, so that a Maxima
starting meanwhile loads either the old files or the new). Returns true when both
compiled files are in place and up to date; NIL, with the compiled files removed, when
GCL could not compile them (no gcc): the bridge then loads the sources."
  (let* ((directory (uiop:ensure-directory-pathname directory))
         (scratch (uiop:ensure-directory-pathname
                   (merge-pathnames (format nil "tmp-~D/" (random (expt 2 40) (make-random-state t)))
                                    directory)))
         (names '("maxima-server-functions" "maxima-server"))
         (script (merge-pathnames "compile.lisp" scratch)))
    (ensure-directories-exist scratch)
    (unwind-protect
         (progn
           (dolist (name names)
             (uiop:copy-file (merge-pathnames (format nil "~A.lisp" name) *server-file*)
                             (merge-pathnames (format nil "~A.lisp" name) scratch)))
           (with-open-file (out script :direction :output :if-exists :supersede)
             (with-standard-io-syntax
               (let ((*print-readably* nil))
                 (format out "(in-package :maxima)~%")
                 (dolist (name names)
                   (format out "(compile-file ~S)~%"
                           (namestring (merge-pathnames (format nil "~A.lisp" name) scratch))))
                 (format out "(si::bye 0)~%"))))
           (uiop:run-program (list program "--very-quiet" "--init=ames-bridge-no-init"
                                   "-p" (namestring script))
                             :input nil :output nil :error-output nil :ignore-error-status t)
           (dolist (name names)
             (let ((compiled (merge-pathnames (format nil "~A.o" name) scratch))
                   (target (merge-pathnames (format nil "~A.o" name) directory)))
               (if (probe-file compiled)
                   (rename-file compiled target)
                   (when (probe-file target) (delete-file target)))))
           (and (compiled-server-file directory) t))
      (uiop:delete-directory-tree scratch :validate t :if-does-not-exist :ignore))))
