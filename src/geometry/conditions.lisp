;;;; src/geometry/conditions.lisp -- the conditions the geometry layer signals.

(in-package #:ames.geometry)

(define-condition geometry-error (ames-error)
  ()
  (:documentation "The parent of every condition of the geometry layer."))

(define-condition invalid-shape (geometry-error)
  ((shape :initarg :shape :initform nil :reader invalid-shape-form
          :documentation "The whole shape form (as written in the scenario)."))
  (:documentation "A shape form that does not describe a valid shape: an unknown head,
a malformed coordinate, a clockwise or self-intersecting polygon, outline pieces that
do not join, a zero radius, a degenerate segment, ... DATUM is the offending part,
SHAPE the whole form, DETAIL says what is wrong.")
  (:report (lambda (condition stream)
             (format-report stream "Invalid shape: ~A~%  at fault: ~S~@[~%  in shape: ~S~]"
                            (ames-error-detail condition)
                            (ames-error-datum condition)
                            (let ((whole (invalid-shape-form condition)))
                              (and (not (equal whole (ames-error-datum condition))) whole))))))

(define-condition undecidable-geometric-fact (geometry-error)
  ((fact :initarg :fact :reader undecidable-fact
         :documentation "The relation (in the prefix algebra) that could not be decided.")
   (subject :initarg :subject :initform nil :reader undecidable-subject
            :documentation "The shape form, body pair or contact the fact is about."))
  (:documentation "A geometric fact (the sign of an expression in the shapes'
parameters) that neither exact arithmetic nor the Maxima bridge could decide under
the current assumptions. Signalled with the restarts ASSUME-TRUE and ASSUME-FALSE,
through which a caller may choose the answer.")
  (:report (lambda (condition stream)
             (format-report stream "Cannot decide the geometric fact ~S~@[ about ~S~]~@[ (~A)~]."
                            (undecidable-fact condition)
                            (undecidable-subject condition)
                            (ames-error-detail condition)))))

(define-condition unsupported-shape-pair (geometry-error)
  ((observer :initarg :observer :initform nil :reader unsupported-observer)
   (obstacle :initarg :obstacle :initform nil :reader unsupported-obstacle))
  (:documentation "A pair of shapes whose configuration-space obstacle this layer
cannot build (for instance two unbounded half-planes, or a concave arc against a
polygon). OBSERVER and OBSTACLE name the bodies; DETAIL says why.")
  (:report (lambda (condition stream)
             (format-report stream "Cannot build the contacts of ~S seen by ~S: ~A"
                            (unsupported-obstacle condition)
                            (unsupported-observer condition)
                            (ames-error-detail condition)))))

(define-condition position-not-on-contact (geometry-error)
  ((contact :initarg :contact :reader position-contact))
  (:documentation "A relative position that was required to lie on a simple contact
but does not. DATUM is the position.")
  (:report (lambda (condition stream)
             (format-report stream "The relative position ~S does not lie on the contact ~A."
                            (ames-error-datum condition)
                            (position-contact condition)))))

(define-condition bodies-overlap (geometry-error)
  ((observer :initarg :observer :reader overlap-observer)
   (obstacle :initarg :obstacle :reader overlap-obstacle))
  (:documentation "Two bodies placed so that their interiors overlap: an impossible
(invalid starting) configuration. DATUM is the relative position.")
  (:report (lambda (condition stream)
             (format-report stream "~S and ~S overlap: at the relative position ~S the one ~
                                    penetrates the other."
                            (overlap-observer condition) (overlap-obstacle condition)
                            (ames-error-datum condition)))))
