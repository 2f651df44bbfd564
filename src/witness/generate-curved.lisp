;;;; src/witness/generate-curved.lisp -- random scenarios on arcs, with bumpers, and under
;;;; universal gravitation (the families the witness's siconos_arcs.py models).
;;;;
;;;; Speeds that decide the outcome are rationals chosen strictly inside the range of the
;;;; outcome wanted (checked exactly): a particle in a loop below sqrt(2 g r) swings, between
;;;; sqrt(2 g r) and sqrt(5 g r) leaves the loop, above sqrt(5 g r) loops; on a dome's top it
;;;; needs less than sqrt(g r) to slide down it before leaving it; a probe below the escape
;;;; speed sqrt(2 G M / R) turns and falls back; a bumper shorter than v sqrt(m/k) lets the
;;;; block reach the wall.

(in-package #:ames.witness)

(defun speed-between (low2 high2 &optional (denominator 40))
  "A random rational v > 0 with LOW2 < v^2 < HIGH2 (rationals, 0 <= LOW2 < HIGH2 apart
enough), checked exactly."
  (loop for v = (random-ratio (+ (sqrt (float low2 1d0)) 1/100)
                              (- (sqrt (float high2 1d0)) 1/100) denominator)
        when (and (plusp v) (< low2 (* v v) high2)) return v))

(defun side () "+1 or -1: which way a scenario runs." (pick 1 -1))

(defun family-loop (name)
  "A particle launched along the bottom of a vertical loop (inside a fixed circle), either
way: too slow to pass the centre's height (it swings), slow enough to leave the loop
above it, or fast enough to loop."
  (let* ((g (random-ratio 5 15)) (r (random-ratio 1/2 2)) (gr (* g r))
         (v (ecase (pick :swing :leave :loop)
              (:swing (speed-between (* 1/5 gr) (* 19/10 gr)))
              (:leave (speed-between (* 21/10 gr) (* 49/10 gr)))
              (:loop (speed-between (* 51/10 gr) (* 8 gr))))))
    (scenario-text name "A particle launched inside a vertical loop."
                   (parameters-text 'g g 'r r 'v v)
                   (list (format nil "(restitution ~A)" (restitution-choice))
                         "(body loop :fixed t :shape (arc :center (0 r) :radius r :from 0 :to (* 2 pi) :solid :outside))"
                         (format nil "(body particle :mass 1 :position (0 0) :velocity (~A 0) :shape point)"
                                 (if (plusp (side)) "v" "(- v)")))
                   3)))

(defun family-bowl (name)
  "A particle in a bowl (the lower half of a fixed circle): released at rest at an angle
from the bottom, on either side, or launched from the bottom too slowly to reach the rim;
it swings forever."
  (let ((g (random-ratio 5 15)) (r (random-ratio 1/2 2)) (s (side)))
    (multiple-value-bind (position velocity)
        (if (zerop (random 2 *random*))
            (values (format nil "((* ~D r (sin a)) (- r (* r (cos a))))" s) "(0 0)")
            (values "(0 0)" (format nil "((* ~D ~A) 0)" s (speed-between 0 (* 19/10 g r)))))
      (scenario-text name "A particle swings in a bowl."
                     (parameters-text 'g g 'r r 'a (random-ratio 1/5 7/5 20))
                     (list "(body bowl :fixed t :shape (arc :center (0 r) :radius r :from pi :to (* 2 pi) :solid :outside))"
                           (format nil "(body particle :mass 1 :position ~A :velocity ~A :shape point)"
                                   position velocity))
                     3))))

(defun family-dome (name)
  "A particle on a dome (the upper half of a fixed circle on the floor): at rest a little
off its top, either side, or at the top pushed sideways slower than sqrt(g r); it slides,
leaves the dome and lands on the floor."
  (let ((g (random-ratio 5 15)) (r (random-ratio 1/2 2)) (s (side)))
    (multiple-value-bind (position velocity)
        (if (zerop (random 2 *random*))
            (values (format nil "((* ~D r (sin a)) (* r (cos a)))" s) "(0 0)")
            (values "(0 r)" (format nil "((* ~D ~A) 0)" s (speed-between 1/100 (* 9/10 g r)))))
      (scenario-text name "A particle slides off a dome onto the floor."
                     (parameters-text 'g g 'r r 'a (random-ratio 1/20 1 20))
                     (list (format nil "(restitution ~A)" (restitution-choice)) (floor-text)
                           "(body dome :fixed t :shape (arc :center (0 0) :radius r :from 0 :to pi :solid :inside))"
                           (format nil "(body particle :mass 1 :position ~A :velocity ~A :shape point)"
                                   position velocity))
                     3))))

(defun family-bumper (name)
  "A block sliding on a frictionless floor into a bumper spring on a wall, on the left or
the right: it compresses the bumper and comes back; one time in four the bumper is too
short (l0 < v sqrt(m/k)) and the block hits the wall."
  (let* ((m (random-ratio 1/2 3)) (k (random-ratio 1 20)) (v (random-ratio 1/2 4))
         (reach2 (/ (* v v m) k))          ; the compression's square were there no wall
         (l0 (if (zerop (random 4 *random*))
                 (speed-between (* 1/10 reach2) (* 9/10 reach2))
                 (speed-between (* 11/10 reach2) (+ (* 4 reach2) 1))))
         (d (random-ratio 1/4 2)) (w (random-ratio 1/2 3/2))
         (left (plusp (side))))
    (scenario-text name "A block slides into a bumper spring on a wall."
                   (parameters-text 'g (random-ratio 5 15) 'm m 'k k 'v v 'l0 l0 'd d)
                   (list (format nil "(restitution ~A)" (restitution-choice)) (floor-text)
                         (if left
                             "(body wall :fixed t :shape (half-plane (0 0) (0 1)))"
                             "(body wall :fixed t :shape (half-plane (0 1) (0 0)))")
                         (format nil "(body block :mass m :position (~A 0) :velocity (~A 0) :shape (polygon (0 0) (~A 0) (~A 1) (0 1)))"
                                 (if left "(+ l0 d)" (format nil "(- (+ l0 d ~A))" w)) (if left "(- v)" "v") w w)
                         (format nil "(spring bumper :from (wall (0 1/2)) :toward (~D 0) :stiffness k :rest-length l0)"
                                 (if left 1 -1)))
                   4)))

(defun space-scenario-text (name description parameters clauses states)
  "A scenario without terrestrial gravity (SCENARIO-TEXT's form otherwise)."
  (format nil "(scenario ~(~A~)~%  ~S~%  ~A~%~{  ~A~%~}  (simulate :states ~D))~%"
          name description parameters clauses states))

(defun family-gravitation (name)
  "Universal gravitation: a probe launched straight up (along +y, +x or -x) from a fixed
planet below or above the escape speed, or two spheres released at rest that fall
together and collide."
  (if (zerop (random 3 *random*))
      (let ((a (random-ratio 1/4 1)) (b (random-ratio 1/4 1)))
        (space-scenario-text name "Two spheres released at rest fall together."
                             (parameters-text 'big-g (random-ratio 1/2 2) 'm1 (random-ratio 1/2 3)
                                              'm2 (random-ratio 1/2 3) 'd (+ a b (random-ratio 1/2 4)))
                             (list "(gravitation big-g)" (format nil "(restitution ~A)" (pick 0 1/2))
                                   (format nil "(body first :mass m1 :position (0 0) :velocity (0 0) :shape (circle ~A))" a)
                                   (format nil "(body second :mass m2 :position (d 0) :velocity (0 0) :shape (circle ~A))" b))
                             2))
      (let* ((big-m (random-ratio 500 2000)) (r (random-ratio 5 15)) (escape2 (/ (* 2 big-m) r))
             (v (if (zerop (random 2 *random*))
                    (speed-between (* 1/5 escape2) (* 9/10 escape2))
                    (speed-between (* 11/10 escape2) (* 2 escape2))))
             (direction (pick '(0 1) '(1 0) '(-1 0))))
        (space-scenario-text name "A probe launched straight up from a planet."
                             (parameters-text 'big-g 1 'big-m big-m 'r r 'v v)
                             (list "(gravitation big-g)"
                                   "(body planet :mass big-m :fixed t :position (0 0) :shape (circle r))"
                                   (format nil "(body probe :mass 1 :position ((* ~D r) (* ~D r)) :velocity ((* ~D v) (* ~D v)) :shape point)"
                                           (first direction) (second direction) (first direction) (second direction)))
                             2))))

(defparameter *curved-families*
  '((:loop . family-loop) (:bowl . family-bowl) (:dome . family-dome)
    (:bumper . family-bumper) (:gravitation . family-gravitation))
  "The families on arcs, with bumpers and under gravitation, added to *FAMILIES*.")

(dolist (entry *curved-families*)
  (unless (assoc (car entry) *families*)
    (setf *families* (append *families* (list entry)))))
