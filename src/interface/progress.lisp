;;;; src/interface/progress.lisp -- what bin/ames says while it works: its version, and, on a
;;;; terminal, one line per state finished (a long run is not silent for a minute).

(in-package #:ames)

(defparameter *version*
  #.(let ((system (asdf:find-system "ames" nil)))
      (or (and system (asdf:component-version system)) "unknown"))
  "AMES's version, from ames.asd.")

(defun version-text ()
  "The line `ames --version` prints: AMES's version and the Lisp it runs on."
  (format nil "AMES ~A (the Algebraic MEchanics Simulator), ~A ~A"
          *version* (lisp-implementation-type) (lisp-implementation-version)))

(defun error-output-terminal-p ()
  "True when the standard error (file descriptor 2) is a terminal."
  (eql 1 (ignore-errors (sb-unix:unix-isatty 2))))

(defun report-progress (history state)
  "Write on the standard error one line saying that STATE of HISTORY's run has finished."
  (ignore-errors
   (format *error-output* "~&ames: ~A: state ~D finished~@[ (~A)~]~%"
           (visible-text (string-downcase (princ-to-string
                                           (scenario-name (history-scenario history)))))
           (state-index state)
           (let ((event (state-end-event state)))
             (cond ((null event) nil)
                   ((keywordp event) (string-downcase (substitute #\Space #\- (symbol-name event))))
                   ((and (consp event) (keywordp (first event)))
                    (string-downcase (substitute #\Space #\- (symbol-name (first event)))))
                   (t nil))))
   (finish-output *error-output*)))

(defun note-symbolic-parameters (scenario settings)
  "Under --numeric: say on the standard error which parameters of SCENARIO have neither a
(:value N) default nor a --set value in SETTINGS (an alist (NAME . NUMBER)), and so stay
symbolic in the report."
  (let ((bare (loop for parameter in (scenario-parameters scenario)
                    for name = (scenario-parameter-name parameter)
                    unless (or (scenario-parameter-value parameter)
                               (assoc (symbol-name name) settings
                                      :test (lambda (a b) (string-equal a (string b)))))
                      collect (string-downcase (symbol-name name)))))
    (when bare
      (format *error-output* "~&ames: note: ~A: --numeric, but ~{~A~^, ~} ~A no (:value N) default ~
                              and no --set value: ~A symbolic~%"
              (visible-text (string-downcase (princ-to-string (scenario-name scenario))))
              bare (if (rest bare) "have" "has") (if (rest bare) "they stay" "it stays")))))

(defun call-with-progress (thunk &key (progress (error-output-terminal-p)))
  "Call THUNK; when PROGRESS (by default, when the standard error is a terminal), with
a line on the standard error as each state finishes (REPORT-PROGRESS)."
  (let ((*state-hook* (if progress #'report-progress *state-hook*)))
    (funcall thunk)))
