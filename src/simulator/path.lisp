;;;; src/simulator/path.lisp -- termination along a curved contact: where (in arc length) each
;;;; condition fires ahead of the body, and how long the body takes to get there.
;;;;
;;;; On a curved contact the motion has one degree of freedom, the arc length s, and its
;;;; energy integral w^2 = E(s) (thesis section 2.6.3). A condition is a function of s;
;;;; it fires at the nearest root ahead of the start (in the direction of motion) where
;;;; it turns true. The time to travel from s0 to s1 is the integral of ds / |w|: a closed
;;;; form where the bridge finds one, else :NO-CLOSED-FORM with a number when parameter
;;;; values are given.

(in-package #:ames.simulator)

(defun ahead-p (run group s)
  "Whether the arc length S lies strictly ahead of GROUP's start in its direction of
motion: :TRUE, :FALSE or :UNKNOWN. On a circle, a turn of less than a quarter has the
sign of its sine, which Maxima can expand where inverse trigonometric terms defeat
sign()."
  (let* ((s0 (group-s0 group)) (direction (group-direction group))
         (answer (decide run `(> (* ,direction (- ,s ,s0)) 0)))
         (radius (group-radius run group)))
    (if (and (eq answer :unknown) radius)
        (let ((turn (tidy run `(/ (- ,s ,s0) ,radius))))
          (if (holds run `(> ,(tidy run `(cos ,turn) :trigexpand) 0))
              (decide run `(> (* ,direction ,(tidy run `(sin ,turn) :trigexpand)) 0))
              :unknown))
        answer)))

(defun group-radius (run group)
  "The radius of GROUP's curved contact, or NIL (a straight path, or a :LINE motion)."
  (and (group-contact group)
       (ames.geometry:contact-radius (contact-geometry run (group-contact group)))))

(defun nearer-p (run group a b)
  "Whether the arc length A comes before B in GROUP's direction: :TRUE, :FALSE or :UNKNOWN."
  (let ((answer (or (numeric-angle-order run group a b)
                    (decide run `(< (* ,(group-direction group) (- ,a ,b)) 0)))))
    (if (and (eq answer :unknown) (group-radius run group))
        (ahead-p run (let ((copy (copy-group group))) (setf (group-s0 copy) a) copy) b)
        answer)))

(defun roots-in-arc (run expression)
  "The roots in +ARC-LENGTH+ of EXPRESSION = 0 that Maxima's solve() finds, simplified;
those proven not real (an asin or acos of a quantity proven beyond [-1, 1], such as the
lift-off point of a ball fast enough to loop) left out."
  (handler-case
      (loop for solution in (ames.maxima:solve-equations (run-bridge run) (list `(= ,expression 0))
                                                         (list +arc-length+))
            for root = (tidy run (cdr (first solution)))
            unless (not-real-p run root)
              collect root)
    (ames.maxima:solve-failed () :failed)))

(defun not-real-p (run expression)
  "True when EXPRESSION has an asin or acos of a quantity proven outside [-1, 1]."
  (and (consp expression)
       (or (and (member (first expression) '(asin acos))
                (or (eq (decide run `(<= ,(second expression) 1)) :false)
                    (eq (decide run `(>= ,(second expression) -1)) :false)))
           (some (lambda (x) (not-real-p run x)) (rest expression)))))

(defun crossing-ahead (run group function)
  "The nearest arc length ahead of GROUP's start where FUNCTION (of the arc length)
reaches zero going negative: (values :AT S), (values :NEVER) or (values :UNKNOWN FACT).
Among solve()'s roots first; on a circle, when none of them is found ahead, over every
turn of the circle in the direction of motion (CIRCLE-CROSSING): solve() lists the
principal roots only, which may lie behind the body or miss the other family."
  (multiple-value-bind (status s) (crossing-among-roots run group function)
    (if (or (eq status :at) (null (group-radius run group)))
        (values status s)
        (multiple-value-bind (circle-status circle-s) (circle-crossing run group function)
          (cond (circle-status (values circle-status circle-s))
                ;; solve()'s principal roots prove nothing about the other turns
                ((eq status :never) (values :unknown `(:roots-of (= ,(tidy run function) 0))))
                (t (values status s)))))))

(defun crossing-among-roots (run group function)
  "CROSSING-AHEAD's answer among the roots solve() lists."
  (let ((function (tidy run function :full)))
    (when (free-of-p +arc-length+ function)
      (return-from crossing-among-roots (values :never)))
    (let ((roots (roots-in-arc run function)) (best nil))
      (when (eq roots :failed)
        (return-from crossing-among-roots (values :unknown `(:roots-of (= ,function 0)))))
      (dolist (root roots)
        (case (ahead-p run group root)
          (:true
           (let ((slope (tidy run `(* ,(group-direction group)
                                      ,(ames.geometry:differentiate function +arc-length+)))))
             (case (decide run `(<= ,(at-arc slope root) 0))
               (:true (if (or (null best) (eq (nearer-p run group root best) :true))
                          (setf best root)
                          (unless (eq (nearer-p run group best root) :true)
                            (return-from crossing-among-roots (values :unknown `(< ,root ,best))))))
               (:unknown (return-from crossing-among-roots (values :unknown `(< ,(at-arc slope root) 0)))))))
          (:unknown (return-from crossing-among-roots
                      (values :unknown `(> (* ,(group-direction group) (- ,root ,(group-s0 group))) 0))))))
      (if best (values :at best) (values :never)))))

(defun relation-arc (run group relation over-arc)
  "Where RELATION first holds ahead: (values :AT S), (values :NEVER) or (values
:UNKNOWN FACT). OVER-ARC turns an expression into a function of the arc length."
  (if (eq (first relation) 'or)
      (let ((best nil) (unknown nil))
        (dolist (part (rest relation))
          (multiple-value-bind (status s) (relation-arc run group part over-arc)
            (case status
              (:at (if (or (null best) (eq (nearer-p run group s best) :true))
                       (setf best s)
                       (unless (eq (nearer-p run group best s) :true) (setf unknown `(< ,s ,best)))))
              (:unknown (setf unknown s)))))
        (cond (unknown (values :unknown unknown)) (best (values :at best)) (t (values :never))))
      (crossing-ahead run group (funcall over-arc (violation-function relation)))))

(defun meeting-arc (run group meeting over-arc)
  "Where the body moving along GROUP's curve first meets a contact from its exterior:
(values :AT S RATE) with RATE the gap's rate in time there, (values :NEVER) or (values
:UNKNOWN FACT)."
  (let* ((gap (tidy run (funcall over-arc (ames.geometry:meeting-gap meeting))))
         (extent (mapcar (lambda (r) (funcall over-arc r)) (ames.geometry:meeting-extent meeting)))
         (speed (group-speed group)))
    (multiple-value-bind (status s) (crossing-ahead run group gap)
      (if (not (eq status :at))
          (values status s)
          (let* ((rate (tidy run `(* ,(at-arc (ames.geometry:differentiate gap +arc-length+) s)
                                     ,(at-arc speed s))))
                 (answers (mapcar (lambda (r) (decide run (at-arc r s))) extent)))
            (cond ((every (lambda (a) (eq a :true)) answers) (values :at s rate))
                  ((member :unknown answers) (values :unknown (at-arc (nth (position :unknown answers) extent) s)))
                  (t (values :unknown `(:meets-beyond-the-first-root ,s)))))))))

(defun path-candidate (run solved group condition)
  "When CONDITION, over GROUP's motion along its curve, fires: a CANDIDATE (its TIME
the travel time, its AT-ARC the arc length), :NEVER, or (values :UNKNOWN FACT). On a
curved contact the body must reach that arc length with its speed squared >= 0: when
that is open the answer is :UNKNOWN with it; when it is proven negative (the body turns
back first, at a point not found) UNSUPPORTED-SITUATION is signalled naming the body."
  (let* ((relation (ames.engine:termination-condition-relation condition))
         (meeting (relation-meeting run solved relation))   ; guarded-meetings.lisp
         (over-arc (lambda (x) (motion-value (list group) (over-state-terms run solved x)))))
    (multiple-value-bind (status s rate)
        (cond (meeting
               (meeting-arc run group meeting over-arc))
              ((speed-function-p run group (speed-condition-function relation over-arc))
               ;; the speed along the path changes sign: a turning point (turns.lisp)
               (turning-crossing run solved group (speed-condition-function relation over-arc)))
              ((positive-where-reached-p run group (speed-condition-function relation over-arc))
               (values :never))
              (t (relation-arc run group relation over-arc)))
      (when (and (eq status :at) (eq (group-kind group) :path)
                 (eq :unknown (decide run `(>= ,(at-arc (group-speed-squared group) s) 0))))
        ;; whether the body gets there at all is open
        (return-from path-candidate
          (values :unknown `(>= ,(at-arc (group-speed-squared group) s) 0))))
      (when (and (eq status :at) (eq (group-kind group) :path)
                 (holds run `(< ,(at-arc (group-speed-squared group) s) 0)))
        ;; the energy integral is negative there: the body stops and turns back on the
        ;; way. When the knowledge base watches for that (a condition on the speed along
        ;; this path, see TURNING-WATCHED-P), that turning point ends the state first
        ;; and this condition does not fire in it
        (when (turning-watched-p run solved group)
          (return-from path-candidate :never))
        (error 'unsupported-situation
               :datum (group-bodies group)
               :detail (format nil "The body would stop and turn back on the curve before ~
                                    ~(~A~), where its speed squared is negative; a turning ~
                                    point on a curve is not supported yet."
                               (let ((*print-pretty* nil)) (princ-to-string (condition-event condition nil))))))
      (case status
        (:at (make-candidate condition
                             (condition-event condition (and rate (holds run `(< ,rate 0)) rate))
                             (arc-travel-time run group s)
                             :at-arc s :group group :rate rate))
        (:never :never)
        (t (values :unknown s))))))

(defun turning-point (run group)
  "The nearest arc length ahead where the speed vanishes (the body turns back), or NIL."
  (multiple-value-bind (status s) (crossing-ahead run group (group-speed-squared group))
    (and (eq status :at) s)))

;;; Travel time along the curve

(defun arc-travel-time (run group s1)
  "The time GROUP's body takes from its start to the arc length S1: the bridge's closed
form of the travel-time integral when it has one (AMES.MAXIMA:TRAVEL-TIME; an elliptic
integral on a circle under a constant force), else (:NO-CLOSED-FORM :FROM-ARC-LENGTH S0
:TO-ARC-LENGTH S1 :SPEED-SQUARED E), whose number NUMERIC-TRAVEL-TIME gives."
  (let ((s0 (group-s0 group)) (energy (group-speed-squared group)))
    (if (holds run `(= ,s1 ,s0))
        0
        (multiple-value-bind (time kind)
            (ames.algebra:travel-time (run-bridge run) energy +arc-length+ s0 s1
                                     :direction (group-direction group))
          (if (eq kind :closed-form)
              time
              (list :no-closed-form :from-arc-length s0 :to-arc-length s1
                                    :speed-squared energy))))))

(defun numeric-travel-time (bridge energy s0 s1 values)
  "The time to travel from arc length S0 to S1 when the speed squared is ENERGY (in
+ARC-LENGTH+), under the parameter VALUES; NIL when it has no value there."
  (handler-case (ames.algebra:numeric-travel-time bridge energy +arc-length+ s0 s1
                                                 (mapcar (lambda (entry)
                                                           (cons (car entry) (cdr entry)))
                                                         values))
    (ames.maxima:numeric-evaluation-failed () nil)))

(defun numeric-or-nil (bridge expression values)
  "The number EXPRESSION takes under VALUES, or NIL when it has none (a symbol left over,
or not a real)."
  (and (not (keywordp expression))
       (not (and (consp expression) (keywordp (first expression))))
       (handler-case (ames.maxima:numeric-value bridge expression values)
         (ames.maxima:numeric-evaluation-failed () nil))))
