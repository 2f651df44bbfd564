;;;; src/witness/generate-rotation.lisp -- random scenarios with rotating bodies (the
;;;; language's "Rotation"): a uniform disc or a hoop on a fixed incline or on a floor,
;;;; released or launched, with friction (it rolls, or slides while it spins up, and may
;;;; start rolling: (:stops-sliding DISC FACE)) or without (it slides, its spin constant).
;;;; The witness simulates them with siconos_rotation.py (three degrees of freedom per body,
;;;; Moreau-Jean time stepping: first order, compared to *FIRST-ORDER-TOLERANCE*).
;;;;
;;;; Until AMES runs rotating bodies it refuses them (SCENARIO-AWAITING); WITNESS-CHECK
;;;; reports such a scenario as unsupported, by AMES, rather than refused.
;;;;
;;;; Inclines are Pythagorean triangles (a, b, c), so that the slope's unit vectors and the
;;;; disc's centre, r along the slope's normal from its point of contact, stay rational.

(in-package #:ames.witness)

(defun wheel-text (name inertia r position velocity omega)
  "A rotating round body NAME (INERTIA :uniform or :ring) of radius R."
  (format nil "(body ~A :mass m :inertia ~(~S~) :shape (circle ~A) :position (~{~A~^ ~}) :velocity (~{~A~^ ~}) :angular-velocity ~A)"
          name inertia r position velocity omega))

(defun friction-text (a b &optional (none 1/4))
  "A friction clause between A and B with coefficient mu, or none (with probability NONE)."
  (if (< (random 1d0 *random*) none) "" (format nil "(friction ~A ~A :static mu)" a b)))

(defun family-disc-incline (name)
  "A disc or a hoop on a fixed incline: released at rest, launched up the slope rolling, or
launched down it without spin; friction below or above the rolling threshold (tan a / 3
for a disc, tan a / 2 for a hoop), or none. The incline stands on the floor: coming down,
the disc hits the floor in the corner while it still touches the slope (plastic impact),
then rolls or slides along the floor."
  (destructuring-bind (a b c) (pick '(4 3 5) '(3 4 5) '(12 5 13) '(8 15 17))
    (let* ((scale (random-ratio 1 2)) (l (* a scale)) (hh (* b scale))
           (f (random-ratio 1/4 1/2)) (r (random-ratio 1/10 1/4 20))
           (inertia (pick :uniform :ring)) (v (random-ratio 1/4 2))
           (start (pick :rest :up-rolling :down-sliding))
           ;; the point of contact at a fraction f down the slope from its top (0 hh)
           (centre (list (+ (* f l) (/ (* r b) c)) (+ (* (- 1 f) hh) (/ (* r a) c))))
           (down (list (/ a c) (- (/ b c)))))
      (scenario-text name "A disc or a hoop on an incline."
                     (parameters-text 'g (random-ratio 5 15) 'm (random-ratio 1/2 3)
                                      'mu (random-ratio 1/20 1 20))
                     (list (floor-text)
                           (format nil "(body incline :fixed t :shape (polygon (0 0) (~A 0) (0 ~A)))" l hh)
                           (ecase start
                             (:rest (wheel-text "disc" inertia r centre '(0 0) 0))
                             (:up-rolling (wheel-text "disc" inertia r centre
                                                      (mapcar (lambda (d) (* (- v) d)) down) (/ v r)))
                             (:down-sliding (wheel-text "disc" inertia r centre
                                                        (mapcar (lambda (d) (* v d)) down) 0)))
                           (friction-text "disc" "incline")
                           ;; the floor rough one time in four: an impact on a rough
                           ;; contact ends what the witness can say (its impacts have
                           ;; Coulomb friction, AMES's none: reported unsupported)
                           (friction-text "disc" "floor" 3/4))
                     3))))

(defun family-disc-floor (name)
  "A disc or a hoop launched along a floor with a spin that does not match rolling (none,
backspin, or too much topspin), with friction (it slides until it rolls) or without."
  (let* ((r (random-ratio 1/10 1/2 20)) (v (random-ratio 1/2 4))
         (omega (* (/ v r) (pick 0 1/2 -1/2 -2 2))))
    (scenario-text name "A disc launched along a floor with spin."
                   (parameters-text 'g (random-ratio 5 15) 'm (random-ratio 1/2 3)
                                    'mu (random-ratio 1/20 1 20))
                   (list (floor-text)
                         (wheel-text "disc" (pick :uniform :ring) r (list 0 r) (list v 0) omega)
                         (friction-text "disc" "floor"))
                   3)))

(defparameter *rotation-families*
  '((:disc-incline . family-disc-incline) (:disc-floor . family-disc-floor))
  "The families with rotating bodies, added to *FAMILIES*.")

(dolist (entry *rotation-families*)
  (unless (assoc (car entry) *families*)
    (setf *families* (append *families* (list entry)))))
