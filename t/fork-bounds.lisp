;;;; t/fork-bounds.lisp -- the bound of a run's tree (src/simulator/branching.lisp, issue 23),
;;;; and a state whose end is a root without closed form (src/simulator/rootless-ends.lisp).
;;;;
;;;; The depth bound counts the states at which a path forks, not its forks: the forks
;;;; nested within one state's analysis (its choice search's facts, then the order of its
;;;; events) split one finite set of questions, and a pushed block's textbook tipping state
;;;; is three of them deep (it tips; its front edge does not slide back; nor forward), its
;;;; end a fourth (its torques balance before or after its centre passes over the edge).
;;;; Those count against *FORKS-PER-STATE-LIMIT* at the path's first forking state; a fork
;;;; at a later state counts one more level against *BRANCH-DEPTH-LIMIT* and forks once
;;;; (the thesis's corner: B rises or falls at t = 0, then a fork at state 1, whose nested
;;;; fact stays at the bound, as before), and the count of the whole tree's branches (each
;;;; one simulated) bounds everything.

(in-package #:ames.tests)

(def-suite fork-bounds :in all-tests
  :description "The tree's bound: forking states per path, forks nested within a state.")

(in-suite fork-bounds)

(defun room-after-forks (indices &optional (alternatives 2))
  "The plist *BRANCHING* holds below forks at the states INDICES (from the root), each
with ALTERNATIVES branches."
  (let ((ames.simulator::*branching* nil))
    (dolist (index indices ames.simulator::*branching*)
      (setf ames.simulator::*branching*
            (ames.simulator::nested-branching index (make-list alternatives))))))

(defun room-p (indices index)
  "Whether a path below forks at INDICES may fork again at the state INDEX."
  (let ((ames.simulator::*branching* (room-after-forks indices)))
    (ames.simulator::branch-room-p index)))

(test forks-within-one-state-count-once-toward-the-depth
  "Four forks at state 0 (the pushed block's: tips, lower and upper friction limit of its
front edge, the order of its end angles) stay one forking state deep; a fifth there is
refused, a fork at the next state is one more level, and a third forking state is
refused, as is any fork once the branch count is full."
  (let ((ames.simulator::*forks-per-state-limit* 4)
        (ames.simulator::*branch-depth-limit* 2)
        (ames.simulator::*branch-limit* 24))
    (is (room-p '() 0))
    (is (= 1 (getf (room-after-forks '(0 0 0)) :depth)))
    (is (= 3 (getf (room-after-forks '(0 0 0)) :nested)))
    (is (room-p '(0 0 0) 0) "the fourth fork within state 0")
    (is (not (room-p '(0 0 0 0) 0)) "a fifth fork within state 0")
    (is (room-p '(0 0 0 0) 1) "a fork at state 1 after four at state 0")
    (is (= 2 (getf (room-after-forks '(0 0 1)) :depth)))
    (is (= 1 (getf (room-after-forks '(0 0 1)) :nested)))
    (is (not (room-p '(0 1) 1)) "a second fork at a later forking state (the corner's)")
    (is (not (room-p '(0 0 1) 1)))
    (is (not (room-p '(0 1) 2)) "a third forking state")
    ;; the count of branches on the path: three forks of 7 (21) leave no room under 24
    (let ((ames.simulator::*branching* (room-after-forks '(0 0 0) 7)))
      (is (not (ames.simulator::branch-room-p 0))))
    ;; and of the whole tree: a branch whose forks grew the tree to 22 branches leaves
    ;; its sibling (3 on its own path) no room
    (let ((root (room-after-forks '(0) 3)))
      (let ((ames.simulator::*branching* root))
        (is (ames.simulator::branch-room-p 0))
        (let ((ames.simulator::*branching* (ames.simulator::nested-branching 0 (make-list 10))))
          (ames.simulator::nested-branching 1 (make-list 9))))
      (let ((ames.simulator::*branching* root))
        (is (= 3 (getf root :count)))
        (is (not (ames.simulator::branch-room-p 0)) "the sibling, after the tree grew to 22")))))

;;; A state's end at a root without closed form (src/simulator/rootless-ends.lisp)

(defun rootless-ambiguity (state)
  "The ambiguity of STATE's end at the root of a normal force along its angle, a root
with no closed form: the missing fact (:ROOTS-OF (= N 0))."
  (make-condition 'ames.simulator::ambiguous-transition
                  :missing-fact '(:roots-of (= (+ (* 3 (cos s) (sin s)) (cos s) -1/2) 0))
                  :state state))

(test a-state-ending-at-a-root-without-closed-form-is-kept-undecided
  "Without numbers, a state whose end is a root without closed form is appended to the
history, undecided, its duration waiting for values; with values (the root is then
searched with numbers), or for a missing inequality, or for another state, it is not."
  (let* ((scenario (ames:parse-scenario
                    '(scenario s "x" (parameters (g :positive)) (gravity g)
                      (body b :mass 1 :shape (circle 1) :position (0 0) :velocity (0 0)))))
         (without (make-instance 'ames.simulator::run :bridge nil :values '() :scenario scenario))
         (with (make-instance 'ames.simulator::run :bridge nil :values '((g . 10)) :scenario scenario)))
    (flet ((fresh () (make-instance 'ames.simulator::simulation-history :scenario scenario))
           (state () (make-instance 'ames.simulator::qualitative-state :index 0)))
      (let ((history (fresh)) (state (state)))
        (is (ames.simulator::note-rootless-end without history 0 (rootless-ambiguity state)))
        (is (equal (list state) (ames.simulator::history-states history)))
        (is (eq :undecided (ames.simulator::history-outcome history)))
        (is (eq :undecided (ames.simulator::state-end-event state)))
        (is (equal '(:no-closed-form :needs :parameter-values) (ames.simulator::state-duration state))))
      (let ((history (fresh)))
        (is (not (ames.simulator::note-rootless-end with history 0 (rootless-ambiguity (state)))))
        (is (not (ames.simulator::note-rootless-end without history 1 (rootless-ambiguity (state)))))
        (is (not (ames.simulator::note-rootless-end
                  without history 0
                  (make-condition 'ames.simulator::ambiguous-transition
                                  :missing-fact '(> g 1) :state (state)))))
        (is (null (ames.simulator::history-states history)))
        (is (eq :complete (ames.simulator::history-outcome history)))))))
