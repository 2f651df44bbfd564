;;;; t/scenario-reader.lisp -- tests of the restricted scenario reader, files of several scenarios, and scenarios/.

(in-package #:ames.tests)

(in-suite scenario)

(defvar *evaluated* nil
  "Set by code that a scenario text tries to run; it must stay NIL.")

(defun read-condition (text)
  "The condition that reading TEXT's forms signals, or NIL."
  (handler-case (progn (ames:read-scenario-forms text) nil)
    (ames-error (condition) condition)))

(defun symbols-of (tree)
  "The symbols in TREE."
  (cond ((and tree (symbolp tree)) (list tree))
        ((consp tree) (append (symbols-of (car tree)) (symbols-of (cdr tree))))
        (t '())))

(defun good-scenario-text (name)
  "The text of a small valid scenario called NAME."
  (format nil "(scenario ~A \"ok\"
  (parameters (m :positive) (g :positive))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body p :mass m :position (0 0) :velocity (0 0) :shape point))~%" name))

(test reader-reads-the-language
  (let ((forms (ames:read-scenario-forms
                (format nil "; a comment~%(scenario s \"a string; not a comment\" #| block #| nested |# |#~%  (parameters (g :positive (:value 9.81)) (k (:value 3/4)) (n (:value -12)))~%  (gravity (* g (sin pi))) (body b :fixed t :shape point))~%(second form)"))))
    (is (= 2 (length forms)))
    (destructuring-bind (scenario-word name description parameters gravity body) (first forms)
      (is (eq (find-symbol "SCENARIO" '#:ames-scenario) scenario-word))
      (is (eq (find-package '#:ames-scenario) (symbol-package name)))
      (is (string= "a string; not a comment" description))
      (let ((g-spec (second parameters)))
        (is (eq :positive (second g-spec)))
        (is (eq :value (first (third g-spec))))
        (is (typep (second (third g-spec)) 'double-float))
        (is (= 9.81d0 (second (third g-spec)))))
      (is (eql 3/4 (second (second (third parameters)))))
      (is (eql -12 (second (second (fourth parameters)))))
      (is (eq '* (first (second gravity))))
      (is (eq 'sin (first (third (second gravity)))))
      (is (eq 'pi (second (third (second gravity)))))
      (is (eq t (fourth body))))
    (is (every (lambda (symbol)
                 (member (symbol-package symbol)
                         (list (find-package '#:ames-scenario) (find-package '#:keyword)
                               (find-package '#:common-lisp))))
               (symbols-of forms)))
    ;; the only COMMON-LISP symbols are the algebra's operators, PI, T and NIL
    (is (every (lambda (symbol)
                 (or (not (eq (symbol-package symbol) (find-package '#:common-lisp)))
                     (member symbol '(* sin pi t nil))))
               (symbols-of forms)))))

(test reader-rejects-forbidden-syntax
  (dolist (text '("#.(foo)" "(scenario s #.(setf *evaluated* t))" "#S(foo)" "#P\"/tmp\""
                  "#+sbcl 1" "#-sbcl 1" "#'car" "#(1 2)" "#\\a" "#:foo" "#x10" "#1=(a)"
                  "#1#" "'a" "(scenario 'a)" "`a" "(a ,b)" "cl-user::foo" "cl:car" "ames::x"
                  "(ames.tests::*evaluated*)" "::foo" "(:a:b)" "foo:" "(a :)" "(|a|:b)"
                  "(a . b)" "(a" ")" "\"abc" "#| open" "(a #| open)" "1e999" "..." "(a b) )"))
    (let ((condition (read-condition text)))
      (is (typep condition 'ames:scenario-read-error) "~S gave ~A" text condition)
      (when condition
        (is (integerp (ames:scenario-read-error-line condition)))
        (is (integerp (ames:scenario-read-error-column condition)))
        (is (ames-error-datum condition))
        (is (plusp (length (princ-to-string condition)))))))
  (is (null *evaluated*)))

(test reader-reads-nothing-it-should-not
  (dolist (text '("(scenario s cl-user::ames-scenario-test-unique-xyzzy)"
                  "(ames::ames-scenario-test-unique-plugh)"
                  "(no-such-package-ames-qq::x)"
                  "(scenario s #.(setf ames.tests::*evaluated* t))"
                  "#.(progn (setf ames.tests::*evaluated* t) 1)"
                  "(scenario s #+#.(progn (setf ames.tests::*evaluated* t) :sbcl) 1)"))
    (is (typep (read-condition text) 'ames:scenario-read-error) "~S was read" text))
  (is (null (find-symbol "AMES-SCENARIO-TEST-UNIQUE-XYZZY" '#:cl-user)))
  (is (null (find-symbol "AMES-SCENARIO-TEST-UNIQUE-PLUGH" '#:ames)))
  (is (null (find-package "NO-SUCH-PACKAGE-AMES-QQ")))
  (is (null *evaluated*))
  ;; escaped colons are part of a name, not a package prefix
  (let ((form (first (ames:read-scenario-forms "(|a:b| c\\:d)"))))
    (is (equal '("a:b" "C:D") (mapcar #'symbol-name form)))
    (is (every (lambda (symbol) (eq (symbol-package symbol) (find-package '#:ames-scenario)))
               form))))

(test reader-errors-give-line-and-column
  (let ((condition (read-condition (format nil "~%~%  (scenario s #.(x))"))))
    (is (eql 3 (ames:scenario-read-error-line condition)))
    (is (eql 14 (ames:scenario-read-error-column condition)))
    (is (search "line 3" (princ-to-string condition))))
  (let ((condition (read-condition (format nil "(a)~%(b cl-user::c)"))))
    (is (eql 2 (ames:scenario-read-error-line condition)))
    (is (eql 10 (ames:scenario-read-error-column condition))))
  (let ((condition (handler-case (ames:read-scenarios-from-string "(scenario s" :file "f.lisp")
                     (ames-error (c) c))))
    (is (equal "f.lisp" (ames:scenario-read-error-file condition)))
    (is (search "f.lisp" (princ-to-string condition)))))

(test reader-limits-depth-length-and-size
  (let ((deep (concatenate 'string (make-string 10000 :initial-element #\()
                           (make-string 10000 :initial-element #\)))))
    (is (search "nested" (princ-to-string (read-condition deep)))))
  (is (search "nested" (princ-to-string (read-condition (make-string 200000 :initial-element #\()))))
  (is (search "token" (princ-to-string (read-condition (make-string 5000 :initial-element #\7)))))
  (is (typep (read-condition (make-string (+ 1 (* 4 1024 1024)) :initial-element #\Space))
             'ames:scenario-read-error))
  ;; within the limits, a long list and a big number are fine
  (is (= 3000 (length (first (ames:read-scenario-forms
                              (format nil "(~{~D~^ ~})" (alexandria:iota 3000)))))))
  (is (= (expt 10 1000) (first (ames:read-scenario-forms
                                (format nil "1~v@{0~}" 1000 nil))))))

(test one-bad-scenario-does-not-stop-the-others
  (dolist (bad (list "(scenario bad #.(setf ames.tests::*evaluated* t))"
                     "(scenario bad (frob))"
                     "(scenario bad (parameters (x (> x 2) (< x 1))) (body b :fixed t :shape point))"
                     "(scenario bad (body b :fixed t :shape (polygon (0 0) (0 1) (1 0))))"
                     "(scenario bad cl-user::x)"
                     "#S(scenario :bad t)"
                     ")"
                     "42"))
    (let ((text (concatenate 'string (good-scenario-text "first") bad (string #\Newline)
                             (good-scenario-text "second"))))
      ;; :collect skips the bad one and returns its condition
      (multiple-value-bind (scenarios conditions)
          (ames:read-scenarios-from-string text :on-error :collect)
        (is (equal '("FIRST" "SECOND")
                   (mapcar (lambda (s) (symbol-name (ames:scenario-name s))) scenarios))
            "~S: ~S" bad scenarios)
        (is (= 1 (length conditions)))
        (is (typep (first conditions) 'ames:scenario-error)))
      ;; :signal lets a handler choose the SKIP-SCENARIO restart
      (let ((seen '()))
        (multiple-value-bind (scenarios conditions)
            (handler-bind ((ames:scenario-error
                             (lambda (condition)
                               (push condition seen)
                               (is (find-restart 'ames:skip-scenario condition))
                               (ames:skip-scenario condition))))
              (ames:read-scenarios-from-string text))
          (is (= 2 (length scenarios)))
          (is (equal seen conditions))))
      ;; and without a handler the condition reaches the caller
      (signals ames:scenario-error (ames:read-scenarios-from-string text))))
  (is (null *evaluated*))
  ;; a last scenario that is never closed leaves the first intact
  (multiple-value-bind (scenarios conditions)
      (ames:read-scenarios-from-string
       (concatenate 'string (good-scenario-text "first") "(scenario open (body")
       :on-error :collect)
    (is (= 1 (length scenarios)))
    (is (typep (first conditions) 'ames:scenario-read-error)))
  (signals control-error (ames:skip-scenario)))

(test scenario-files-are-read-from-disk
  (uiop:with-temporary-file (:pathname path :stream stream :direction :output
                             :external-format :utf-8)
    (write-string (good-scenario-text "one") stream)
    (write-line "(scenario two (frob))" stream)
    (write-string (good-scenario-text "three") stream)
    :close-stream
    (multiple-value-bind (scenarios conditions) (ames:read-scenario-file path :on-error :collect)
      (is (= 2 (length scenarios)))
      (is (= 1 (length conditions)))
      (is (search "line 6" (princ-to-string (first conditions))))
      (is (search "line 7" (ames:scenario-source (second scenarios))))))
  (let ((missing (merge-pathnames "no-such-scenario-file.lisp" (uiop:temporary-directory))))
    (signals ames:scenario-file-error (ames:read-scenario-file missing))
    (multiple-value-bind (scenarios conditions) (ames:read-scenario-file missing :on-error :collect)
      (is (null scenarios))
      (is (typep (first conditions) 'ames:scenario-file-error))
      (is (ames-error-datum (first conditions)))))
  (uiop:with-temporary-file (:pathname path :stream stream :direction :output
                             :element-type '(unsigned-byte 8))
    (write-sequence (coerce #(40 255 254 41) '(vector (unsigned-byte 8))) stream)
    :close-stream
    (signals ames:scenario-file-error (ames:read-scenario-file path))))

(test the-scenarios-directory
  (let ((expected '("block-on-incline" "particle-on-sphere" "particle-on-wedge"
                    "particle-under-plane" "projectile-off-table" "two-blocks-in-corner")))
    (is (subsetp expected (mapcar #'pathname-name (scenario-files)) :test #'string=))
    (dolist (file (scenario-files))
      (multiple-value-bind (scenarios conditions) (ames:read-scenario-file file :on-error :collect)
        (is (null conditions) "~A: ~{~A~}" (pathname-name file) conditions)
        (is (<= 1 (length scenarios)) "~A holds no scenario" (pathname-name file))
        ;; one scenario is named as its file; several (variants side by side) are named
        ;; each on its own (no two alike)
        (is (= (length scenarios)
               (length (remove-duplicates (mapcar #'ames:scenario-name scenarios))))
            "~A: two scenarios with one name" (pathname-name file))
        (dolist (scenario scenarios)
          (when scenario
            (when (= 1 (length scenarios))
              (is (string-equal (pathname-name file) (symbol-name (ames:scenario-name scenario)))))
            (is (stringp (ames:scenario-description scenario)))
            (is (ames:scenario-moving-bodies scenario))))
        (let ((text (uiop:read-file-string file)))
          (is (eql 0 (search ";;;; " text)) "~A does not begin with ;;;;" file)
          (is (search "Expected results" text) "~A states no expected results" file))))))

(test the-wedge-file-is-the-language-example
  ;; scenarios/particle-on-wedge.lisp is exactly the example of scenario-language.md
  (let* ((file (find "particle-on-wedge" (scenario-files) :key #'pathname-name :test #'string=))
         (form (first (ames:read-scenario-forms (uiop:read-file-string file)))))
    (is (same-by-name-p *wedge-form* form))))

(test simple-starting-contacts-are-exact
  ;; Where a body is meant to touch another at the start, its reference point lies
  ;; exactly on the other's boundary (checked numerically at the default values and at
  ;; other values satisfying the assumptions).
  (flet ((scenario (name)
           (first (ames:read-scenario-file
                   (find name (scenario-files) :key #'pathname-name :test #'string=))))
         (value (expression bindings)
           (ames:constant-value expression bindings))
         (near (x y) (< (abs (- x y)) 1d-12)))
    (let* ((sphere (scenario "particle-on-sphere"))
           (particle (ames:find-scenario-body 'ames-scenario::particle sphere))
           (bindings (ames:scenario-parameter-values sphere))
           (position (ames:scenario-body-position particle)))
      (is (near (+ (expt (value (first position) bindings) 2)
                   (expt (value (second position) bindings) 2))
                (expt (value 'ames-scenario::r bindings) 2))))
    (let* ((wedge (scenario "particle-on-wedge"))
           (bindings '((ames-scenario::h . 2) (ames-scenario::a . 0.7d0)))
           (position (ames:scenario-body-position
                      (ames:find-scenario-body 'ames-scenario::particle wedge)))
           (x (value (first position) bindings))
           (y (value (second position) bindings)))
      ;; on the slope x tan a + y = h, strictly between its ends
      (is (near (+ (* x (tan 0.7d0)) y) 2))
      (is (< 0 y 2)))
    (let* ((corner (scenario "two-blocks-in-corner"))
           (bindings (ames:scenario-parameter-values corner))
           (a (ames:find-scenario-body 'ames-scenario::block-a corner))
           (b (ames:find-scenario-body 'ames-scenario::block-b corner))
           (xa (value (first (ames:scenario-body-position a)) bindings))
           (yb (value (second (ames:scenario-body-position b)) bindings))
           (l1 (value 'ames-scenario::l1 bindings))
           (l2 (value 'ames-scenario::l2 bindings))
           (l3 (value 'ames-scenario::l3 bindings)))
      ;; B's corner (0, yb) on A's face from (xa, l1) to (xa + l3, l2), inside it
      (let ((s (/ (- xa) l3)))
        (is (< 0 s 1))
        (is (near yb (+ l1 (* s (- l2 l1)))))))))
