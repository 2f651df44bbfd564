;;;; src/simulator/prefetch-values.lisp -- the simplified values a state will ask for, asked together.
;;;;
;;;; QUANTITY-VALUE simplifies a solved quantity's value fully (one round trip each, then
;;;; kept in the solved model). A state of N bodies asks it for the rates of 4 N state
;;;; variables and for every quantity its reports name: on a loaded machine each round
;;;; trip waits for both processes. PREFETCH-QUANTITY-VALUES asks the same
;;;; simplifications first, many in a round trip (AMES.MAXIMA:PREFETCH-SIMPLIFICATIONS),
;;;; so that QUANTITY-VALUE finds them in the bridge's cache: the same answers, fewer
;;;; round trips.

(in-package #:ames.simulator)

(defun rational-expression-p (expression)
  "True when EXPRESSION is built of numbers, variables and quantity terms with + - * /
and integer powers only: its full simplification is ratsimp's and factor's, quick. A
closed form with roots or angles (a corner's) may take long alone, and a batch that runs
into the request's timeout is asked again one by one: such values are not prefetched."
  (cond ((or (atom expression) (quantity-term-p expression)) t)
        ((member (first expression) '(+ - * /))
         (every #'rational-expression-p (rest expression)))
        ((eq (first expression) 'expt)
         (and (integerp (third expression)) (rational-expression-p (second expression))))
        (t nil)))

(defun prefetch-quantity-values (run solved terms)
  "Ask RUN's bridge together the full simplifications QUANTITY-VALUE will ask of SOLVED
for the quantity TERMS (those it has not kept, which SOLVED solves, state terms left
out, rational ones only: see RATIONAL-EXPRESSION-P). Returns nothing useful."
  (let ((values (make-hash-table :test #'equal))
        (seen (make-hash-table :test #'equal))
        (expressions '()))
    (loop for (term . value) in (solved-model-values solved)
          do (unless (nth-value 1 (gethash term values))
               (setf (gethash term values) value)))
    (dolist (term terms)
      (multiple-value-bind (value found) (gethash term values)
        (when (and found
                   (not (gethash term seen))
                   (not (nth-value 1 (gethash term (solved-model-simplified solved))))
                   (not (member term (solved-model-state solved) :test #'equal))
                   (rational-expression-p value))
          (setf (gethash term seen) t)
          (push value expressions))))
    (when expressions
      (ames.maxima:prefetch-simplifications (run-bridge run) (nreverse expressions)))))

(defun reported-quantity-terms (run)
  "The quantity terms of every entry RUN's model reports, each once, that
OVER-STATE-TERMS reads with QUANTITY-VALUE (not arc lengths, their rates, gaps or the
state's constants, which it writes otherwise)."
  (let ((terms '()))
    (labels ((walk (form)
               (cond ((quantity-term-p form)
                      (unless (or (member (first form) '(ames.kb:path-position ames.kb:path-speed
                                                         ames.kb:contact-gap))
                                  (state-constant-term-p form))
                        (push form terms)))
                     ((consp form) (mapc #'walk form)))))
      (loop for (nil entry) in (model-reported (run-model run))
            do (walk entry)))
    (remove-duplicates terms :test #'equal)))
