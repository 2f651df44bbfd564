;;;; src/scenario/input.lisp -- the bytes of a scenario file, whatever the file is: a plain file,
;;;; a pipe, a device, a named pipe, the standard input ("-").
;;;;
;;;; The bytes are read to their end, never by the file's length (a pipe's and a device's is
;;;; 0), and no further than the limit of scenario text (+LARGEST-FILE+ characters, at most
;;;; 4 bytes each): a longer input (a 50 MB file, /dev/zero) is refused with a message that
;;;; names that limit. Reading waits for data no longer than the time left in the budget
;;;; of the run (a named pipe without a writer, a terminal nobody types on), so that
;;;; --time-limit holds; outside a budget it waits as long as it takes.

(in-package #:ames.scenario)

(defconstant +largest-file+ (* 4 1024 1024)
  "The largest scenario text accepted, in characters.")

(defconstant +largest-input-octets+ (* 4 +largest-file+)
  "The most bytes a scenario file may hold: +LARGEST-FILE+ characters of UTF-8.")

(defconstant +o-nonblock+ #o4000
  "Linux's O_NONBLOCK (SB-UNIX has no name for it): open a named pipe without waiting for
its writer.")

(define-condition input-failure (error)
  ((detail :initarg :detail :reader input-failure-detail))
  (:documentation "Internal: the input could not be read; DETAIL says why.")
  (:report (lambda (condition stream) (write-string (input-failure-detail condition) stream))))

(defun input-fail (control &rest arguments)
  "Signal INPUT-FAILURE with the detail CONTROL applied to ARGUMENTS."
  (error 'input-failure :detail (apply #'format nil control arguments)))

(defun standard-input-name-p (name)
  "True when NAME (a string or pathname) is \"-\", the standard input."
  (equal (if (pathnamep name) (namestring name) name) "-"))

(defun open-input (pathname)
  "A file descriptor open for reading PATHNAME (\"-\": a duplicate of the standard
input), without waiting for a writer. Signals INPUT-FAILURE."
  (if (standard-input-name-p pathname)
      (or (sb-unix:unix-dup 0) (input-fail "cannot read the standard input"))
      (let ((native (sb-ext:native-namestring (merge-pathnames pathname))))
        (multiple-value-bind (fd errno)
            (sb-unix:unix-open native (logior sb-unix:o_rdonly +o-nonblock+) 0)
          (or fd (input-fail "cannot open the file: ~A" (sb-int:strerror errno)))))))

(defun wait-for-input (fd)
  "Wait until FD has something to read (data or its end), no longer than the time left
in the running budget. Signals INPUT-FAILURE when that time runs out."
  (let ((left (budget-time-left)))
    (when (and left (<= left 0))
      (input-fail "nothing came to read within the time limit"))
    (unless (sb-sys:wait-until-fd-usable fd :input left)
      (input-fail "nothing came to read within the time limit of ~A s~@[ (a named pipe with no writer?)~]"
                  (current-time-limit) t))))

(defun read-input-octets (pathname)
  "Every byte of PATHNAME (see this file's header) as an (unsigned-byte 8) vector.
Signals INPUT-FAILURE when it cannot be opened or read, when it holds more than
+LARGEST-INPUT-OCTETS+ bytes, or when nothing comes within the time left."
  (let ((fd (open-input pathname))
        (buffer (make-array 65536 :element-type '(unsigned-byte 8)))
        (octets (make-array 0 :element-type '(unsigned-byte 8) :adjustable t :fill-pointer 0)))
    (unwind-protect
         (loop
           (wait-for-input fd)
           (multiple-value-bind (count errno)
               (sb-sys:with-pinned-objects (buffer)
                 (sb-unix:unix-read fd (sb-sys:vector-sap buffer) (length buffer)))
             (cond ((null count)
                    (unless (member errno (list sb-unix:eagain sb-unix:eintr))
                      (input-fail "cannot read the file: ~A" (sb-int:strerror errno))))
                   ((zerop count) (return (coerce octets '(simple-array (unsigned-byte 8) (*)))))
                   ((> (+ count (fill-pointer octets)) +largest-input-octets+)
                    (input-fail "the input is longer than the limit of scenario text: ~:D characters (~:D bytes of UTF-8); split it into several files"
                                +largest-file+ +largest-input-octets+))
                   (t (loop for i below count do (vector-push-extend (aref buffer i) octets
                                                                     (max 65536 (fill-pointer octets))))))))
      (sb-unix:unix-close fd))))
