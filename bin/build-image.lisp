;;;; bin/build-image.lisp -- saves the executable image that bin/ames runs.
;;;; Usage: sbcl --non-interactive --load bin/build-image.lisp OUTPUT-PATH

(require :asdf)
(asdf:load-asd (merge-pathnames "../ames.asd" *load-truename*))
(asdf:load-system "ames")
(let ((output (car (last sb-ext:*posix-argv*))))
  (sb-ext:save-lisp-and-die output
                            :executable t
                            :save-runtime-options t
                            :toplevel (lambda ()
                                        (uiop:symbol-call :ames :main
                                                          (rest sb-ext:*posix-argv*)))))
