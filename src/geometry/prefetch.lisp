;;;; src/geometry/prefetch.lisp -- the simplifications every contact pair will ask, asked first in few round trips.
;;;;
;;;; Building the contact pairs of N bodies tidies the expressions of every simple contact
;;;; of N^2 pairs (TIDY: Maxima's :FULL simplification), one round trip each.
;;;; CALL-WITH-PREFETCHED-CONTACT-PAIRS walks the pairs first as MAKE-CONTACT-PAIR will, in two passes
;;;; (the pieces' expressions; then, with the pieces tidied, the contacts' tangents, angles
;;;; and lengths), and asks each pass's simplifications together
;;;; (AMES.MAXIMA:PREFETCH-SIMPLIFICATIONS): MAKE-CONTACT-PAIR then finds them in the
;;;; bridge's cache, and the obstacles' boundaries computed on the way are reused. The
;;;; pairs built are the same; only the round trips are fewer. A pair
;;;; that fails here (an unsupported pair, an undecidable fact) is skipped: building it
;;;; later signals what it signals, where the caller handles it.

(in-package #:ames.geometry)

(defun piece-expressions (piece)
  "The expressions TIDY-PIECE tidies of PIECE before it builds the tidied piece (an
arc's end angle, which depends on the tidied start, is left out)."
  (etypecase piece
    (line-piece (append (line-piece-start piece) (line-piece-end piece)))
    (arc-piece (append (arc-piece-center piece)
                       (list (arc-piece-radius piece) (arc-piece-from piece))))))

(defun measure-expressions (decider piece)
  "The expressions MAKE-SIMPLE-CONTACT tidies of PIECE once it is tidied: the arc's end
angle, and the contact's tangent, angle and length (see SIMPLE-CONTACT-MEASURES)."
  (let* ((tidied (tidy-piece decider piece))
        (measures (simple-contact-measures decider tidied)))
    (append (and (arc-piece-p piece)
                 (list (e+ (arc-piece-from tidied) (arc-signed-sweep piece))))
            (getf measures :tangent)
            (list (getf measures :tangent-angle))
            (let ((length (getf measures :length)))
              (and (not (eq length :infinite)) (list length))))))

(defun pairs-pieces (specs bridge fixed boundaries)
  "For each pair of SPECS (NAME-1 SHAPE-1 NAME-2 SHAPE-2) that the geometry can build,
its decider and the pieces of its obstacle's boundary: a list of (DECIDER . PIECES). The
boundaries computed are remembered in the table BOUNDARIES (see
*REMEMBERED-BOUNDARIES*)."
  (loop for (name-1 shape-1 name-2 shape-2) in specs
        for entry = (handler-case
                        (multiple-value-bind (observer observer-shape obstacle obstacle-shape)
                            (choose-observer name-1 shape-1 name-2 shape-2 :bridge bridge :fixed fixed)
                          (let ((decider (ensure-decider bridge (list obstacle :seen-by observer))))
                            (multiple-value-bind (sum-pieces inside-test)
                                (obstacle-boundary decider observer-shape obstacle-shape)
                              (setf (gethash (cons observer-shape obstacle-shape) boundaries)
                                    (list sum-pieces inside-test))
                              (cons decider (mapcar #'sum-piece-piece sum-pieces)))))
                      (budget-exceeded (condition) (error condition))
                      (ames-error () nil))
        when entry collect entry))

(defun call-with-prefetched-contact-pairs (specs thunk &key bridge fixed)
  "Call THUNK, which builds the contact pairs of SPECS, a list of (NAME-1 SHAPE-1 NAME-2
SHAPE-2) (FIXED as for MAKE-CONTACT-PAIR), after asking BRIDGE, in few round trips, the
simplifications MAKE-CONTACT-PAIR will ask (see this file's header); the obstacles'
boundaries computed on the way are reused by MAKE-CONTACT-PAIR inside THUNK. Call under
the assumptions the pairs are built under. Returns THUNK's values. Signals
BUDGET-EXCEEDED when the run's time is up, and what THUNK signals."
  (if (null bridge)
      (funcall thunk)
      (let* ((boundaries (make-hash-table :test #'equal))
             (entries (pairs-pieces specs bridge fixed boundaries)))
        (ames.maxima:prefetch-simplifications
         bridge (loop for (nil . pieces) in entries
                      append (mapcan #'piece-expressions pieces)))
        (ames.maxima:prefetch-simplifications
         bridge (loop for (decider . pieces) in entries
                      append (loop for piece in pieces
                                   append (handler-case (measure-expressions decider piece)
                                            (budget-exceeded (condition) (error condition))
                                            (ames-error () nil)))))
        (setf entries nil)
        (let ((*remembered-boundaries* boundaries))
          (funcall thunk)))))
