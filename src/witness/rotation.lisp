;;;; src/witness/rotation.lisp -- the model's part for rotating bodies (issue 23): read by
;;;; witness/siconos_rotation.py, which simulates a body with an "inertia" with three degrees
;;;; of freedom (x, y, theta).
;;;;
;;;; A rotating body adds "inertia", "theta" and "omega" (its start angle and angular
;;;; velocity) and "forces_at" (the forces with an :at, each {"point": own frame, "force":
;;;; world}); the model adds "hinges" ({"name", "body": index, "offset": own frame, "point":
;;;; the world point it is pinned at}) and "probes" ({"body": name, "angle": value}: the
;;;; angles the queries ask about with (reaches (angle B) VALUE), whose crossings the driver
;;;; reports as (:reaches BODY "angle") events).

(in-package #:ames.witness)

(defun body-rotation-model (scenario body values)
  "The entries that a rotating BODY adds to its model (NIL for a translating one)."
  (when (scenario-body-rotating-p body)
    `(("inertia" . ,(value-of (scenario-body-inertia body) values "a moment of inertia"))
      ("theta" . ,(value-of (scenario-body-angle body) values "an angle"))
      ("omega" . ,(value-of (scenario-body-angular-velocity body) values "an angular velocity"))
      ("forces_at" . (:array ,@(loop for force in (scenario-forces scenario)
                                     when (and (eq (scenario-force-body force) (scenario-body-name body))
                                               (scenario-force-point force))
                                       collect `(("point" . (:array ,@(point-of (scenario-force-point force) values "a point")))
                                                 ("force" . (:array ,@(point-of (scenario-force-value force) values "a force"))))))))))

(defun pinned-point (body point values)
  "The world position at the start of BODY's point POINT (own frame)."
  (let ((theta (value-of (scenario-body-angle body) values "an angle")))
    (destructuring-bind (x y) (point-of (scenario-body-position body) values "a position")
      (destructuring-bind (px py) (point-of point values "a hinge's point")
        (list (+ x (- (* (cos theta) px) (* (sin theta) py)))
              (+ y (* (sin theta) px) (* (cos theta) py)))))))

(defun angle-probes (scenario values)
  "The probes of the angles SCENARIO's queries ask (reaches (angle B) VALUE) about."
  (let ((probes '()))
    (labels ((walk (x)
               (when (consp x)
                 (when (and (member (first x) '(:reaches :reaches-time))
                            (consp (second x)) (eq (first (second x)) :angle))
                   (pushnew `(("body" . ,(string-downcase (second (second x))))
                              ("angle" . ,(value-of (third x) values "an angle")))
                            probes :test #'equal))
                 (when (alexandria:proper-list-p x) (mapc #'walk x)))))
      (mapc (lambda (query) (walk (second query))) (scenario-queries scenario)))
    (nreverse probes)))

(defun rotation-model (scenario values)
  "The model's entries for the hinges and the angle probes of SCENARIO."
  `(("hinges" . (:array ,@(loop for hinge in (scenario-hinges scenario)
                                for body = (find-scenario-body (scenario-hinge-body hinge) scenario)
                                collect `(("name" . ,(string-downcase (scenario-hinge-name hinge)))
                                          ("body" . ,(position body (scenario-moving-bodies scenario)))
                                          ("offset" . (:array ,@(point-of (scenario-hinge-point hinge) values "a hinge's point")))
                                          ("point" . (:array ,@(pinned-point body (scenario-hinge-point hinge) values)))))))
    ("probes" . (:array ,@(angle-probes scenario values)))))
