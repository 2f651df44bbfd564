;;;; t/phenomena.lisp -- each phenomenon in one place (issue 22, step 1): the registry of
;;;; src/kb/phenomena.lisp describes every force, impulse and event the components name; no
;;;; layer outside src/kb/ names a force, event or mode of the mechanics in its code; and the
;;;; energy query is the report's total (checked on every scenario's run of the
;;;; every-format suite, see CHECK-ENERGY-QUERY-IS-THE-REPORT-TOTAL).

(in-package #:ames.tests)

(def-suite phenomena :in all-tests
  :description "The registry of phenomena and the layers that must name none (src/kb/phenomena.lisp).")

(in-suite phenomena)

;;; What the knowledge bases name

(defun walk-forms (form function)
  "Call FUNCTION on FORM and on every list inside it (conses walked as lists)."
  (when (consp form)
    (funcall function form)
    (loop for tail on form while (consp tail) do (walk-forms (car tail) function))))

(defun component-keywords (kinds)
  "The keywords the components of AMES's knowledge bases name, as an alist keyword ->
what it is (:MODE, :EVENT, :FORCE or :IMPULSE), restricted to KINDS: their modes, the
events of their conditions (:EVENT and :IMPACT), the kinds of the entries they report in
:FORCES and :IMPULSES."
  (let ((found '()))
    (flet ((note (keyword kind)
             (when (member kind kinds) (pushnew (cons keyword kind) found :key #'car))))
      (dolist (kb (ames.kb:knowledge-bases))
        (dolist (component (ames.engine:knowledge-base-components kb))
          (dolist (mode (ames.engine:component-mode-names component)) (note mode :mode))
          (walk-forms (ames.engine:component-definition component)
                      (lambda (form)
                        (if (eq (first form) 'ames.kb:reported)
                            (when (and (consp (third form)) (keywordp (first (third form))))
                              (case (second form)
                                (:forces (note (first (third form)) :force))
                                (:impulses (note (first (third form)) :impulse))))
                            (loop for (key value) on form
                                  when (and (member key '(:event :impact)) (consp value)
                                            (keywordp (first value)))
                                    do (note (first value) :event))))))))
    found))

(test every-force-impulse-and-event-is-described-by-a-phenomenon
  "Each kind of force and impulse entry a component reports and each event a condition
names, in a state's model, has its phenomenon's description (so that every report words
it the same way); the impact model's own events (whether a contact pushes or a rope
jerks) are the consistency search's working and never reach a report."
  (let ((impact-choices '(:impulse :would-pull :jerk :would-push)))
    (loop for (keyword . kind) in (component-keywords '(:force :impulse :event))
          do (is-true (ecase kind
                        (:force (nth-value 1 (ames.kb:force-description keyword)))
                        (:impulse (nth-value 1 (ames.kb:impulse-description keyword)))
                        (:event (or (nth-value 1 (ames.kb:event-description keyword))
                                    (member keyword impact-choices))))
                      "~S (~(~A~)) is described by no phenomenon" keyword kind))))

(test each-query-quantity-of-a-phenomenon-reads-a-described-force
  "A query quantity a phenomenon answers reads a force kind some phenomenon describes,
with how many names lead its entries."
  (dolist (phenomenon ames.kb:*phenomena*)
    (loop for (quantity . plist) in (ames.kb::phenomenon-quantities phenomenon)
          for described = (ames.kb:force-description (getf plist :force))
          do (is-true described "~S reads the undescribed force ~S" quantity (getf plist :force))
             (is (integerp (getf described :names))))))

(test define-phenomenon-replaces-a-phenomenon-of-the-same-name
  "Redefining a phenomenon (reloading its file) replaces it in place: the order of the
phenomena, which orders the situation's entities, does not change."
  (let ((ames.kb:*phenomena* (copy-list ames.kb:*phenomena*)))
    (let ((before (mapcar #'ames.kb:phenomenon-name ames.kb:*phenomena*)))
      (eval '(ames.kb:define-phenomenon ames.kb::friction "A stand-in."
              (:force :friction :names 2 :words "stand-in ~A ~A")))
      (is (equal before (mapcar #'ames.kb:phenomenon-name ames.kb:*phenomena*)))
      (is (equal "stand-in ~A ~A" (getf (ames.kb:force-description :friction) :words))))
    (signals error (macroexpand '(ames.kb:define-phenomenon nonsense (:colour :red))))))

;;; No layer outside the kb names them

(defparameter *keyword-exceptions*
  '(("src/simulator/integrators.lisp" :path "a kind of group of bodies (one degree of freedom along path coordinates), not the mode")
    ("src/simulator/path.lisp" :path "the group kind")
    ("src/simulator/states.lisp" :path "the group kind")
    ("src/simulator/termination.lisp" :path "the group kind")
    ("src/simulator/turns.lisp" :path "the group kind")
    ("src/simulator/states.lisp" :contact "the key of a path note's contact")
    ("src/simulator/impacts.lisp" :contact "the key of a belief's contact")
    ("src/simulator/impacts.lisp" :impulse "the key of an impact event's impulse (any kind's)")
    ("src/report/phrases.lisp" :impulse "the key of an impact event's impulse (any kind's)")
    ("src/report/view-notes.lisp" :contact "the key of a path note's contact")
    ("src/geometry/conditions.lisp" :contact "a condition's slot initarg")
    ("src/geometry/contacts.lisp" :contact "a condition's slot initarg")
    ("src/geometry/minkowski.lisp" :normal "a piece's normal vector")
    ("src/simulator/touching.lisp" :normal "the key of a contact point's unit normal")
    ("src/report/svg.lisp" :normal "the key of a contact point's unit normal"))
  "The (FILE KEYWORD REASON) where a keyword of the mechanics occurs outside src/kb/ with
another meaning (listed in the README's \"Each phenomenon in one place\").")

(defun source-keywords (file)
  "Every keyword in the code of the Lisp source FILE (read with the reader: comments and
strings, docstrings among them, are no code), each file read in its own package (AMES's
own sources: #. is read as written)."
  (let ((*package* (find-package '#:cl-user)) (*read-eval* t) (found '()))
    (with-open-file (in file :external-format :utf-8)
      (loop for form = (read in nil in)
            until (eq form in)
            do (when (and (consp form) (eq (first form) 'in-package))
                 (setf *package* (find-package (second form))))
               (labels ((walk (x)
                          (cond ((keywordp x) (pushnew x found))
                                ((consp x) (walk (car x)) (walk (cdr x)))
                                ((and (vectorp x) (not (stringp x))) (map nil #'walk x)))))
                 (walk form))))
    found))

(test no-force-event-or-mode-is-named-outside-the-kb
  "No source file outside src/kb/ names a mode, an event or a kind of force of the
mechanics in its code (comments and docstrings may), except src/scenario/ (the clause
tables of the language), src/witness/ (the independent witness models the physics again
on purpose) and the listed uses of a keyword with another meaning (*KEYWORD-EXCEPTIONS*)."
  (let ((keywords (component-keywords '(:mode :event :force :impulse)))
        (root (asdf:system-relative-pathname "ames" "src/"))
        (checked 0)
        (used '()))
    (dolist (file (directory (merge-pathnames "**/*.lisp" root)))
      (let ((relative (enough-namestring file (asdf:system-relative-pathname "ames" ""))))
        (unless (or (search "src/kb/" relative) (search "src/scenario/" relative)
                    (search "src/witness/" relative)
                    (search "maxima-server" (pathname-name file)))
          (incf checked)
          (dolist (keyword (source-keywords file))
            (let ((entry (assoc keyword keywords)))
              (when entry
                (let ((exception (find-if (lambda (exception)
                                            (and (string= (first exception) relative)
                                                 (eq (second exception) keyword)))
                                          *keyword-exceptions*)))
                  (push exception used)
                  (is-true exception "~A names the ~(~A~) ~S" relative (cdr entry) keyword))))))))
    (is (> checked 100))
    ;; the list of exceptions stays true: each is still needed
    (dolist (exception *keyword-exceptions*)
      (is (member exception used) "no longer needed: ~S" exception))))

;;; The energy query is the report's total (run in the every-format suite, on its runs)

(defun check-energy-query-is-the-report-total (bridge history)
  "On each path of HISTORY, the query (value (energy) :at (start N)) and (end N), answered
by the query machinery on HISTORY itself (no second run), equals the total energy K + U
the report prints for state N (the sum of the kb's :ENERGY terms, REPORT-TOTAL-ENERGY)
wherever the report has one in closed form (Maxima-checked). Returns how many it compared."
  (let* ((scenario (ames:history-scenario history))
         (name (ames:scenario-name scenario))
         (compared 0))
    (loop for (facts nil . states) in (ames.simulator::history-paths history)
          do (ames.maxima:with-assumptions
                 (bridge (append (ames:scenario-assumption-relations scenario) facts))
               (dolist (state states)
                 (unless (ames.simulator::fork-state-p state)
                   (dolist (at '(:start :end))
                     (let ((expected (report-total-energy state at)))
                       (when expected
                         (incf compared)
                         (let ((answer (handler-case
                                           (ames.simulator::value-at
                                            bridge scenario states '(:energy)
                                            (list at (ames.simulator::state-index state)))
                                         (ames-error (condition) condition))))
                           (if (typep answer 'condition)
                               (fail "~A ~(~A~) ~D: the energy query is not answered (~A) where the report has ~S"
                                     name at (ames.simulator::state-index state) answer expected)
                               (is-same bridge (format nil "~A energy at ~(~A~) ~D" name at
                                                       (ames.simulator::state-index state))
                                        answer expected))))))))))
    compared))
