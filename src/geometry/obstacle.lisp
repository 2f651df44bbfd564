;;;; src/geometry/obstacle.lisp -- the contacts of a pair of bodies: observer, obstacle, queries.
;;;;
;;;; For each pair of bodies one is the OBSERVER and the other the OBSTACLE; the relative
;;;; position is q = position(observer) - position(obstacle) and the configuration-space
;;;; obstacle, in the obstacle's frame, is B (+) (-A) (thesis section 2.5.2). Its
;;;; boundary, split into simple contacts, is built once per pair by MAKE-CONTACT-PAIR.
;;;; The observer is chosen as the thesis does (the smaller body observes), with the
;;;; rules: a point always observes; a half-plane or another thin surface (segment, arc
;;;; track) never does unless both bodies are such; a body with a concave arc does not
;;;; observe a body without; a fixed body (when the caller says which are fixed) does
;;;; not observe a moving one; otherwise the smaller area observes, and when that cannot
;;;; be decided (or the areas are equal) the first body given observes.

(in-package #:ames.geometry)

(defclass contact-pair ()
  ((observer :initarg :observer :reader pair-observer
             :documentation "The observer body's name.")
   (obstacle :initarg :obstacle :reader pair-obstacle
             :documentation "The obstacle body's name.")
   (observer-shape :initarg :observer-shape :reader pair-observer-shape)
   (obstacle-shape :initarg :obstacle-shape :reader pair-obstacle-shape)
   (contacts :initarg :contacts :reader pair-contacts
             :documentation "The simple contacts, in counter-clockwise order.")
   (inside-test :initarg :inside-test :reader pair-inside-test
                :documentation "A function of (decider q): true when q penetrates.")
   (decider :initarg :decider :reader pair-decider))
  (:documentation "The configuration-space view of two bodies: which observes which,
and every simple contact between them."))

(defmethod print-object ((pair contact-pair) stream)
  (print-unreadable-object (pair stream :type t)
    (format stream "~A seen by ~A, ~D contact~:P" (pair-obstacle pair) (pair-observer pair)
            (length (pair-contacts pair)))))

(defun choose-observer (name-1 shape-1 name-2 shape-2 &key bridge fixed)
  "Which of two bodies observes the other. Returns (values OBSERVER-NAME OBSERVER-SHAPE
OBSTACLE-NAME OBSTACLE-SHAPE). FIXED lists the names of the bodies glued to the fixed
frame. See the file header for the rules. Never signals for an undecidable size: the
first body then observes."
  (let ((decider (ensure-decider bridge (list name-1 name-2))))
    (flet ((first-observes () (values name-1 shape-1 name-2 shape-2))
           (second-observes () (values name-2 shape-2 name-1 shape-1))
           (kind (s) (shape-kind s)))
      (cond ((eq (kind shape-1) :point) (first-observes))
            ((eq (kind shape-2) :point) (second-observes))
            ((and (shape-surface-p shape-1) (not (shape-surface-p shape-2))) (second-observes))
            ((and (shape-surface-p shape-2) (not (shape-surface-p shape-1))) (first-observes))
            ((eq (kind shape-1) :half-plane) (second-observes))
            ((eq (kind shape-2) :half-plane) (first-observes))
            ((and (shape-decomposable-p shape-1) (not (shape-decomposable-p shape-2))) (first-observes))
            ((and (shape-decomposable-p shape-2) (not (shape-decomposable-p shape-1))) (second-observes))
            ((and (member name-1 fixed) (not (member name-2 fixed))) (second-observes))
            ((and (member name-2 fixed) (not (member name-1 fixed))) (first-observes))
            (t (let ((a1 (shape-area shape-1)) (a2 (shape-area shape-2)))
                 (if (and (not (fact-known-p decider (list '< a1 a2)))
                          (fact-known-p decider (list '< a2 a1)))
                     (second-observes)
                     (first-observes))))))))

(defun make-contact-pair (name-1 shape-1 name-2 shape-2 &key bridge fixed)
  "The CONTACT-PAIR of the bodies NAME-1 and NAME-2 with SHAPE-1 and SHAPE-2 (from
PARSE-SHAPE): the observer is chosen by CHOOSE-OBSERVER (FIXED lists the fixed bodies'
names) and every simple contact of the obstacle seen by it is built. BRIDGE decides symbolic facts (call under the scenario's
assumptions). Signals UNSUPPORTED-SHAPE-PAIR for pairs this layer cannot handle (two
half-planes; a concave arc against anything but a point, or a bowl against anything
but a point or a disc) and UNDECIDABLE-GEOMETRIC-FACT when a needed fact cannot be
decided."
  (multiple-value-bind (observer observer-shape obstacle obstacle-shape)
      (choose-observer name-1 shape-1 name-2 shape-2 :bridge bridge :fixed fixed)
    (make-contact-pair-with-observer observer observer-shape obstacle obstacle-shape
                                     :bridge bridge)))

(defun make-contact-pair-with-observer (observer observer-shape obstacle obstacle-shape
                                        &key bridge)
  "Like MAKE-CONTACT-PAIR, with the observer given."
  (let ((decider (ensure-decider bridge (list obstacle :seen-by observer))))
    (flet ((unsupported (detail)
             (error 'unsupported-shape-pair :observer observer :obstacle obstacle
                                            :datum (list (shape-form observer-shape)
                                                         (shape-form obstacle-shape))
                                            :detail detail)))
      (multiple-value-bind (sum-pieces inside-test)
          (handler-case (remembered-obstacle-boundary decider observer-shape obstacle-shape)
            (unsupported-shape-pair (condition) (unsupported (ames-error-detail condition))))
        (let* ((contacts (loop for sp in sum-pieces
                               for i from 0
                               collect (make-simple-contact
                                        decider (sum-piece-piece sp)
                                        :observer observer :obstacle obstacle
                                        :observer-feature (sum-piece-observer-feature sp)
                                        :obstacle-feature (sum-piece-obstacle-feature sp)
                                        :index i))))
          (link-neighbours decider contacts)
          (make-instance 'contact-pair :observer observer :obstacle obstacle
                                       :observer-shape observer-shape
                                       :obstacle-shape obstacle-shape
                                       :contacts contacts :inside-test inside-test
                                       :decider decider))))))

(defun link-neighbours (decider contacts)
  "Record, for each contact, the contact that continues past each of its ends (when
the two ends are known to coincide)."
  (dolist (a contacts)
    (when (contact-end a)
      (dolist (b contacts)
        (when (and (not (eq a b)) (member (contact-kind b) '(:segment :arc))
                   (vector-known-equal-p decider (contact-end a) (contact-start b)))
          (push (cons :end b) (contact-neighbours a))
          (push (cons :start a) (contact-neighbours b)))))))

;;; Building the boundary

(defun pieces-inside-test (parts boundary)
  "A penetration test for the union of convex PARTS (lists of pieces) whose boundary is
BOUNDARY (pieces): q is inside a closed part and on no boundary piece."
  (if (null (rest parts))
      (lambda (decider q) (inside-convex-p decider q (first parts) :strict t))
      (lambda (decider q)
        (and (some (lambda (part) (inside-convex-p decider q part)) parts)
             (notany (lambda (piece) (point-on-piece-p decider q piece)) boundary)))))

(defvar *remembered-boundaries* nil
  "NIL, or an EQUAL hash table (OBSERVER-SHAPE . OBSTACLE-SHAPE) -> (SUM-PIECES
INSIDE-TEST), the OBSTACLE-BOUNDARY values already computed under the facts in force
(bound by CALL-WITH-PREFETCHED-CONTACT-PAIRS).")

(defun remembered-obstacle-boundary (decider observer-shape obstacle-shape)
  "OBSTACLE-BOUNDARY's values, taken from *REMEMBERED-BOUNDARIES* when they are there."
  (let ((entry (and *remembered-boundaries*
                    (gethash (cons observer-shape obstacle-shape) *remembered-boundaries*))))
    (if entry
        (values-list entry)
        (obstacle-boundary decider observer-shape obstacle-shape))))

(defun obstacle-boundary (decider observer-shape obstacle-shape)
  "The simple-contact pieces (SUM-PIECEs) of OBSTACLE-SHAPE seen by OBSERVER-SHAPE, and
the penetration test (a function of decider and q)."
  (let ((observer-kind (shape-kind observer-shape))
        (obstacle-kind (shape-kind obstacle-shape)))
    (cond ((and (eq observer-kind :half-plane) (eq obstacle-kind :half-plane))
           (error 'unsupported-shape-pair :detail "two unbounded half-planes never need contacts"))
          ((eq observer-kind :half-plane)
           (error 'unsupported-shape-pair :detail "a half-plane cannot be the observer"))
          ((and (eq observer-kind :point) (not (shape-decomposable-p obstacle-shape)))
           (point-against-concave-boundary decider obstacle-shape))
          ((and (eq obstacle-kind :arc) (eq (shape-solid-side obstacle-shape) :outside))
           (if (eq observer-kind :circle)
               (disc-in-bowl decider observer-shape obstacle-shape)
               (error 'unsupported-shape-pair
                      :detail "a bowl (an arc track with its solid outside) can only be touched by a point or a disc")))
          ((not (shape-decomposable-p obstacle-shape))
           (error 'unsupported-shape-pair
                  :detail "an outline with a concave arc can only be touched by a point"))
          ((not (shape-decomposable-p observer-shape))
           (error 'unsupported-shape-pair
                  :detail "a body with a concave arc can only be touched by a point"))
          ((eq obstacle-kind :half-plane)
           (half-plane-boundary decider observer-shape obstacle-shape))
          (t (general-boundary decider observer-shape obstacle-shape)))))

(defun part-sums (decider observer-shape obstacle-shape)
  (let ((observer-parts (mapcar (lambda (part) (mapcar #'negate-feature part))
                                (convex-parts decider observer-shape :role :observer)))
        (obstacle-parts (convex-parts decider obstacle-shape :role :obstacle)))
    (loop for b in obstacle-parts
          nconc (loop for a in observer-parts
                      collect (convex-sum decider b a)))))

(defun general-boundary (decider observer-shape obstacle-shape)
  (let* ((sums (part-sums decider observer-shape obstacle-shape))
         (boundary (union-boundary decider sums)))
    (values (exposed-sum-pieces decider boundary)
            (if (and (eq (shape-kind observer-shape) :point) (eq (shape-kind obstacle-shape) :point))
                (constantly nil)
                (pieces-inside-test (mapcar (lambda (sum) (mapcar #'sum-piece-piece sum)) sums)
                                    (mapcar #'sum-piece-piece boundary))))))

(defun half-plane-boundary (decider observer-shape obstacle-shape)
  "A half-plane seen by any decomposable body: the line shifted by the body's farthest
point (or face) in the direction of the half-plane's outward normal."
  (let* ((sums (part-sums decider observer-shape obstacle-shape))
         (normal (line-normal (first (shape-boundary obstacle-shape))))
         (best nil))
    (dolist (sum sums)
      (let ((candidate (first sum)))
        (if (null best)
            (setf best candidate)
            (let ((ahead (dot normal (v- (line-piece-start (sum-piece-piece candidate))
                                         (line-piece-start (sum-piece-piece best))))))
              (case (sign-of decider ahead)
                (:positive (setf best candidate))
                (:zero (when (and (eq (first (sum-piece-observer-feature candidate)) :edge)
                                  (not (eq (first (sum-piece-observer-feature best)) :edge)))
                         (setf best candidate))))))))
    (let ((line (sum-piece-piece best)))
      (values (list best)
              (lambda (decider q)
                (negative-p decider (dot (line-normal line) (v- q (line-piece-start line)))))))))

;;; The special cases outside the convex machinery

(defun point-against-concave-boundary (decider shape)
  "A point against a shape with a concave arc (a bowl, or an outline with a bite): the
boundary itself (for a track, its exterior side)."
  (declare (ignore decider))
  (let ((pieces (shape-boundary shape)))
    (values (loop for piece in pieces
                  collect (make-sum-piece piece (piece-name piece) '(:point) nil))
            (if (eq (shape-kind shape) :arc)
                (constantly nil)
                (lambda (decider q)
                  (and (point-in-outline-p decider q pieces)
                       (notany (lambda (piece) (point-on-piece-p decider q piece)) pieces)))))))

(defun circular-segment-pieces (arc)
  "The closed region between the arc piece ARC and its chord, as counter-clockwise pieces."
  (if (eq (arc-piece-sense arc) :ccw)
      (list arc (make-line-piece (piece-end arc) (piece-start arc)))
      (let ((forward (make-arc-piece (arc-piece-center arc) (arc-piece-radius arc)
                                     (arc-piece-to arc) (arc-piece-from arc) :ccw)))
        (list forward (make-line-piece (piece-end forward) (piece-start forward))))))

(defun point-in-outline-p (decider q pieces)
  "True when Q lies in the closed region bounded by the closed outline PIECES: in the
polygon of its piece ends or a bulge of a convex arc, and not strictly inside the bite
of a concave arc."
  (let ((corners (mapcar #'piece-start pieces)))
    (and (or (and (>= (length corners) 3)
                  (some (lambda (part)
                          (inside-convex-p decider q (mapcar #'feature-piece
                                                             (remove :vertex part :key #'feature-kind))))
                        (polygon-parts decider corners
                                       (lambda (i) (list :edge i)) (lambda (i) (list :vertex i)))))
             (some (lambda (piece)
                     (and (arc-piece-p piece) (eq (arc-piece-sense piece) :ccw)
                          (inside-convex-p decider q (circular-segment-pieces piece))))
                   pieces))
         (notany (lambda (piece)
                   (and (concave-arc-p piece)
                        (inside-convex-p decider q (circular-segment-pieces piece) :strict t)))
                 pieces))))

(defun disc-in-bowl (decider disc bowl)
  "A disc against a bowl (an arc track with its solid outside): the concentric arc
R - rho on the inside, and a cap of radius rho around each end of the track."
  (let* ((arc (first (shape-boundary bowl)))
         (rho (shape-radius disc))
         (radius (arc-piece-radius arc))
         (inner-radius (e- radius rho)))
    (unless (positive-p decider inner-radius)
      (error 'unsupported-shape-pair
             :detail (format nil "the disc (radius ~S) does not fit in the bowl (radius ~S)" rho radius)))
    (let ((inner (make-arc-piece (arc-piece-center arc) inner-radius
                                 (arc-piece-from arc) (arc-piece-to arc) :cw
                                 :full (arc-piece-full arc)))
          (pieces '()))
      (unless (arc-piece-full arc)
        (multiple-value-bind (start-range end-range) (track-contact-ranges arc)
          (push (make-sum-piece (range-arc-piece decider (piece-start arc) rho start-range)
                                '(:vertex 1) '(:circle) nil)
                pieces)
          (push (make-sum-piece inner '(:arc 0) '(:circle) nil) pieces)
          (push (make-sum-piece (range-arc-piece decider (piece-end arc) rho end-range)
                                '(:vertex 0) '(:circle) nil)
                pieces)))
      (when (arc-piece-full arc)
        (push (make-sum-piece inner '(:arc 0) '(:circle) nil) pieces))
      (values (nreverse pieces)
              (lambda (decider q)
                (let* ((w (v- q (arc-piece-center arc)))
                       (d2 (norm-squared w)))
                  (if (direction-in-range-p decider w (arc-position-range arc) :closed t)
                      (and (fact-holds-p decider (list '< (esquare inner-radius) d2))
                           (fact-holds-p decider (list '< d2 (esquare (e+ radius rho)))))
                      (or (fact-holds-p decider (list '< (norm-squared (v- q (piece-start arc))) (esquare rho)))
                          (fact-holds-p decider (list '< (norm-squared (v- q (piece-end arc))) (esquare rho)))))))))))

;;; Queries

(defun contacts-at (pair q)
  "The simple contacts of PAIR on which the relative position Q = (X Y) lies, each as
(CONTACT . S) with S its arc length there. Q is position(observer) -
position(obstacle)."
  (loop for contact in (pair-contacts pair)
        when (position-on-contact-p contact q)
          collect (cons contact (contact-parameter contact q))))

(defun penetrates-p (pair q)
  "True when, at the relative position Q, the observer's interior overlaps the
obstacle's: an impossible configuration (for instance an invalid start). Asks only the
facts that change the answer (see CALL-DECIDING-WHAT-MATTERS)."
  (deciding-what-matters ((pair-decider pair))
    (funcall (pair-inside-test pair) (pair-decider pair) (mapcar #'normalize-expression q))))

(defun check-separation (pair q)
  "Signal BODIES-OVERLAP when the relative position Q penetrates (see PENETRATES-P);
return Q otherwise. The restart CONTINUE ignores the overlap."
  (when (penetrates-p pair q)
    (cerror "Go on with the overlapping bodies." 'bodies-overlap
            :observer (pair-observer pair) :obstacle (pair-obstacle pair) :datum q
            :detail "the bodies overlap"))
  q)

(defun relative-position (pair observer-position obstacle-position)
  "The relative position q of PAIR from the two bodies' positions (lists (X Y))."
  (declare (ignore pair))
  (v- (mapcar #'normalize-expression observer-position)
      (mapcar #'normalize-expression obstacle-position)))
