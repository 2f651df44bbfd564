;;;; src/witness/model-curved.lisp -- what of a scenario is not linear in the positions:
;;;; fixed arcs and circles, universal gravitation, bumpers (see witness/siconos_arcs.py).
;;;;
;;;; A fixed arc is its centre (world frame), radius, angles and solid side; a fixed circle
;;;; (a planet, a sphere) is a whole arc with the solid inside. Gravitation is its constant
;;;; and the fixed bodies with a mass (attractors); the free bodies' masses are in the model
;;;; already. A bumper is its fixed attachment point (world frame), direction, rest length
;;;; and stiffness; a bumper on a free body is refused.

(in-package #:ames.witness)

(defun arc-model (shape origin values)
  "The driver's arc for the checked arc or circle SHAPE of a fixed body at ORIGIN."
  (ecase (shape-kind shape)
    (:circle `(("center" . (:array ,@origin)) ("radius" . ,(value-of (second shape) values "a radius"))
               ("whole" . :true) ("solid" . "inside")))
    (:arc (let* ((plist (rest shape))
                 (from (value-of (getf plist :from) values "an arc's angle"))
                 (to (value-of (getf plist :to) values "an arc's angle")))
            `(("center" . (:array ,@(mapcar #'+ origin (point-of (getf plist :center) values "an arc's centre"))))
              ("radius" . ,(value-of (getf plist :radius) values "an arc's radius"))
              ("from" . ,from) ("to" . ,to)
              ("whole" . ,(if (>= (- to from) (- (* 2 pi) 1d-12)) :true :false))
              ("solid" . ,(string-downcase (symbol-name (or (getf plist :solid) :inside)))))))))

(defun obstacle-arcs (body values)
  "The arcs of the fixed BODY (none but for an arc or circle)."
  (let ((shape (scenario-body-shape body)))
    (when (member (shape-kind shape) '(:arc :circle))
      (list (arc-model shape (point-of (scenario-body-position body) values "a position") values)))))

(defun curved-obstacle-p (body)
  "True when the fixed BODY is an arc or a circle (no faces: OBSTACLE-ARCS has it)."
  (member (shape-kind (scenario-body-shape body)) '(:arc :circle)))

(defun bumpers-model (scenario values)
  "The driver's bumpers: springs with a :toward, attached to a fixed body."
  (loop for spring in (scenario-springs scenario)
        for (body-name point) = (scenario-spring-from spring)
        for body = (find-scenario-body body-name scenario)
        when (scenario-spring-toward spring)
          collect (progn
                    (unless (scenario-body-fixed-p body)
                      (unsupported (scenario-spring-name spring) "the witness models bumpers on fixed bodies only"))
                    `(("name" . ,(string-downcase (scenario-spring-name spring)))
                      ("k" . ,(value-of (scenario-spring-stiffness spring) values "a stiffness"))
                      ("rest" . ,(value-of (scenario-spring-rest-length spring) values "a rest length"))
                      ("point" . (:array ,@(mapcar #'+ (point-of point values "an attachment point")
                                                   (point-of (scenario-body-position body) values "a position"))))
                      ("toward" . (:array ,@(point-of (scenario-spring-toward spring) values "a direction")))))))

(defun curved-model-entries (scenario values samples)
  "The model's entries for gravitation, bumpers and the SAMPLES (times at which the
driver reports the state), only those the scenario has."
  (append
   (when (scenario-gravitation scenario)
     `(("gravitation" . ,(value-of (scenario-gravitation scenario) values "the gravitational constant"))
       ("attractors" . (:array ,@(loop for body in (scenario-fixed-bodies scenario)
                                       when (scenario-body-mass body)
                                         collect `(("name" . ,(string-downcase (scenario-body-name body)))
                                                   ("q" . (:array ,@(point-of (scenario-body-position body) values "a position")))
                                                   ("mass" . ,(value-of (scenario-body-mass body) values "a mass"))))))))
   (let ((bumpers (bumpers-model scenario values)))
     (when bumpers `(("bumpers" . (:array ,@bumpers)))))
   (when samples
     `(("samples" . (:array ,@(mapcar (lambda (x) (coerce x 'double-float)) samples)))))))
