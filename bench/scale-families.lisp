;;;; bench/scale-families.lisp -- the scale families of issue 16 as scenario forms (data),
;;;; for any number N of bodies, and a writer of them to scenario files.
;;;;
;;;; Every family uses unit square blocks with symbolic masses m1 ... mN:
;;;;   chain      N blocks touching in a row on a floor, the first pushed by f into a wall:
;;;;              at rest forever; each contact force and the wall's reaction are f.
;;;;   stack      N blocks stacked on a floor at rest: the normal force under block k is
;;;;              g (mk + ... + mN).
;;;;   pull       a stack of N whose top block is pulled sideways by f: it slides off,
;;;;              falls to the floor and slides on; the rest of the stack stays at rest.
;;;;   drops      N blocks side by side, released from rest at heights 2, 4, ..., 2 N: block k
;;;;              lands on the floor after sqrt(4 k / g), in turn.
;;;;   plank      N blocks on a plank pulled from under them along the floor (numbers for
;;;;              g, f and the plank's mass so that the order of events is decided): each
;;;;              block leaves the plank's end and falls to the floor.
;;;; Loaded by bench/bench-scale.lisp; prints nothing.

(defpackage #:ames.bench.scale-families
  (:use #:cl)
  (:export #:family-scenario #:write-family-file #:+families+)
  (:documentation "Scenario forms of the scale families, for benchmarks."))

(in-package #:ames.bench.scale-families)

(defparameter +families+ '(:chain :stack :pull :drops :plank)
  "The scale families, in the order the bench runs them.")

(defun name (control &rest arguments)
  "The symbol (in this package, compared by name by AMES) written by CONTROL and ARGUMENTS."
  (intern (string-upcase (apply #'format nil control arguments)) '#:ames.bench.scale-families))

(defun unit-square ()
  "The shape of a unit square block, its reference point its lower left corner."
  '(polygon (0 0) (1 0) (1 1) (0 1)))

(defun block-clause (k x y &key (velocity '(0 0)))
  "The body clause of block K (mass mK) with its lower left corner at (X Y)."
  `(body ,(name "b~D" k) :mass ,(name "m~D" k) :position (,x ,y) :velocity ,velocity
         :shape ,(unit-square)))

(defun mass-parameters (n)
  "The parameter specs of the masses m1 ... mN."
  (loop for k from 1 to n collect `(,(name "m~D" k) :positive)))

(defun floor-clause ()
  "The floor y = 0, solid below."
  '(body floor :fixed t :shape (half-plane (1 0) (0 0))))

(defun chain (n)
  "N blocks in a row on the floor, the first pushed by f toward a wall against the last."
  `(scenario ,(name "chain-~D" n)
     "A chain of touching blocks on a floor pushed into a wall."
     (parameters ,@(mass-parameters n) (g :positive) (f :positive))
     (gravity g)
     ,(floor-clause)
     (body wall :fixed t :shape (half-plane (,n 1) (,n 0)))
     ,@(loop for k from 1 to n collect (block-clause k (1- k) 0))
     (force push :on b1 :value (f 0))
     (simulate :states 2)))

(defun stack-scenario (name description n &key pulled)
  "N blocks stacked on the floor; when PULLED, the top block is pulled sideways by f."
  `(scenario ,name ,description
     (parameters ,@(mass-parameters n) (g :positive) ,@(and pulled '((f :positive))))
     (gravity g)
     ,(floor-clause)
     ,@(loop for k from 1 to n collect (block-clause k 0 (1- k)))
     ,@(and pulled `((force pull :on ,(name "b~D" n) :value (f 0))))
     (simulate :states ,(if pulled 4 2))))

(defun stack (n)
  "N blocks stacked on the floor, at rest."
  (stack-scenario (name "stack-~D" n) "A stack of blocks at rest on a floor." n))

(defun pull (n)
  "A stack of N whose top block is pulled sideways by f."
  (stack-scenario (name "pull-~D" n) "A stack of blocks whose top block is pulled off sideways." n
                  :pulled t))

(defun drops (n)
  "N blocks side by side released at heights 2, 4, ..., 2 N above the floor."
  `(scenario ,(name "drops-~D" n)
     "Blocks released side by side at different heights land in turn."
     (parameters ,@(mass-parameters n) (g :positive))
     (gravity g)
     ,(floor-clause)
     ,@(loop for k from 1 to n collect (block-clause k (* 2 (1- k)) (* 2 k)))
     (simulate :states ,(+ n 2))))

(defun plank (n)
  "N blocks on a plank pulled from under them: g = 10, f = 1, the plank's mass 1."
  `(scenario ,(name "plank-~D" n)
     "Blocks fall off the end of a plank pulled from under them."
     (parameters ,@(mass-parameters n))
     (gravity 10)
     ,(floor-clause)
     (body plank :mass 1 :position (0 0) :velocity (0 0)
           :shape (polygon (0 0) (,(* 2 n) 0) (,(* 2 n) 1) (0 1)))
     ,@(loop for k from 1 to n collect (block-clause k (1- (* 2 k)) 1))
     (force pull :on plank :value (1 0))
     (simulate :states ,(+ (* 2 n) 2))))

(defun family-scenario (family n)
  "The scenario form of FAMILY (one of +FAMILIES+) with N blocks."
  (ecase family
    (:chain (chain n)) (:stack (stack n)) (:pull (pull n)) (:drops (drops n)) (:plank (plank n))))

(defun write-family-file (family n directory)
  "Write FAMILY's scenario with N blocks to DIRECTORY/FAMILY-N.lisp; return the pathname."
  (let ((path (merge-pathnames (format nil "~(~A~)-~D.lisp" family n) directory)))
    (ensure-directories-exist path)
    (with-open-file (stream path :direction :output :if-exists :supersede)
      (with-standard-io-syntax
        (let ((*package* (find-package '#:ames.bench.scale-families))
              (*print-case* :downcase)
              (*print-right-margin* 100))
          (format stream ";;;; ~(~A~) of ~D blocks, written by bench/scale-families.lisp~%" family n)
          (pprint (family-scenario family n) stream)
          (terpri stream))))
    path))
