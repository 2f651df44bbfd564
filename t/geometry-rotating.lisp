;;;; t/geometry-rotating.lisp -- contacts of a rotating body as functions of (x, y, theta).
;;;;
;;;; The ladder's ends on its wall and floor, a block resting on an incline by two corners,
;;;; a fixed corner under a rotating face; every formula is checked by Maxima: against the
;;;; textbook's, and the rates against Maxima's own derivatives of the gap (chain rule
;;;; over the configuration and its rates).

(in-package #:ames.tests)

(def-suite geometry-rotating :in geometry
  :description "Contacts of rotating polygons and segments with fixed faces (rotating-contacts.lisp).")

(in-suite geometry-rotating)

(defparameter *r-configuration* (ames.geometry:make-configuration 'x 'y 'th)
  "A rotating body's configuration in plain names.")

(defun r-time-derivative (bridge expression rates)
  "The time derivative of EXPRESSION when each name of the alist RATES (NAME . RATE)
varies at RATE: the chain rule through Maxima's partial derivatives."
  (ames.maxima:simplify
   bridge `(+ 0 ,@(loop for (name . rate) in rates
                        collect `(* ,(ames.maxima:maxima-derivative bridge expression name) ,rate)))))

(defparameter *r-rates* '((x . vx) (y . vy) (th . w) (vx . ax) (vy . ay) (w . al))
  "Positions, velocities and accelerations of the configuration, in plain names.")

(defun r-ladder-contacts (bridge)
  "The ladder's corner contacts with its floor and its wall (all four pairs)."
  (let ((ladder (ames.geometry:parse-shape '(segment ((- (/ l 2)) 0) ((/ l 2) 0)) :bridge bridge))
        (floor (ames.geometry:parse-shape '(half-plane (1 0) (0 0)) :bridge bridge))
        (wall (ames.geometry:parse-shape '(half-plane (0 0) (0 1)) :bridge bridge)))
    (values (ames.geometry:corner-contacts bridge ladder *r-configuration* floor)
            (ames.geometry:corner-contacts bridge ladder *r-configuration* wall)
            ladder floor wall)))

(test rotating-ladder-ends-on-wall-and-floor
  (g-call-with-bridge
   '((> l 0) (> a 0) (< a (/ pi 2)))
   (lambda (bridge)
     (multiple-value-bind (on-floor on-wall ladder floor wall) (r-ladder-contacts bridge)
       (let ((foot (find '(:vertex 0) on-floor :key #'ames.geometry:rotating-contact-feature :test #'equal))
             (top (find '(:vertex 1) on-wall :key #'ames.geometry:rotating-contact-feature :test #'equal)))
         ;; the foot's height and the top's distance from the wall, textbook
         (is (g-same-meaning-p bridge (ames.geometry:rotating-contact-gap foot) '(- y (* (/ l 2) (sin th)))))
         (is (g-same-meaning-p bridge (ames.geometry:rotating-contact-gap top) '(+ x (* (/ l 2) (cos th)))))
         (is (g-same-meaning-p bridge (ames.geometry:rotating-contact-normal foot) '(0 1)))
         (is (g-same-meaning-p bridge (ames.geometry:rotating-contact-normal top) '(1 0)))
         (is (null (ames.geometry:rotating-contact-extent foot)))
         ;; torque of the wall's push N at the top: the arm is (l/2) (cos th, sin th)
         (is (g-same-meaning-p bridge (ames.geometry:contact-torque top '(n 0)) '(- (* n (/ l 2) (sin th))))))
       ;; at the scenario's start the foot touches the floor and the top the wall, nothing else
       (let* ((start (ames.geometry:make-configuration '(* (/ l 2) (cos a)) '(* (/ l 2) (sin a)) '(- pi a)))
              (floor-touching (ames.geometry:resting-face-contacts bridge ladder start floor))
              (wall-touching (ames.geometry:resting-face-contacts bridge ladder start wall)))
         (is (equal '((:vertex 0)) (mapcar #'ames.geometry:rotating-contact-feature floor-touching)))
         (is (equal '((:vertex 1)) (mapcar #'ames.geometry:rotating-contact-feature wall-touching)))
         (is (g-same-meaning-p bridge (ames.geometry:rotating-contact-point (first floor-touching))
                               '((* l (cos a)) 0)))
         (is (g-same-meaning-p bridge (ames.geometry:rotating-contact-point (first wall-touching))
                               '(0 (* l (sin a))))))))))

(test rotating-gap-rates-are-the-gaps-derivatives
  (g-call-with-bridge
   '((> l 0) (> w0 0) (> h0 0))
   (lambda (bridge)
     (let* ((box (ames.geometry:parse-shape '(polygon ((- w0) (- h0)) (w0 (- h0)) (w0 h0) ((- w0) h0))
                                            :bridge bridge))
            (incline (ames.geometry:parse-shape '(polygon (0 0) (4 0) (0 3)) :bridge bridge))
            (contacts (append (ames.geometry:corner-contacts bridge box *r-configuration* incline)
                              (list (ames.geometry:face-on-vertex bridge '((- w0) (- h0)) '(w0 (- h0))
                                                                  '(1 2) *r-configuration*)
                                    (ames.geometry:face-on-vertex bridge '(w0 (- h0)) '(w0 h0)
                                                                  '((/ l 3) 0) *r-configuration*)))))
       (is (= 14 (length contacts)))
       (dolist (contact contacts)
         (let* ((gap (ames.geometry:rotating-contact-gap contact))
                (rate (ames.geometry:contact-gap-rate contact '(vx vy) 'w))
                (acceleration (ames.geometry:contact-gap-acceleration contact '(vx vy) 'w '(ax ay) 'al)))
           (is (ames.maxima:equivalent-p bridge rate (r-time-derivative bridge gap *r-rates*))
               "gap rate of ~S" (ames.geometry:rotating-contact-kind contact))
           (is (ames.maxima:equivalent-p bridge acceleration (r-time-derivative bridge rate *r-rates*))
               "gap acceleration of ~S" (ames.geometry:rotating-contact-kind contact))))))))

(test rotating-fixed-corner-under-a-turning-face
  (g-call-with-bridge
   '((> w0 0) (> h0 0))
   (lambda (bridge)
     ;; a w0 x h0 half-size box whose bottom face rests on a fixed corner at the origin
     (let ((contact (ames.geometry:face-on-vertex bridge '((- w0) (- h0)) '(w0 (- h0)) '(0 0)
                                                  *r-configuration*)))
       ;; the gap: the corner's distance outside the turned bottom face
       (is (g-same-meaning-p bridge (ames.geometry:rotating-contact-gap contact)
                             '(+ (* y (cos th)) (- (* x (sin th))) (- h0))))
       ;; the push on the box is along the face's inward normal (-sin th, cos th)
       (is (g-same-meaning-p bridge (ames.geometry:rotating-contact-normal contact)
                             '((- (sin th)) (cos th))))
       (is (g-same-meaning-p bridge (ames.geometry:rotating-contact-place contact)
                             '(+ w0 (- (* x (cos th))) (- (* y (sin th))))))
       (is (g-same-meaning-p bridge (ames.geometry:rotating-contact-extent contact) '(* 2 w0)))
       ;; at rest level on the corner: touching, the corner at the face's middle
       (let ((level (ames.geometry:face-on-vertex bridge '((- w0) (- h0)) '(w0 (- h0)) '(0 0)
                                                  (ames.geometry:make-configuration 0 'h0 0))))
         (is (eql 0 (ames.maxima:simplify bridge (ames.geometry:rotating-contact-gap level))))
         (is (ames.maxima:equivalent-p bridge (ames.geometry:rotating-contact-place level) 'w0)))))))

(test rotating-block-rests-on-an-incline-by-two-corners
  (g-call-with-bridge
   '((> h 0) (> a 0) (< a (/ pi 2)) (> w 0) (< w h) (> k 0) (< k h) (> k (/ w (tan a))))
   (lambda (bridge)
     (let* ((block (ames.geometry:parse-shape '(polygon ((- (/ w 2)) (- (/ k 2))) ((/ w 2) (- (/ k 2)))
                                                        ((/ w 2) (/ k 2)) ((- (/ w 2)) (/ k 2)))
                                              :bridge bridge))
            (incline (ames.geometry:parse-shape *g-wedge-form* :bridge bridge))
            (start (ames.geometry:make-configuration '(+ (/ h (* 2 (tan a))) (* (/ k 2) (sin a)))
                                                     '(+ (/ h 2) (* (/ k 2) (cos a))) '(- a)))
            (resting (ames.geometry:resting-face-contacts bridge block start incline)))
       ;; the bottom face's two ends on the slope (the wedge's edge 1)
       (is (equal '((:vertex 0) (:vertex 1)) (mapcar #'ames.geometry:rotating-contact-feature resting)))
       (is (every (lambda (c) (equal '(:edge 1) (ames.geometry:rotating-contact-other-feature c))) resting))
       (dolist (contact resting)
         (is (g-same-meaning-p bridge (ames.geometry:rotating-contact-normal contact) '((sin a) (cos a)))))
       ;; the weight's torque about the downhill corner (vertex 1, the slope falling toward
       ;; +x): (c - p) x (0, -m g) = m g r_x with r = p - c the corner's arm, that is
       ;; -m g ((k/2) sin a - (w/2) cos a): clockwise when tan a > w/k (it tips)
       (let* ((downhill (second resting))
              (arm (ames.geometry:rotating-contact-arm downhill)))
         (is (g-same-meaning-p bridge `(* ,(first arm) m g)
                               '(- (* m g (- (* (/ k 2) (sin a)) (* (/ w 2) (cos a))))))))))))
