;;;; t/scenario-fuzz.lisp -- fuzzing the scenario validator and reader with mutated scenarios.
;;;;
;;;; The valid scenarios of scenarios/ (and the REPL wedge) are mutated, with a fixed
;;;; random seed, in ways that always make them malformed (a bad atom anywhere, a
;;;; required property dropped, a clause duplicated, garbled or wrapped, the parameters
;;;; dropped, deep, huge, dotted or circular structure, an odd keyword list). Each such
;;;; form must end in an AMES-ERROR whose datum is non-nil and whose report prints, both
;;;; given as a form and printed and read back from text. Wilder mutations (numbers,
;;;; floats, symbols, swaps, drops anywhere, garbled text) may happen to stay valid;
;;;; they must end in a SCENARIO or an AMES-ERROR, nothing else. The bounds on form
;;;; size make a hang impossible; a generous timeout turns one into a failure anyway.

(in-package #:ames.tests)

(in-suite scenario)

(defun fuzz-seed-forms ()
  "The valid scenario forms that mutations start from."
  (cons *wedge-form*
        (loop for file in (scenario-files)
              append (ames:read-scenario-forms (uiop:read-file-string file)))))

(defun random-element (list state)
  "An element of the non-empty LIST, chosen with the random STATE."
  (nth (random (length list) state) list))

(defun element-paths (tree)
  "The path (a list of indices) of every element of every proper list in TREE."
  (let ((paths '()))
    (labels ((walk (x path)
               (when (and (consp x) (alexandria:proper-list-p x))
                 (loop for element in x
                       for i from 0
                       do (push (append path (list i)) paths)
                          (walk element (append path (list i)))))))
      (walk tree '()))
    (nreverse paths)))

(defun replace-at (tree path new)
  "A copy of TREE with the element at PATH replaced by NEW."
  (if (null path)
      new
      (loop for element in tree
            for i from 0
            collect (if (= i (first path)) (replace-at element (rest path) new) element))))

(defun edit-list-at (tree path function)
  "A copy of TREE where the list holding the element at PATH is replaced by the result
of FUNCTION on that list and the element's index."
  (if (null (rest path))
      (funcall function tree (first path))
      (loop for element in tree
            for i from 0
            collect (if (= i (first path)) (edit-list-at element (rest path) function) element))))

(defun nested (depth atom)
  "ATOM inside DEPTH lists."
  (let ((x atom)) (dotimes (i depth x) (setf x (list x)))))

(defun circular-list-of (&rest elements)
  "A circular list of ELEMENTS."
  (let ((list (copy-list elements)))
    (setf (cdr (last list)) list)
    list))

(defun bad-atoms ()
  "Values that are wrong wherever they stand in a scenario (bar the description slot)."
  (list #c(1 2) (vector 1 2) #\x :zork nil "a string" (nested 150 'h) '(1 . 2)
        sb-ext:double-float-positive-infinity sb-ext:single-float-negative-infinity
        (circular-list-of 'g 1)))

(defun clause-indices (form word)
  "The indices in FORM of its clauses headed by WORD (compared by name)."
  (loop for clause in form
        for i from 0
        when (and (consp clause) (symbolp (car clause)) (string= (car clause) word))
          collect i))

(defun moving-body-indices (form)
  "The indices in FORM of its clauses declaring a body that is neither fixed nor driven
(each of :mass, :position, :velocity and :shape is required of it: a driven body has no
mass and its position defaults)."
  (remove-if (lambda (i) (or (member :fixed (nth i form)) (member :driven (nth i form))))
             (clause-indices form "BODY")))

(defun malformed-mutation (form state)
  "A mutation of the valid scenario FORM that is malformed whatever the dice say, and
its kind."
  (let ((kind (random-element '(:bad-atom :bad-atom :bad-atom :drop-required
                                :duplicate-clause :garble-head :wrap :drop-parameters
                                :odd-keywords :huge)
                              state)))
    (values
     (ecase kind
       (:bad-atom
        (let ((path (random-element (remove '(2) (element-paths form) :test #'equal) state)))
          (replace-at form path (random-element (bad-atoms) state))))
       (:drop-required
        (let* ((i (random-element (moving-body-indices form) state))
               (key (random-element '(:mass :position :velocity :shape) state))
               (arguments (copy-list (cddr (nth i form)))))
          (remf arguments key)
          (replace-at form (list i) (list* (first (nth i form)) (second (nth i form)) arguments))))
       (:duplicate-clause
        (let ((i (random-element (append (clause-indices form "GRAVITY")
                                         (clause-indices form "SIMULATE")
                                         (clause-indices form "BODY")
                                         (clause-indices form "PARAMETERS"))
                                 state)))
          (append form (list (nth i form)))))
       (:garble-head
        (let ((i (random-element (cons 0 (loop for i from 3 below (length form) collect i)) state)))
          (replace-at form (if (zerop i) (list 0) (list i 0))
                      (random-element '(frob bodies paramter gravityy simulation 7 "body"
                                        (body) :body)
                                      state))))
       (:wrap
        (if (zerop (random 2 state))
            (list form)
            (let ((i (+ 3 (random (- (length form) 3) state))))
              (replace-at form (list i) (list (nth i form))))))
       (:drop-parameters
        ;; a scenario written in numbers has no parameters to drop: wrapped instead (no
        ;; draw of the dice, so the other forms' mutations stay as they were)
        (if (clause-indices form "PARAMETERS")
            (remove-if (lambda (clause)
                         (and (consp clause) (symbolp (car clause)) (string= (car clause) "PARAMETERS")))
                       form)
            (list form)))
       (:odd-keywords
        (let* ((i (random-element (clause-indices form "BODY") state))
               (clause (nth i form))
               (j (+ 2 (random (- (length clause) 2) state))))
          (replace-at form (list i) (append (subseq clause 0 j) (subseq clause (1+ j))))))
       (:huge
        (let ((path (random-element (remove '(2) (element-paths form) :test #'equal) state)))
          (replace-at form path (make-list 120000 :initial-element 1)))))
     kind)))

(defun wild-mutation (form state)
  "A random mutation of FORM that may or may not leave it valid."
  (let* ((paths (element-paths form))
         (path (random-element paths state))
         (atoms (list 0 1 -1 1/3 1.5 -0.0d0 1d300 (expt 10 400) (- (expt 2 200)) 'g 'h 'pi 'sin
                      '+ 't 'ames-scenario::particle 'ames-scenario::m :positive :fixed
                      '(/ 1 0) '(sin) '(expt 10 (expt 10 10)) '(sqrt -1) '(+ 1 2)
                      '(polygon (0 0) (1 0) (0 1)) '(circle 1) 'point '(0 0) '())))
    (ecase (random 4 state)
      (0 (replace-at form path (random-element atoms state)))
      (1 (edit-list-at form path (lambda (list i) (append (subseq list 0 i) (subseq list (1+ i))))))
      (2 (edit-list-at form path (lambda (list i)
                                   (append (subseq list 0 i) (list (nth i list)) (subseq list i)))))
      (3 (let ((other (random-element paths state)))
           (flet ((prefix-p (a b) (and (<= (length a) (length b)) (equal a (subseq b 0 (length a))))))
             (if (or (prefix-p path other) (prefix-p other path))
                 form
                 (replace-at (replace-at form path (elt-at form other)) other (elt-at form path)))))))))

(defun elt-at (tree path)
  "The element of TREE at PATH."
  (if (null path) tree (elt-at (nth (first path) tree) (rest path))))

(defun garbled-text (text state)
  "TEXT with a few characters inserted, deleted or changed at random."
  (let ((characters (coerce text 'list))
        (alphabet "()#:'`,\"|;\\. x1e@"))
    (dotimes (i (1+ (random 4 state)) (coerce characters 'string))
      (let ((at (random (max 1 (length characters)) state))
            (new (char alphabet (random (length alphabet) state))))
        (setf characters
              (ecase (random 3 state)
                (0 (append (subseq characters 0 at) (list new) (nthcdr at characters)))
                (1 (append (subseq characters 0 at) (nthcdr (1+ at) characters)))
                (2 (append (subseq characters 0 at) (list new) (nthcdr (1+ at) characters)))))))))

(defun printed-form (form)
  "FORM printed as a scenario file would hold it."
  (with-standard-io-syntax
    (let ((*package* (find-package '#:ames-scenario)) (*print-circle* t)
          (*print-readably* nil))
      (prin1-to-string form))))

(defun proper-ames-error-p (condition)
  "True when CONDITION is an AMES-ERROR with a datum and a report that prints."
  (and (typep condition 'ames-error)
       (ames-error-datum condition)
       (plusp (length (princ-to-string condition)))))

(defun validation-outcome (form)
  "What validating FORM gives: a SCENARIO or an AMES-ERROR."
  (handler-case (ames:parse-scenario form)
    (ames-error (condition) condition)))

(defun call-with-time-limit (seconds thunk)
  "Call THUNK; fail the current test if it runs longer than SECONDS."
  (handler-case (sb-ext:with-timeout seconds (funcall thunk))
    (sb-ext:timeout () (fail "the fuzz run did not end within ~D seconds (a hang)" seconds))))

(test fuzz-malformed-forms-end-in-ames-errors
  (call-with-time-limit
   120
   (lambda ()
     (let ((state (sb-ext:seed-random-state 20261121))
           (seeds (fuzz-seed-forms))
           (rejected 0) (failures '()) (kinds '()))
       (dotimes (i 1400)
         (multiple-value-bind (mutant kind) (malformed-mutation (random-element seeds state) state)
           (pushnew kind kinds)
           (let ((outcome (validation-outcome mutant)))
             (if (proper-ames-error-p outcome)
                 (incf rejected)
                 (push (list kind mutant outcome) failures)))
           ;; the same form as a file holds it, except the huge ones (slow to print)
           (unless (or (eq kind :huge) (/= 0 (mod i 3)))
             (multiple-value-bind (scenarios conditions)
                 (ames:read-scenarios-from-string (printed-form mutant) :on-error :collect)
               (unless (and (null scenarios) conditions
                            (every #'proper-ames-error-p conditions))
                 (push (list kind :text mutant scenarios conditions) failures))))))
       (is (>= rejected 1000))
       (is (= 8 (length kinds)) "mutation kinds tried: ~S" kinds)
       (is (null failures) "~D malformed forms were not rejected properly, e.g.~%~{~S~%~}"
           (length failures) (subseq failures 0 (min 3 (length failures))))))))

(test fuzz-wild-mutations-end-in-a-scenario-or-an-ames-error
  (call-with-time-limit
   120
   (lambda ()
     (let ((state (sb-ext:seed-random-state 19940601))
           (seeds (fuzz-seed-forms))
           (outcomes (list :valid 0 :rejected 0)) (failures '()))
       (dotimes (i 1000)
         (let* ((mutant (let ((form (random-element seeds state)))
                          (dotimes (j (1+ (random 3 state)) form)
                            (setf form (wild-mutation form state)))))
                (outcome (validation-outcome mutant)))
           (cond ((ames:scenario-p outcome) (incf (getf outcomes :valid)))
                 ((proper-ames-error-p outcome) (incf (getf outcomes :rejected)))
                 (t (push (list mutant outcome) failures)))))
       (is (plusp (getf outcomes :rejected)))
       (is (null failures) "~D wild mutants misbehaved, e.g. ~S" (length failures)
           (first failures))))))

(test fuzz-garbled-scenario-text
  (call-with-time-limit
   120
   (lambda ()
     (let ((state (sb-ext:seed-random-state 8642476))
           (texts (mapcar #'uiop:read-file-string (scenario-files)))
           (failures '()) (conditions-seen 0))
       (dotimes (i 400)
         (let ((text (garbled-text (random-element texts state) state)))
           (multiple-value-bind (scenarios conditions)
               (ames:read-scenarios-from-string text :on-error :collect)
             (incf conditions-seen (length conditions))
             (unless (and (every #'ames:scenario-p scenarios)
                          (every #'proper-ames-error-p conditions))
               (push text failures)))))
       (is (plusp conditions-seen))
       (is (null failures) "~D garbled texts misbehaved, e.g.~%~A" (length failures)
           (first failures))))))
