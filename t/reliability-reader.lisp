;;;; t/reliability-reader.lisp -- reading on after a fault, bad bytes, the line of each fault, parameter values.

(in-package #:ames.tests)

(in-suite reliability)

(defun small-scenario-text (name &optional (extra ""))
  "The text of a small valid scenario NAME (five lines), with EXTRA before its last )."
  (format nil "(scenario ~A \"ok\"
  (parameters (m :positive) (g :positive))
  (gravity g)
  (body floor :fixed t :shape (half-plane (1 0) (0 0)))
  (body p :mass m :position (0 1) :velocity (0 0) :shape point)~A)~%" name extra))

(defun read-collecting (text)
  "The names (strings) of the scenarios read from TEXT, and the conditions."
  (multiple-value-bind (scenarios conditions)
      (ames:read-scenarios-from-string text :file "f.lisp" :on-error :collect)
    (values (mapcar (lambda (s) (symbol-name (ames:scenario-name s))) scenarios) conditions)))

(test a-fault-spoils-only-its-own-scenario
  (dolist (case '(("(scenario broken (body b" 6 17 "not closed")
                  ("(scenario broken \"a string never closed" 6 17 "string")
                  ("#| a comment never closed" 6 0 "comment")
                  ("(scenario broken (body |a name never closed" 6 23 "|")
                  ("(scenario broken (parameters (m :positive)" 6 17 "not closed")
                  ("'" 6 0 "not closed")
                  ("#." 6 0 "not closed")))
    (destructuring-bind (bad line column word) case
      (let ((text (concatenate 'string (small-scenario-text "one") bad (string #\Newline)
                               (small-scenario-text "two") (small-scenario-text "three"))))
        (multiple-value-bind (names conditions) (read-collecting text)
          (is (equal '("ONE" "TWO" "THREE") names) "~S lost scenarios: ~S" bad names)
          (is (= 1 (length conditions)) "~S: ~S" bad conditions)
          (let ((condition (first conditions)))
            (is (typep condition 'ames:scenario-read-error))
            (when (typep condition 'ames:scenario-read-error)
              (is (eql line (ames:scenario-read-error-line condition)) "~S: ~A" bad condition)
              (is (eql column (ames:scenario-read-error-column condition)) "~S: ~A" bad condition)
              (is (search word (princ-to-string condition)))
              (is (search "line 7" (princ-to-string condition))
                  "~S: the message does not say where reading goes on: ~A" bad condition))))))))

(test a-commented-out-scenario-is-no-fault
  (multiple-value-bind (names conditions)
      (read-collecting (concatenate 'string (small-scenario-text "one")
                                    (format nil "#|~%(scenario old (frob)~%|#~%")
                                    (small-scenario-text "two")))
    (is (equal '("ONE" "TWO") names))
    (is (null conditions))))

(test bad-bytes-spoil-only-the-scenario-that-holds-them
  (flet ((octets (&rest parts)
           (apply #'concatenate '(vector (unsigned-byte 8))
                  (mapcar (lambda (part)
                            (if (stringp part)
                                (sb-ext:string-to-octets part :external-format :utf-8)
                                (coerce part '(vector (unsigned-byte 8)))))
                          parts))))
    (uiop:with-temporary-file (:pathname path :stream stream :direction :output
                               :element-type '(unsigned-byte 8))
      (write-sequence (octets (format nil "; caf") '(#xE9) (format nil " in a comment~%")
                              (small-scenario-text "one")
                              "(scenario two \"caf" '(#xE9) (format nil "\"~%")
                              (format nil "  (body b :fixed t :shape point))~%")
                              (small-scenario-text "three")
                              (format nil "#| a block comment ") '(#xFF #xFE) (format nil " |#~%")
                              (small-scenario-text "four"))
                      stream)
      :close-stream
      (multiple-value-bind (scenarios conditions) (ames:read-scenario-file path :on-error :collect)
        (is (equal '("ONE" "THREE" "FOUR")
                   (mapcar (lambda (s) (symbol-name (ames:scenario-name s))) scenarios)))
        (is (= 1 (length conditions)))
        (let ((condition (first conditions)))
          (is (typep condition 'ames:scenario-file-error))
          (is (eql 7 (ames:scenario-read-error-line condition)))
          (is (eql 18 (ames:scenario-read-error-column condition)))
          (is (search "#xE9" (princ-to-string condition)))))))
  ;; the decoder: overlong forms, surrogates and stray continuation bytes are bad bytes
  (flet ((bad (bytes) (nth-value 1 (ames.scenario:decode-utf-8 (coerce bytes '(vector (unsigned-byte 8)))))))
    (is (null (bad '(#x61 #xC3 #xA9 #xE2 #x82 #xAC #xF0 #x9F #x98 #x80))))
    (is (equal '((0 . #xC0) (1 . #x80)) (bad '(#xC0 #x80))))
    (is (equal '((0 . #xED) (1 . #xA0) (2 . #x80)) (bad '(#xED #xA0 #x80))))
    (is (equal '((1 . #x80)) (bad '(#x61 #x80 #x62))))
    (is (string= "ab" (ames.scenario:decode-utf-8 (coerce '(#xEF #xBB #xBF #x61 #x62)
                                                 '(vector (unsigned-byte 8))))))))

(test validation-errors-name-the-line-of-the-fault
  (flet ((message (text)
           (multiple-value-bind (names conditions) (read-collecting text)
             (declare (ignore names))
             (princ-to-string (first conditions)))))
    (is (search "f.lisp, line 6" (message (small-scenario-text "one" "
  (force push :on nobody :value (1 0))"))))
    (is (search "f.lisp, line 7" (message (small-scenario-text "one" "
  (body q :mass m :position (0 5)
     :velocity (0 0) :shape point :fixed maybe)"))))
    (is (search "f.lisp, line 3" (message "(scenario s
  (parameters (m :positive))
  (gravity undeclared)
  (body b :mass m :position (0 0) :velocity (0 0) :shape point))")))
    ;; the scenario's own line when the fault is the whole form
    (is (search "f.lisp, line 2" (message "
(scenario s (parameters (m :positive)))")))))

(test parameter-values-are-checked
  (dolist (bad (list 42 '(1 2) '((g . "9.81")) '((g . 1) (g . 2)) '(("g" . 1) (g . 2))
                     '((nil . 1)) '((g . #c(1 1))) (list (cons 'g sb-ext:double-float-positive-infinity))
                     (let ((l (list (cons 'g 1)))) (setf (cdr l) l) l)))
    (let ((condition (handler-case (ames:check-parameter-values bad) (ames-error (c) c))))
      (is (typep condition 'ames:parameter-values-error) "~S gave ~S" bad condition)
      (when condition (is (plusp (length (princ-to-string condition)))))))
  (is (equal '((g . 1)) (ames:check-parameter-values '((g . 1)))))
  (let ((scenario (first (ames:read-scenarios-from-string (small-scenario-text "one")))))
    (is (equal (list (cons (find-symbol "G" '#:ames-scenario) 981/100))
               (ames:check-parameter-values '(("g" . 981/100)) scenario)))
    (signals ames:undeclared-symbol-error (ames:check-parameter-values '((h . 1)) scenario))
    ;; through RUN-FILE at the REPL, a bad argument is an AMES-ERROR naming it
    (uiop:with-temporary-file (:pathname path :stream stream :direction :output)
      (write-string (small-scenario-text "one") stream)
      :close-stream
      (let ((condition (handler-case (ames:run-file path :settings 42) (ames-error (c) c))))
        (is (typep condition 'ames:parameter-values-error))
        (is (eql 42 (ames-error-datum condition)))))))
