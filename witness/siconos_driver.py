#!/usr/bin/python3
"""siconos_driver.py -- the independent witness of AMES: simulate a model with Siconos.

Reads a model description (JSON, on the standard input or from the file given as the
first argument), simulates it with Siconos's event-driven scheme (LsodarOSI + EventDriven,
LCPs at the impact and the acceleration level), and prints one s-expression on the
standard output:

  (:status :ok
   :events ((:time T :pairs ((KIND A B) ...) :positions ((BODY (X Y)) ...)
             :velocities ((BODY (VX VY)) ...) :after ((BODY (VX VY)) ...)) ...)
   [:truncated "why the run was cut before T_END"]
   :end (:time T :positions (...) :velocities (...)))
or
  (:status :unsupported :message "...")   the model has what the witness cannot model
  (:status :error :message "...")         the witness failed

KIND is :collision (an impact: a contact closing with approach speed), :contact (a contact
closing with no approach speed), :leaves (a body in contact passing the end of a face:
the face's extent is handled here, not by Siconos, so that a body leaving a table top is
not held by the table's infinite line), or :lift-off (a contact opening on a face).
Positions and velocities of an event are those just before it; :after the velocities
just after; :speed the largest approach speed of its impacts (0 for other events).

The model (every number a float, in one fixed frame, y up):
  {"t_end": T, "gravity": G,
   "bodies": [{"name": N, "mass": M, "q": [X, Y], "v": [VX, VY],
               "shape": {"kind": "point"} | {"kind": "circle", "r": R}
                      | {"kind": "polygon", "vertices": [[X, Y], ...]},   (own frame, ccw)
               "force": [FX, FY]}],                                  (constant, besides gravity)
   "obstacles": [{"name": N, "faces": [{"a": [X, Y], "b": [X, Y], "infinite": BOOL}]}],
                                                (world frame; solid on the left of a -> b)
   "restitution": [[A, B, E], ...], "default_restitution": E,
   "springs": [{"name": N, "k": K, "rest": L0 or null, "a": POINT, "b": POINT}],
   "ropes": [{"name": N, "length": L, "points": [POINT, ...]}]}
  where POINT is {"body": INDEX, "offset": [X, Y]} (a free body's point, own frame) or
  {"point": [X, Y]} (a fixed point: a fixed body's point or pulley).

Springs and ropes are linear in the positions as long as each keeps the direction of its
start (a spring along a line, a rope's pieces vertical or along an incline): the driver
checks that at every step and cuts its run (:truncated) when one turns. A rope is the
unilateral constraint L - (sum of its pieces) >= 0 with Newton's law e = 0: its closing is
(:tightens ROPE ROPE), its opening (:slackens ROPE ROPE). Where a rope's piece turns (or
closes at its pulley), the model is simulated again from the start with the rope's length
constraint exact and each piece's closing at its pulley a unilateral relation
(siconos_ropes.py, siconos_rope_driver.py: the swings' turning points (:turns BODY BODY), (:strikes-pulley BODY
HOLDER)). At the times the model asks for ("samples"), the driver reports its state and
the least gaps of the pairs near zero (siconos_grazes.py: contacts reached with no
approach speed, which Lsodar's root finding cannot see); a model with "gap_probe" asks
for a pair's gap along a given motion instead (siconos_probe_gaps.py).

A model with a rotating body (an "inertia") or a hinge is simulated by siconos_rotation.py
(three degrees of freedom per body, Moreau-Jean time stepping; see there). Models with arcs
or circles (fixed, or two free round bodies), universal gravitation ("gravitation": G,
"attractors": fixed bodies with a mass) or bumpers go to siconos_arcs.ArcDriver, which adds
turning points (:turns B B) and the state at requested times ("samples": [T, ...], printed
as :samples).

Otherwise bodies translate (no rotation), in modules by meaning: siconos_contacts.py (the
bodies, the faces' contacts), siconos_segment.py (one Siconos model), siconos_extents.py
(the faces' extents), siconos_impacts.py (an impact by Newton's law where Siconos fails
after one), siconos_sexp.py (the answer); this file holds the driver that runs them. Every possible contact is a face (of an obstacle or of a
free polygon body) against the support point of another free body: its gap is linear in
the positions, so each is a LagrangianLinearTIR with a NewtonImpactNSL. The driver keeps
the set of contacts whose face extent covers the body (and that the body is not behind);
when a body leaves or enters an extent, the time is found on the cubic Hermite
interpolant of the last two recorded states (exact for motion under constant forces) and
the Siconos model is rebuilt from that state.
"""

import json
import math  # noqa: F401
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import numpy as np  # noqa: E402,F401

try:
    import siconos.kernel as sk  # noqa: F401
except ImportError:  # pragma: no cover
    print('(:status :error :message "siconos is not importable by this python")')
    sys.exit(0)

# the translating witness, by meaning (the names stay importable from here)
from siconos_lines import LineLeft, Rope, Spring  # noqa: E402,F401  (springs and ropes)
from siconos_impacts import newton_impact  # noqa: E402  (where Siconos fails after an impact)
from siconos_contacts import (LOOK_AHEAD, Body, Contact, Unsupported, hermite,  # noqa: E402,F401
                              make_contacts, onto_contacts, pair_names, restitution)
from siconos_segment import Segment, lagrangian_system  # noqa: E402,F401
from siconos_extents import Extents  # noqa: E402
from siconos_grazes import Trace  # noqa: E402  (least gaps near given times: grazes)
from siconos_sexp import print_answer, sx_number, sx_states, sx_string, sx_vec  # noqa: E402,F401

TOL = 1e-8          # gap / speed tolerance (lengths and speeds are O(1) in the models)
MAX_EVENTS = 200000  # nonsmooth events in one segment (micro-rebounds of resting contacts with e = 1 too)


class Driver(Extents, Trace):
    segment_class = Segment   # the kind of Siconos model built for each segment

    def __init__(self, model):
        self.model = model
        self.bodies = [Body(b) for b in model["bodies"]]
        self.contacts = self.make_contacts(model)
        qs = [b.q.copy() for b in self.bodies]
        self.springs = [Spring(spec, qs) for spec in model.get("springs", [])]
        self.ropes = [Rope(spec, qs) for spec in model.get("ropes", [])]
        self.contacts += self.ropes
        self.t_end = float(model["t_end"])
        # the output step: extents are crossed on the Hermite interpolant of two outputs,
        # exact for motion under constant forces, so a long run may take long steps; with
        # springs (sines) the step stays 0.01 s
        self.dt = float(model.get("dt", 0.01 if model.get("springs") else
                                  max(0.01, self.t_end / 200.0)))
        self.events = []
        self.in_contact = set()
        self.smooth_event = None
        self.impacted, self.impact_time = set(), None   # the contacts the last impact closed
        self.truncated = None
        self.excluded, self.last_left = set(), []

    def make_contacts(self, model):
        return make_contacts(model, self.bodies)

    def record(self, t, pairs, qs, vs, after, speed=0.0):
        if self.events and abs(self.events[-1]["time"] - t) <= 1e-9 * max(1.0, abs(t)):
            last = self.events[-1]
            for p in pairs:
                if p not in last["pairs"]:
                    last["pairs"].append(p)
            last["after"] = after
            last["speed"] = max(last["speed"], speed)
            return
        self.events.append({"time": t, "pairs": list(pairs), "q": qs, "v": vs, "after": after,
                            "speed": speed})

    def touching(self, c, qs, vs):
        return abs(c.gap(qs)) <= 1e-7 and abs(c.rate(vs)) <= 1e-7

    def run(self):
        t = 0.0
        qs = [b.q.copy() for b in self.bodies]
        vs = [b.v.copy() for b in self.bodies]
        rebuilds = 0
        while t < self.t_end - 1e-12 and not self.truncated:
            rebuilds += 1
            if rebuilds > 2000:
                raise RuntimeError("too many changes of the active contacts")
            t_before = t
            t, qs, vs = self.segment(t, qs, vs)
            # a contact that leaves its face the moment its model starts (a body on the
            # very end of a face) is left out of the next model at that moment
            if t - t_before <= 1e-12 * max(1.0, abs(t)):
                self.excluded |= set(self.last_left)
            else:
                self.excluded = set()
        return t, qs, vs

    def segment(self, t0, qs, vs):
        active = [c for c in self.contacts if c.active(qs, vs) and c not in self.excluded]
        qs = onto_contacts(active, qs)
        active += [c for c in self.contacts if c not in active and c not in self.excluded
                   and self.corner_held(c, active, qs, vs)]
        self.last_left = []
        inactive = [c for c in self.contacts if c not in active]
        # a body touching a face and at its very end, moving off it, leaves it now
        leaving = [c for c in self.in_contact if c not in active and c.covers(qs)
                   and self.touching(c, qs, vs)]
        if leaving and t0 > 0:
            self.record(t0, [(":leaves",) + pair_names(c, self.bodies) for c in leaving], qs, vs, vs)
        resting = {c for c in active if self.touching(c, qs, vs)}
        self.trace(t0, qs, vs)
        seg = self.segment_class(self.model, self.bodies, active, t0, qs, vs, self.t_end, self.dt,
                                 self.springs, resting)
        tp, qp, vp = t0, qs, vs
        count = 0
        while seg.sim.hasNextEvent():
            try:
                seg.sim.advanceToEvent()
            except Exception:
                held = [c for c in self.in_contact | resting if getattr(c, "owner", None) is not None]
                if not held:
                    raise
                # Lsodar crawls (then stops: Istate = -1) on two free bodies held together
                # by a force that varies (blocks pushed against each other by a spring)
                self.truncated = "Siconos's integrator stopped at %s with %s held against %s" % (
                    repr(tp), *pair_names(held[0], self.bodies))
                return tp, qp, vp
            nxt = seg.em.nextEvent()
            ns = nxt.getType() == 2
            count += 1 if ns else 0
            if count > MAX_EVENTS:
                raise RuntimeError("more than %d nonsmooth events in a segment" % MAX_EVENTS)
            t1 = nxt.getDoubleTimeOfEvent()
            q1, v1 = seg.state()
            try:
                for line in self.springs + self.ropes:
                    line.check(q1)
            except LineLeft as e:
                self.truncated = str(e)
                return tp, qp, vp
            # has a contact's extent changed between tp and t1?
            change = self.extent_change(active, inactive, tp, qp, vp, t1, q1, v1)
            if change is not None:
                tc, qc, vc, left = change
                self.last_left = left
                pairs = [(":leaves",) + pair_names(c, self.bodies)
                         for c in left if self.touching(c, qc, vc)]
                if pairs:
                    self.record(tc, pairs, qc, vc, vc)
                return tc, qc, vc
            try:
                seg.sim.processEvents()
            except Exception:
                # Siconos 4.4's EventDriven may fail after it has solved an impact (an
                # std::exception from its acceleration-level problem: two blocks caught
                # up with plastically while a spring drives them): the impact is applied
                # here by Newton's law and the next model starts from it
                after = newton_impact(self.model, self.bodies, active, q1, v1) if ns else None
                pairs, speed, closed = self.closures(active, q1, v1, after) if after else ([], 0, ())
                if not pairs:
                    raise
                self.record(t1, pairs, q1, v1, after, speed)
                self.trace(t1, q1, v1)
                self.impacted, self.impact_time = closed, t1
                self.in_contact = {c for c in active if self.touching(c, q1, after)}
                return t1, q1, after
            q2, v2 = seg.state()
            self.trace(t1, q1, v1)
            self.trace(t1, q2, v2)
            pairs = []
            if ns:
                pairs, speed, closed = self.closures(active, q1, v1, v2)
                if pairs:
                    self.record(t1, pairs, q1, v1, v2, speed)
                    self.impacted, self.impact_time = closed, t1
                else:
                    self.smooth_event = (t1, q1, v1)
            touching = {c for c in active if self.touching(c, q2, v2)}
            opened = [c for c in active if c in self.in_contact and c not in touching]
            if not (ns and pairs):   # contacts opened by an impact belong to the impact
                self.lift_offs(opened, tp, v2)
            self.in_contact = touching
            tp, qp, vp = t1, q2, v2
            if any(c in resting for c in opened):   # give it its own e again
                return tp, qp, vp
            if t1 >= self.t_end - 1e-12:
                break
        return tp, qp, vp

    def closures(self, active, q1, v1, v2):
        """The contacts of ACTIVE an impact at Q1 closed (an approach speed in V1 that the
        velocities after, V2, raised): (PAIRS SPEED CLOSED), SPEED the largest approach speed."""
        pairs, speed, closed = [], 0.0, set()
        for c in active:
            if abs(c.gap(q1)) <= 1e-7:
                before, after = c.rate(v1), c.rate(v2)
                if before < -1e-9 and after > before + 1e-12:
                    pairs.append((c.kinds["close"],) + pair_names(c, self.bodies))
                    speed = max(speed, -before)
                    closed.add(c)
        return pairs, speed, closed

    def lift_offs(self, opened, tp, vs):
        """The contacts OPENED (touching at the last step, apart now, with no impact) lifted
        off at the nonsmooth event where Siconos's acceleration-level LCP let them go (the
        last one, at or after TP); without one, at TP."""
        if not opened or tp <= 0.0:   # at the start: the initial modes, not an event
            return
        # a contact an impact closed and the forces open at once, with no nonsmooth event
        # since (a plastic collision that a spring pulls apart): it never held, no lift-off
        if self.impact_time is not None and (self.smooth_event is None
                                             or self.smooth_event[0] < self.impact_time):
            opened = [c for c in opened if c not in self.impacted]
            if not opened:
                return
        t, q, v = self.smooth_event if self.smooth_event and self.smooth_event[0] >= tp - 1e-12 \
            else (tp, None, None)
        if q is None:
            if max(c.rate(vs) for c in opened) < 1e-4:
                return   # the residue of a Zeno sequence's end (a rebound under Siconos's tolerance)
            raise RuntimeError("a contact opened without a nonsmooth event")
        self.record(t, [(c.kinds["open"],) + pair_names(c, self.bodies) for c in opened], q, v, v)


def main():
    text = open(sys.argv[1]).read() if len(sys.argv) > 1 else sys.stdin.read()
    simulate(json.loads(text))


def simulate(model):
    """Simulate MODEL (a decoded model description) and print the s-expression answer."""
    if model.get("gap_probe"):   # a pair's gap along a given motion (siconos_probe_gaps.py)
        from siconos_probe_gaps import probe_gaps
        try:
            print(probe_gaps(model))
        except Exception as e:
            print("(:status :error :message %s)" % sx_string("%s: %s" % (type(e).__name__, e)))
        return
    if model.get("hinges") or any("inertia" in b for b in model.get("bodies", [])):
        from siconos_rotation import main_rotation   # bodies that turn: 3 degrees of freedom
        main_rotation(model)
        return
    try:
        from siconos_arcs import ArcDriver, curved_model_p
        if curved_model_p(model):
            driver = ArcDriver(model)
        elif model.get("friction"):
            from siconos_friction import FrictionDriver
            driver = FrictionDriver(model)
        else:
            driver = Driver(model)
        t, qs, vs = driver.run()
        if (driver.truncated or "").startswith("rope ") and not model.get("springs"):
            # a rope piece turned (or closed): the exact rope (siconos_ropes.py) from the start
            from siconos_rope_driver import turning_rope_driver
            try:
                exact = turning_rope_driver(model)
                t, qs, vs = exact.run()
                driver = exact
            except Unsupported:
                pass    # the linear rope's run, cut where it turned
    except Unsupported as e:
        print("(:status :unsupported :message %s)" % sx_string(str(e)))
        return
    except Exception as e:  # the witness failed: say so, never a result
        print("(:status :error :message %s)" % sx_string("%s: %s" % (type(e).__name__, e)))
        return
    print_answer(driver, t, qs, vs)


if __name__ == "__main__":
    main()
