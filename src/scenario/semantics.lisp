;;;; src/scenario/semantics.lisp -- the checks of a scenario that need Maxima: assumptions, signs, orientation.
;;;;
;;;; PARSE-SCENARIO decides what numbers decide. What depends on symbolic parameters
;;;; is decided here, through the Maxima bridge, under the scenario's own assumptions:
;;;;   - the assumptions are consistent (the bridge's INCONSISTENT-ASSUMPTIONS becomes a
;;;;     CONTRADICTORY-ASSUMPTIONS-ERROR naming the parameter);
;;;;   - every mass is positive, every radius positive, every :until time positive;
;;;;   - every arc runs counter-clockwise by at most a full turn;
;;;;   - every polygon's vertices run counter-clockwise (its signed area is positive).
;;;; A fact that is false is the matching SCENARIO-ERROR; a fact that Maxima cannot
;;;; decide is a MISSING-ASSUMPTION-ERROR naming it (the scenario-language page: "where
;;;; it cannot be decided, the scenario is rejected with an error naming the fact that
;;;; is missing").
;;;;
;;;; CHECK-SCENARIO-GEOMETRY then hands every shape to the geometry layer's parser
;;;; (self-intersecting polygons, outlines that do not join...) and builds the
;;;; configuration-space contacts of every pair of bodies that are not both fixed, to
;;;; reject bodies that overlap at the start. Fixed bodies are all part of the fixed
;;;; frame: they may touch or overlap each other (a floor and a wall). Geometry's
;;;; conditions are wrapped into SCENARIO-ERRORs naming the body or the pair.
;;;; CHECK-SCENARIO runs both under one scope of the scenario's assumptions, and returns
;;;; the shapes and pairs it built as the scenario's WORLD (world.lisp), which the
;;;; simulator runs in: the geometry is derived once.

(in-package #:ames.scenario)

(define-condition missing-assumption-error (scenario-error)
  ((fact :initarg :fact :initform nil :reader missing-assumption-fact
         :documentation "The relation that the assumptions neither prove nor refute."))
  (:documentation "A fact the scenario needs (a positive mass, a counter-clockwise
polygon...) that its parameter assumptions do not decide. DATUM is the fact."))

(setf (documentation 'missing-assumption-fact 'function)
      "The relation that the scenario's assumptions neither prove nor refute.")

(defun scenario-detail (scenario control &rest arguments)
  "The detail string of a condition about SCENARIO: CONTROL applied to ARGUMENTS,
forms printed short and in the scenario's package."
  (with-standard-io-syntax
    (let ((*print-readably* nil) (*print-level* 4) (*print-length* 8)
          (*package* (form-package (scenario-name scenario))))
      (apply #'format nil control arguments))))

(defun location-body (scenario location)
  "The body of SCENARIO that LOCATION (\"body X\" or \"bodies X and Y\") names first, or
NIL."
  (find-if (lambda (body)
             (let ((name (symbol-name (scenario-body-name body))))
               (or (equal location (format nil "body ~A" name))
                   (eql 0 (search (format nil "bodies ~A and " name) location)))))
           (scenario-bodies scenario)))

(defun location-clause (scenario location)
  "The clause of SCENARIO's form that LOCATION names by its words (\"spring S\",
\"friction A B\", \"clause GRAVITATION\": the clause's word, then its first names), or NIL."
  (let* ((words (cl-ppcre:split "\\s+" (string-upcase location)))
         (words (if (equal (first words) "CLAUSE") (rest words) words))
         (form (scenario-form scenario)))
    (and words (alexandria:proper-list-p form)
         (find-if (lambda (clause)
                    (and (alexandria:proper-list-p clause)
                         (>= (length clause) (length words))
                         (every (lambda (word x) (and (symbolp x) (string= word (symbol-name x))))
                                words clause)))
                  form))))

(defun location-source (scenario location)
  "\"FILE, line N\" for LOCATION in SCENARIO: the clause of the body that LOCATION
names first, else the clause LOCATION names (LOCATION-CLAUSE), else the scenario's
SOURCE."
  (let ((body (location-body scenario location))
        (positions (scenario-positions scenario)))
    (if body
        (scenario-body-source scenario (scenario-body-name body))
        (let* ((clause (and positions (location-clause scenario location)))
               (line (and clause (form-line positions clause))))
          (if line (source-description positions line) (scenario-source scenario))))))

(defun location-context (scenario location)
  "The ERROR-CONTEXT of LOCATION (a string such as \"body X\") in SCENARIO: its file,
the line of the body's clause (else the scenario's), the scenario's name."
  (let* ((positions (scenario-positions scenario))
         (body (location-body scenario location))
         (form (scenario-form scenario))
         (clause (and body (alexandria:proper-list-p form)
                      (find-if (lambda (clause) (and (consp clause) (consp (cdr clause))
                                                     (eq (second clause) (scenario-body-name body))))
                               form))))
    (make-error-context :file (and positions (source-text-file positions))
                        :line (and positions (or (and clause (form-line positions clause))
                                                 (form-line positions form)))
                        :scenario (scenario-name scenario) :location location)))

(defun semantic-reject (scenario class location datum control &rest arguments)
  "Signal a scenario error of CLASS about SCENARIO at LOCATION (a string)."
  (error class :scenario (scenario-name scenario) :location location
               :source (location-source scenario location) :datum datum
               :detail (apply #'scenario-detail scenario control arguments)))

(defun polygon-signed-area (polygon)
  "Twice the signed area of the checked POLYGON, as an expression: positive when its
vertices run counter-clockwise."
  (let ((vertices (rest polygon)))
    (cons '+ (loop for (a b) on (append vertices (list (first vertices)))
                   while b
                   collect `(- (* ,(first a) ,(second b)) (* ,(first b) ,(second a)))))))

(defun shape-facts (shape)
  "The facts SHAPE (checked) needs, as a list of (RELATION WHAT CLASS)."
  (flet ((arc-facts (arc)
           (destructuring-bind (&key radius from to &allow-other-keys) (rest arc)
             (list (list `(> ,radius 0) "the arc's radius is positive" 'scenario-shape-error)
                   (list `(> ,to ,from) "the arc's :to exceeds its :from" 'scenario-shape-error)
                   (list `(<= (- ,to ,from) (* 2 pi)) "the arc turns at most a full circle"
                         'scenario-shape-error)))))
    (ecase (shape-kind shape)
      ((:point :segment :half-plane) '())
      (:circle (list (list `(> ,(second shape) 0) "the circle's radius is positive"
                           'scenario-shape-error)))
      (:arc (arc-facts shape))
      (:outline (loop for piece in (rest shape)
                      when (eq (first piece) 'ames-scenario:arc)
                        append (arc-facts piece)))
      (:polygon (list (list `(> ,(polygon-signed-area shape) 0)
                            "the polygon's vertices run counter-clockwise"
                            'scenario-shape-error
                            :datum shape
                            :if-false (format nil "they run clockwise; list them counter-clockwise: ~A"
                                              (short-form-string (counter-clockwise-polygon shape)
                                                                 (form-package shape)))))))))

(defun scenario-facts (scenario)
  "Every fact SCENARIO needs, as a list of (LOCATION RELATION WHAT CLASS . OPTIONS), the
OPTIONS a plist: :LENIENT true for a fact checked only where the assumptions decide it,
:DATUM the form at fault (else RELATION), :IF-FALSE what the message adds when it is
false (the vertices in the right order, say)."
  (append
   (loop for body in (scenario-bodies scenario)
         for location = (format nil "body ~A" (symbol-name (scenario-body-name body)))
         append (append
                 (when (scenario-body-mass body)
                   (list (list location `(> ,(scenario-body-mass body) 0)
                               "the mass is positive" 'scenario-expression-error)))
                 (mapcar (lambda (fact) (cons location fact))
                         (shape-facts (scenario-body-shape body)))))
   (when (scenario-until scenario)
     (list (list "clause SIMULATE" `(> ,(scenario-until scenario) 0)
                 "the :until time is positive" 'scenario-expression-error)))
   (coefficient-facts scenario)
   (rotation-facts scenario)))

(defun decide-fact (bridge relation)
  "The truth of RELATION under the bridge's current assumptions; when Maxima's first
answer is :UNKNOWN, asks again about the fully simplified difference of its sides."
  (let ((verdict (ames.algebra:decide bridge relation)))
    (if (eq verdict :unknown)
        (ames.algebra:decide bridge
                            (make-relation (first relation)
                                           (ames.maxima:simplify
                                            bridge `(- ,(relation-lhs relation)
                                                       ,(relation-rhs relation))
                                            :strategy :full)
                                           0))
        verdict)))

(defun assumption-location (scenario fact)
  "Where SCENARIO declares the assumption FACT: \"parameter X\", or the clause."
  (let ((parameter (find-if (lambda (parameter)
                              (member fact (scenario-parameter-assumptions parameter)
                                      :test (lambda (fact assumption)
                                              (equal fact (assumption-relation
                                                           (scenario-parameter-name parameter)
                                                           assumption)))))
                            (scenario-parameters scenario))))
    (if parameter
        (format nil "parameter ~A" (symbol-name (scenario-parameter-name parameter)))
        "clause PARAMETERS")))

(defun call-with-scenario-assumptions (scenario bridge thunk)
  "Call THUNK with SCENARIO's parameter assumptions in force in BRIDGE; return its
values. Signals CONTRADICTORY-ASSUMPTIONS-ERROR, naming the parameter, when Maxima
finds the assumptions inconsistent (the bridge's INCONSISTENT-ASSUMPTIONS is its CAUSE)."
  (handler-case
      (ames.maxima:call-with-assumptions bridge (scenario-assumption-relations scenario) thunk)
    (ames.maxima:inconsistent-assumptions (condition)
      (let ((fact (ames.maxima:inconsistent-assumptions-fact condition)))
        (error 'contradictory-assumptions-error
               :scenario (scenario-name scenario)
               :location (assumption-location scenario fact)
               :source (scenario-source scenario)
               :datum (or fact (scenario-assumption-relations scenario))
               :cause condition
               :detail (scenario-detail scenario "the assumption ~S contradicts the others"
                                        fact))))))

(defun check-facts (scenario bridge)
  "Decide every fact SCENARIO needs (see SCENARIO-FACTS) under the assumptions in
force; signal for the first that is false or undecided."
  (loop for (location relation what class . options) in (scenario-facts scenario)
        for lenient = (getf options :lenient)
        do (ecase (if (and lenient (not (expression-variables relation)))
                      ;; a number: decided exactly, never asked of Maxima's sign rules
                      (or (ames.algebra:value-truth relation '((nil . 0))) :unknown)
                      (decide-fact bridge relation))
             (:true)
             (:false (semantic-reject scenario class location (or (getf options :datum) relation)
                                      "it is false that ~A~@[; ~A~]" what
                                      (getf options :if-false)))
             (:unknown
              (unless lenient
               (error 'missing-assumption-error
                     :scenario (scenario-name scenario) :location location
                     :source (location-source scenario location) :datum relation :fact relation
                     :detail (scenario-detail scenario "the assumptions do not show that ~A; ~
                                                        declare what makes ~S hold"
                                              what relation)))))))

(defun check-scenario-assumptions (scenario bridge)
  "Check, through the Maxima BRIDGE and under SCENARIO's parameter assumptions, what
PARSE-SCENARIO could not decide with numbers: that the assumptions are consistent, that
masses, radii and the :until time are positive, that arcs and polygons run
counter-clockwise. Returns SCENARIO.
Signals CONTRADICTORY-ASSUMPTIONS-ERROR (wrapping the bridge's INCONSISTENT-ASSUMPTIONS)
naming the parameter, SCENARIO-EXPRESSION-ERROR or SCENARIO-SHAPE-ERROR naming the body
for a fact that is false, MISSING-ASSUMPTION-ERROR naming the fact that the assumptions
do not decide, and the bridge's own conditions when Maxima fails."
  (call-with-scenario-assumptions scenario bridge
                                  (lambda () (check-facts scenario bridge)))
  scenario)

(defun call-wrapping-geometry-conditions (scenario location thunk)
  "Call THUNK; turn the geometry layer's INVALID-SHAPE, UNSUPPORTED-SHAPE-PAIR and
UNDECIDABLE-GEOMETRIC-FACT into SCENARIO-ERRORs of SCENARIO at LOCATION; give other
AMES-ERRORs leaving THUNK (a BUDGET-EXCEEDED, a Maxima failure) the context of LOCATION."
  (flet ((wrap (class condition datum &rest initargs)
           (apply #'error class
                  :scenario (scenario-name scenario) :location location
                  :source (location-source scenario location) :cause condition
                  :datum (or datum location)
                  :detail (ames-error-detail condition)
                  initargs)))
    (handler-case
        ;; other conditions (the budget's, Maxima's) leave as they are, with the place
        (handler-bind ((ames-error
                         (lambda (condition)
                           (unless (or (ames-error-context condition)
                                       (typep condition '(or scenario-error
                                                          ames.geometry:invalid-shape
                                                          ames.geometry:unsupported-shape-pair
                                                          ames.geometry:undecidable-geometric-fact)))
                             (setf (ames-error-context condition)
                                   (location-context scenario location))))))
          (funcall thunk))
      (ames.geometry:invalid-shape (condition)
        (wrap 'scenario-shape-error condition (ames-error-datum condition)))
      (ames.geometry:unsupported-shape-pair (condition)
        (wrap 'scenario-shape-error condition (ames-error-datum condition)))
      (ames.geometry:undecidable-geometric-fact (condition)
        (let ((fact (ames.geometry:undecidable-fact condition)))
          (error 'missing-assumption-error
                 :scenario (scenario-name scenario) :location location
                 :source (location-source scenario location) :cause condition
                 :datum (or fact location) :fact fact
                 :detail (scenario-detail scenario "the geometry needs to know whether ~S, ~
                                                    and ~A"
                                          fact (ames-error-detail condition))))))))

(defun scenario-pair (scenario bridge body shape other other-shape)
  "The contact pair of SCENARIO's bodies BODY and OTHER, of the parsed SHAPE and
OTHER-SHAPE, checked not to overlap at the start; geometry conditions named by the pair."
  (let ((location (format nil "bodies ~A and ~A"
                          (symbol-name (scenario-body-name body))
                          (symbol-name (scenario-body-name other)))))
    (call-wrapping-geometry-conditions
     scenario location
     (lambda ()
       (let* ((pair (ames.geometry:make-contact-pair
                     (scenario-body-name body) shape
                     (scenario-body-name other) other-shape
                     :bridge bridge
                     ;; as the simulator does, so that the two agree on
                     ;; the observer and the bridge's cache serves both
                     :fixed (mapcar #'scenario-body-name
                                    (scenario-fixed-bodies scenario))))
              (observer (if (eq (ames.geometry:pair-observer pair)
                                (scenario-body-name body))
                            body other))
              (obstacle (if (eq observer body) other body)))
         (when (ames.geometry:penetrates-p
                pair (ames.geometry:relative-position
                      pair (scenario-body-position observer)
                      (scenario-body-position obstacle)))
           (semantic-reject
            scenario 'overlapping-bodies-error location
            (list (scenario-body-name body) (scenario-body-name other))
            "~A and ~A overlap at the start"
            (symbol-name (scenario-body-name body))
            (symbol-name (scenario-body-name other))))
         pair)))))

(defun scenario-geometry (scenario bridge)
  "Parse every shape of SCENARIO with the geometry layer and check that no two bodies,
not both fixed, overlap at the start; return the WORLD so built (the shapes and the
contact pairs). Call under the scenario's assumptions."
  (let* ((shapes
           (loop for body in (scenario-bodies scenario)
                 collect (let ((body body))
                           (call-wrapping-geometry-conditions
                            scenario (format nil "body ~A" (symbol-name (scenario-body-name body)))
                            (lambda ()
                              (ames.geometry:parse-shape (scenario-body-shape body)
                                                         :bridge bridge))))))
         ;; each pair of bodies not both fixed: (BODY SHAPE OTHER OTHER-SHAPE)
         (pairings (loop for (body . more-bodies) on (scenario-bodies scenario)
                         for (shape . more-shapes) on shapes
                         append (loop for other in more-bodies
                                      for other-shape in more-shapes
                                      unless (or (and (scenario-body-fixed-p body)
                                                      (scenario-body-fixed-p other))
                                                 ;; a turning polygon's contacts are its
                                                 ;; corners' (the simulator's corners.lisp):
                                                 ;; no translating obstacle describes them
                                                 (corner-shaped-rotating-p body)
                                                 (corner-shaped-rotating-p other))
                                        collect (list body shape other other-shape))))
         (deferred (screened-pairings scenario pairings))
         (ordinals (and deferred (pairing-ordinals pairings deferred)))
         (built (if deferred
                    (loop for pairing in pairings for ordinal from 0
                          unless (gethash ordinal deferred) collect pairing)
                    pairings))
         (pairs
           ;; the pairs' simplifications asked first, many in a round trip, and the
           ;; obstacles' boundaries computed once (no result changes)
           (ames.geometry:call-with-prefetched-contact-pairs
            (loop for (body shape other other-shape) in built
                  collect (list (scenario-body-name body) shape
                                (scenario-body-name other) other-shape))
            (lambda ()
              (loop for (body shape other other-shape) in built
                    collect (scenario-pair scenario bridge body shape other other-shape)))
            :bridge bridge
            :fixed (mapcar #'scenario-body-name (scenario-fixed-bodies scenario)))))
    (make-world scenario
                (mapcar (lambda (body shape) (cons (scenario-body-name body) shape))
                        (scenario-bodies scenario) shapes)
                pairs
                :ordinals ordinals
                :deferred (loop for ordinal from 0
                                for (body nil other) in pairings
                                when (and deferred (gethash ordinal deferred))
                                  collect (list ordinal (scenario-body-name body)
                                                (scenario-body-name other))))))

(defun check-scenario-geometry (scenario bridge)
  "Check SCENARIO's shapes with the geometry layer (ames.geometry:parse-shape) and that
no two of its bodies (not both fixed) overlap at the start, through the Maxima BRIDGE
under the scenario's assumptions. Returns SCENARIO.
Signals SCENARIO-SHAPE-ERROR naming the body (wrapping geometry's INVALID-SHAPE) or the
pair (UNSUPPORTED-SHAPE-PAIR), OVERLAPPING-BODIES-ERROR naming the pair,
MISSING-ASSUMPTION-ERROR for a geometric fact that the assumptions do not decide, and
CONTRADICTORY-ASSUMPTIONS-ERROR. The second value is the WORLD built (see world.lisp)."
  (values scenario
          (call-with-scenario-assumptions scenario bridge
                                          (lambda () (scenario-geometry scenario bridge)))))

(defun check-scenario (scenario bridge)
  "Every check of SCENARIO that needs Maxima and geometry, under one scope of its
assumptions (and whatever BRIDGE has in force besides): CHECK-SCENARIO-ASSUMPTIONS, then
CHECK-SCENARIO-GEOMETRY. Returns SCENARIO and, as a second value, its WORLD: the shapes
and contact pairs the checks built, which the simulation runs in. Signals what they
signal."
  (values scenario
          (call-with-scenario-assumptions scenario bridge
                                          (lambda ()
                                            (check-facts scenario bridge)
                                            (scenario-geometry scenario bridge)))))
