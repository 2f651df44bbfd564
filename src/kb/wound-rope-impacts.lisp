;;;; src/kb/wound-rope-impacts.lisp -- a rope wound on a turning disc at an impact (the wound
;;;; rope phenomenon of wound-ropes.lisp, its impact part): the jerk of a yo-yo's string pulled
;;;; taut, a massive pulley's rope going slack when its weight lands.

(in-package #:ames.kb)

;;; At an impact (impacts.lisp; ropes.lisp's jerk of a rope wound on no disc)
;;;
;;; A rope wound on a disc takes part in an impact like any rope at its full length: a
;;; plastic jerk J >= 0, the same all along, leaving its length not growing just after. Its
;;; length counts the rope the disc has paid out, exactly: for the wound piece
;;; sqrt(|w|^2 - R^2) - SENSE R (theta - theta0), w = P - C at the impact and theta the
;;; disc's angle then; its rate just after is -u . (v'_P - v'_C) - SENSE R omega' (u from P
;;; toward the tangent point, as in a state). On the disc the jerk pulls at the tangent
;;; point toward P: the angular impulse SENSE R J about its centre.

(defun impact-wound-vector (situation segment)
  "w = P - C at the impact: from the wound SEGMENT's disc centre to its neighbouring point."
  (multiple-value-bind (neighbour disc) (wound-piece situation segment)
    (mapcar (lambda (p c) `(- ,p ,c))
            (impact-point situation neighbour) (impact-point situation (list disc '(0 0))))))

(defun impact-wound-direction (situation segment sense)
  "u at the impact: the unit vector from the wound SEGMENT's neighbouring point toward its
tangent point, -(l w + SENSE R k x w) / |w|^2."
  (let* ((radius (nth-value 2 (wound-piece situation segment)))
         (w (impact-wound-vector situation segment))
         (l (straight-length w radius))
         (kw (list `(- ,(second w)) (first w)))
         (w2 (ames.geometry:dot w w)))
    (mapcar (lambda (a b) `(- (/ (+ (* ,l ,a) (* ,sense ,radius ,b)) ,w2))) w kw)))

(defun impact-piece-length (situation segment sense)
  "The length a rope's SEGMENT counts at the impact: a straight piece's distance between
its points, a wound piece's straight length less the rope its disc has paid out."
  (if (wound-segment-p situation segment)
      (multiple-value-bind (neighbour disc radius) (wound-piece situation segment)
        (declare (ignore neighbour))
        `(- ,(straight-length (impact-wound-vector situation segment) radius)
            (* ,sense ,radius (- ,(body-entity-property situation disc :angle)
                                 ,(entity-property (entity-named situation segment) :start-angle)))))
      (multiple-value-bind (a b) (segment-points situation segment)
        (ames.geometry:vector-length (mapcar (lambda (q p) `(- ,q ,p))
                                             (impact-point situation b) (impact-point situation a))))))

(defun impact-piece-rate-after (situation segment sense)
  "The rate of IMPACT-PIECE-LENGTH just after the impact, over the velocities after."
  (flet ((after (body) (list `(vel-after ,body :x) `(vel-after ,body :y))))
    (if (wound-segment-p situation segment)
        (multiple-value-bind (neighbour disc radius) (wound-piece situation segment)
          `(- (- ,(ames.geometry:dot (impact-wound-direction situation segment sense)
                                     (mapcar (lambda (p c) `(- ,p ,c))
                                             (after (point-body neighbour)) (after disc))))
              (* ,sense ,radius (angvel-after ,disc))))
        (multiple-value-bind (a b) (segment-points situation segment)
          (ames.geometry:dot (impact-segment-direction situation segment)
                             (mapcar (lambda (q p) `(- ,q ,p)) (after (point-body b)) (after (point-body a))))))))

(defun register-wound-rope-impact-templates (kb)
  "Register in KB the template functions of wound ropes at an impact."
  (flet ((reg (head function documentation)
           (register-template kb head function :documentation documentation)))
    (reg 'winding-indicator
         (lambda (situation rope) (entity-property (entity-named situation rope) :winding-indicator))
         "p0 x w0 of a rope wound on a disc: its sign is the rope's winding sense.")
    (reg 'winding-undecided
         (lambda (situation rope)
           (declare (ignore situation))
           (error 'unmodelled-situation
                  :datum rope
                  :detail (format nil "The rope ~(~A~) is wound on a disc at a point in line with the disc's centre and the rope's next point: which side of the disc it leaves is not said."
                                  rope)))
         "Signals UNMODELLED-SITUATION: a wound rope's side is not told.")
    (reg 'wound-rope-at-length
         (lambda (situation rope sense)
           `(>= ,(sum-over-segments situation rope
                                    (lambda (s) (impact-piece-length situation s sense)))
                ,(entity-property (entity-named situation rope) :length)))
         "A wound rope is at its full length at the impact.")
    (reg 'wound-rope-shortening-after
         (lambda (situation rope sense)
           `(- ,(sum-over-segments situation rope
                                   (lambda (s) (impact-piece-rate-after situation s sense)))))
         "Minus the rate of a wound rope's length just after the impact.")
    (reg 'wound-pull-direction
         (lambda (situation segment sense axis)
           (let ((u (impact-wound-direction situation segment sense)))
             (axis-component (if (nth-value 3 (wound-piece situation segment)) u (mapcar (lambda (x) `(- ,x)) u))
                             axis)))
         "A component of the wound piece's unit vector from its :FROM end toward its :TO end at the impact.")
    (reg 'wound-piece-radius
         (lambda (situation segment) (nth-value 2 (wound-piece situation segment)))
         "The radius a wound piece leaves its disc at.")))

(register-wound-rope-impact-templates *impacts*)

;; At an impact as in a state: the sense in which turning the disc pays the rope out is
;; the state's component ROPE-WINDING itself (wound-ropes.lisp), registered here too.
(ames.engine:register-component *impacts*
                                (ames.engine:find-component *mechanics* 'rope-winding))

(defcomponent wound-rope-kinematics-at-impact (:knowledge-base *impacts*)
  "How fast a wound rope's length shrinks just after the impact (its separation: negative
when it would stretch), the rope its disc pays out counted."
  (:arguments (?rope :entity rope :where (:wound t))
              (?sense :belief (rope-winding ?rope :sense ?sense)))
  (:equations (= (separation-after ?rope) (wound-rope-shortening-after ?rope ?sense))))

(defcomponent wound-rope-jerk (:knowledge-base *impacts*)
  "A wound rope at its full length may jerk: an impulse J >= 0 along it that leaves its
length not changing just after (a plastic jerk); without one its length must not grow."
  (:arguments (?rope :entity rope :where (:wound t))
              (?sense :belief (rope-winding ?rope :sense ?sense)))
  (:activation (wound-rope-at-length ?rope ?sense) (approaching-after ?rope)
               (:event (:jerk ?rope)))
  (:deactivation (:when (< (rope-impulse ?rope) 0) :event (:would-push ?rope)))
  (:assert (jerked ?rope)
           (reported :impulses (:rope-impulse ?rope (rope-impulse ?rope))))
  (:equations (= (separation-after ?rope) 0)))

(defcomponent wound-rope-segment-jerk (:knowledge-base *impacts*)
  "A jerked rope's wound piece pulls its neighbouring point's body toward the disc and the
disc toward that body with the rope's impulse (Newton's third law gives the second); on
the disc it acts at the tangent point, its angular impulse SENSE R J."
  (:arguments (?rope :entity rope)
              (?sense :belief (rope-winding ?rope :sense ?sense))
              (?segment :entity wound-rope-segment
                        :where (:rope ?rope :from (?body1 ?_) :to (?body2 ?_) :disc ?disc)))
  (:activation (:believes (jerked ?rope)))
  (:assert (impulse (rope-pull ?segment ?body1) :from ?body2 :on ?body1 :contact ?segment)
           (impulse (rope-pull ?segment ?body2) :from ?body1 :on ?body2 :contact ?segment)
           (impulse-acts-at (rope-pull ?segment ?disc) :on ?disc))
  (:equations (= (impulse-x (rope-pull ?segment ?body1))
                 (* (rope-impulse ?rope) (wound-pull-direction ?segment ?sense :x)))
              (= (impulse-y (rope-pull ?segment ?body1))
                 (* (rope-impulse ?rope) (wound-pull-direction ?segment ?sense :y)))
              (= (angular-impulse-of (rope-pull ?segment ?disc))
                 (* ?sense (wound-piece-radius ?segment) (rope-impulse ?rope)))))
