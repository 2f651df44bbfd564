;;;; src/report/phrases.lisp -- words for what a report names: features, contacts, forces, events.
;;;;
;;;; A PHRASE is a list of strings (words) and (:MATH EXPRESSION) segments (formulas, already
;;;; presented), so that each format writes the formulas its own way. Contacts are named by
;;;; their features as a person sees them ("particle on the slope of wedge"): an edge by the
;;;; direction its outward normal points, decided under the scenario's assumptions (the top,
;;;; the base, the left or right side, the slope, the underside; "edge N" when that is not
;;;; decided or not unique). Forces and events are looked up in phrase tables by their kind;
;;;; any kind the tables do not know is still printed, generically, from its entry: no entry
;;;; the knowledge base reports can break a report.

(in-package #:ames.report)

(defun name-text (name)
  "A body, force or rope NAME (a symbol) as a word: its name in lower case."
  (if (symbolp name) (string-downcase (symbol-name name)) (princ-to-string name)))

(defun keyword-words (keyword)
  "A keyword as words: :energy-lost -> \"energy lost\"."
  (substitute #\Space #\- (string-downcase (symbol-name keyword))))

(defun phrase (&rest parts)
  "A phrase of PARTS: strings are words, other expressions become (:MATH EXPRESSION),
and NIL parts are dropped."
  (loop for part in parts
        when part
          collect (if (or (stringp part) (and (consp part) (eq (first part) :math)))
                      part
                      (list :math part))))

(defun phrase-text (phrase &optional (formula-function #'text-form))
  "PHRASE as one string: its words, and each formula written by FORMULA-FUNCTION."
  (with-output-to-string (out)
    (dolist (part phrase)
      (write-string (if (stringp part) part (funcall formula-function (second part))) out))))

;;; Features

(defun body-shape-form (presenter name)
  "The shape form of the scenario body named NAME, or NIL."
  (let ((body (find-scenario-body name (presenter-scenario presenter))))
    (and body (scenario-body-shape body))))

(defun sign-under-assumptions (presenter expression)
  ":POSITIVE, :NEGATIVE or :ZERO when the assumptions decide the sign of EXPRESSION, else NIL."
  (cond ((and (realp expression) (zerop expression)) :zero)
        ((realp expression) (if (plusp expression) :positive :negative))
        ((holds-under-assumptions-p presenter (list '> expression 0)) :positive)
        ((holds-under-assumptions-p presenter (list '< expression 0)) :negative)
        ((handler-case (ames.maxima:equivalent-p (presenter-bridge presenter) expression 0)
           (ames.maxima:maxima-condition () nil))
         :zero)))

(defun edge-points (shape index)
  "The start and end points of edge INDEX of the shape form SHAPE, or NIL. A polygon's
edge i runs from vertex i to vertex i+1; a half-plane's or segment's edge 0 from its
first point to its second."
  (case (shape-kind shape)
    (:polygon (let ((vertices (rest shape)))
                (and (< index (length vertices))
                     (list (nth index vertices) (nth (mod (1+ index) (length vertices)) vertices)))))
    ((:half-plane :segment) (and (eql index 0) (list (second shape) (third shape))))))

(defun edge-facing (presenter shape index)
  "Where the outward normal of edge INDEX of SHAPE points (the solid on the edge's left):
:UP, :DOWN, :LEFT, :RIGHT, :UP-RIGHT, :UP-LEFT, :DOWN-RIGHT, :DOWN-LEFT, or NIL when
not decided."
  (let ((points (edge-points shape index)))
    (when points
      (destructuring-bind ((x1 y1) (x2 y2)) points
        ;; the outward normal of a counter-clockwise boundary is (dy, -dx)
        (let ((nx (sign-under-assumptions presenter (list '- y2 y1)))
              (ny (sign-under-assumptions presenter (list '- x1 x2))))
          (cond ((and (eq nx :zero) (eq ny :positive)) :up)
                ((and (eq nx :zero) (eq ny :negative)) :down)
                ((and (eq ny :zero) (eq nx :positive)) :right)
                ((and (eq ny :zero) (eq nx :negative)) :left)
                ((and (eq nx :positive) (eq ny :positive)) :up-right)
                ((and (eq nx :negative) (eq ny :positive)) :up-left)
                ((and (eq nx :positive) (eq ny :negative)) :down-right)
                ((and (eq nx :negative) (eq ny :negative)) :down-left)))))))

(defun edge-word (shape facing &optional qualified)
  "The word for an edge of SHAPE facing FACING; QUALIFIED tells a slant's side too."
  (let ((side (and qualified (case facing ((:up-right :down-right) "right ") ((:up-left :down-left) "left ")))))
    (if (member (shape-kind shape) '(:half-plane))
        (case facing (:up "surface") (:down "underside") ((:left :right) "face")
              ((:up-right :up-left) "slope") ((:down-right :down-left) "overhang"))
        (case facing (:up "top") (:down "base") (:left "left side") (:right "right side")
              ((:up-right :up-left) (format nil "~@[~A~]slope" side))
              ((:down-right :down-left) (format nil "~@[lower ~A~]~:[underside~;face~]" side side))))))

(defun edge-name (presenter body index)
  "\"the slope\" for edge INDEX of BODY when its facing is decided and no other edge of
the body has the same word (\"the right slope\" when that tells them apart), else
\"edge INDEX\"."
  (let* ((key (list :edge-facings body))
         (shape (body-shape-form presenter body))
         (facings (multiple-value-bind (known found) (gethash key (presenter-cache presenter))
                    (if found
                        known
                        (setf (gethash key (presenter-cache presenter))
                              (loop for i from 0 below (case (shape-kind shape)
                                                         (:polygon (length (rest shape)))
                                                         ((:half-plane :segment) 1)
                                                         (t 0))
                                    collect (edge-facing presenter shape i))))))
         (plain (mapcar (lambda (f) (edge-word shape f)) facings))
         (qualified (mapcar (lambda (f) (edge-word shape f t)) facings)))
    (flet ((unique (words)
             (let ((word (nth index words)))
               (and word (= 1 (count word words :test #'equal)) word))))
      (let ((word (or (unique plain) (unique qualified))))
        (if word (format nil "the ~A" word) (format nil "edge ~D" index))))))

(defun feature-phrase (presenter feature)
  "A phrase naming FEATURE, such as (:edge 1 :of wedge): (\"the slope of wedge\")."
  (if (not (and (consp feature) (keywordp (first feature))))
      (list (format nil "~(~A~)" feature))
      (let* ((kind (first feature))
             (index (and (integerp (second feature)) (second feature)))
             (body (getf (if index (cddr feature) (rest feature)) :of))
             (shape (and body (body-shape-form presenter body)))
             (of (name-text body)))
        (case kind
          (:point (list of))
          (:circle (list (format nil "the rim of ~A" of)))
          (:arc (list (if (eq (shape-kind shape) :arc) (format nil "the arc of ~A" of)
                          (format nil "arc ~D of ~A" index of))))
          (:edge (list (format nil "~A of ~A" (if shape (edge-name presenter body index)
                                                  (format nil "edge ~D" index))
                               of)))
          (:vertex (let ((vertex (and (eq (shape-kind shape) :polygon) (nth index (rest shape)))))
                     (if vertex
                         (phrase "the corner (" (present presenter (first vertex)) ", "
                                 (present presenter (second vertex)) (format nil ") of ~A" of))
                         (list (format nil "vertex ~D of ~A" index of)))))
          (t (list (format nil "~A~@[ ~D~] of ~A" (keyword-words kind) index of)))))))

(defun supporting-p (presenter feature)
  "True when FEATURE is an edge whose outward normal points up (a floor, a slope)."
  (and (consp feature) (eq (first feature) :edge)
       (let ((body (getf (cddr feature) :of)))
         (member (edge-facing presenter (body-shape-form presenter body) (second feature))
                 '(:up :up-right :up-left)))))

(defun contact-phrase (presenter contact)
  "A phrase for CONTACT (B1 B2 :FEATURE F :OBSERVER-FEATURE G): \"particle on the slope
of wedge\", \"the right side of block-b against the face of wall\"."
  (destructuring-bind (b1 b2 &key feature observer-feature &allow-other-keys) contact
    (let ((observer (if observer-feature (feature-phrase presenter observer-feature) (list (name-text b1))))
          (obstacle (if feature (feature-phrase presenter feature) (list (name-text b2)))))
      (cond ((supporting-p presenter feature) (append observer (list " on ") obstacle))
            ((supporting-p presenter observer-feature) (append obstacle (list " on ") observer))
            ((member (first feature) '(:circle :arc)) (append observer (list " on ") obstacle))
            (t (append observer (list " against ") obstacle))))))

;;; Forces

(defun vector-value-p (x)
  "True when X is a vector (X Y) of arithmetic expressions."
  (and (consp x) (= 2 (length x)) (every (lambda (c) (valid-expression-p c :kind :arithmetic)) x)))

(defparameter *force-phrases*
  '((:normal "normal force of ~*~A on ~:*~:*~A" 2 "N")
    (:gravity "weight of ~A" 1 nil)
    (:external "external force ~A on ~A" 2 nil)
    (:friction "friction of ~*~A on ~:*~:*~A" 2 "F")
    (:spring "spring ~A on ~A" 2 nil)
    (:tension "tension in ~A" 1 "T")
    (:gravitation "gravitation of ~*~A on ~:*~:*~A" 2 nil)
    (:drag "drag ~A on ~A" 2 nil))
  "Each force kind with the FORMAT control of its label (over its leading names), how
many names lead its entry, and the symbol of a scalar value.")

(defun force-entry (entry)
  "The parts of a reported force ENTRY (KIND NAME... VALUE [:KEY VALUE ...]) as
(values LABEL SYMBOL VALUE OPTIONS): LABEL a string, SYMBOL a string or NIL, VALUE an
expression, a vector (X Y) or NIL, OPTIONS a plist. Unknown kinds are taken apart
generically: the names first, the value last."
  (let* ((kind (first entry))
         (positional (loop for x in (rest entry) until (keywordp x) collect x))
         (options (nthcdr (length positional) (rest entry)))
         (known (assoc kind *force-phrases*))
         (value-p (lambda (x) (or (vector-value-p x)
                                  (and (not (symbolp x)) (valid-expression-p x :kind :arithmetic)))))
         (names (if known
                    (subseq positional 0 (min (third known) (length positional)))
                    (if (and positional (funcall value-p (car (last positional))))
                        (butlast positional)
                        positional)))
         (value (let ((rest (nthcdr (length names) positional)))
                  (and rest
                       (if known
                           (or (vector-value-p (first rest))
                               (valid-expression-p (first rest) :kind :arithmetic))
                           (funcall value-p (first rest)))
                       (first rest)))))
    (values (if (and known (= (length names) (third known)))
                (apply #'format nil (second known) (mapcar #'name-text names))
                (format nil "~A~{ ~A~}" (keyword-words kind) (mapcar #'name-text names)))
            (if (vector-value-p value) nil (and known (fourth known)))
            value
            options)))

(defparameter *impulse-phrases*
  '((:impulse "impulse of ~*~A on ~:*~:*~A" 2)
    (:rope-impulse "impulse of the jerk along ~A" 1))
  "Each impulse kind an impact reports, with the FORMAT control of its label over its
leading names and how many names lead its entry.")

(defun impulse-entry (entry)
  "The parts of an impact's impulse ENTRY (KIND NAME... MAGNITUDE) as (values LABEL
MAGNITUDE): LABEL a string, MAGNITUDE an expression or NIL. Unknown kinds are taken apart
generically: the names first, the magnitude last."
  (let* ((kind (first entry))
         (known (assoc kind *impulse-phrases*))
         (value (car (last (rest entry))))
         (magnitude (and (rest entry) (not (symbolp value))
                         (valid-expression-p value :kind :arithmetic) value))
         (names (if magnitude (butlast (rest entry)) (rest entry))))
    (values (if (and known (= (length names) (third known)))
                (apply #'format nil (second known) (mapcar #'name-text names))
                (format nil "~A~{ ~A~}" (keyword-words kind) (mapcar #'name-text names)))
            magnitude)))

;;; Events

(defun contact-of (state a b)
  "The contact of STATE between A and B (either way round), or NIL."
  (find-if (lambda (c) (or (and (eq (first c) a) (eq (second c) b))
                           (and (eq (first c) b) (eq (second c) a))))
           (state-contacts state)))

(defun event-phrase (presenter event &optional state)
  "A phrase for an end EVENT of STATE (any kind the knowledge base names; unknown kinds
generically, their options as \"key value\")."
  (cond
    ((eq event :none) (list "nothing more changes"))
    ((eq event :undecided) (list "undecided: the assumptions do not decide which event comes first"))
    ((not (and (consp event) (keywordp (first event)))) (list (format nil "~(~A~)" event)))
    (t
     (let* ((kind (first event))
            (positional (loop for x in (rest event) until (keywordp x) collect x))
            (options (nthcdr (length positional) (rest event)))
            (a (name-text (first positional))) (b (name-text (second positional)))
            ;; an impact's impulse and energy lost have their own section ("the impact")
            (shown-elsewhere (if (and state (getf (state-notes state) :impact))
                                 '(:endpoint :impulse :energy-lost)
                                 '(:endpoint)))
            (extra (loop for (key value) on options by #'cddr
                         when (and key (not (member key shown-elsewhere)))
                           append (list (format nil ", ~A " (keyword-words key))
                                        (if (valid-expression-p value :kind :arithmetic)
                                            (list :math (present presenter value))
                                            (format nil "~(~A~)" value))))))
       (append
        (case kind
          (:leaves (let ((contact (and state (contact-of state (first positional) (second positional)))))
                     (if contact
                         (append (list (format nil "~A reaches the end of " a))
                                 (let ((feature (getf (cddr contact) :feature)))
                                   (if (eq (first contact) (first positional))
                                       (feature-phrase presenter feature)
                                       (feature-phrase presenter (getf (cddr contact) :observer-feature)))))
                         (list (format nil "~A leaves ~A past the end of the contact" a b)))))
          (:lift-off (list (format nil "~A lifts off ~A (the normal force would turn attractive)" a b)))
          (:contact (list (format nil "~A comes into contact with ~A" a b)))
          (:collision (list (format nil "~A collides with ~A" a b)))
          (:contact-ends (list (format nil "the contact of ~A with ~A ends" a b)))
          (:starts-sliding (list (format nil "~A starts sliding on ~A" a b)))
          (:stops-sliding (list (format nil "~A stops sliding on ~A" a b)))
          (:slackens (list (format nil "~A goes slack" a)))
          (:tightens (list (format nil "~A becomes taut" a)))
          (:branch (list "the run branches"))
          (:time-limit (phrase "the time limit t = " (present presenter (first positional)) " is reached"))
          (t (list (format nil "~A~{ ~A~}" (keyword-words kind) (mapcar #'name-text positional)))))
        (remove nil extra))))))
