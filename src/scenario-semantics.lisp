;;;; src/scenario-semantics.lisp -- the checks of a scenario that need Maxima: assumptions, signs, orientation.
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

(in-package #:ames)

(define-condition missing-assumption-error (scenario-error)
  ((fact :initarg :fact :initform nil :reader missing-assumption-fact
         :documentation "The relation that the assumptions neither prove nor refute."))
  (:documentation "A fact the scenario needs (a positive mass, a counter-clockwise
polygon...) that its parameter assumptions do not decide. DATUM is the fact."))

(defun scenario-detail (scenario control &rest arguments)
  "The detail string of a condition about SCENARIO: CONTROL applied to ARGUMENTS,
forms printed short and in the scenario's package."
  (with-standard-io-syntax
    (let ((*print-readably* nil) (*print-level* 4) (*print-length* 8)
          (*package* (form-package (scenario-name scenario))))
      (apply #'format nil control arguments))))

(defun semantic-reject (scenario class location datum control &rest arguments)
  "Signal a scenario error of CLASS about SCENARIO at LOCATION (a string)."
  (error class :scenario (scenario-name scenario) :location location
               :source (scenario-source scenario) :datum datum
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
                            'scenario-shape-error))))))

(defun scenario-facts (scenario)
  "Every fact SCENARIO needs, as a list of (LOCATION RELATION WHAT CLASS)."
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
                 "the :until time is positive" 'scenario-expression-error)))))

(defun decide-fact (bridge relation)
  "The truth of RELATION under the bridge's current assumptions; when Maxima's first
answer is :UNKNOWN, asks again about the fully simplified difference of its sides."
  (let ((verdict (ames.maxima:decide bridge relation)))
    (if (eq verdict :unknown)
        (ames.maxima:decide bridge
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

(defun check-scenario-assumptions (scenario bridge)
  "Check, through the Maxima BRIDGE and under SCENARIO's parameter assumptions, what
PARSE-SCENARIO could not decide with numbers: that the assumptions are consistent, that
masses, radii and the :until time are positive, that arcs and polygons run
counter-clockwise. Returns SCENARIO.
Signals CONTRADICTORY-ASSUMPTIONS-ERROR (wrapping the bridge's INCONSISTENT-ASSUMPTIONS)
naming the parameter, SCENARIO-EXPRESSION-ERROR or SCENARIO-SHAPE-ERROR naming the body
for a fact that is false, MISSING-ASSUMPTION-ERROR naming the fact that the assumptions
do not decide, and the bridge's own conditions when Maxima fails."
  (let ((facts (scenario-facts scenario)))
    (handler-case
        (ames.maxima:call-with-assumptions
         bridge (scenario-assumption-relations scenario)
         (lambda ()
           (loop for (location relation what class) in facts
                 do (ecase (decide-fact bridge relation)
                      (:true)
                      (:false (semantic-reject scenario class location relation
                                               "it is false that ~A: ~S" what relation))
                      (:unknown
                       (error 'missing-assumption-error
                              :scenario (scenario-name scenario) :location location
                              :source (scenario-source scenario) :datum relation
                              :fact relation
                              :detail (scenario-detail
                                       scenario "the assumptions do not show that ~A; ~
                                                 declare what makes ~S hold"
                                       what relation)))))))
      (ames.maxima:inconsistent-assumptions (condition)
        (let ((fact (ames.maxima:inconsistent-assumptions-fact condition)))
          (error 'contradictory-assumptions-error
                 :scenario (scenario-name scenario)
                 :location (assumption-location scenario fact)
                 :source (scenario-source scenario)
                 :datum (or fact (scenario-assumption-relations scenario))
                 :cause condition
                 :detail (scenario-detail scenario "the assumption ~S contradicts the others"
                                          fact)))))
    scenario))
