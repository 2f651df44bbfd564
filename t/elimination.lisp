;;;; t/elimination.lisp -- the one-pass elimination of a model's definitions
;;;; (src/simulator/elimination.lisp) gives what substituting one definition at a time gives.
;;;;
;;;; The specification is the plain algorithm: take the first equation (in order) that,
;;;; as it reads now, is (= TERM EXPR) or (= EXPR TERM) with TERM an unknown not in EXPR;
;;;; substitute EXPR for TERM in every other equation; repeat. ELIMINATE-DEFINITIONS
;;;; decides on sets of unknowns and writes each equation once: its definitions (order,
;;;; terms, expressions) and remaining equations must be EQUAL to the plain algorithm's,
;;;; on random systems (chains of definitions, terms defined by terms, definitions that
;;;; appear only once another is substituted, zeros folded) and on a chain of blocks; and
;;;; its allocation must stay proportional to what it returns.

(in-package #:ames.tests)

(def-suite elimination :in all-tests
  :description "Definitions eliminated in one pass, as one at a time.")

(in-suite elimination)

(defun plain-elimination (equations unknowns)
  "The specification of ELIMINATE-DEFINITIONS, one definition at a time: (values the
remaining equations, zeros folded, X = X dropped; the definitions in order)."
  (let ((remaining (coerce equations 'vector))
        (gone (make-array (length equations) :initial-element nil))
        (live (copy-list unknowns))
        (definitions '()))
    (flet ((definition (equation)
             (flet ((try (term expression)
                      (when (and (ames.base:quantity-term-p term)
                                 (member term live :test #'equal)
                                 (ames.base:free-of-p term expression))
                        (return-from definition (values term expression)))))
               (try (second equation) (third equation))
               (try (third equation) (second equation))
               nil)))
      (loop
        (let ((index (position-if (lambda (i) (and (not (aref gone i)) (definition (aref remaining i))))
                                  (alexandria:iota (length remaining)))))
          (unless index (return))
          (multiple-value-bind (term expression) (definition (aref remaining index))
            (setf (aref gone index) t
                  live (remove term live :test #'equal))
            (push (cons term expression) definitions)
            (dotimes (i (length remaining))
              (unless (aref gone i)
                (setf (aref remaining i)
                      (ames.base:substitute-expressions (list (cons term expression))
                                                        (aref remaining i)))))))))
    (values (remove-if (lambda (e) (equal (second e) (third e)))
                       (loop for i below (length remaining)
                             unless (aref gone i)
                               collect (ames.simulator::fold-zeros (aref remaining i))))
            (nreverse definitions))))

(defun random-elimination-system (state)
  "A random system drawn with the random STATE: (values EQUATIONS UNKNOWNS). Unknowns
(u 1) ... (u 7); (x 1) a state term and a, b parameters that are never eliminated;
expressions of depth up to 3 with zeros; most equations define a term (on either side,
sometimes by another term or by an expression holding the term itself)."
  (let* ((unknowns (loop for k from 1 to 7 collect (list 'u k)))
         (atoms (append unknowns '((x 1) a b 0 1 2))))
    (labels ((pick (list) (nth (random (length list) state) list))
             (expression (depth)
               (if (or (zerop depth) (zerop (random 3 state)))
                   (pick atoms)
                   (list* (pick '(+ - *))
                          (expression (1- depth))
                          (loop repeat (random 3 state) collect (expression (1- depth))))))
             (equation ()
               (let ((term (pick unknowns))
                     (other (case (random 4 state)
                              (0 (pick unknowns))
                              (t (expression 3)))))
                 (if (zerop (random 3 state))
                     (list '= other term)
                     (list '= term other)))))
      (values (loop repeat (+ 2 (random 9 state)) collect (equation))
              unknowns))))

(test elimination-is-substitution-one-definition-at-a-time
  (let ((state (sb-ext:seed-random-state 2411))
        (defining 0))
    (dotimes (trial 400)
      (multiple-value-bind (equations unknowns) (random-elimination-system state)
        (multiple-value-bind (compact definitions)
            (ames.simulator::eliminate-definitions equations unknowns)
          (multiple-value-bind (expected-compact expected-definitions)
              (plain-elimination equations unknowns)
            (when (rest definitions) (incf defining))
            (is (equal expected-definitions definitions)
                "definitions of ~S:~% ~S~% expected ~S" equations definitions expected-definitions)
            (is (equal expected-compact compact)
                "equations left of ~S:~% ~S~% expected ~S" equations compact expected-compact)))))
    ;; the draw exercises chains of definitions, not only single ones
    (is (> defining 200))))

(defun block-chain-system (n &key (at-rest t))
  "The equations of a chain of N blocks as the knowledge base writes them: each block's
acceleration its relative acceleration to the next plus the next's (the last's 0), and
Newton's law with the contact forces on both sides; AT-REST, each relative acceleration
0. (values EQUATIONS UNKNOWNS)."
  (let ((equations '()) (unknowns '()))
    (loop for k from 1 to n
          do (push `(= (acc ,k) (+ (rel-acc ,k) (acc ,(1+ k)))) equations)
             (push `(= (* (m ,k) (acc ,k)) (- (force ,k) (force ,(1+ k)))) equations)
             (when at-rest (push `(= (rel-acc ,k) 0) equations))
             (setf unknowns (list* `(acc ,k) `(rel-acc ,k) `(force ,k) unknowns)))
    (push `(= (acc ,(1+ n)) 0) equations)
    (values (nreverse equations) (cons `(acc ,(1+ n)) unknowns))))

(test elimination-of-a-block-chain
  ;; a chain of 60 blocks at rest: every acceleration and relative acceleration is
  ;; defined (the chain of definitions acc k = rel-acc k + acc k+1); what remains is
  ;; Newton's law of each block, m_k * (0 + 0 + ... + 0) = force_k - force_k+1, and
  ;; back-substituted every acceleration is 0
  (multiple-value-bind (equations unknowns) (block-chain-system 60)
    (multiple-value-bind (compact definitions)
        (ames.simulator::eliminate-definitions equations unknowns)
      (multiple-value-bind (expected-compact expected-definitions)
          (plain-elimination equations unknowns)
        (is (equal expected-definitions definitions))
        (is (equal expected-compact compact)))
      (is (= 60 (length compact)))
      (is (every (lambda (e) (eql 0 (second e))) compact))
      (let ((values (ames.simulator::back-substitute '() definitions)))
        (is (every (lambda (k)
                     (eql 0 (ames.simulator::fold-zeros
                             (cdr (assoc `(acc ,k) values :test #'equal)))))
                   (alexandria:iota 61 :start 1)))))))

(defun cons-count (tree)
  "The number of conses of TREE."
  (if (consp tree) (+ 1 (cons-count (car tree)) (cons-count (cdr tree))) 0))

(test elimination-allocates-in-proportion-to-its-result
  ;; substituting one definition at a time rewrites block k's law once per definition of
  ;; the chain after it: N^3 conses for the N^2 of the result (about 85 times the
  ;; result's size at N = 200); written once, a few times the result's size
  (multiple-value-bind (equations unknowns) (block-chain-system 200 :at-rest nil)
    (let* ((before (sb-ext:get-bytes-consed))
           (compact (ames.simulator::eliminate-definitions equations unknowns))
           (consed (- (sb-ext:get-bytes-consed) before))
           (result-bytes (* 16 (cons-count compact))))
      (is (< consed (* 12 result-bytes))
          "~D bytes allocated for a result of ~D" consed result-bytes))))
