;;;; bench/bench-engine.lisp -- the component engine on a large house: instances re-derived
;;;; per transition against the instances a transition affects (target: ratio <= 1.2),
;;;; and the time of an incremental transition against a rebuild from scratch.
;;;; Prints numbers; asserts nothing.

(defpackage #:ames.bench.engine
  (:use #:cl)
  (:documentation "The component engine benchmark, on a heating knowledge base of its own."))

(in-package #:ames.bench.engine)

(defun seconds-since (start)
  "Seconds of real time since the internal time START."
  (/ (- (get-internal-real-time) start) internal-time-units-per-second))

;;; A heating knowledge base (the same shape as the tests' toy: modes, activation and
;;; deactivation, a pair of beliefs, a collection, a required belief)

(defun property-template (key)
  "A template function giving the property KEY of the entity its argument names."
  (lambda (situation name)
    (ames.engine:entity-property (ames.engine:find-entity situation name) key)))

(defun make-house-kb ()
  "A knowledge base of heaters, doors and rooms."
  (let ((kb (ames.engine:make-knowledge-base :name "house")))
    (ames.engine:register-template kb 'setpoint (property-template :setpoint))
    (ames.engine:register-template kb 'rating (property-template :rating))
    (ames.engine:register-template kb 'power (lambda (situation flow)
                                               (declare (ignore situation))
                                               (cons 'heat-power flow)))
    (ames.engine:register-template kb 'sum-of (lambda (situation flows)
                                                (declare (ignore situation))
                                                (if flows
                                                    (cons '+ (mapcar (lambda (f) (list 'power f))
                                                                     flows))
                                                    0)))
    (ames.engine:defcomponent heater (:knowledge-base kb)
      "A heater heats its room while the room is below the setpoint."
      (:arguments (?heater :entity heater :where (:room ?room)))
      (:mode on
        (:entry (< (temperature ?room) (setpoint ?heater)))
        (:assert (heat-flow (output ?heater) :into ?room :from ?heater :kind radiant))
        (:equations (= (power (output ?heater)) (rating ?heater)))
        (:transition :to off :when (>= (temperature ?room) (setpoint ?heater))))
      (:mode off
        (:entry (>= (temperature ?room) (setpoint ?heater)))
        (:transition :to on :when (< (temperature ?room) (setpoint ?heater)))))
    (ames.engine:defcomponent open-door (:knowledge-base kb)
      "Heat flows through an open door."
      (:arguments (?door :entity door :where (:between ?room1 :and ?room2)))
      (:activation (> (opening ?door) 0))
      (:deactivation (<= (opening ?door) 0))
      (:assert (heat-flow (through ?door ?room1) :into ?room1 :from ?room2)
               (heat-flow (through ?door ?room2) :into ?room2 :from ?room1))
      (:equations (= (power (through ?door ?room1))
                     (* k (opening ?door) (- (temperature ?room2) (temperature ?room1))))))
    (ames.engine:defcomponent exchange-balance (:knowledge-base kb)
      "What one room gains through an exchange, the other loses."
      (:arguments (?gain :belief (heat-flow ?gain :into ?room1 :from ?room2))
                  (?loss :belief (heat-flow ?loss :into ?room2 :from ?room1)))
      (:equations (= (power ?gain) (- (power ?loss)))))
    (ames.engine:defcomponent energy-balance (:knowledge-base kb)
      "A room warms at the rate of all the heat flowing into it."
      (:arguments (?room :entity room)
                  (?flows :collect ?f :matching (heat-flow ?f :into ?room)))
      (:equations (= (* c (temperature-rate ?room)) (sum-of ?flows))))
    (ames.engine:defcomponent heated-room (:knowledge-base kb)
      "A room a heater blows into has its air stirred."
      (:arguments (?room :entity room))
      (:activation (:believes (heat-flow ?_ :into ?room :kind radiant)))
      (:equations (= (stirring ?room) 1)))
    kb))

(defun house-entities (room-names heater-names door-names)
  "Rooms in a ring, a heater in each, a door between neighbours."
  (let ((n (length room-names)))
    (append
     (mapcar (lambda (room) (list 'room room)) room-names)
     (loop for room in room-names for heater in heater-names
           collect (list 'heater heater :room room :rating 'p :setpoint 's))
     (loop for i below n for door in door-names
           collect (list 'door door :between (nth i room-names)
                         :and (nth (mod (1+ i) n) room-names))))))

(defun numbered-names (prefix count)
  "COUNT fresh uninterned symbols PREFIX0, PREFIX1... (names for a generated house)."
  (loop for i below count collect (make-symbol (format nil "~A~D" prefix i))))

(defun random-values (rooms doors random-state)
  "Random initial temperatures and door openings, as a hash table quantity -> number."
  (let ((values (make-hash-table :test #'equal)))
    (setf (gethash 's values) 20)
    (dolist (room rooms) (setf (gethash (list 'temperature room) values)
                               (+ 10 (random 20 random-state))))
    (dolist (door doors) (setf (gethash (list 'opening door) values) (random 3 random-state)))
    values))

(defun decider (values)
  "A decider for relations (< > <= >=) between a known quantity and a number or
known quantity."
  (lambda (relation)
    (flet ((value (x) (if (realp x) x (gethash x values))))
      (let ((a (value (second relation))) (b (value (third relation))))
        (if (and a b)
            (if (ecase (first relation)
                  (< (< a b)) (> (> a b)) (<= (<= a b)) (>= (>= a b)))
                :true :false)
            :unknown)))))

;;; What a transition affects

(defun contributions (model)
  "A table instance key -> what the instance contributes to the state: whether it is
qualified and active, its mode and its equations."
  (let ((table (make-hash-table :test #'equal)))
    (dolist (instance (ames.engine:model-instances model) table)
      (setf (gethash (ames.engine:instance-key instance) table)
            (list (ames.engine:instance-qualified-p instance)
                  (ames.engine:instance-active-p instance)
                  (ames.engine:instance-mode instance)
                  (ames.engine:instance-equations instance))))))

(defun affected-count (before after)
  "How many instance keys contribute differently in the tables BEFORE and AFTER."
  (let ((count 0))
    (maphash (lambda (key contribution)
               (unless (equal contribution (gethash key after)) (incf count)))
             before)
    count))

(defun run-engine-benchmark (&key (rooms 300) (transitions 60) (rebuild-every 10))
  "Build the house model, fire TRANSITIONS random termination conditions one at a
time, and print re-derived against affected instances and timings."
  (let* ((random-state (sb-ext:seed-random-state 1994))
         (room-names (numbered-names "R" rooms))
         (door-names (numbered-names "D" rooms))
         (situation (ames.engine:make-situation
                     (house-entities room-names (numbered-names "H" rooms) door-names)))
         (engine (ames.engine:make-engine (make-house-kb)))
         (start (get-internal-real-time))
         (model (ames.engine:build-model engine situation
                                         :decider (decider (random-values room-names door-names
                                                                          random-state)))))
    (format t "~&House of ~D rooms: ~D potential instances, ~D active, ~D equations, ~
               ~D JTMS nodes; built in ~,3F s~%"
            rooms (length (ames.engine:model-instances model))
            (length (ames.engine:model-active-instances model))
            (length (ames.engine:model-equations model))
            (ames.tms:jtms-node-count (ames.engine:model-jtms model))
            (seconds-since start))
    (let ((total-rederived 0) (total-affected 0) (worst 0) (transition-time 0) (rebuild-time 0)
          (rebuilds 0) (mismatches 0))
      (dotimes (step transitions)
        (let* ((conditions (ames.engine:model-termination-conditions model))
               (fired (nth (random (length conditions) random-state) conditions))
               (values (random-values room-names door-names random-state))
               (before (contributions model))
               (start (get-internal-real-time)))
          (multiple-value-bind (model report)
              (ames.engine:apply-transition model
                                            (list (ames.engine:termination-condition-change fired))
                                            :decider (decider values))
            (incf transition-time (seconds-since start))
            (let ((rederived (ames.engine:transition-report-rederived-count report))
                  (affected (affected-count before (contributions model))))
              (incf total-rederived rederived)
              (incf total-affected affected)
              (when (plusp affected) (setf worst (max worst (/ rederived affected)))))
            (when (zerop (mod step rebuild-every))
              (let ((start (get-internal-real-time)))
                (when (ames.engine:check-incremental model :signal nil) (incf mismatches))
                (incf rebuild-time (seconds-since start))
                (incf rebuilds))))))
      (format t "~D transitions: ~,2F instances re-derived and ~,2F affected per transition; ~
                 ratio ~,3F (worst single transition ~,3F; target <= 1.2)~%"
              transitions (/ total-rederived transitions) (/ total-affected transitions)
              (if (plusp total-affected) (/ total-rederived total-affected) 0)
              (float worst))
      (format t "Incremental transition: ~,3F ms mean; rebuild from scratch and compare: ~
                 ~,1F ms mean (~D rebuilds, ~D mismatches)~%"
              (/ (* 1000 transition-time) transitions)
              (if (plusp rebuilds) (/ (* 1000 rebuild-time) rebuilds) 0)
              rebuilds mismatches))))

(run-engine-benchmark)
