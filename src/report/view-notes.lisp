;;;; src/report/view-notes.lisp -- what a report says of a state's notes: its path, its end on a
;;;; curve, a numeric trajectory, a periodic motion, an impact, a Zeno accumulation, the
;;;; velocities it starts with, and its energy and momentum (NOTE-VIEWS, called by
;;;; STATE-VIEW in view.lisp).

(in-package #:ames.report)

(defun path-note (presenter value)
  "The phrases of a :PATH-COORDINATES note."
  (let ((s (arc-length-symbol presenter))
        (speed (cdr (assoc +arc-speed+ (presenter-renamings presenter))))
        (energy (getf value :energy-integral)))
    (remove nil
            (list (phrase (format nil "~A is the arc length along the contact of ~{~A~^ with ~}; it starts at "
                                  (name-text s) (mapcar #'name-text (getf value :contact)))
                          (list '= s (present presenter (getf value :arc-length-from))))
                  (and (getf value :tangential-acceleration)
                       (phrase "tangential acceleration "
                               (list '= (make-symbol (format nil "~A''" (symbol-name s)))
                                     (present presenter (getf value :tangential-acceleration)))))
                  (and energy
                       (phrase "energy integral "
                               (if (and (consp energy) (eq (first energy) '=))
                                   (list '= (list 'expt speed 2) (present presenter (third energy)))
                                   (present presenter energy))
                               (if (eq (getf value :ode) :closed-form)
                                   " (the motion also has a closed form in time)"
                                   " (no closed form in time)")))))))

(defun end-on-curve-phrase (presenter value)
  "\"at s = VALUE\"; when VALUE is presented as A asin(E) or A acos(E), also the angle as
a textbook gives it: \"where sin(s/A) = E\"."
  (let* ((s (arc-length-symbol presenter))
         (shown (present presenter value))
         (factors (and (consp shown) (eq (first shown) '*) (rest shown)))
         (inverse (find-if (lambda (f) (and (consp f) (member (first f) '(asin acos)) (= 2 (length f))))
                           factors))
         (scale (and inverse (remove inverse factors :count 1))))
    (append (phrase "at " (list '= s shown))
            (and inverse scale
                 (phrase ", where "
                         (list '= (list (if (eq (first inverse) 'asin) 'sin 'cos)
                                        (list '/ s (if (rest scale) (cons '* scale) (first scale))))
                               (second inverse)))))))

(defun note-views (presenter state)
  "The notes of STATE as (LABEL . PHRASES), those the view shows elsewhere left out."
  (loop for (key value) on (state-notes state) by #'cddr
        append (case key
                 ;; :line-coordinates is the simulator's working (the coordinate along the
                 ;; line of two bodies, in the knowledge base's terms): the positions show it
                 ((:numeric :events :line-coordinates :fork))
                 (:numeric-trajectory
                  (list (cons "integrated numerically" (numeric-trajectory-phrases value))))
                 (:undecided (list (cons "undecided" (list (list (datum-text value))))))
                 (:end-arc-length (list (cons "ends on the curve"
                                              (list (end-on-curve-phrase presenter value)))))
                 (:path-coordinates (list (cons "on the curve" (path-note presenter value))))
                 (:periodic (list (cons "periodic" (periodic-phrases presenter state value))))
                 (:impact (list (cons "the impact" (impact-phrases presenter value))))
                 (:accumulation
                  (list (cons "the impacts repeat" (accumulation-phrases presenter value))))
                 (:energy (list (cons "energy" (energy-phrases presenter value))))
                 (:momentum (list (cons "momentum" (momentum-phrases presenter value))))
                 (:missing-fact
                  (list (cons "the run branches on" (list (phrase (present-relation presenter value))))))
                 (:initial-velocities
                  (list (cons "velocities just after the impact"
                              (initial-velocity-phrases presenter value))))
                 (t (list (cons (keyword-words key) (other-note-phrases presenter value)))))))

(defun numeric-trajectory-phrases (groups)
  "The phrases of a state's :NUMERIC-TRAJECTORY note, GROUPS (plists with :SAMPLES): how
many samples of the motion were integrated."
  (list (list (format nil "~D sample~:P of the motion" 
                      (reduce #'+ (mapcar (lambda (g) (length (getf g :samples))) groups))))))

(defun periodic-phrases (presenter state value)
  "The phrases of STATE's :PERIODIC note VALUE (a plist: :PERIOD, :COORDINATE or none
for the arc length, :BETWEEN the two turning points): the period, with its number when
STATE has one, and the turning points."
  (list (let ((number (getf (state-numbers state) :period)))
          (phrase "period " (present presenter (getf value :period))
                  (if number (format nil " (~A)" (number-text number)) "")))
        ;; along a curve the arc length; else the coordinate
        ;; that oscillates (a position term)
        (let ((coordinate (if (getf value :coordinate)
                              (present presenter (getf value :coordinate))
                              (arc-length-symbol presenter))))
          (phrase "between turning points at "
                  (list '= coordinate
                        (present presenter (first (getf value :between))))
                  " and "
                  (list '= coordinate
                        (present presenter (second (getf value :between))))))))

(defun impact-phrases (presenter value)
  "The phrases of a state's :IMPACT note VALUE: each body's velocity just before and
just after (bodies at rest throughout left out), each rotating body's angular velocity
likewise, each non-zero impulse, and the kinetic energy lost."
  (append
   (loop for (body after) in (getf value :velocities-after)
         for before = (body-entry (getf value :velocities-before) body)
         unless (and (equal before '(0 0)) (equal after '(0 0)))
           collect (phrase (format nil "~A: velocity (" (name-text body))
                           (present presenter (first before)) ", "
                           (present presenter (second before)) ") just before, ("
                           (present presenter (first after)) ", "
                           (present presenter (second after)) ") just after"))
   (loop for (body after) in (getf value :angular-velocities-after)
         for before = (body-entry (getf value :angular-velocities-before) body)
         unless (and (eql before 0) (eql after 0))
           collect (phrase (format nil "~A: angular velocity " (name-text body))
                           (present presenter before) " just before, "
                           (present presenter after) " just after"))
   (loop for entry in (getf value :impulses)
         for (label magnitude) = (multiple-value-list (impulse-entry entry))
         unless (or (null magnitude) (eql magnitude 0))
           collect (phrase (format nil "~A: " label)
                           (present presenter magnitude)))
   (list (phrase "kinetic energy lost: " (present presenter (getf value :energy-lost))))))

(defun accumulation-phrases (presenter value)
  "The phrases of a state's :ACCUMULATION note VALUE (:FACTOR, :CYCLE, :TIME): impacts
repeating with a shrinking cycle that accumulate at a finite time."
  (list (phrase "each cycle " (present presenter (getf value :factor))
                " times the one before (the first lasted "
                (present presenter (getf value :cycle))
                "): they accumulate at t = "
                (present presenter (getf value :time))
                ", and the run goes on from there at rest")))

(defun initial-velocity-phrases (presenter velocities)
  "The phrases of a state's :INITIAL-VELOCITIES note, VELOCITIES ((BODY (VX VY)) ...):
each body's velocity."
  (loop for (body velocity) in velocities
        collect (phrase (format nil "~A: (" (name-text body))
                        (present presenter (first velocity)) ", "
                        (present presenter (second velocity)) ")")))

(defun other-note-phrases (presenter value)
  "The phrases of a note no view knows, VALUE: the expression presented when it is one,
else the datum as text."
  (list (if (valid-expression-p value :kind :arithmetic)
            (phrase (present presenter value))
            (list (datum-text value)))))

(defun sum-presented (presenter terms)
  "The sum of the expressions TERMS presented (0 when there are none)."
  (present presenter (if (rest terms) (cons '+ terms) (or (first terms) 0))))

(defun shown-terms (section entries)
  "The kinds of terms of SECTION (AMES.KB:REPORTED-TERMS) the report lists for a state
whose section holds ENTRIES: those shown always, and those of which it holds a term."
  (remove-if-not (lambda (term)
                   (or (eq (ames.kb:term-shown term) :always)
                       (ames.kb:term-entries term entries)))
                 (ames.kb:reported-terms section)))

(defun energy-phrases (presenter entries)
  "The energy of a state's :ENERGY note ENTRIES ((KIND SUBJECT E) ...): the sum of each
kind of term the knowledge base declares (see SHOWN-TERMS), labelled with its words,
then the total of them all, written with the kinds' symbols (K + U: T names a tension).
The total is constant where the forces are conservative and nothing is lost."
  (let ((terms (shown-terms :energy entries)))
    (append
     (loop for term in terms
           collect (phrase (ames.kb:term-label term) " = "
                           (sum-presented presenter (mapcar #'third (ames.kb:term-entries term entries)))))
     (list (phrase (format nil "total ~{~A~^ + ~} = " (mapcar #'ames.kb:term-symbol terms))
                   (sum-presented presenter
                                  (loop for term in terms
                                        append (mapcar #'third (ames.kb:term-entries term entries)))))))))

(defun momentum-phrases (presenter entries)
  "The totals of a state's :MOMENTUM note ENTRIES ((KIND BODY VALUE) ...), one for each
kind of term the knowledge base declares (see SHOWN-TERMS), labelled with its words: a
vector kind's (X Y) summed by components, a scalar kind's as one sum."
  (loop for term in (shown-terms :momentum entries)
        for values = (mapcar #'third (ames.kb:term-entries term entries))
        collect (if (ames.kb:term-vector term)
                    (phrase (ames.kb:term-label term) ": ("
                            (sum-presented presenter (mapcar #'first values)) ", "
                            (sum-presented presenter (mapcar #'second values)) ")")
                    (phrase (ames.kb:term-label term) ": " (sum-presented presenter values)))))
