;;;; src/maxima-bridge/maxima-server.lisp -- the request server that runs INSIDE Debian's Maxima (GCL).
;;;;
;;;; The AMES bridge starts `maxima --very-quiet -p <this file>`. Loading this file never
;;;; returns: it runs its own read loop on the pipe, so Maxima's own top level (and its
;;;; infix parser) never sees a byte the bridge sends. This file is GCL code, not part of the
;;;; SBCL system; ames.asd lists it as a static file, like maxima-server-functions.lisp, the
;;;; Maxima functions the bridge calls, which it loads.
;;;;
;;;; Protocol (one request per line, each preceded by an empty line, see below):
;;;;   (ID :HELLO NONCE)   answer ready; NONCE (an integer) becomes part of the frame markers
;;;;   (ID :EVAL FORM)     validate FORM, then evaluate it with MEVAL
;;;; Every reply is one frame:
;;;;   @AMES<nonce>@BEGIN <newline> (ID STATUS SECONDS . DATA) <newline> @AMES<nonce>@END
;;;; STATUS is :OK (DATA = (result)), :ERROR (DATA = (message)), :QUESTION (DATA = (parts...)),
;;;; :INTERRUPTED, :LISP-ERROR (DATA = (message)) or :REJECTED (DATA = (reason)). Results are
;;;; printed as Maxima's internal Lisp form, so the client never parses infix text. Output that
;;;; Maxima prints by itself (warnings) falls outside the frames and is ignored by the client.
;;;;
;;;; Safety: GCL's reader evaluates #.(...) even with *READ-EVAL* nil (measured), so a request
;;;; line is read only when every character is in AMES-REQUEST-LINE-P's small set (letters,
;;;; digits, blanks and ( ) $ % _ . : + -; no # | \ " ' ` , ;). FORM must then pass AMES-VALIDATE
;;;; before MEVAL sees it:
;;;; every operator and function is on a whitelist, every other symbol is a mangled AMES name
;;;; ($AMESV<letters>, $AMESX<letters> or $AMESCTX<letters>) or one of a few constants, and the only atoms are
;;;; integers and floats (no strings, no ratios, no vectors). The bridge builds requests itself
;;;; from its own translation, so this check is a second wall, not the first.
;;;;
;;;; Questions: Maxima asks (asksign, "Is n equal to -1?") through RETRIEVE, which is redefined
;;;; below to signal AMES-QUESTION; the request then ends with a :QUESTION reply instead of
;;;; reading the next request as an answer.
;;;;
;;;; Interrupts: SIGINT makes GCL signal "Console interrupt." as an ERROR in the running code;
;;;; it is reported as :INTERRUPTED and the loop goes on. A SIGINT that lands while the loop
;;;; waits in READ-LINE loses the next character read, which is why every request line is
;;;; preceded by an empty line.

(in-package :maxima)

(defvar *ames-frame-begin* "@AMES@BEGIN")
(defvar *ames-frame-end* "@AMES@END")

(defvar *ames-input* nil
  "The request pipe: /dev/stdin opened afresh (GCL reads it about twice as fast as
*TERMINAL-IO*).")

(defvar *ames-output* nil
  "The reply pipe: /dev/stdout opened afresh. Maxima's own printing still goes to
*STANDARD-OUTPUT*, outside the frames.")

(defvar *ames-readtable* (copy-readtable nil)
  "A standard readtable, whatever Maxima did to the current one.")

(defvar *ames-allowed-heads*
  '(;; the algebra
    mplus mtimes mexpt mquotient mminus rat mlist
    %sin %cos %tan %asin %acos %atan %sqrt %log mabs $atan2 %derivative
    %sinh %cosh %tanh %asinh %acosh %atanh
    %elliptic_f %elliptic_kc %elliptic_e %jacobi_sn %jacobi_cn %jacobi_dn %jacobi_am %gamma
    mequal mnotequal mlessp mgreaterp mleqp mgeqp mand mor mnot $equal $notequal
    ;; operations the bridge uses
    $ratsimp $trigsimp $trigreduce $trigexpand $radcan $expand $factor $factorsum $fullratsimp
    $solve $is $sign $assume $supcontext $killcontext $float $tex
    $ode2 $ic2 $integrate $diff $substitute $ratsubst $hipow $ratcoef $freeof $num $denom
    $realroots $nroots $rhs $lhs $realpart $imagpart
    $ilt $taylor $ratdisrep
    ;; helpers defined in this file
    $ames_pop_context $ames_polynomial_coefficients $ames_expression_size $ames_square_free_part
    $ames_simplification_candidates $ames_trigsimp)
  "The only heads (operators and functions) a request may contain.")

(defvar *ames-allowed-atoms* '(nil t $%pi $%e $all $initial)
  "The only symbols besides mangled AMES names that a request may contain.")

(defvar *ames-allowed-flags* '(simp ratsimp)
  "Flags that may follow a head in a request, e.g. ((MPLUS SIMP) ...).")

(defun ames-mangled-name-p (symbol)
  "True for the names the bridge generates: $AMESV<letters>, $AMESX<letters> and
$AMESCTX<letters>."
  (let ((name (symbol-name symbol)))
    (flet ((letters-after (prefix)
             (let ((n (length prefix)))
               (and (> (length name) n)
                    (string= prefix name :end2 n)
                    (every #'(lambda (c) (char<= #\A c #\Z)) (subseq name n))))))
      (and (eq (symbol-package symbol) (find-package :maxima))
           (or (letters-after "$AMESV") (letters-after "$AMESX") (letters-after "$AMESCTX"))))))

(defvar *ames-request-pattern* "^[A-Za-z0-9 ()$%_.:+-]*$"
  "The request alphabet, as a regular expression GCL matches in C (SI::STRING-MATCH): far
faster than a predicate called per character by GCL's interpreter.")

(defun ames-request-line-p (line)
  "True when every character of LINE is in the request alphabet. (The C matcher stops at
a NUL character, so NUL is looked for separately.)"
  (and (eql 0 (si::string-match *ames-request-pattern* line))
       (not (find (code-char 0) line))))

(defun ames-validate (form)
  "Return NIL when FORM is acceptable, else a string saying what was rejected."
  (cond ((integerp form) nil)
        ((floatp form) nil)
        ((symbolp form)
         (if (or (member form *ames-allowed-atoms*) (ames-mangled-name-p form))
             nil
             (format nil "symbol ~S is not allowed" form)))
        ((not (consp form)) (format nil "atom ~S is not allowed" form))
        ((not (and (consp (car form)) (symbolp (caar form))))
         (format nil "~S is not an operator form" form))
        ((not (member (caar form) *ames-allowed-heads*))
         (format nil "operator ~S is not allowed" (caar form)))
        ((not (and (null (cdr (last (car form))))
                   (every #'(lambda (flag) (member flag *ames-allowed-flags*)) (cdar form))))
         (format nil "flags ~S are not allowed" (car form)))
        ((not (null (cdr (last form)))) "an improper list is not allowed")
        (t (dolist (argument (cdr form) nil)
             (let ((complaint (ames-validate argument)))
               (when complaint (return complaint)))))))

;;; Questions become replies.

(define-condition ames-question (condition)
  ((message :initarg :message :reader ames-question-message))
  (:documentation "Maxima tried to ask a question (asksign and friends)."))

(defun retrieve (msg flag)
  "Replaces Maxima's RETRIEVE: instead of reading an answer, report the question."
  (declare (ignore flag))
  (signal 'ames-question :message msg)
  ;; Unreachable under the server loop, which always handles AMES-QUESTION.
  (merror "AMES server: a question arose outside a request."))

(defun ames-question-parts (message)
  "The parts (strings and expressions) of a question MESSAGE."
  (cond ((stringp message) (list message))
        ((and (consp message) (consp (car message)) (eq (caar message) 'mtext))
         (copy-list (cdr message)))
        (t (list message))))

;;; The Maxima functions the bridge calls ($AMES_...), and the presentation's, live in
;;; their own file beside this one (GCL code too); loaded here, after the whitelist they
;;; extend and before the loop. Beside the compiled server (build/gcl/, see the bridge's
;;; compiled-server.lisp) it is compiled too.

(let ((compiled (merge-pathnames "maxima-server-functions.o" *load-truename*)))
  (load (if (probe-file compiled)
            compiled
            (merge-pathnames "maxima-server-functions.lisp" *load-truename*))))

;;; The loop.

(defun ames-now ()
  (if (fboundp 'si::gettimeofday)
      (si::gettimeofday)
      (/ (get-internal-real-time) (float internal-time-units-per-second 1d0))))

(defun ames-disrep (result)
  "RESULT with a top-level CRE form turned back into general form."
  (if (and (consp result) (consp (car result)) (eq (caar result) 'mrat))
      ($ratdisrep result)
      result))

(defun ames-evaluate (form)
  "Evaluate the validated FORM; return (STATUS . DATA)."
  (let* ((errcatch (cons bindlist loclist))
         (saved errcatch)
         (outcome :unfinished))
    (unwind-protect
         (progn
           (setq outcome
                 (catch 'macsyma-quit
                   (handler-case
                       (let (($errormsg nil) (*mdebug* nil))
                         (list :ok (ames-disrep (rat-error-to-merror (meval form)))))
                     (ames-question (c)
                       (list* :question (ames-question-parts (ames-question-message c))))
                     (maxima-$error ()
                       (list :error
                             (string-trim '(#\Newline #\Space)
                                          (with-output-to-string (*standard-output*)
                                            ($errormsg)))))
                     (error (c)
                       (let ((message (format nil "~A" c)))
                         (if (search "Console interrupt" message)
                             (list :interrupted)
                             (list :lisp-error message)))))))
           (unless (consp outcome)
             (setq outcome (list :error "Maxima aborted the computation."))))
      (unless (eq (car outcome) :ok)
        (errlfun1 saved)))
    outcome))

(defun ames-reply (id status seconds data)
  "Print one complete frame in a single write."
  (let ((text (let ((*print-pretty* nil) (*print-circle* nil) (*print-base* 10)
                    (*print-radix* nil) (*print-level* nil) (*print-length* nil)
                    (*package* (find-package :maxima)))
                (format nil "~%~A~%~S~%~A~%" *ames-frame-begin*
                        (list* id status seconds data) *ames-frame-end*))))
    (write-string text *ames-output*)
    (finish-output *ames-output*)))

(defun ames-read-request (line)
  "The request form on LINE, or :FORBIDDEN-CHARACTER when LINE leaves the alphabet."
  (if (not (ames-request-line-p line))
      :forbidden-character
      (let ((*read-eval* nil) (*readtable* *ames-readtable*)
            (*package* (find-package :maxima))
            (*read-default-float-format* 'double-float))
        (read-from-string line))))

(defun ames-answer (request)
  "The reply (STATUS . DATA) to the well-formed REQUEST (ID KIND . ARGUMENTS)."
  (case (cadr request)
    (:hello
     (let ((nonce (caddr request)))
       (cond ((not (integerp nonce)) (list :rejected "malformed hello"))
             (t (setq *ames-frame-begin* (format nil "@AMES~D@BEGIN" nonce)
                      *ames-frame-end* (format nil "@AMES~D@END" nonce))
                (list :ok (si::getpid))))))
    (:eval
     (let* ((form (caddr request))
            (complaint (if (cdddr request)
                           "a request carries exactly one form"
                           (ames-validate form))))
       (if complaint
           (list :rejected complaint)
           ;; sums of variables put in the order the simplifier inserts fastest
           ;; (maxima-server-functions.lisp): the same answer, sooner
           (ames-evaluate (ames-presort-sums form)))))
    (t (list :rejected "unknown request kind"))))

(defun ames-handle (line)
  "Handle one request LINE: read, validate, evaluate, reply."
  (let ((id nil) (start (ames-now)) (reply nil))
    (handler-case
        (let ((request (ames-read-request line)))
          (cond ((eq request :forbidden-character)
                 (setq reply (list :rejected "a character outside the request alphabet")))
                ((not (and (consp request) (integerp (car request)) (consp (cdr request))))
                 (setq reply (list :rejected "malformed request")))
                (t (setq id (car request)
                         reply (ames-answer request)))))
      (error (c)
        (let ((message (format nil "~A" c)))
          (setq reply (if (search "Console interrupt" message)
                          (list :interrupted)
                          (list :rejected (format nil "unreadable request: ~A" message)))))))
    (ames-reply id (car reply) (- (ames-now) start) (cdr reply))))

(defun ames-serve ()
  "Read requests from the pipe until end of input, then leave Maxima."
  (setq $display2d nil $ratprint nil $solvetrigwarn nil $programmode t
        $errormsg nil
        *ames-input* (open "/dev/stdin")
        *ames-output* (open "/dev/stdout" :direction :output :if-exists :append))
  (loop
    (let ((line (handler-case (read-line *ames-input* nil :eof)
                  (error () :interrupted))))
      (cond ((eq line :eof) (return))
            ((eq line :interrupted))
            ((string= (string-trim '(#\Space #\Tab #\Return) line) ""))
            (t (handler-case (ames-handle line)
                 (error () nil))))))
  (si::bye 0))

(ames-serve)
