;;;; src/witness/compare-slow-impacts.lisp -- AMES's impacts too slow for the witness to see.
;;;;
;;;; The rotation witness counts a contact's closing as a collision only above its stated
;;;; :collision-speed (max(0.05, 20 g h): slower, Moreau-Jean's contact just starts pressing,
;;;; and its chatter would otherwise be taken for impacts). A rocking body can re-strike far
;;;; slower: a square block landing plastically on its corner (seed 2026 block-step #433)
;;;; lifts that corner by under a micrometre and brings it down again 10.6 ms later at
;;;; 0.5 mm/s. AMES's impact gives its approach speed without any geometry: with restitution
;;;; e, the impulse J = m* (1 + e) v and the energy lost E = m* v^2 (1 - e^2) / 2 (m* the
;;;; effective mass at the contact), so v = 2 E / (J (1 - e)) <= 2 E / (J (1 - e_max)), e_max
;;;; the scenario's largest restitution. A collision of AMES's whose speed is under half the
;;;; witness's, which the witness has not as its next event, is not witnessed: :UNSUPPORTED,
;;;; said so (never an agreement).

(in-package #:ames.witness)

(defvar *largest-restitution* nil
  "The largest coefficient of restitution of the scenario's pairs (from the witness's
model: MODEL-LARGEST-RESTITUTION), or NIL when unknown.")

(defun model-largest-restitution (model)
  "The largest restitution of the witness's MODEL (an alist for MODEL-JSON): its default
and its pairs'."
  (let ((pairs (cdr (assoc "restitution" model :test #'equal))))
    (reduce #'max (cons (cdr (assoc "default_restitution" model :test #'equal))
                        (loop for entry in (and (consp pairs) (rest pairs))
                              when (and (consp entry) (realp (car (last entry))))
                                collect (car (last entry))))
            :key (lambda (x) (if (realp x) x 1)))))

(defun impact-speed-bound (event values)
  "An upper bound of the approach speed of AMES's collision EVENT, 2 E / (J (1 - e_max))
from its :IMPULSE J and :ENERGY-LOST E under VALUES; NIL when one is unknown or e_max is 1."
  (let* ((data (member-if #'keywordp (rest event)))
         (j (and (getf data :impulse) (number-of (getf data :impulse) values)))
         (e (and (getf data :energy-lost) (number-of (getf data :energy-lost) values))))
    (when (and (realp j) (realp e) (plusp j) (realp *largest-restitution*) (< *largest-restitution* 1))
      (/ (* 2 (abs e)) (* j (- 1 *largest-restitution*))))))

(defun check-seeable-impact (walk event)
  "End the comparison as :UNSUPPORTED when AMES's EVENT is a collision slower than half
the witness's stated :COLLISION-SPEED and the witness's next event is not it."
  (let ((threshold (getf (walk-witness walk) :collision-speed))
        (next (first (walk-events walk))))
    (when (and (realp threshold) (consp event) (eq (event-kind event) :collision)
               (not (and next (event-matches-p event next))))
      (let ((speed (impact-speed-bound event (walk-values walk))))
        (when (and speed (< speed (/ threshold 2)))
          (finish walk :unsupported "it ends with ~S at an approach speed of at most ~,2E m/s, under the ~A m/s at which the witness sees a collision"
                  (event-head event) speed threshold))))))
