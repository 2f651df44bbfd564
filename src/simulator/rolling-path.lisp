;;;; src/simulator/rolling-path.lisp -- a rotating body on a curved contact whose turning is
;;;; tied to its motion along the curve: a disc rolling over a corner (or on a curved face).
;;;;
;;;; A :PATH group has one degree of freedom, the arc length s, integrated by its energy
;;;; integral w^2 = E(s) (integrators.lisp). A rotating body in it has two more state
;;;; variables, its angle and angular velocity; the group keeps its one degree of freedom
;;;; when the model ties them to the path: when the angular acceleration is a constant
;;;; multiple c of the tangential acceleration (alpha = c dw/dt: rolling without slipping,
;;;; where the contact point's relative velocity is held at 0; c = 0 on a frictionless
;;;; contact, where no force turns the disc) and the angular velocity starts at c w0
;;;; (rolling from the start; no spin at all on the frictionless contact). Then, for the
;;;; whole state, omega = c w and theta = theta0 + c (s - s0): functions of s, like the
;;;; position. The energy integral already holds the rotational energy (the tangential
;;;; acceleration solved with the rotation in the model: (2/3) g sin for a disc). A state
;;;; where these are not proven keeps the rotating group :NUMERIC.

(in-package #:ames.simulator)

(defun path-rotation-factors (run solved group)
  "For GROUP (a :PATH group along its contact), the alist ((BODY . C) ...) over its
rotating bodies, C a constant with (angacc BODY) = C (path-acc CONTACT :tangential) in
SOLVED and (angvel BODY) = C (path-speed CONTACT) at the start (see the file header);
NIL when some body's rotation is not so tied (or the group does not rotate)."
  (let* ((contact (group-contact group))
         (w-term `(ames.kb:path-speed ,contact))
         (tangential (cdr (assoc w-term (solved-model-rates solved) :test #'equal)))
         (w0 (cdr (assoc w-term (solved-model-initial solved) :test #'equal)))
         (bodies (group-rotating-bodies run group)))
    (when (and bodies tangential w0
               (not (eq :true (decide run `(= ,tangential 0)))))
      (loop for body in bodies
            for alpha = (angular-rate solved body)
            for c = (and alpha (tidy run `(/ ,alpha ,tangential) :full))
            unless (and c (not (mentions-state-p solved c)) (free-of-p 'tau c)
                        (eq :true (decide run `(= ,(body-angular-velocity run body) (* ,c ,w0)))))
              return nil
            collect (cons body c)))))

(defun path-rotation-motion (run group factors)
  "The motion entries ((angle B) . THETA(s)) and ((angvel B) . OMEGA(s)) of the rotating
bodies FACTORS ties to GROUP's path (see PATH-ROTATION-FACTORS), over +ARC-LENGTH+."
  (loop for (body . c) in factors
        collect (cons `(ames.kb:angle ,body)
                      (tidy run `(+ ,(body-angle run body) (* ,c (- ,+arc-length+ ,(group-s0 group))))))
        collect (cons `(ames.kb:angvel ,body) (tidy run `(* ,c ,(group-speed group))))))

(defun integrate-rolling-path (run solved group)
  "Integrate GROUP along its curved contact (INTEGRATE-PATH) when its rotating bodies are
tied to the path (PATH-ROTATION-FACTORS), their angles and angular velocities added to
its motion; NIL (nothing done) otherwise."
  (let ((factors (path-rotation-factors run solved group)))
    (when factors
      (integrate-path run solved group)
      (setf (group-motion group) (append (group-motion group)
                                         (path-rotation-motion run group factors)))
      group)))
