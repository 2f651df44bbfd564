;;;; src/simulator/structure.lisp -- solving a compact model by its structure: the block
;;;; triangular decomposition of its equations.
;;;;
;;;; Each equation mentions a few unknowns. A perfect matching of equations to unknowns
;;;; (each equation paired with an unknown it mentions, every unknown used once) orders the
;;;; system: equation E needs the equation matched to each other unknown E mentions to be
;;;; solved first. The strongly connected components of that graph are the blocks (a
;;;; group of bodies that do not touch the others is one block or several; a chain of
;;;; pushes is a string of one-equation blocks), and Tarjan's algorithm yields them with
;;;; every block after those it needs. Solving block by block, each with the values found
;;;; so far substituted, gives the whole system's solutions: when every block has exactly
;;;; one, so has the whole system (for a linear one its determinant is the product of the
;;;; blocks'). Maxima then solves many small systems in place of one large one, and a
;;;; block whose equations did not change since an earlier state is answered from the
;;;; bridge's cache. Where the structure does not help (no perfect matching: a singular or
;;;; redundant model) or a block has no unique solution, the whole system is solved at
;;;; once, as before, so that the verdicts (none, several) are the whole system's.

(in-package #:ames.simulator)

(defun equation-unknown-indices (equations unknowns)
  "For each of EQUATIONS, the indices (in UNKNOWNS) of the unknowns it mentions: a vector
of lists."
  (let ((index (make-hash-table :test #'equal)))
    (loop for unknown in unknowns for i from 0 do (setf (gethash unknown index) i))
    (map 'vector (lambda (equation)
                   (remove-duplicates
                    (loop for term in (expression-variables equation)
                          for i = (gethash term index)
                          when i collect i)))
         equations)))

(defun perfect-matching (occurrences unknown-count)
  "A perfect matching of the equations (OCCURRENCES, as EQUATION-UNKNOWN-INDICES gives
them) to UNKNOWN-COUNT unknowns by augmenting paths: a vector unknown index -> equation
index, or NIL when there is none (the counts differ, or the model is structurally
singular)."
  (let* ((count (length occurrences))
         (owner (make-array unknown-count :initial-element nil)))
    (unless (= count unknown-count)
      (return-from perfect-matching nil))
    (dotimes (equation count owner)
      (let ((seen (make-array unknown-count :initial-element nil)))
        (labels ((augment (e)
                   (dolist (u (aref occurrences e) nil)
                     (unless (aref seen u)
                       (setf (aref seen u) t)
                       (when (or (null (aref owner u)) (augment (aref owner u)))
                         (setf (aref owner u) e)
                         (return t))))))
          (unless (augment equation)
            (return-from perfect-matching nil)))))))

(defun equation-blocks (occurrences owner)
  "The strongly connected components of the equations' dependency graph (equation E
needs the equation OWNER matches to each unknown E mentions), by Tarjan's algorithm:
a list of lists of equation indices, every block after the blocks it needs."
  (let* ((count (length occurrences))
         (numbers (make-array count :initial-element nil))
         (low (make-array count :initial-element 0))
         (on-stack (make-array count :initial-element nil))
         (stack '()) (next 0) (blocks '()))
    (labels ((visit (e)
               (setf (aref numbers e) next (aref low e) next)
               (incf next)
               (push e stack)
               (setf (aref on-stack e) t)
               (dolist (u (aref occurrences e))
                 (let ((needed (aref owner u)))
                   (cond ((null (aref numbers needed))
                          (visit needed)
                          (setf (aref low e) (min (aref low e) (aref low needed))))
                         ((aref on-stack needed)
                          (setf (aref low e) (min (aref low e) (aref numbers needed)))))))
               (when (= (aref low e) (aref numbers e))
                 (let ((block '()))
                   (loop for member = (pop stack)
                         do (setf (aref on-stack member) nil)
                            (push member block)
                         until (= member e))
                   (push (sort block #'<) blocks)))))
      (dotimes (e count)
        (unless (aref numbers e) (visit e))))
    (nreverse blocks)))

(defun block-dependencies (blocks occurrences owner)
  "For each of BLOCKS (EQUATION-BLOCKS' order), the positions in BLOCKS of the other
blocks it needs: a vector of lists."
  (let ((position-of (make-hash-table)))
    (loop for block in blocks for i from 0
          do (dolist (e block) (setf (gethash e position-of) i)))
    (coerce (loop for block in blocks for i from 0
                  collect (remove i (remove-duplicates
                                     (loop for e in block
                                           append (mapcar (lambda (u) (gethash (aref owner u) position-of))
                                                          (aref occurrences e))))))
            'vector)))

(defun independent-run-end (dependencies start)
  "The end (exclusive) of the longest run of blocks from START on, in order, none of
which needs another of the run: they can be solved together."
  (loop for end from (1+ start) below (length dependencies)
        unless (every (lambda (needed) (< needed start)) (aref dependencies end))
          return end
        finally (return (length dependencies))))

(defun solve-by-blocks (run equations unknowns)
  "Solve EQUATIONS for UNKNOWNS block by block (see the file header): the alist of the
unique solution, or NIL when the structure does not settle it (the caller then solves
the whole system). Also returns the number of blocks. The solve() requests of a run of
blocks none of which needs another are asked together first (one round trip, the same
requests in the same order: AMES.MAXIMA:PREFETCH-SOLUTIONS)."
  (let* ((occurrences (equation-unknown-indices equations unknowns))
         (owner (perfect-matching occurrences (length unknowns))))
    (when owner
      (let* ((blocks (equation-blocks occurrences owner))
             (dependencies (block-dependencies blocks occurrences owner))
             (unknown-vector (coerce unknowns 'vector))
             (equation-vector (coerce equations 'vector))
             ;; the values found so far, the first of a term winning (as ASSOC over them
             ;; in order would find it): no list search per node of each block's equations
             (table (make-hash-table :test #'equal))
             (prefetched 0))
        (flet ((block-system (block)
                 (cons (mapcar (lambda (e) (substitute-from-table table (aref equation-vector e)))
                               block)
                       (loop for u from 0 below (length owner)
                             when (member (aref owner u) block)
                               collect (aref unknown-vector u)))))
          (loop for block in blocks
                for i from 0
                do (when (>= i prefetched)
                     (setf prefetched (independent-run-end dependencies i))
                     (when (> (- prefetched i) 1)
                       (ames.maxima:prefetch-solutions
                        (run-bridge run)
                        (mapcar #'block-system (subseq blocks i prefetched)))))
                   (destructuring-bind (block-equations . block-unknowns) (block-system block)
                     (let ((solutions (handler-case (ames.maxima:solve-equations (run-bridge run)
                                                                                 block-equations block-unknowns)
                                        (ames.maxima:solve-failed () :failed))))
                       (unless (and (consp solutions) (null (rest solutions)))
                         (return-from solve-by-blocks nil))
                       (loop for (term . value) in (first solutions)
                             unless (nth-value 1 (gethash term table))
                               do (setf (gethash term table) value)))))
          (values (loop for unknown in unknowns
                        collect (multiple-value-bind (value found) (gethash unknown table)
                                  (and found (cons unknown value))))
                  (length blocks)))))))

;;; A system Maxima cannot solve for its radicals

(defun radical-kernels (expression)
  "The distinct subexpressions of EXPRESSION that are radicals, (sqrt X) or (expt X P)
with P a non-integer rational, outermost first."
  (let ((found '()))
    (labels ((walk (x)
               (cond ((quantity-term-p x))
                     ((and (consp x)
                           (or (eq (first x) 'sqrt)
                               (and (eq (first x) 'expt) (rationalp (third x))
                                    (not (integerp (third x))))))
                      (pushnew x found :test #'equal))
                     ((consp x) (mapc #'walk (rest x))))))
      (walk expression))
    (nreverse found)))

(defun solve-with-radicals-named (run equations unknowns)
  "The solution of EQUATIONS for UNKNOWNS solved with each radical free of the unknowns
replaced by a term of its own, (RADICAL-KERNEL K), put back into the values after; NIL
when there is no such radical to name."
  (let* ((kernels (remove-if (lambda (kernel)
                               (some (lambda (term) (member term unknowns :test #'equal))
                                     (expression-variables kernel)))
                             (radical-kernels (cons 'and equations))))
         (names (loop for kernel in kernels for k from 0
                      collect (cons kernel (list 'radical-kernel k)))))
    (when names
      (let ((solution (solve-whole run (mapcar (lambda (equation)
                                                 (ames.algebra:substitute-subexpressions
                                                  names equation))
                                               equations)
                                   unknowns))
            (back (mapcar (lambda (entry) (cons (cdr entry) (car entry))) names)))
        (mapcar (lambda (entry) (cons (car entry) (substitute-expressions back (cdr entry))))
                solution)))))
