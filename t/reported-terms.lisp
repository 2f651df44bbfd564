;;;; t/reported-terms.lisp -- the kinds of energy and momentum terms are declared in the
;;;; knowledge base (src/kb/terms.lisp), and the report and the queries read what is
;;;; declared: a new kind, or a new term of a declared kind, needs no change outside src/kb/.

(in-package #:ames.tests)

(in-suite phenomena)

(defun reported-section-kinds (section)
  "The kinds of the terms the components of AMES's knowledge bases report in SECTION."
  (let ((found '()))
    (dolist (kb (ames.kb:knowledge-bases) found)
      (dolist (component (ames.engine:knowledge-base-components kb))
        (walk-forms (ames.engine:component-definition component)
                    (lambda (form)
                      (when (and (eq (first form) 'ames.kb:reported) (eq (second form) section)
                                 (consp (third form)) (keywordp (first (third form))))
                        (pushnew (first (third form)) found))))))))

(test every-reported-energy-and-momentum-term-is-declared
  "Each kind of term a component reports in :ENERGY or :MOMENTUM is declared, in that
section, with a label (so the report words it and the queries find it)."
  (dolist (section '(:energy :momentum))
    (let ((kinds (reported-section-kinds section)))
      (is-true kinds "no component reports in ~S" section)
      (dolist (kind kinds)
        (let ((term (find kind (ames.kb:reported-terms section) :key #'ames.kb:term-kind)))
          (is-true term "~S of ~S is not declared in src/kb/" kind section)
          (when term (is (plusp (length (ames.kb:term-label term))))))))))

(defun state-with-sections (sections)
  "A qualitative state holding only the reported SECTIONS (a plist)."
  (make-instance 'ames.simulator::qualitative-state :reported-sections sections))

(test a-bodys-terms-of-a-kind-add-up
  "A query declared for a kind of term sums the body's own entries of it: the kinetic
energy of a body adds its translation's term and any other of its motions' (a list
subject ending in the body); momentum adds by components; a fixed body's is zero."
  (let* ((state (state-with-sections
                 '(:energy ((:kinetic b (* 1/2 m (expt v 2)))
                            (:potential (:gravity b) (* m g y))
                            (:kinetic (:rotation b) (* 1/2 i (expt w 2)))
                            (:kinetic c (* 1/2 mc (expt u 2))))
                   :momentum ((:momentum b ((* m v) 0)) (:momentum c (0 (* mc u)))))))
         (kinetic (ames.kb:query-reported-term :kinetic-energy))
         (momentum (ames.kb:query-reported-term :momentum)))
    (is (eq :kinetic (ames.kb:term-kind kinetic)))
    (is (equal '(+ (* 1/2 m (expt v 2)) (* 1/2 i (expt w 2)))
               (ames.simulator::reported-body-term state kinetic 'b nil)))
    (is (equal '(* 1/2 mc (expt u 2)) (ames.simulator::reported-body-term state kinetic 'c nil)))
    (is (eql 0 (ames.simulator::reported-body-term state kinetic 'b t)))
    (is (null (ames.simulator::reported-body-term state kinetic 'd nil)))
    (is (equal '((* m v) 0) (ames.simulator::reported-body-term state momentum 'b nil)))
    (is (equal '(0 0) (ames.simulator::reported-body-term state momentum 'b t)))
    (is (null (ames.kb:query-reported-term :speed)))))

(test a-newly-declared-kind-is-listed-where-reported
  "A kind declared without :SHOWN :ALWAYS is listed by the report only in a state that
reports a term of it; the declared kinds shown always are listed everywhere; a query
declared for it is answered from the body's terms."
  (let ((saved ames.kb::*reported-terms*))
    (unwind-protect
         (progn
           (ames.kb:define-reported-term :test-spin :section :momentum :label "test spin"
                                         :query :test-spin)
           (let ((with '((:momentum b (p 0)) (:test-spin b l1) (:test-spin (:rotation b) l2)))
                 (without '((:momentum b (p 0)))))
             (is (equal '(:momentum :test-spin)
                        (mapcar #'ames.kb:term-kind (ames.report::shown-terms :momentum with))))
             (is (equal '(:momentum)
                        (mapcar #'ames.kb:term-kind (ames.report::shown-terms :momentum without))))
             (is (equal '(+ l1 l2)
                        (ames.simulator::reported-body-term
                         (state-with-sections (list :momentum with))
                         (ames.kb:query-reported-term :test-spin) 'b nil)))))
      (setf ames.kb::*reported-terms* saved))
    (is (null (ames.kb:query-reported-term :test-spin)))))
