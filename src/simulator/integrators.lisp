;;;; src/simulator/integrators.lisp -- the state's ODEs classified and integrated, group by group.
;;;;
;;;; The free bodies fall into GROUPS: bodies that act on one another (a force believed
;;;; from one free body on another: a contact between them, later a spring or a rope) are
;;;; in one group; bodies that touch only fixed bodies are alone. Each group's ODEs (the
;;;; DERIVATIVE beliefs, with the solved rates) get the integrator they need:
;;;;   :CONSTANT  every acceleration is constant: positions are polynomials in TAU;
;;;;   :PATH      one body on one curved contact with a fixed obstacle, its tangential
;;;;              acceleration a function of the arc length s alone: a conservative motion
;;;;              of one degree of freedom, integrated by its energy integral w^2 = E(s);
;;;;              events are found along s and their times by the travel-time integral
;;;;              (closed form where the bridge finds one, a number under --set);
;;;;   :LINEAR    accelerations linear in the positions and velocities with constant
;;;;              coefficients (springs): closed forms through the bridge;
;;;;   :LINE      one degree of freedom along a fixed line of the configuration space
;;;;              (two bodies falling together under gravitation): like :PATH, by its
;;;;              energy integral (line.lisp); when the group is no such motion, :NUMERIC;
;;;;   :SPEED-LINE accelerations that depend on the velocities alone and keep the group on a
;;;;              fixed line (quadratic drag): a Riccati equation in the speed along it,
;;;;              closed forms in TAU (speed-line.lisp); else :NUMERIC;
;;;;   :ROTATION-PATH one rotating body held to one degree of freedom, its angle (a ladder
;;;;              on its wall and floor): like :LINE along the angle (rotation-path.lisp);
;;;;   :NUMERIC   anything else: no closed form (numbers only under --set).
;;;; A :PATH or :NUMERIC group that starts at rest in equilibrium (every rate zero at the
;;;; start) is :CONSTANT instead: it stays there (equilibrium.lisp).

(in-package #:ames.simulator)

(defstruct (group (:constructor make-group (bodies)))
  "Free bodies that move together, and how: KIND (see the file header); MOTION, an alist
state term -> its value over the group's VARIABLE (TAU, or the arc length for :PATH);
for :PATH, the CONTACT, the initial arc length S0, the DIRECTION (+1 or -1) of motion,
and SPEED-SQUARED, the energy integral E(s)."
  bodies (kind :constant) (variable 'tau) motion contact s0 direction speed-squared
  ode-kind end-state samples terms speed line)

(defconstant +arc-length+ 'arc-length
  "The variable standing for the arc length s along a curved contact.")

(defun interaction-edges (run)
  "Pairs (A B) of free bodies between which the model believes a force."
  (let ((free (free-body-names run)) (edges '()))
    (dolist (belief (ames.engine:model-beliefs (run-model run)) edges)
      (when (eq (first belief) 'ames.kb:force)
        (let ((from (getf (cddr belief) :from)) (on (getf (cddr belief) :on)))
          (when (and (member from free) (member on free) (not (eq from on)))
            (pushnew (list from on) edges :test #'equal)))))))

(defun coupling-edges (run solved)
  "Pairs (A B) of free bodies where A's accelerations in SOLVED depend on B's position or
velocity: bodies coupled with no force between them (a rope over a pulley of a fixed body
pulls each end from the pulley, yet its tension depends on both ends' motion)."
  (let ((free (free-body-names run)) (edges '()))
    (dolist (a free edges)
      (dolist (axis '(:x :y))
        (let* ((rate (cdr (assoc `(ames.kb:vel ,a ,axis) (solved-model-rates solved) :test #'equal)))
               (mentioned (mentioned-terms rate)))
          (dolist (term (solved-model-state solved))
            (when (and (member (first term) '(ames.kb:pos ames.kb:vel))
                       (not (eq (second term) a))
                       (member (second term) free)
                       (mentioned-p term mentioned rate))
              (pushnew (list a (second term)) edges :test #'equal))))))))

(defun body-groups (run &optional solved)
  "The free bodies split into GROUPs of bodies that act on one another (or, given the
SOLVED model, whose accelerations depend on one another's motion), in body order."
  (let ((groups (mapcar #'list (free-body-names run))))
    (dolist (edge (append (interaction-edges run) (and solved (coupling-edges run solved))))
      (let ((a (find (first edge) groups :test #'member))
            (b (find (second edge) groups :test #'member)))
        (unless (eq a b)
          (setf groups (cons (append a b) (remove b (remove a groups)))))))
    (mapcar (lambda (bodies)
              (make-group (sort (copy-list bodies) #'<
                                :key (lambda (b) (position b (free-body-names run))))))
            (sort groups #'< :key (lambda (g) (reduce #'min (mapcar (lambda (b) (position b (free-body-names run))) g)))))))

(defun group-state-terms (run solved group)
  "The state terms of SOLVED that belong to GROUP: its bodies' positions and velocities
(and angles and angular velocities) and the path coordinates of contacts whose observer is in it."
  (remove-if-not (lambda (term)
                   (member (case (first term)
                             ((ames.kb:pos ames.kb:vel ames.kb:angle ames.kb:angvel) (second term))
                             (t (first (contact-bodies run (second term)))))
                           (group-bodies group)))
                 (solved-model-state solved)))

(defun path-terms (solved)
  "The curved contacts whose path coordinates are state terms of SOLVED."
  (loop for term in (solved-model-state solved)
        when (eq (first term) 'ames.kb:path-position)
          collect (second term)))

(defun mentions-state-p (solved expression)
  "True when EXPRESSION mentions a state term of SOLVED."
  (let ((table (state-terms-table solved)))
    (if (gethash :every-term table)
        ;; a quantity term occurs where EXPRESSION-VARIABLES finds it (see MENTIONED-TERMS)
        (some (lambda (term) (and (consp term) (gethash term table)))
              (expression-variables expression))
        (some (lambda (term) (not (free-of-p term expression))) (solved-model-state solved)))))

(defun classify-group (run solved group)
  "GROUP's KIND, set on it and returned (and its state TERMS)."
  (setf (group-terms group) (group-state-terms run solved group))
  (let* ((curved (remove-if-not (lambda (contact)
                                  (member (ames.geometry:contact-observer (contact-geometry run contact))
                                          (group-bodies group)))
                                (path-terms solved)))
         (rates (append (loop for body in (group-bodies group)
                              append (loop for axis in '(:x :y)
                                           collect (cdr (assoc `(ames.kb:vel ,body ,axis)
                                                               (solved-model-rates solved) :test #'equal))))
                        (rotation-rates run solved group))))
    (setf (group-kind group)
          (cond ((and (null curved) (notany (lambda (r) (mentions-state-p solved r)) rates))
                 :constant)
                ;; a body held at rest in its angle (a block sliding flat on two corners)
                ((and (null curved) (frozen-rotation-constant-p run solved group rates))
                 :constant)
                ((and curved (null (rest curved)) (null (rest (group-bodies group)))
                      (body-fixed-p run (second (contact-bodies run (first curved))))
                      (let ((tangential (cdr (assoc `(ames.kb:path-speed ,(first curved))
                                                    (solved-model-rates solved) :test #'equal))))
                        (and (free-of-p 'tau tangential)
                             (every (lambda (term)
                                      (or (free-of-p term tangential)
                                          (equal term `(ames.kb:path-position ,(first curved)))))
                                    (solved-model-state solved)))))
                 (setf (group-contact group) (first curved))
                 :path)
                ((and (null curved) (linear-rates-p run solved group rates)) :linear)
                ((null curved) :line)
                (t :numeric)))))

(defun linear-rates-p (run solved group rates)
  "True when RATES are linear in GROUP's state terms with constant coefficients."
  (let ((terms (group-state-terms run solved group)))
    (every (lambda (rate)
             (every (lambda (term)
                      (let* ((symbol (state-symbol term))
                             (d (ames.geometry:differentiate
                                 (substitute-expressions (list (cons term symbol)) rate) symbol)))
                        (and (not (mentions-state-p solved (substitute-expressions
                                                            (list (cons symbol term)) d)))
                             (free-of-p symbol d)
                             (free-of-p 'tau d))))
                    terms))
           (progn run rates))))

;;; :CONSTANT -- polynomials in TAU

(defun integrate-constant (run solved group)
  "Fill GROUP's motion: each body's position and velocity (and a rotating body's angle and
angular velocity) as polynomials in TAU."
  (setf (group-motion group)
        (loop for body in (group-bodies group)
              append (loop for axis in '(:x :y)
                           for p0 = (axis-of (body-position run body) axis)
                           for v0 = (axis-of (body-velocity run body) axis)
                           for a = (substitute-expressions
                                    (solved-model-initial solved)
                                    (cdr (assoc `(ames.kb:vel ,body ,axis)
                                                (solved-model-rates solved) :test #'equal)))
                           collect (cons `(ames.kb:pos ,body ,axis)
                                         (tidy run `(+ ,p0 (* ,v0 tau) (* 1/2 ,a (expt tau 2))) :full))
                           collect (cons `(ames.kb:vel ,body ,axis)
                                         (tidy run `(+ ,v0 (* ,a tau)) :full))))
        (group-motion group) (append (group-motion group)
                                     (integrate-rotation-constant run solved group)))
  group)

;;; :PATH -- one degree of freedom along a curved contact

(defun integrate-path (run solved group)
  "Fill GROUP's motion along its curved contact: the energy integral E(s) = w^2 and
every state term as a function of the arc length s (+ARC-LENGTH+), in the direction
of motion. Signals AMBIGUOUS-TRANSITION when the direction is not decided."
  (let* ((contact (group-contact group))
         (geometry (contact-geometry run contact))
         (observer (first (group-bodies group)))
         (obstacle (second (contact-bodies run contact)))
         (s-term `(ames.kb:path-position ,contact))
         (w-term `(ames.kb:path-speed ,contact))
         (s0 (cdr (assoc s-term (solved-model-initial solved) :test #'equal)))
         (w0 (cdr (assoc w-term (solved-model-initial solved) :test #'equal)))
         (tangential (substitute-expressions (list (cons s-term +arc-length+))
                                             (cdr (assoc w-term (solved-model-rates solved)
                                                         :test #'equal))))
         (ode (ames.maxima:solve-autonomous-ode (run-bridge run) tangential +arc-length+
                                                :initial-position s0 :initial-velocity w0))
         (energy (tidy run (ames.maxima:ode-solution-speed-squared ode)))
         (direction (let ((sign (sign-direction (sign-of run w0))))
                      (if sign
                          sign
                          (let ((push (sign-direction (sign-of run (at-arc tangential s0)))))
                            (if push
                                push
                                (error 'ambiguous-transition
                                       :datum w0 :missing-fact `(> ,(at-arc tangential s0) 0)
                                       :detail "direction of motion along a curved contact"))))))
         (speed `(* ,direction (sqrt ,energy)))
         (point (ames.geometry:v+ (body-position run obstacle)
                      (ames.geometry:contact-point geometry +arc-length+)))
         (tangent (ames.geometry:contact-unit-tangent geometry +arc-length+)))
    (setf (group-variable group) +arc-length+
          (group-s0 group) s0
          (group-direction group) direction
          (group-speed-squared group) energy
          (group-ode-kind group) (ames.maxima:ode-solution-kind ode)
          (group-motion group)
          (list (cons `(ames.kb:pos ,observer :x) (tidy run (first point)))
                (cons `(ames.kb:pos ,observer :y) (tidy run (second point)))
                (cons `(ames.kb:vel ,observer :x) (tidy run `(* ,speed ,(first tangent))))
                (cons `(ames.kb:vel ,observer :y) (tidy run `(* ,speed ,(second tangent))))
                (cons s-term +arc-length+)
                (cons w-term (tidy run speed)))
          (group-speed group) (tidy run speed))
    group))

(defun at-arc (expression s)
  "EXPRESSION at arc length S."
  (substitute-expressions (list (cons +arc-length+ s)) expression))

;;; All groups

(defun integrate-groups (run solved)
  "The state's GROUPs, classified and integrated in closed form where they can be.
A :LINEAR group goes to the bridge's linear ODE solver when it has one, else it is
integrated numerically like a :NUMERIC group (when the termination conditions are
searched, under parameter values: see numeric.lisp)."
  (let ((groups (body-groups run solved)))
    (dolist (group groups groups)
      (setf (group-kind group) (rotation-kind run solved group (classify-group run solved group)))
      (ecase (group-kind group)
        (:constant (unless (and (frozen-rotation-p run solved group)
                                ;; at rest in equilibrium, as before a body was held
                                (integrate-equilibrium run solved group))
                     (integrate-constant run solved group)))
        ;; at rest in equilibrium: no direction of motion (equilibrium.lisp)
        (:path (or (integrate-equilibrium run solved group)
                   (integrate-path run solved group)))
        (:linear (unless (integrate-linear run solved group)
                   (setf (group-kind group) :numeric)))
        (:line (unless (or (integrate-line run solved group)
                           ;; velocity-dependent forces along a line (speed-line.lisp)
                           (integrate-speed-line run solved group))
                 (setf (group-kind group) :numeric)))
        ;; a rotating body left one degree of freedom, its angle (rotation-path.lisp)
        (:numeric (or (integrate-equilibrium run solved group)
                      ;; a disc rolling along its curve: one degree of freedom (rolling-path.lisp)
                      (and (group-contact group)
                           (integrate-rolling-path run solved group)
                           (setf (group-kind group) :path))
                      (integrate-rotation-path run solved group)))))))

(defun integrate-linear (run solved group)
  "Fill GROUP's motion through the bridge's closed-form solver of linear ODEs with
constant coefficients (springs along fixed directions: sines and cosines in TAU), a
rotating body's angle and angular velocity with its position and velocity.
Returns GROUP, or NIL when the bridge finds no closed form (the group is then
integrated numerically): a failed or unverifiable solution, or a sign question the
assumptions leave open."
  (let* ((bodies (group-bodies group))
         (rotating (group-rotating-bodies run group))
         (positions (append (loop for b in bodies append (list `(ames.kb:pos ,b :x) `(ames.kb:pos ,b :y)))
                            (loop for b in rotating collect `(ames.kb:angle ,b))))
         (velocities (append (loop for b in bodies append (list `(ames.kb:vel ,b :x) `(ames.kb:vel ,b :y)))
                             (loop for b in rotating collect `(ames.kb:angvel ,b))))
         (accelerations (mapcar (lambda (v) (cdr (assoc v (solved-model-rates solved) :test #'equal)))
                                velocities))
         (initial (lambda (terms)
                    (mapcar (lambda (term) (cdr (assoc term (solved-model-initial solved) :test #'equal)))
                            terms))))
    (handler-case
        (multiple-value-bind (position-values velocity-values)
            (call-answering-sign-questions
             run "the sign that selects the closed form of a linear motion"
             (lambda ()
               (ames.algebra:solve-linear-odes (run-bridge run) accelerations positions velocities
                                              (funcall initial positions) (funcall initial velocities))))
          (setf (group-motion group)
                (mapcar (lambda (entry) (cons (car entry) (tidy run (cdr entry) :full)))
                        (append position-values velocity-values)))
          group)
      ((or ames.maxima:solve-failed ames.maxima:maxima-question) () nil))))

(defun group-of-term (groups term)
  "The GROUP among GROUPS whose state term TERM is, or NIL."
  (find-if (lambda (group) (member term (group-terms group) :test #'equal)) groups))

(defun motion-value (groups expression)
  "EXPRESSION (over state terms) with every state term replaced by its motion in the
group that has it."
  (substitute-expressions
   (loop for term in (expression-variables expression)
         for group = (and (quantity-term-p term) (group-of-term groups term))
         for entry = (and group (assoc term (group-motion group) :test #'equal))
         when entry collect entry)
   expression))
