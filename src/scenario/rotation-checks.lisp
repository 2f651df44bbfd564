;;;; src/scenario/rotation-checks.lisp -- the checks of the rotation section that need the whole
;;;; scenario (the bodies with the hinges, forces, ropes and queries that name them), and the
;;;; facts that the semantic checks decide under the assumptions (see rotation.lisp's header
;;;; for the choices).

(in-package #:ames.scenario)

(defun named-clause (validation word name)
  "The clause (WORD NAME ...) of the form being validated (words and names compared by
name), or NIL."
  (find-if (lambda (clause)
             (and (consp clause) (proper-list-p clause) (named-p (first clause) word)
                  (consp (rest clause)) (second clause) (symbolp (second clause))
                  (same-name-p (second clause) name)))
           (rest (validation-form validation))))

(defun clause-value (clause key)
  "The value of KEY among the keyword arguments of CLAUSE (WORD NAME . ARGUMENTS)."
  (loop for (k v) on (cddr clause) by #'cddr
        when (eq k key) return v))

(defun rotating-body (validation scenario name datum why)
  "The body NAME of SCENARIO, which must rotate; else a SCENARIO-SYNTAX-ERROR at DATUM
saying WHY it must."
  (let ((body (find-scenario-body name scenario)))
    (unless (and body (scenario-body-rotating-p body))
      (reject validation 'scenario-syntax-error datum
              "~A; ~A does not rotate: give it an :inertia (a value, :uniform or :ring)"
              why (show name)))
    body))

(defun turned-point (body point)
  "BODY's point POINT (own frame) turned by its start :angle, as expressions (X Y)."
  (let ((theta (scenario-body-angle body)))
    (destructuring-bind (px py) point
      (if (eql theta 0)
          (list px py)
          (list `(- (* (cos ,theta) ,px) (* (sin ,theta) ,py))
                `(+ (* (sin ,theta) ,px) (* (cos ,theta) ,py)))))))

(defun point-velocity (body point)
  "The velocity at the start of BODY's point POINT (own frame): v + omega k x R p."
  (let ((omega (scenario-body-angular-velocity body)))
    (destructuring-bind (dx dy) (turned-point body point)
      (destructuring-bind (vx vy) (scenario-body-velocity body)
        (if (eql omega 0)
            (list vx vy)
            (list `(- ,vx (* ,omega ,dy)) `(+ ,vy (* ,omega ,dx))))))))

(defun check-hinges (validation scenario)
  "Each hinge's body rotates, has no other hinge, and starts with its pin at rest."
  (let ((pinned '()))
    (dolist (hinge (scenario-hinges scenario))
      (let* ((clause (named-clause validation "HINGE" (scenario-hinge-name hinge)))
             (body (progn (enter validation (format nil "hinge ~A" (symbol-name (scenario-hinge-name hinge)))
                                 clause)
                          (rotating-body validation scenario (scenario-hinge-body hinge)
                                         (clause-value clause :body)
                                         "a hinged body turns about its hinge")))
             (velocity (point-velocity body (scenario-hinge-point hinge))))
        (when (member (scenario-body-name body) pinned)
          (reject validation 'scenario-syntax-error clause
                  "~A already has a hinge: a body pinned at two points cannot move (make it :fixed)"
                  (show (scenario-body-name body))))
        (push (scenario-body-name body) pinned)
        (when (some #'nonzero-number-p velocity)
          (reject validation 'scenario-syntax-error (clause-value clause :at)
                  "the hinge's point must be at rest at the start, but ~A's :velocity and ~
                   :angular-velocity move it at ~A" (show (scenario-body-name body))
                  (show (mapcar #'folded velocity))))))))

(defun numeric-values (points)
  "The double-float coordinates of POINTS ((X Y) ...), or NIL when one is not a number."
  (loop for (x y) in points
        for vx = (expression-value x) for vy = (expression-value y)
        unless (and vx vy) return nil
        collect (list (float vx 1d0) (float vy 1d0))))

(defun inside-polygon-p (point vertices)
  "True when the numeric POINT (X Y) lies in the polygon of numeric VERTICES (on its
boundary, within round-off, or inside by the winding number)."
  (destructuring-bind (x y) point
    (let ((winding 0)
          (scale (reduce #'max (mapcar (lambda (v) (max (abs (first v)) (abs (second v)))) vertices)
                         :initial-value 1d0)))
      (loop for (a b) in (polygon-edges (cons nil vertices))
            for (ax ay) = a for (bx by) = b
            for cross = (- (* (- bx ax) (- y ay)) (* (- x ax) (- by ay)))
            do (when (and (<= (abs cross) (* 1d-12 scale scale))
                          (<= (min ax bx) x (max ax bx)) (<= (min ay by) y (max ay by)))
                 (return-from inside-polygon-p t))
               (cond ((and (<= ay y) (> by y) (> cross 0)) (incf winding))
                     ((and (> ay y) (<= by y) (< cross 0)) (decf winding))))
      (/= winding 0))))

(defun point-outside-shape-p (point shape)
  "True when the numbers show that POINT (own frame) is outside SHAPE; NIL when it is
inside or on it, or when the numbers do not tell."
  (let ((p (first (numeric-values (list point)))))
    (when p
      (case (shape-kind shape)
        (:circle (let ((r (expression-value (second shape))))
                   (and r (> (+ (expt (first p) 2) (expt (second p) 2))
                             (* (expt (float r 1d0) 2) (+ 1 1d-12))))))
        ((:polygon :segment)
         (let ((vertices (numeric-values (rest shape))))
           (and vertices
                (if (eq (shape-kind shape) :segment)
                    (not (inside-polygon-p p (append vertices (reverse vertices))))
                    (not (inside-polygon-p p vertices))))))))))

(defun check-force-points (validation scenario)
  "Each force with an :at acts on a rotating body, at a point of its shape."
  (dolist (force (scenario-forces scenario))
    (when (scenario-force-point force)
      (let* ((clause (named-clause validation "FORCE" (scenario-force-name force)))
             (at (clause-value clause :at)))
        (enter validation (format nil "force ~A" (symbol-name (scenario-force-name force))) clause)
        (let ((body (rotating-body validation scenario (scenario-force-body force) at
                                   "a force's :at is where it acts for its torque on a rotating body")))
          (when (point-outside-shape-p (scenario-force-point force) (scenario-body-shape body))
            (reject validation 'scenario-syntax-error at
                    "the point ~A is outside ~A's shape ~A: a force acts at a point of the body"
                    (show (scenario-force-point force)) (show (scenario-body-name body))
                    (show (scenario-body-shape body)))))))))

(defun check-wound-ropes (validation scenario)
  "Each wound end of a rope is on a rotating disc, at a radius that is not 0 and within it."
  (dolist (rope (scenario-ropes scenario))
    (let ((clause (named-clause validation "ROPE" (scenario-rope-name rope))))
      (dolist (end (scenario-rope-wound-ends rope))
        (destructuring-bind (name point)
            (if (eq end :first) (first (scenario-rope-through rope)) (car (last (scenario-rope-through rope))))
          (enter validation (format nil "rope ~A" (symbol-name (scenario-rope-name rope))) clause)
          (let* ((datum (let ((through (clause-value clause :through)))
                          (if (eq end :first) (first through) (car (last through)))))
                 (body (rotating-body validation scenario name datum
                                      "a rope winds on a disc that turns"))
                 (shape (scenario-body-shape body)))
            (cond ((not (eq (shape-kind shape) :circle))
                   (reject validation 'scenario-syntax-error datum
                           "a rope winds on a disc (a drum, an axle, a pulley): ~A's shape ~
                            must be (circle R)" (show name)))
                  ((zero-vector-p point)
                   (reject validation 'scenario-syntax-error datum
                           "~A is ~A's centre: a wound rope needs a radius to wind on"
                           (show point) (show name)))
                  ((point-outside-shape-p point shape)
                   (reject validation 'scenario-syntax-error datum
                           "~A lies outside ~A's disc: a rope winds on its rim or on an axle inside it"
                           (show point) (show name))))))))))

(defparameter +rotation-quantities+ '(:angle :angular-velocity :angular-acceleration
                                        :angular-momentum)
  "The query quantities of a rotating body.")

(defun check-rotation-queries (validation scenario)
  "Each rotation quantity of a query names a rotating body, each (hinge-force H) a hinge."
  (dolist (query (scenario-queries scenario))
    (let ((clause (named-clause validation "QUERY" (first query))))
      (labels ((walk (x)
                 (when (and (consp x) (proper-list-p x))
                   (cond ((and (member (first x) +rotation-quantities+) (= (length x) 2))
                          (enter validation "clause QUERY" clause)
                          (rotating-body validation scenario (second x) (second x)
                                         (format nil "(~(~A~) ...) asks about a rotating body"
                                                 (first x))))
                         ((and (eq (first x) :hinge-force) (= (length x) 2)
                               (not (find-scenario-hinge (second x) scenario)))
                          (enter validation "clause QUERY" clause)
                          (reject validation 'undeclared-symbol-error (second x)
                                  "~A is not a hinge" (show (second x)))))
                   (mapc #'walk x))))
        (walk (second query))))))

(defun check-rotation (validation scenario)
  "Check what the rotation section asks of the whole SCENARIO (hinges, forces' :at, wound
ropes, rotation queries: see rotation.lisp); return SCENARIO. Signals a SCENARIO-ERROR
naming the clause at fault."
  (check-hinges validation scenario)
  (check-force-points validation scenario)
  (check-wound-ropes validation scenario)
  (check-rotation-queries validation scenario)
  scenario)

;;; What the assumptions decide

(defun within-disc (point circle)
  "The relation: POINT (own frame) lies in the checked CIRCLE about the origin."
  `(<= (+ (expt ,(first point) 2) (expt ,(second point) 2)) (expt ,(second circle) 2)))

(defun rotation-facts (scenario)
  "The facts of the rotation section that symbols leave open, as SCENARIO-FACTS lists
them: a positive inertia, at most m r^2 for a disc; a :uniform body's centroid at its
reference point; a hinge's pin at rest; a disc's :at and wound points within it (and
the wound one off its centre)."
  (append
   (loop for body in (scenario-rotating-bodies scenario)
         for location = (format nil "body ~A" (symbol-name (scenario-body-name body)))
         for inertia = (scenario-body-inertia body)
         for shape = (scenario-body-shape body)
         append (append
                 (when (eq (scenario-body-inertia-kind body) :value)
                   (list (list location `(> ,inertia 0) "the moment of inertia is positive"
                               'scenario-expression-error)))
                 (when (and (eq (scenario-body-inertia-kind body) :value) (eq (shape-kind shape) :circle))
                   (list (list location `(<= ,inertia (* ,(scenario-body-mass body) (expt ,(second shape) 2)))
                               "a disc's moment of inertia about its centre is at most m r^2"
                               'scenario-expression-error :lenient t)))
                 (when (eq (scenario-body-inertia-kind body) :uniform)
                   (loop for c in (centroid shape)
                         unless (numberp c)
                           collect (list location `(= ,c 0)
                                         "the reference point is the shape's centroid (:inertia :uniform)"
                                         'scenario-shape-error)))))
   (loop for force in (scenario-forces scenario)
         for point = (scenario-force-point force)
         for body = (find-scenario-body (scenario-force-body force) scenario)
         when (and point (eq (shape-kind (scenario-body-shape body)) :circle))
           collect (list (format nil "force ~A" (symbol-name (scenario-force-name force)))
                         (within-disc point (scenario-body-shape body))
                         "the force's :at is a point of the disc" 'scenario-syntax-error :lenient t))
   (loop for rope in (scenario-ropes scenario)
         for location = (format nil "rope ~A" (symbol-name (scenario-rope-name rope)))
         append (loop for end in (scenario-rope-wound-ends rope)
                      for (name point) = (if (eq end :first)
                                             (first (scenario-rope-through rope))
                                             (car (last (scenario-rope-through rope))))
                      for shape = (scenario-body-shape (find-scenario-body name scenario))
                      collect (list location `(> (+ (expt ,(first point) 2) (expt ,(second point) 2)) 0)
                                    "the wound end is off the disc's centre" 'scenario-syntax-error)
                      collect (list location (within-disc point shape)
                                    "the wound end is within the disc" 'scenario-syntax-error :lenient t)))
   (loop for hinge in (scenario-hinges scenario)
         for body = (find-scenario-body (scenario-hinge-body hinge) scenario)
         append (loop for v in (point-velocity body (scenario-hinge-point hinge))
                      unless (numberp v)
                        collect (list (format nil "hinge ~A" (symbol-name (scenario-hinge-name hinge)))
                                      `(= ,v 0) "the hinge's point is at rest at the start"
                                      'scenario-syntax-error :lenient t)))))

;;; What the simulator cannot do yet

(defun rotating-attachments (scenario)
  "The attachments to SCENARIO's rotating bodies whose forces would have a moment that
the knowledge base does not model yet, as (BODY-NAME . WHAT): a spring or a rope end at
a point other than the centre (a rope end wound on a disc is modelled: wound-ropes.lisp),
a pulley or a bumper (its axis would turn) on a rotating body."
  (flet ((rotating (name)
           (let ((body (find-scenario-body name scenario)))
             (and body (scenario-body-rotating-p body))))
         (off-centre (point) (not (zero-vector-p point))))
    (append
     (loop for spring in (scenario-springs scenario)
           for from = (scenario-spring-from spring)
           if (and (scenario-spring-bumper-p spring) (rotating (first from)))
             ;; a bumper's axis would turn with the body
             collect (cons (first from) (format nil "bumper ~A is fixed on it"
                                                (symbol-name (scenario-spring-name spring))))
           else
             append (loop for end in (list from (scenario-spring-to spring))
                          when (and end (rotating (first end)) (off-centre (second end)))
                            collect (cons (first end) (format nil "spring ~A is attached off its centre"
                                                              (symbol-name (scenario-spring-name spring))))))
     (loop for rope in (scenario-ropes scenario)
           for through = (scenario-rope-through rope)
           append (loop for end in (list (first through) (car (last through)))
                        for wound in (list (member :first (scenario-rope-wound-ends rope))
                                           (member :last (scenario-rope-wound-ends rope)))
                        when (and (consp end) (rotating (first end))
                                  (not wound) (off-centre (second end)))
                          collect (cons (first end)
                                        (format nil "rope ~A is tied to it off its centre (wind it ~
                                                     on a disc with :wound)"
                                                (symbol-name (scenario-rope-name rope))))))
     (loop for pulley in (scenario-pulleys scenario)
           when (rotating (scenario-pulley-body pulley))
             collect (cons (scenario-pulley-body pulley)
                           (format nil "pulley ~A is fixed on it"
                                   (symbol-name (scenario-pulley-name pulley))))))))

(defun corner-shaped-rotating-p (body)
  "True when BODY is a free rotating polygon or segment: its contacts are those of its
corners (the simulator's corners.lisp), not those of a translating shape."
  (and (scenario-body-rotating-p body) (not (scenario-body-fixed-p body))
       (member (shape-kind (scenario-body-shape body)) '(:polygon :segment))))

(defun corners-on-fixed-faces-p (scenario body)
  "True when the rotating polygon or segment BODY can touch only with its corners on
fixed straight faces: every other body is fixed and bounded by straight faces."
  (and (corner-shaped-rotating-p body)
       (every (lambda (other)
                (or (eq other body)
                    (and (scenario-body-fixed-p other)
                         (member (shape-kind (scenario-body-shape other)) '(:polygon :segment :half-plane)))))
              (scenario-bodies scenario))))

(defun rotation-awaiting (scenario)
  "The rotating bodies of SCENARIO that AMES does not simulate yet, as (DATUM REASON): a
rotating polygon or segment that could touch anything but fixed straight faces (its
corners on those are simulated, see CORNERS-ON-FIXED-FACES-P), one with an attachment
whose moment is not modelled (see
ROTATING-ATTACHMENTS)."
  (append
   (loop for body in (scenario-rotating-bodies scenario)
         when (and (not (eq (shape-kind (scenario-body-shape body)) :circle))
                   (rest (scenario-bodies scenario))
                   (not (corners-on-fixed-faces-p scenario body)))
           collect (list (scenario-body-name body)
                         (format nil "body ~A rotates and is not a disc: AMES simulates the ~
                                      contacts of a rotating polygon or segment only with fixed ~
                                      straight faces (its corners on them), not yet with ~
                                      other bodies"
                                 (symbol-name (scenario-body-name body)))))
   (loop for (name . what) in (rotating-attachments scenario)
         collect (list name (format nil "body ~A rotates and ~A: AMES does not simulate the ~
                                        moment of that force yet" (symbol-name name) what)))))

(defun scenario-awaiting (scenario)
  "What SCENARIO asks that AMES does not simulate yet, as a list of (DATUM REASON): the
rotating bodies of ROTATION-AWAITING (hinges, rotating polygons in contact, attachments
off a rotating body's centre). NIL for a scenario AMES runs. The simulator refuses a
scenario with any (never runs a rotating body as a translating one)."
  (rotation-awaiting scenario))
