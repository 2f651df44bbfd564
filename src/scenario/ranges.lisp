;;;; src/scenario/ranges.lisp -- the physical range of every coefficient a clause declares, checked
;;;; under the assumptions and again on a run's numbers.
;;;;
;;;; A coefficient outside its physical range gives a wrong answer, not an error: friction
;;;; with mu < 0 accelerates a block forever, a restitution above 1 makes energy, a negative
;;;; stiffness turns Hooke's oscillation into sinh. So each of these is a fact the scenario
;;;; must make hold (COEFFICIENT-FACTS), decided like a mass's sign by CHECK-FACTS under the
;;;; parameters' assumptions (false: an error naming the clause; undecided: a
;;;; MISSING-ASSUMPTION-ERROR asking to declare it):
;;;;   friction A B     0 <= mu-s, 0 <= mu-k <= mu-s
;;;;   restitution      0 <= e <= 1
;;;;   spring S         k > 0, rest length > 0
;;;;   rope R           length > 0; each piece between its points > 0 at the start (lenient)
;;;;   gravitation      G > 0
;;;; One fact is checked only where it can be decided (LENIENT): a rope is at least as long
;;;; as the path through its attachment points and pulleys at the start (taut when equal);
;;;; shorter, it could not be tied. A defaulted rest length (the start distance) is lenient
;;;; too. CHECK-COEFFICIENT-VALUES checks every one of them again on the numbers of a run
;;;; (--set, --numeric), so that a value names the clause it breaks.

(in-package #:ames.scenario)

(defun scenario-pulley-named (scenario name)
  "The SCENARIO-PULLEY of SCENARIO named NAME (a symbol), or NIL."
  (find name (scenario-pulleys scenario) :key #'scenario-pulley-name))

(defun rope-point-at-start (scenario point)
  "Where the rope's POINT is at the start: (BODY (X Y)) is the body's position plus (X Y),
a pulley name its body's position plus its point; a list (X Y) of expressions."
  (multiple-value-bind (body offset)
      (if (consp point)
          (values (first point) (second point))
          (let ((pulley (scenario-pulley-named scenario point)))
            (values (scenario-pulley-body pulley) (scenario-pulley-point pulley))))
    (let ((position (scenario-body-position
                     (find body (scenario-bodies scenario) :key #'scenario-body-name))))
      (mapcar (lambda (p x) `(+ ,p ,x)) (or position '(0 0)) offset))))

(defun rope-start-path-length (scenario rope)
  "The length at the start of the path of ROPE through its points (an expression): the
sum of its pieces' (ROPE-PIECE-LENGTHS)."
  (cons '+ (rope-piece-lengths scenario rope)))

(defun body-names-location (word bodies)
  "\"WORD A B\" for the clause WORD about BODIES, or \"clause WORD\" without bodies."
  (if bodies
      (format nil "~(~A~)~{ ~A~}" word (mapcar #'symbol-name bodies))
      (format nil "clause ~A" word)))

(defun friction-facts (friction)
  "The facts of one SCENARIO-FRICTION: its coefficients are not negative, and the
kinetic does not exceed the static."
  (let ((location (body-names-location "FRICTION" (scenario-friction-bodies friction)))
        (static (scenario-friction-static friction))
        (kinetic (scenario-friction-kinetic friction)))
    (append (list (list location `(>= ,static 0)
                        "the :static coefficient of friction is not negative"
                        'scenario-expression-error))
            (unless (equal kinetic static)
              (list (list location `(>= ,kinetic 0)
                          "the :kinetic coefficient of friction is not negative"
                          'scenario-expression-error)
                    (list location `(<= ,kinetic ,static)
                          "the :kinetic coefficient of friction does not exceed the :static one"
                          'scenario-expression-error))))))

(defun restitution-facts (entry)
  "The facts of one restitution ENTRY (BODY1 BODY2 E): 0 <= E <= 1."
  (destructuring-bind (body-1 body-2 e) entry
    (let ((location (body-names-location "RESTITUTION" (and body-1 (list body-1 body-2)))))
      (list (list location `(>= ,e 0) "the coefficient of restitution is not negative"
                  'scenario-expression-error)
            (list location `(<= ,e 1) "the coefficient of restitution is at most 1"
                  'scenario-expression-error)))))

(defun spring-facts (spring)
  "The facts of one SCENARIO-SPRING: its stiffness and rest length are positive (the
rest length leniently when it defaults to the distance of the ends at the start)."
  (let ((location (format nil "spring ~A" (symbol-name (scenario-spring-name spring)))))
    (list (list location `(> ,(scenario-spring-stiffness spring) 0)
                "the spring's stiffness is positive" 'scenario-expression-error)
          (list location `(> ,(scenario-spring-rest-length spring) 0)
                "the spring's rest length is positive" 'scenario-expression-error
                :lenient (and (scenario-spring-to spring)
                              (not (atom (scenario-spring-rest-length spring)))
                              (eq (first (scenario-spring-rest-length spring)) 'sqrt))))))

(defun rope-piece-lengths (scenario rope)
  "The start length of each straight piece of ROPE's path, between one of its points and
the next (expressions). A piece ending wound on a disc (:wound) runs to its tangent point:
sqrt(d^2 - R^2), d the distance of the next point from the disc's centre, R the wound
point's distance from it."
  (let* ((through (scenario-rope-through rope))
         (points (mapcar (lambda (point) (rope-point-at-start scenario point)) through))
         (wound (scenario-rope-wound-ends rope))
         (last (1- (length points))))
    (flet ((distance-squared (a b)
             `(+ (expt (- ,(first b) ,(first a)) 2) (expt (- ,(second b) ,(second a)) 2))))
      (loop for (a b) on points
            for index from 0
            while b
            collect (let* ((first-wound (and (= index 0) (member :first wound)))
                           (wound-point (cond (first-wound (first through))
                                              ((and (= index (1- last)) (member :last wound))
                                               (nth last through)))))
                      (if wound-point
                          ;; OTHER: the piece's end that is not on the disc
                          (let ((centre (rope-point-at-start scenario (list (first wound-point) '(0 0))))
                                (other (if first-wound b a)))
                            `(sqrt (- ,(distance-squared centre other)
                                      ,(distance-squared '(0 0) (second wound-point)))))
                          `(sqrt ,(distance-squared a b))))))))

(defun rope-facts (scenario rope)
  "The facts of one SCENARIO-ROPE: its length is positive, and (leniently) at least the
length of its path at the start, and each piece of that path of a positive length (an end
at its own pulley has no direction: Hooke's and the tension's 0/0)."
  (let ((location (format nil "rope ~A" (symbol-name (scenario-rope-name rope))))
        (length (scenario-rope-length rope)))
    (list* (list location `(> ,length 0) "the rope's length is positive"
                 'scenario-expression-error)
           (list location `(>= ,length ,(rope-start-path-length scenario rope))
                 "the rope is at least as long as its path through its ends and pulleys at the start"
                 'scenario-expression-error :lenient t)
           (loop for piece in (rope-piece-lengths scenario rope)
                 collect (list location `(> ,piece 0)
                               "each piece of the rope between its ends and pulleys has a length at the start (no point at the next one)"
                               'scenario-expression-error :lenient t)))))

(defun coefficient-facts (scenario)
  "Every physical range SCENARIO's clauses need, as a list of (LOCATION RELATION WHAT
CLASS . OPTIONS) like SCENARIO-FACTS (see this file's header)."
  (append (mapcan #'friction-facts (scenario-frictions scenario))
          (mapcan #'restitution-facts (scenario-restitutions scenario))
          (mapcan #'spring-facts (scenario-springs scenario))
          (mapcan (lambda (rope) (rope-facts scenario rope)) (scenario-ropes scenario))
          (kb-clause-facts scenario)
          (let ((g (scenario-gravitation scenario)))
            (when g
              (list (list "clause GRAVITATION" `(> ,g 0)
                          "the gravitational constant is positive"
                          'scenario-expression-error))))))

(defun check-coefficient-values (scenario values)
  "Check every fact of COEFFICIENT-FACTS whose parameters all have a value in VALUES (an
alist (PARAMETER-SYMBOL . NUMBER)) at those values. Returns VALUES. Signals
PARAMETER-VALUE-ERROR naming the clause and the values when one is false."
  (loop for (location relation what) in (coefficient-facts scenario)
        for variables = (expression-variables relation)
        when (and variables (every (lambda (variable) (assoc variable values)) variables)
                  (eq (ames.algebra:value-truth relation values) :false))
          do (error 'parameter-value-error
                    :scenario (scenario-name scenario) :location location
                    :source (location-source scenario location) :datum relation
                    :detail (scenario-detail
                             scenario "with ~{~A = ~A~^, ~} it is false that ~A"
                             (loop for (name . value) in values
                                   when (member name variables)
                                     append (list name value))
                             what)))
  values)
