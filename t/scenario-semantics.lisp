;;;; t/scenario-semantics.lisp -- tests of the scenario checks made through Maxima (src/scenario-semantics.lisp).

(in-package #:ames.tests)

(in-suite scenario)

(defun call-with-scenario-bridge (function)
  "Call FUNCTION with a fresh Maxima bridge, closed afterwards."
  (let ((bridge (ames.maxima:make-bridge)))
    (unwind-protect (funcall function bridge)
      (ames.maxima:close-bridge bridge))))

(defun semantic-condition (bridge form)
  "The AMES-ERROR that checking the valid scenario FORM through BRIDGE signals, or NIL."
  (let ((scenario (ames:parse-scenario form)))
    (handler-case (progn (ames:check-scenario-assumptions scenario bridge) nil)
      (ames-error (condition) condition))))

(defun one-body-scenario (parameters &rest body-arguments)
  "A scenario with PARAMETERS (specs) and one body B with BODY-ARGUMENTS."
  `(scenario s (parameters ,@parameters) (body b ,@body-arguments)))

(test scenario-files-pass-the-maxima-checks
  (call-with-scenario-bridge
   (lambda (bridge)
     (dolist (file (scenario-files))
       (let ((scenario (first (ames:read-scenario-file file))))
         (is (eq scenario (ames:check-scenario-assumptions scenario bridge))
             "~A failed the Maxima checks" (pathname-name file)))))))

(test maxima-finds-what-numbers-cannot
  (call-with-scenario-bridge
   (lambda (bridge)
     (flet ((check (type location form &optional datum)
              (let ((condition (semantic-condition bridge form)))
                (is (typep condition type) "~S gave ~A" form condition)
                (when condition
                  (is (equal location (ames:scenario-error-location condition)))
                  (is (ames-error-datum condition))
                  (is (plusp (length (princ-to-string condition))))
                  (when datum
                    (is (equal datum (ames-error-datum condition))))))))
       ;; contradictory assumptions, laid at the parameter that states the fact
       (check 'ames:contradictory-assumptions-error "parameter Y"
              (one-body-scenario '((x (> x y)) (y (> y x))) :fixed t :shape 'point))
       (let ((condition (semantic-condition
                         bridge (one-body-scenario '((x (> x y)) (y (> y x))) :fixed t :shape 'point))))
         (is (typep (ames:scenario-error-cause condition) 'ames.maxima:inconsistent-assumptions)))
       ;; false facts name the body
       (check 'ames:scenario-expression-error "body B"
              (one-body-scenario '((m :positive)) :mass '(- m) :position '(0 0) :velocity '(0 0)
                                 :shape 'point)
              '(> (- m) 0))
       (check 'ames:scenario-shape-error "body B"
              (one-body-scenario '((h :positive)) :fixed t
                                 :shape '(polygon (0 0) (0 h) (h 0))))
       (check 'ames:scenario-shape-error "body B"
              (one-body-scenario '((r (< r 0))) :fixed t :shape '(circle r)))
       (check 'ames:scenario-shape-error "body B"
              (one-body-scenario '((a :positive) (c (< c a))) :fixed t
                                 :shape '(arc :center (0 0) :radius 1 :from a :to c)))
       (check 'ames:scenario-expression-error "clause SIMULATE"
              `(scenario s (parameters (t0 :positive))
                         (body b :fixed t :shape point) (simulate :until (- t0))))
       ;; undecided facts name what is missing
       (check 'ames:missing-assumption-error "body B"
              (one-body-scenario '(m) :mass 'm :position '(0 0) :velocity '(0 0) :shape 'point)
              '(> m 0))
       (check 'ames:missing-assumption-error "body B"
              (one-body-scenario '((h :positive) k) :fixed t
                                 :shape '(polygon (0 0) (h 0) (0 k))))
       (let ((condition (semantic-condition
                         bridge (one-body-scenario '(m) :mass 'm :position '(0 0)
                                                          :velocity '(0 0) :shape 'point))))
         (is (equal '(> m 0) (ames:missing-assumption-fact condition))))
       ;; and what holds under the assumptions passes
       (is (null (semantic-condition
                  bridge (one-body-scenario '((h :positive) (a (> a 0) (< a (/ pi 2)))) :fixed t
                                            :shape '(polygon (0 0) ((/ h (tan a)) 0) (0 h))))))
       (is (null (semantic-condition
                  bridge (one-body-scenario '((m1 :positive) (m2 :positive) (r :positive))
                                            :mass '(+ m1 m2) :position '(0 0) :velocity '(0 0)
                                            :shape '(circle (* 2 r))))))))))

(test geometry-checks-shapes-and-start-overlaps
  (call-with-scenario-bridge
   (lambda (bridge)
     (flet ((geometry-condition (form)
              (handler-case (progn (ames:check-scenario-geometry (ames:parse-scenario form) bridge)
                                   nil)
                (ames-error (condition) condition))))
       ;; a point below the floor, a disc sunk into it: overlapping at the start
       (dolist (form '((scenario s (parameters (m :positive))
                        (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                        (body b :mass m :position (0 -1) :velocity (0 0) :shape point))
                       (scenario s (parameters (m :positive) (r :positive))
                        (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                        (body b :mass m :position (0 (/ r 2)) :velocity (0 0) :shape (circle r)))))
         (let ((condition (geometry-condition form)))
           (is (typep condition 'ames:overlapping-bodies-error) "~S gave ~A" form condition)
           (when condition
             (is (equal "bodies FLOOR and B" (ames:scenario-error-location condition)))
             (is (equal '("FLOOR" "B") (mapcar #'symbol-name (ames-error-datum condition)))))))
       ;; touching is not overlapping; fixed bodies may overlap each other
       (is (null (geometry-condition
                  '(scenario s (parameters (m :positive) (r :positive))
                    (body floor :fixed t :shape (half-plane (1 0) (0 0)))
                    (body wall :fixed t :shape (half-plane (r 1) (r -1)))
                    (body b :mass m :position (0 r) :velocity (0 0) :shape (circle r))))))
       ;; a self-intersecting polygon with a positive signed area: geometry's parser
       ;; rejects it, and the condition names the body
       (let ((condition (geometry-condition
                         '(scenario s (body b :fixed t
                                       :shape (polygon (0 0) (4 0) (4 4) (2 -1) (0 4)))))))
         (is (typep condition 'ames:scenario-shape-error) "got ~A" condition)
         (when condition
           (is (equal "body B" (ames:scenario-error-location condition)))
           (is (typep (ames:scenario-error-cause condition) 'ames.geometry:invalid-shape))))))))

(test scenario-files-pass-the-geometry-checks
  (call-with-scenario-bridge
   (lambda (bridge)
     (dolist (file (scenario-files))
       (let ((scenario (first (ames:read-scenario-file file))))
         (is (eq scenario (ames:check-scenario scenario bridge))
             "~A failed the geometry checks" (pathname-name file)))))))
