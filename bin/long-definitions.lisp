;;;; bin/long-definitions.lisp -- the files of src/ over about 400 lines and the definitions
;;;; over about 60 (the project's rule), counted with the Lisp reader: each top-level DEFUN,
;;;; DEFMACRO, DEFMETHOD or DEFGENERIC from its first line to its last, docstring included.
;;;;
;;;;   sbcl --noinform --non-interactive --no-sysinit --no-userinit --load bin/long-definitions.lisp
;;;;
;;;; from the checkout's root. Loads the system (the sources' packages must exist to read
;;;; them); the Maxima server's files (GCL code of package MAXIMA) are not read. Prints the
;;;; longest first; a development aid, not a test.

(require :asdf)
(asdf:load-asd (truename "ames.asd"))
(asdf:load-system "ames")

(defparameter *longest-file* 400 "Files longer than this many lines are listed.")
(defparameter *longest-definition* 55 "Definitions longer than this many lines are listed.")

(defun line-at (text position)
  "The line number (from 1) of POSITION in TEXT."
  (1+ (count #\Newline text :end position)))

(defun definition-lengths (file)
  "((LINES NAME) ...) for each top-level definition of FILE, read with the packages its
IN-PACKAGE forms name (the sources are AMES's own, so #. is allowed, as when compiling)."
  (let ((text (uiop:read-file-string file))
        (*package* (find-package :cl-user))
        (*read-eval* t)
        (found '()))
    (with-input-from-string (in text)
      (loop
        (let* ((start (progn (peek-char t in nil) (file-position in)))
               (form (read in nil in)))
          (when (eq form in) (return found))
          (when (and (consp form) (eq (first form) 'in-package))
            (setf *package* (find-package (second form))))
          (when (and (consp form) (symbolp (first form))
                     (member (symbol-name (first form))
                             '("DEFUN" "DEFMACRO" "DEFMETHOD" "DEFGENERIC") :test #'string=))
            (push (list (1+ (- (line-at text (file-position in)) (line-at text start)))
                        (second form))
                  found)))))))

(let ((root (truename "src/"))
      (files '())
      (definitions '()))
  (dolist (file (directory "src/**/*.lisp"))
    (unless (search "maxima-server" (pathname-name file))
      (let* ((name (enough-namestring file root))
             (text (uiop:read-file-string file))
             (lines (count #\Newline text)))
        (when (> lines *longest-file*) (push (list lines name) files))
        (loop for (length definition) in (definition-lengths file)
              when (> length *longest-definition*)
                do (push (list length name definition) definitions)))))
  (format t "Files over ~D lines:~%" *longest-file*)
  (loop for (lines name) in (sort files #'> :key #'first)
        do (format t "~5D  ~A~%" lines name))
  (format t "Definitions over ~D lines:~%" *longest-definition*)
  (loop for (lines name definition) in (sort definitions #'> :key #'first)
        do (format t "~5D  ~A  ~(~A~)~%" lines name definition)))
