;;;; src/maxima-bridge/prefetch.lisp -- many requests (simplifications, the sign() questions of DECIDE) asked in few round trips, answered later from the cache.
;;;;
;;;; A caller that will simplify many independent expressions one at a time (the geometry
;;;; tidying every contact of every pair of bodies: N^2 of them in a chain of N blocks) pays
;;;; a round trip each, and on a loaded machine each round trip waits for both processes
;;;; to be scheduled. PREFETCH-SIMPLIFICATIONS asks the same requests SIMPLIFY :FULL would
;;;; send, many in one round trip, and stores each answer in the cache under the key the
;;;; single request has: SIMPLIFY then finds it there. The answers are the ones the single
;;;; requests would get (the same forms, evaluated in turn, each as a request is: see
;;;; ames_each in maxima-server-functions.lisp); a request Maxima fails on is left out of
;;;; the cache, and a batch that fails as a whole (a question, a timeout) is dropped: those
;;;; requests are then asked one at a time as without the prefetch, their conditions
;;;; signalled where they belong.

(in-package #:ames.maxima)

(defparameter *prefetch-batch-size* 48
  "The most requests PREFETCH-SIMPLIFICATIONS sends in one round trip.")

(defun uncached-simplification-requests (bridge expressions)
  "The (KEY . REQUEST) pairs of the :FULL simplification requests of EXPRESSIONS that
BRIDGE's cache does not hold yet, each once, in order. Atoms, numbers and untranslatable
expressions are left out."
  (let ((seen (make-hash-table :test #'equal))
        (cache (bridge-cache bridge))
        (pairs '()))
    (dolist (expression expressions (nreverse pairs))
      (unless (or (atom expression) (rationalp expression))
        (let ((form (handler-case (to-mx bridge expression :any)
                      (maxima-condition () nil))))
          (when (consp form)
            (let* ((request (simplest-form-request form))
                   (key (request-key bridge request)))
              (unless (or (gethash key seen) (nth-value 1 (gethash key cache)))
                (setf (gethash key seen) t)
                (push (cons key request) pairs)))))))))

(defun prefetch-simplifications (bridge expressions)
  "Ask BRIDGE's Maxima for the :FULL simplifications (see SIMPLIFY) of EXPRESSIONS that
it has not answered under the facts in force, up to *PREFETCH-BATCH-SIZE* in a round
trip, and cache each answer as its single request's. Returns nothing useful; a batch
that fails is dropped (see this file's header). Signals MAXIMA-BUDGET-EXCEEDED when the
run's time is up."
  (prefetch-pairs bridge (uncached-simplification-requests bridge expressions)))

(defun prefetch-pairs (bridge pairs)
  "Ask BRIDGE's Maxima the requests of PAIRS ((KEY . REQUEST) ..., none cached), up to
*PREFETCH-BATCH-SIZE* in a round trip, and cache each answer under its KEY. A batch
that fails is dropped (see this file's header). Returns nothing useful. Signals
MAXIMA-BUDGET-EXCEEDED when the run's time is up."
  (loop while pairs
        do (let* ((batch (subseq pairs 0 (min *prefetch-batch-size* (length pairs))))
                  (answers (handler-case
                               (mlist-items (maxima-request bridge (apply #'mcall "$AMES_EACH"
                                                                          (mapcar #'cdr batch))
                                                            :cache nil :datum :prefetch))
                             (maxima-budget-exceeded (condition) (error condition))
                             (maxima-condition () nil)))
                  (cache (bridge-cache bridge)))
             (setf pairs (nthcdr (length batch) pairs))
             (when (= (length answers) (length batch))
               (when (>= (+ (hash-table-count cache) (length batch)) *cache-limit*)
                 (clrhash cache))
               ;; each answer comes as [answer], or as [] when Maxima failed on it: that
               ;; request is asked alone later, and fails where it belongs
               (loop for (key) in batch
                     for answer in answers
                     for items = (and (mform-p answer +mlist+) (mlist-items answer))
                     when (and items (null (rest items)))
                       do (setf (gethash key cache) (first items))))))
  nil)

(defun prefetch-requests (bridge requests)
  "Ask BRIDGE's Maxima, in one round trip, those of the REQUESTS (Maxima forms, as
MAXIMA-REQUEST takes them) that its cache does not hold under the facts in force, each
once, and cache each answer as its single request's: a caller that will ask several
requests one after the other then finds them answered. Nothing is sent when at most one
request is missing (it would cost the round trip it saves). The answers are the ones the
single requests would get; a batch that fails is dropped (see this file's header), and
the single requests are then asked as without the prefetch. Signals
MAXIMA-BUDGET-EXCEEDED when the run's time is up."
  (let ((seen (make-hash-table :test #'equal))
        (cache (bridge-cache bridge))
        (pairs '()))
    (dolist (request requests)
      (let ((key (request-key bridge request)))
        (unless (or (gethash key seen) (nth-value 1 (gethash key cache))
                    (nth-value 1 (inherited-answer bridge request)))
          (setf (gethash key seen) t)
          (push (cons key request) pairs))))
    (when (rest pairs)
      (prefetch-pairs bridge (nreverse pairs)))
    nil))

(defun prefetch-solutions (bridge systems)
  "Ask BRIDGE's Maxima together the solve() requests SOLVE-EQUATIONS will send for each
of SYSTEMS, a list of (EQUATIONS . UNKNOWNS), translated in that order as SOLVE-EQUATIONS
translates them (so that the names Maxima sees are the ones it would see), and cache
each answer as its single request's (PREFETCH-REQUESTS): SOLVE-EQUATIONS then finds
them, and signals its conditions where it would. A system that does not translate is
left to SOLVE-EQUATIONS. Returns nothing useful."
  (prefetch-requests
   bridge
   (loop for (equations . unknowns) in systems
         for request = (handler-case
                           (let* ((equation-forms (mapcar (lambda (e) (equation-to-maxima bridge e))
                                                          equations))
                                  (unknown-forms (mapcar (lambda (u) (to-mx bridge u)) unknowns)))
                             (mcall "$SOLVE" (mlist equation-forms) (mlist unknown-forms)))
                         (error () nil))
         when request collect request)))
