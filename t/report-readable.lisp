;;;; t/report-readable.lisp -- no Lisp in a report for people (issue 25).
;;;;
;;;; The text, LaTeX, HTML and SVG reports and `explain` are for people: none may show a
;;;; symbol with a package prefix, an uninterned symbol, a keyword, a prefix s-expression,
;;;; Maxima's internal names ($%r2) or the simulator's entity names (contact-0, segment-1,
;;;; arc-length), nor a numeric root with a square factor (sqrt(8) is 2 sqrt(2)). READABLE-
;;;; PROBLEMS finds them; EVERY-SCENARIO-IN-EVERY-FORMAT (report-formats.lisp) applies it to
;;;; every scenario of scenarios/ in every format, reusing its one run per scenario. The
;;;; pictures' labels are measured: no two text boxes overlap (LABEL-OVERLAPS, sizes read
;;;; from the picture's own style sheet), and a state is labelled "state N", not a bare number.

(in-package #:ames.tests)

(in-suite report)

(defparameter *lisp-patterns*
  '(("a package prefix" "[A-Za-z][A-Za-z0-9.*+-]*::?[A-Za-z*+%$]")
    ("an uninterned symbol" "#:")
    ("a keyword" "(?:^|[\\s(,\\[]):[a-z][a-z0-9-]*")
    ("a prefix s-expression" "\\((?:\\+|-|\\*|/|expt|sqrt|=|<|>|<=|>=|EXPT|SQRT) [^\\s]")
    ("a Lisp operator in capitals" "\\b(?:SQRT|EXPT|ATAN|NIL|LAMBDA)\\b")
    ("a Maxima internal name" "\\$%|%r[0-9]|\\?\\?")
    ("an entity the simulator named" "\\b(?:contact|segment)-[0-9]+\\b|arc-length|path-position"))
  "What a report for people must not show: (WHAT REGEX).")

(defun visible-text (markup)
  "The text a reader of the HTML or SVG MARKUP sees: styles, scripts, comments and tags
removed, entities decoded."
  (let* ((text (cl-ppcre:regex-replace-all "(?is)<(style|script)[^>]*>.*?</\\1>" markup " "))
         (text (cl-ppcre:regex-replace-all "(?s)<!--.*?-->" text " "))
         (text (cl-ppcre:regex-replace-all "<[^>]*>" text " ")))
    (reduce (lambda (text pair) (cl-ppcre:regex-replace-all (car pair) text (cdr pair)))
            '(("&lt;" . "<") ("&gt;" . ">") ("&quot;" . "\"") ("&amp;" . "&"))
            :initial-value text)))

(defun square-factor-roots (text)
  "The square roots in TEXT (sqrt(...) or \\sqrt{...}) whose radicand is a product led by
an integer with a square factor: sqrt(8 h / g), \\sqrt{8\\,h}, but not sqrt(8 m + 5 e)."
  (let ((found '()))
    (cl-ppcre:do-scans (start end group-starts group-ends "(?:sqrt\\(|\\\\sqrt\\{)([0-9]+)" text)
      (declare (ignore group-ends))
      (let* ((number (parse-integer text :start (aref group-starts 0) :end (position-if-not #'digit-char-p text :start (aref group-starts 0))))
             (open (char text (1- (aref group-starts 0))))
             (close (if (char= open #\() #\) #\}))
             (depth 1)
             (stop (loop for i from (aref group-starts 0) below (length text)
                         do (let ((c (char text i)))
                              (cond ((char= c open) (incf depth))
                                    ((char= c close) (decf depth) (when (zerop depth) (return i)))))
                         finally (return (length text))))
             (radicand (subseq text (aref group-starts 0) stop))
             (sum (let ((d 0))
                    (loop for i from 0 below (length radicand)
                          for c = (char radicand i)
                          do (case c ((#\( #\{) (incf d)) ((#\) #\}) (decf d)))
                          thereis (and (zerop d) (plusp i) (member c '(#\+ #\-)))))))
        (when (and (not sum) (> number 3)
                   (loop for k from 2 to (isqrt number) thereis (zerop (mod number (* k k)))))
          (push (cons "a root with a square factor" (subseq text start (min (length text) (+ end 20)))) found))))
    (nreverse found)))

(defun readable-problems (text)
  "Each (WHAT . EXCERPT) of *LISP-PATTERNS* found in TEXT (a report as people see it), and
each root with a square factor (SQUARE-FACTOR-ROOTS)."
  (append
   (loop for (what pattern) in *lisp-patterns*
         append (let ((matches '()))
                  (cl-ppcre:do-matches (start end pattern text)
                    (push (cons what (subseq text (max 0 (- start 30)) (min (length text) (+ end 30)))) matches))
                  (nreverse matches)))
   (square-factor-roots text)))

(defun repeated-end-lines (explanation)
  "The lines said twice in one \"Why the state ends then\" block of EXPLANATION."
  (loop for block in (rest (cl-ppcre:split "Why the state ends then:" explanation))
        for lines = (remove "" (mapcar (lambda (l) (string-trim " " l))
                                       (cl-ppcre:split "\\n" (subseq block 0 (or (cl-ppcre:scan "\\n(State|Branch) " block)
                                                                                 (length block)))))
                            :test #'string=)
        append (loop for (line . more) on lines when (member line more :test #'string=) collect line)))

(defun check-readable (name format text)
  "Check that TEXT, the FORMAT report of the scenario NAME, shows no Lisp."
  (let ((problems (readable-problems (if (member format '(:html :svg)) (visible-text text) text))))
    (is (null problems) "~A (~(~A~)): ~{~&  ~A in ~S~}" name format
        (loop for (what . excerpt) in (subseq problems 0 (min 5 (length problems)))
              append (list what excerpt)))))

(defun svg-font-sizes (svg)
  "Alist class -> font size in pixels from the <style> of SVG (13 for text by default)."
  (let ((sizes '()))
    (cl-ppcre:do-register-groups (class size) ("\\.([a-z-]+)\\{[^}]*font-size:([0-9.]+)px" svg)
      (push (cons class (let ((*read-default-float-format* 'double-float))
                          (float (read-from-string size) 1d0)))
            sizes))
    sizes))

(defun svg-text-boxes (svg)
  "Each <text> of SVG as (TEXT LEFT TOP RIGHT BOTTOM): its font size from its class, its
width 0.6 of the size per character, its height the size (baseline at 0.8 of it)."
  (let ((sizes (svg-font-sizes svg)) (boxes '()))
    (cl-ppcre:do-register-groups (attributes content) ("<text([^>]*)>([^<]*)</text>" svg)
      (let* ((class (or (cl-ppcre:scan-to-strings "(?<=class=\")[^\"]+" attributes) ""))
             (size (or (cdr (assoc class sizes :test #'string=)) 13d0))
             (x (let ((*read-default-float-format* 'double-float))
                  (float (read-from-string (cl-ppcre:scan-to-strings "(?<= x=\")[-0-9.]+" attributes)) 1d0)))
             (y (let ((*read-default-float-format* 'double-float))
                  (float (read-from-string (cl-ppcre:scan-to-strings "(?<= y=\")[-0-9.]+" attributes)) 1d0)))
             (text (visible-text content))
             (width (* 0.6d0 size (length text)))
             (left (cond ((search "text-anchor=\"middle\"" attributes) (- x (/ width 2)))
                         ((search "text-anchor=\"end\"" attributes) (- x width))
                         (t x))))
        (push (list text left (- y (* 0.8d0 size)) (+ left width) (+ y (* 0.2d0 size))) boxes)))
    (nreverse boxes)))

(defun label-overlaps (svg)
  "The pairs of texts of SVG whose boxes overlap."
  (loop for (a . more) on (svg-text-boxes svg)
        append (loop for b in more
                     when (destructuring-bind (ta l1 t1 r1 b1) a
                            (declare (ignore ta))
                            (destructuring-bind (tb l2 t2 r2 b2) b
                              (declare (ignore tb))
                              (and (< l1 r2) (< l2 r1) (< t1 b2) (< t2 b1))))
                       collect (list (first a) (first b)))))

(defun check-picture-labels (name svg)
  "No two labels of the picture SVG overlap, and no state is labelled by a bare number."
  (let ((overlaps (label-overlaps svg)))
    (is (null overlaps) "~A: overlapping labels ~S" name (subseq overlaps 0 (min 5 (length overlaps)))))
  (is (not (cl-ppcre:scan "class=\"state-label\"[^>]*>[0-9]+<" svg)) "~A: a state numbered like an axis tick" name))

(defun check-human-formats (bridge history text latex svg)
  "Check HISTORY's TEXT, LATEX and SVG reports, its HTML page and its explanation for Lisp."
  (let ((name (ames:scenario-name (ames:history-scenario history))))
    (check-readable name :text text)
    (check-readable name :latex latex)
    (check-readable name :svg svg)
    (check-picture-labels name svg)
    ;; the page without KaTeX inlined: the same text, a megabyte less to scan
    (let ((ames.report::*katex-directory* #p"/nonexistent/katex/"))
      (check-readable name :html (with-output-to-string (out)
                                   (ames.report:print-history-html history out :bridge bridge))))
    (let ((explanation (with-output-to-string (out) (ames:explain history :stream out :bridge bridge))))
      (check-readable name :explain explanation)
      (is (null (repeated-end-lines explanation)) "~A: explain says twice ~S" name
          (repeated-end-lines explanation)))))

(test readable-patterns-are-found
  "The patterns find what they are for, and pass a plain report line."
  (dolist (bad '("impulse of (- (/ (* (SQRT 2) M1)) on rope" "(AMES.KB:NORMAL-FORCE AMES.SIMULATOR::CONTACT-1)"
                 "a name AMES did not give $%r2" "penetrates contact-0 at once" "the fact :true"
                 "#:G123" "duration sqrt(8 h / g)" "\\sqrt{8\\,h}"))
    (is (readable-problems bad) "not found in ~S" bad))
  (dolist (good '("  tension in rope: T = 2 m1 m2 g / (m1 + m2)" "ends: heavy collides with floor"
                  "position:     x = -v0^2 cos a / (2 g (sin a + mu cos a)) + (1/2) a_x tau^2"
                  "State 0, from t = 0 (1.5)" "velocity (-r, 0)" "2 sqrt(2 h / g)"
                  "after sqrt(8 m1 + 5 e)/(sqrt(e) sqrt(g))" "\\sqrt{27+\\left(23+4\\,\\sin ^2 a\\right)}"))
    (is (null (readable-problems good)) "~S: ~S" good (readable-problems good)))
  (is (equal "a < b" (string-trim " " (visible-text "<style>x:y</style><b>a &lt; b</b>")))))

(test label-overlaps-are-measured
  "Two labels at one place overlap; apart they do not."
  (let ((style "<style>.event-label{font-size:12px}</style>"))
    (is (label-overlaps (format nil "<svg>~A<text class=\"event-label\" x=\"10\" y=\"20\">hits floor</text><text class=\"event-label\" x=\"14\" y=\"26\">hits wall</text></svg>" style)))
    (is (null (label-overlaps (format nil "<svg>~A<text class=\"event-label\" x=\"10\" y=\"20\">hits floor</text><text class=\"event-label\" x=\"10\" y=\"40\">hits wall</text></svg>" style))))))

(test bouncing-ball-labels-apart
  "The bouncing ball's impacts happen at one point: their labels are stacked, not printed
over each other, and its picture has the plots over time."
  (with-fixture simulator-bridge ()
    (let* ((history (history-of "bouncing-ball" bridge))
           (svg (ames.report:history-svg history)))
      (is (<= 2 (length (cl-ppcre:all-matches-as-strings "class=\"event-label\"" svg))))
      (is (null (label-overlaps svg)))
      (dolist (title '("x(t)" "y(t)" "speed |v|" "energy"))
        (is (search (format nil "data-title=\"~A\"" title) svg) "no plot ~A" title))
      (is (<= 3 (length (cl-ppcre:all-matches-as-strings "class=\"event-time\"" svg)))))))

(defun synthetic-state (index &rest branches)
  "A state view for the branch tests: words only, BRANCHES its forks' branch views."
  (list :index index :start (list "0") :duration (list "0") :end (list "the run branches")
        :contacts '() :forces '() :bodies '() :notes '() :final '() :branches branches))

(test branches-nested-and-marked-in-the-text
  "Every branch is shown, numbered by its place in the tree and nested (| once per level),
the selected one marked, a branch with only its fact said not simulated."
  (let* ((view (list :name 'fork :states
                     (ames.report::labelled-branches
                      (list (synthetic-state
                             0
                             (list :assume (list "a > 0") :selected t :outcome :branched
                                   :states (list (synthetic-state
                                                  1
                                                  (list :assume (list "b > 0") :outcome :complete
                                                        :states (list (synthetic-state 2)))
                                                  (list :assume (list "b < 0")))))
                             (list :assume (list "a < 0")))))
                     :outcome :branched))
         (text (with-output-to-string (out) (ames.report::print-view-text view out))))
    (is (search "Branch 1 of 2 (selected by the given values), assuming a > 0:" text) "~A" text)
    (is (search "| Branch 1.1 of 2, assuming b > 0:" text))
    (is (search "| | State 2 (branch 1.1), from t = 0" text))
    (is (search "| End of branch 1.2: not simulated (only its fact is known)" text))
    (is (search "Branch 2 of 2, assuming a < 0:" text))
    (is (search "End of branch 2: not simulated" text))
    (is (not (search "Branch 2 of 2 (selected" text)))))

(test a-branch-failure-is-written-infix
  "The simulator's words for a failed branch print the missing fact as a prefix form: the
report writes it as a formula (read back without evaluation), the words kept."
  (let* ((message "the tree's bound is reached; the missing fact: (> (+ (* mb g l2) (* f l3)) (* (sqrt 2) mb g l1))")
         (phrase (ames.report::failure-phrase message))
         (text (ames.report::phrase-text phrase)))
    (is (readable-problems message))
    (is (search "mb g l2 + f l3 > sqrt(2) mb g l1" text))
    (is (null (readable-problems text)) "~S" text)
    (is (search "the tree's bound is reached; the missing fact: " text))
    (is (= 1 (count-if #'consp phrase)))
    ;; nothing evaluated, nothing that is not a formula taken for one
    (is (equal '("a (list #.(error)) b") (ames.report::failure-phrase "a (list #.(error)) b")))
    ;; words in parentheses stay words, a short quantity term is still a formula
    (is (equal '("wound on it (its tangent point wanders round the disc)")
               (ames.report::failure-phrase "wound on it (its tangent point wanders round the disc)")))
    (is (= 1 (count-if #'consp (ames.report::failure-phrase "at (pos ball :x)"))))))

(test numeric-roots-lose-their-square-factors
  "sqrt(8 h/g) is written 2 sqrt(2 h/g), 2^(3/2) as 2 sqrt(2) and sqrt(32) as 4 sqrt(2):
the same values, no root of a number with a square factor."
  (dolist (expression '((sqrt (/ (* 8 h) g)) (expt 2 3/2) (sqrt 1/2) (* (sqrt 32) m)
                        (/ (sqrt (* 12 h)) (sqrt g)) (expt 18 -1/2)))
    (let* ((arranged (ames.report:arrange expression (plain-arrangement)))
           (text (ames.report:text-form arranged)))
      (is (same-values-at-points-p expression arranged) "~S is not ~S" text expression)
      (is (null (square-factor-roots text)) "~S keeps a square factor" text)
      (is (not (cl-ppcre:scan "sqrt\\((?:8|12|18|32)\\b|\\^\\(3/2\\)" text)) "~S" text))))
