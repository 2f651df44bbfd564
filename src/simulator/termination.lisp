;;;; src/simulator/termination.lisp -- when each termination condition fires, and which fires
;;;; first (thesis section 2.5.8), proven under the scenario's assumptions.
;;;;
;;;; A condition over bodies that move with constant acceleration is a function of TAU,
;;;; and its first time comes from the bridge's proven earliest root. A condition over a
;;;; body moving along a curved contact is a function of the arc length s; its place
;;;; comes from the roots of that function ahead of the start in the direction of motion,
;;;; and its time from the travel-time integral. The candidates of one curved motion are
;;;; ordered by their arc length (the same order as their times, as long as the body
;;;; does not turn back); candidates of different groups by their times.

(in-package #:ames.simulator)

(defstruct (candidate (:constructor make-candidate (condition event time &key at-arc group rate)))
  "A termination CONDITION (an AMES.ENGINE:TERMINATION-CONDITION) that fires at TIME (an
expression, or (:NO-CLOSED-FORM ...)): the EVENT to report; for a curved motion the
arc length AT-ARC where it fires and its GROUP; RATE the rate at which a position-level
condition is reached (an impact when not zero)."
  condition event time at-arc group rate)

(defun candidate-change (candidate)
  "The model change CANDIDATE stands for (NIL for the scenario's own time limit)."
  (and (candidate-condition candidate)
       (ames.engine:termination-condition-change (candidate-condition candidate))))

;;; Functions of TAU: constant accelerations

(defun time-derivative (expression)
  "d EXPRESSION / d TAU."
  (ames.geometry:differentiate expression 'tau))

(defun trigonometric-in-time-p (g)
  "True when G has a sine or cosine of an expression in TAU (a spring's motion)."
  (and (consp g)
       (or (and (member (first g) '(sin cos)) (not (free-of-p 'tau (second g))))
           (some #'trigonometric-in-time-p (rest g)))))

(defun earliest-root-after (run g after)
  "The earliest root of G (a function of TAU) strictly after AFTER, through the bridge:
what ames.algebra:EARLIEST-ROOT returns, without the candidates of an undecided answer;
for a trigonometric function of TAU, ames.algebra:EARLIEST-TRIGONOMETRIC-ROOT's. An
abs() of a linear function of a known sign over the search is written without it first
(abs-signs.lisp)."
  (when (mentions-abs-p g)
    (setf g (tidy run (without-abs-of-known-sign run g after)))
    (when (numerator-without-root-p run g after)   ; abs-signs.lisp
      (return-from earliest-root-after (values :none nil))))
  (if (trigonometric-in-time-p g)
      (multiple-value-bind (root status)
          (ames.algebra:earliest-trigonometric-root (run-bridge run) g 'tau :after after :strictly t)
        (if (eq root :unknown) (values :unknown nil) (values root status)))
      (ames.algebra:earliest-root (run-bridge run) g 'tau :after after :strictly t :candidates nil)))

(defun undecided-sign-fact (run g after)
  "The relation whose truth would settle where the polynomial G in TAU first vanishes:
the sign of a coefficient (from the highest degree down) or of the discriminant that the
assumptions do not decide; else (:EARLIEST-ROOT-OF (= G 0) :CANDIDATES ...). A
polynomial G of higher degree with a repeated factor (a gap closed along a tangent: a
square) has the roots of its square-free part, whose facts are read instead."
  (let* ((g (or (and (not (trigonometric-in-time-p g))
                     (ames.algebra:square-free-part (run-bridge run) g 'tau))
                g))
         (d1 (tidy run (time-derivative g)))
         (d2 (tidy run (time-derivative d1)))
         (c0 (tidy run (at-time g 0)))
         (c1 (tidy run (at-time d1 0)))
         (c2 (tidy run `(/ ,d2 2))))
    (or (and (free-of-p 'tau d2)
             (let ((discriminant (tidy run `(- (* ,c1 ,c1) (* 4 ,c2 ,c0)))))
               (find :unknown
                     (loop for c in (list c2 c1 c0 discriminant)
                           collect `(> ,c 0) collect `(< ,c 0))
                     :key (lambda (fact) (decide run fact)))))
        ;; no candidates for a trigonometric G: Maxima's solve gives principal roots
        ;; at best, and can take longer than a request may
        `(:earliest-root-of (= ,g 0)
          :candidates ,(and (not (trigonometric-in-time-p g))
                            (nth-value 1 (ames.algebra:earliest-root (run-bridge run) g 'tau
                                                                     :after after :strictly t)))))))

(defun first-time-negative (run g)
  "The earliest time TAU > 0 from which G(TAU) < 0 (G a polynomial in TAU or a constant,
not negative just after 0). Returns (values :AT TIME), (values :NEVER) or (values
:UNKNOWN FACT). Where the roots do not settle it, an oscillation's least value or a
proven sign may (sinusoid-floors.lisp); FACT is then the floor's relation when there is
one, to branch on."
  (let ((g (tidy run g)))
    (when (free-of-p 'tau g)
      (return-from first-time-negative (values :never)))
    ;; a root at the start itself is divided out: look strictly after it
    (let ((root (earliest-root-after run g 0)))
      (cond ((eq root :none) (values :never))
            ((eq root :unknown)
             (if (or (sinusoid-never-negative-p run g) (positive-after-start-p run g)
                     (damped-oscillation-never-negative-p run g)
                     (overdamped-never-negative-p run g))  ; exponential-floors.lisp
                 (values :never)
                 (values :unknown (or (sinusoid-floor-fact run g) (undecided-sign-fact run g 0)))))
            (t
             (let ((slope (tidy run (at-time (time-derivative g) root))))
               (case (decide run `(< ,slope 0))
                 (:true (values :at (tidy run root :full)))
                 (:false
                  ;; touches zero and turns back, or a double root: look beyond it
                  (let ((next (earliest-root-after run g root)))
                    (if (or (eq next :none) (sinusoid-never-negative-p run g))
                        (values :never)
                        (values :unknown `(< ,slope 0)))))
                 (t (values :unknown `(< ,slope 0))))))))))

(defun relation-time (run relation over-time)
  "When RELATION (over quantity terms) first holds strictly after the start, with
OVER-TIME turning an expression into a function of TAU: (values :AT TIME), (values
:NEVER) or (values :UNKNOWN FACT)."
  (case (first relation)
    (or (let ((best nil) (unknown nil))
          (dolist (part (rest relation))
            (multiple-value-bind (status value) (relation-time run part over-time)
              (case status
                (:at (cond ((or (null best) (holds run `(< ,value ,best))) (setf best value))
                           ((not (holds run `(<= ,best ,value))) (setf unknown `(< ,value ,best)))))
                (:unknown (setf unknown value)))))
          (cond (unknown (values :unknown unknown))
                (best (values :at best))
                (t (values :never)))))
    (t (first-time-negative run (funcall over-time (violation-function relation))))))

(defun stays-negative-p (run h)
  "True when H, a polynomial of degree at most 2 in TAU, is proven negative for every
TAU > 0: H(0) <= 0, H'(0) <= 0 and H'' <= 0, not all zero. A cheap, sound test that
rules out a meeting without solving for it."
  (when (ames.algebra:refuted-p (run-bridge run) `(< ,h 0) :assuming '((> tau 0)))
    (return-from stays-negative-p nil))
  (let* ((h (tidy run h))
         (d1 (tidy run (time-derivative h)))
         (d2 (tidy run (time-derivative d1)))
         (d3 (tidy run (time-derivative d2))))
    (and (eql d3 0)
         (let ((h0 (at-time h 0)) (d10 (at-time d1 0)))
           (and (holds run `(<= ,h0 0))
                (holds run `(<= ,d10 0))
                (holds run `(<= ,d2 0))
                (or (holds run `(< ,h0 0)) (holds run `(< ,d10 0)) (holds run `(< ,d2 0))))))))

(defun extent-margin (relation)
  "For an extent RELATION (>= X Y) or (<= X Y), the expression that must be >= 0."
  (ecase (first relation)
    ((>= >) `(- ,(relation-lhs relation) ,(relation-rhs relation)))
    ((<= <) `(- ,(relation-rhs relation) ,(relation-lhs relation)))))

(defun roots-outside-extent-p (run gap after extent)
  "True when GAP, a polynomial in TAU of degree 1 or 2 whose earliest root after AFTER
is not decided, has every root Maxima writes in closed form outside the contact's
EXTENT (a relation of EXTENT proven false there): whichever of those roots are real
and come after AFTER, the relative motion does not meet the contact at them. (A point
on the line of a face, but past the face's end, at every time it crosses that line.)"
  (let* ((bridge (run-bridge run))
         (degree (1- (length (ames.maxima:polynomial-coefficients bridge gap 'tau))))
         (checks (remove 'or extent :key #'first)))
    (and checks (<= 1 degree 2)
         (multiple-value-bind (status roots)
             (ames.algebra:earliest-root bridge gap 'tau :after after :strictly t)
           (and (eq status :unknown) (= (length roots) degree)
                (every (lambda (root)
                         (some (lambda (r) (eq (decide run (at-time r root)) :false)) checks))
                       roots))))))

(defun divided-by-tau (run gap)
  "(GAP - GAP(0)) / TAU simplified, GAP a function of TAU that vanishes at 0 (a root at
the start, taken out before the earliest root after it is sought), or NIL when the
division leaves TAU in a denominator (GAP(0) is 0 only after trigonometric identities
rational simplification does not see: the quotient at 0 would divide by 0)."
  (let ((divided (tidy run `(/ (- ,gap ,(at-time gap 0)) tau))))
    (handler-case (progn (tidy run (at-time divided 0)) divided)
      (ames.maxima:maxima-error () nil))))

(defun without-roots-at-start (run gap)
  "GAP (a function of TAU) divided by TAU as often as (up to 4 times) it vanishes at the
start: through its coefficients as a polynomial in TAU, each proven zero, when it is one
(a lift-off from inside a circle leaves tangentially: the gap is of order TAU^3 or
TAU^4, its low coefficients zero only once their radicals are simplified); else by
division (DIVIDED-BY-TAU), as long as the quotient is defined at the start."
  (let ((coefficients (and (not (trigonometric-in-time-p gap))
                           (handler-case (ames.maxima:polynomial-coefficients (run-bridge run) gap 'tau)
                             ((or ames.maxima:maxima-error ames.maxima:untranslatable-expression) () nil)))))
    (if coefficients
        (let ((dropped 0))
          (loop while (and (< dropped 4) (rest coefficients)
                           (holds run `(= ,(first coefficients) 0)))
                do (pop coefficients) (incf dropped))
          (if (zerop dropped)
              gap
              (tidy run (cons '+ (loop for c in coefficients for i from 0
                                       collect `(* ,c (expt tau ,i)))))))
        (progn
          (loop repeat 4
                for divided = (and (not (free-of-p 'tau gap))
                                   (holds run `(= ,(tidy run (at-time gap 0)) 0))
                                   (divided-by-tau run gap))
                while divided
                do (setf gap divided))
          gap))))

(defun meeting-time (run meeting over-time contact)
  "When the relative motion first meets CONTACT from its exterior, strictly after the
start: (values :AT TIME RATE), (values :NEVER) or (values :UNKNOWN FACT NOT-BEFORE),
NOT-BEFORE (or NIL) a time before which it is proven not to meet. MEETING is
the geometry's meeting over state terms; OVER-TIME makes functions of TAU of them.
RATE is the gap's rate then (negative: an impact)."
  (let* ((gap (tidy run (funcall over-time (ames.geometry:meeting-gap meeting))))
         (rate-of (lambda (time) (tidy run (at-time (time-derivative gap) time))))
         (extent (mapcar (lambda (r) (funcall over-time r)) (ames.geometry:meeting-extent meeting))))
    (when (some (lambda (h) (stays-negative-p run h))
                (cons `(- ,gap) (loop for r in extent
                                      unless (eq (first r) 'or) collect (extent-margin r))))
      (return-from meeting-time (values :never)))
    (when (eql gap 0)
      (return-from meeting-time (values :never)))
    (setf gap (without-roots-at-start run gap))
    (let ((after 0))
      (loop repeat 4
            do (let ((root (earliest-root-after run gap after)))
                 (cond ((eq root :none) (return-from meeting-time (values :never)))
                       ((eq root :unknown)
                        (return-from meeting-time
                          (if (or (roots-outside-extent-p run gap after extent)
                                  ;; a gap of one sign has no root (sinusoid-floors.lisp)
                                  (and (exponential-in-time-p gap)
                                       (or (positive-after-p run gap after)
                                           (positive-after-p run `(- ,gap) after))))
                              (values :never)
                              ;; the roots up to AFTER were no meeting: not before it
                              (values :unknown (undecided-sign-fact run gap after)
                                      (and (not (eql after 0)) after)))))
                       (t
                        (let* ((root (tidy run root :full))
                               (rate (funcall rate-of root))
                               (checks (cons `(<= ,rate 0) (mapcar (lambda (r) (at-time r root)) extent)))
                               ;; the first undecided check settles the answer: the
                               ;; checks after it are not asked
                               (answers (loop for r in checks
                                              for answer = (decide run r)
                                              collect answer
                                              until (eq answer :unknown))))
                          (cond ((every (lambda (a) (eq a :true)) answers)
                                 (return-from meeting-time (values :at root rate)))
                                ((member :unknown answers)
                                 ;; it may meet here or later, never before ROOT
                                 (return-from meeting-time
                                   (values :unknown (nth (position :unknown answers) checks)
                                           root)))
                                (t (setf after root))))))))
      (values :unknown `(:meets ,@(contact-bodies run contact))))))

;;; The candidates

(defun condition-groups (run solved groups relation)
  "The GROUPs whose motion a termination RELATION depends on."
  (let ((expression (over-state-terms run solved (relation-as-expression relation))))
    (remove-duplicates
     (loop for term in (expression-variables expression)
           for group = (and (quantity-term-p term) (group-of-term groups term))
           when group collect group))))

(defun relation-as-expression (relation)
  "A list holding every operand of RELATION (for collecting its variables)."
  (if (member (first relation) '(and or not))
      (cons '+ (mapcar #'relation-as-expression (rest relation)))
      (cons '+ (rest relation))))

(defun condition-event (condition rate)
  "The event CONDITION stands for, as its component names it (the impact event when it
is reached at a non-zero RATE), or its model change when the component names none."
  (or (and rate (ames.engine:termination-condition-impact condition))
      (ames.engine:termination-condition-event condition)
      (ames.engine:termination-condition-change condition)))

(defun tau-candidate (run solved groups condition)
  "When CONDITION fires over bodies moving with constant accelerations: a CANDIDATE,
:NEVER, or (values :UNKNOWN FACT NOT-BEFORE) (see MEETING-TIME)."
  (let* ((relation (ames.engine:termination-condition-relation condition))
         (contact (gap-relation-contact relation))
         (over-time (lambda (x) (motion-value groups (over-state-terms run solved x)))))
    (multiple-value-bind (status time rate-or-not-before)
        (cond (contact
               (meeting-time run (contact-meeting-terms run solved contact) over-time contact))
              ((guarded-relation-parts relation)
               ;; a corner's touching within its face (guarded-meetings.lisp)
               (guarded-relation-time-and-rate run condition relation over-time))
              (t (relation-time-and-rate run condition relation over-time)))
      (case status
        (:at (let ((rate rate-or-not-before))
               (multiple-value-bind (approach fact) (if rate (approach-kind run rate) :none)
                 (if (eq approach :unknown)
                     ;; it fires then, as an impact or not
                     (values :unknown fact time)
                     (make-candidate condition
                                     (condition-event condition (and (eq approach :impact) rate))
                                     time :rate rate)))))
        (:never :never)
        (t (values :unknown time rate-or-not-before))))))

(defun approach-kind (run rate)
  "How a condition whose violation function crosses zero at RATE (proven <= 0) is
reached: :IMPACT when RATE is proven negative (an impulsive event), :GRAZING when it is
proven zero; otherwise decided by the run's parameter values (the fact noted as assumed
from them, see COMPARE-TIMES), else (values :UNKNOWN (< RATE 0)). Never guessed: a
contact reached with an undecided velocity is not taken for a touch without impact."
  (cond ((holds run `(< ,rate 0)) :impact)
        ((holds run `(= ,rate 0)) :grazing)
        (t (let* ((fact `(< ,rate 0))
                  (values (run-values run))
                  (number (and values (numeric-or-nil (run-bridge run) rate values))))
             (cond ((and number (< number (- (* 1d-9 (max 1d0 (abs number))))))
                    (push (list :fact fact :from :values) (run-assumed run))
                    :impact)
                   (t (values :unknown fact)))))))

(defun relation-time-and-rate (run condition relation over-time)
  "RELATION-TIME's answer for RELATION, with a third value when it fires and CONDITION
names an impact event: the rate at which RELATION's violation function (see
VIOLATION-FUNCTION) crosses zero then (negative: the condition is reached with a
velocity, an impulsive event)."
  (multiple-value-bind (status time) (relation-time run relation over-time)
    (if (and (eq status :at) (ames.engine:termination-condition-impact condition)
             (not (eq (first relation) 'or)))
        (values status time
                (tidy run (at-time (time-derivative (funcall over-time (violation-function relation)))
                                   time)
                      :full))
        (values status time))))

(defun condition-result (run solved groups reach condition)
  "How the termination CONDITION fires in the state (solved as SOLVED, integrated as
GROUPS; REACH the broad phase's): a list (CANDIDATE), (:NEVER), (:NUMERIC) for a condition
over a :NUMERIC group (watched by a numeric integration), or (:UNKNOWN FACT [NOT-BEFORE])."
  (let* ((relation (ames.engine:termination-condition-relation condition))
         (contact (gap-relation-contact relation))
         (involved (and (not (and contact (cannot-meet-p reach contact)))
                        (condition-groups run solved groups relation))))
    (multiple-value-list
     (cond ((null involved) :never)
           ((some (lambda (g) (eq (group-kind g) :numeric)) involved) :numeric)
           ((and (null (rest involved)) (eq (group-kind (first involved)) :speed-line))
            (speed-line-candidate run solved groups (first involved) condition))
           ((every (lambda (g) (member (group-kind g) '(:constant :linear :speed-line))) involved)
            ;; where the root is undecided, a number under values (numeric-roots.lisp)
            (tau-candidate run solved groups condition))
           ((and (null (rest involved)) (eq (group-kind (first involved)) :rotation-path))
            (turning-candidate run solved (first involved) condition))
           ((and (null (rest involved)) (member (group-kind (first involved)) '(:path :line)))
            (path-candidate run solved (first involved) condition))
           (t (values :unknown `(:no-closed-form ,(condition-event condition nil))))))))

(defun candidates-of (run solved groups)
  "Every termination condition of the model that fires: (values CANDIDATES UNKNOWN
NEVER), UNKNOWN a list of (FACT EVENT [NOT-BEFORE]) for the conditions whose firing is
not decided (NOT-BEFORE a time before which such a condition is proven not to fire),
NEVER the events of the conditions proven never to fire in this state. Conditions over
a :NUMERIC group are watched by a numeric integration (under parameter values) up to
the earliest of the others. A contact the broad phase proves out of reach (see
broad-phase.lisp) never fires."
  (let* ((candidates '()) (unknown '()) (numeric '()) (never '()) (rooted '())
         (reach (make-reach run solved groups))
         (conditions (ames.engine:model-termination-conditions (run-model run))))
    ;; the pairs left out of the world must stay apart (deferred-pairs.lisp)
    (check-deferred-pairs reach)
    ;; the meetings of bodies that do not touch come last, set aside where they are
    ;; proven out of reach before another candidate (horizon-phase.lisp)
    ;; under values, the conditions along an angle that cannot come first are set aside
    ;; by numbers (angle-horizon.lisp)
    (let* ((screen (angle-horizon-screen run solved groups reach conditions))
           (results (condition-results run reach conditions
                                       (lambda (condition)
                                         (or (funcall screen condition)
                                             (condition-result run solved groups reach condition))))))
      (dolist (condition conditions)
        (destructuring-bind (result &optional fact not-before) (gethash condition results)
          (cond ((eq result :numeric) (push condition numeric))
                ((candidate-p result) (push result candidates))
                ((and (eq result :unknown) (numeric-root-fallback-p run fact))
                 (push (cons condition fact) rooted))
                ((eq result :unknown)
                 (push (list* fact (condition-event condition nil)
                              (and not-before (list not-before)))
                       unknown))
                (t (push (condition-event condition nil) never))))))
    ;; candidates along an angle proven beyond another are dropped, the rest worked out
    ;; (pending-candidates.lisp)
    (setf candidates (settle-pending-candidates run candidates))
    ;; roots with no closed form, searched with numbers (numeric-roots.lisp)
    (multiple-value-setq (candidates unknown)
      (add-numeric-roots run solved groups (reverse rooted) candidates unknown))
    (when (some (lambda (g) (eq (group-kind g) :numeric)) groups)
      ;; the scenario's time limit bounds the integration too
      (let* ((bounds (append candidates (let ((limit (time-limit-candidate run)))
                                          (and limit (list limit)))))
             (horizon (loop for c in bounds
                            for time = (numeric-time run (candidate-time c))
                            when time minimize time)))
        (setf candidates (append (numeric-candidates run solved groups (reverse numeric)
                                                     (and bounds horizon))
                                 candidates))))
    (values (nreverse candidates) (nreverse unknown) (nreverse never))))
