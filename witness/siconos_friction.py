"""siconos_friction.py -- the witness where friction forces Moreau-Jean time stepping.

Siconos's event-driven scheme has no Coulomb friction; a model with "friction" entries
([[A, B, MU], ...], one coefficient: Siconos's Coulomb law has no separate static and
kinetic coefficients) is simulated by Moreau-Jean time stepping (MoreauJeanOSI, theta
1/2, a 2-D FrictionContact problem with a NewtonImpactFrictionNSL per contact) with the
fixed step STEP. The scheme is first order: events are located within one step (times by
linear interpolation inside it), so its results are compared to a tolerance of order STEP
(the comparator's *FIRST-ORDER-TOLERANCE*). Events: :collision, :leaves, :lift-off as in
the event-driven driver, and :stops-sliding / :starts-sliding when a touching contact's
tangential relative speed falls to zero (or changes sign) or leaves zero.
"""

import numpy as np
import siconos.kernel as sk

from siconos_driver import (Driver, LineLeft, Unsupported, lagrangian_system, pair_names,
                            restitution)

STEP = 1e-4
GAP_TOL = 1e-6
SPEED_TOL = 1e-6    # tangential speeds: sliding or not
CONFIRM_STEPS = 5   # a slide start counts once it has lasted this many steps
NORMAL_TOL = 5e-3   # normal speeds of a contact that holds: Moreau-Jean lets them swing by
                    # about g STEP from one step to the next (the contact in one step, out
                    # the next), so a touching contact is judged to a few g STEP
JUMP = 1e-2         # a normal speed changing more than this in one step: an impulse


def friction_coefficient(model, a, b):
    for entry in model.get("friction", []):
        if {entry[0], entry[1]} == {a, b}:
            return float(entry[2])
    return 0.0


class FrictionSegment:
    """One Moreau-Jean model from a state with a fixed set of active contacts."""

    def __init__(self, model, bodies, contacts, t0, qs, vs, t_end, springs, resting=()):
        n = len(bodies)
        nsds, self.ds = lagrangian_system(model, bodies, t0, t_end, qs, vs, springs)
        for c in contacts:
            a, b = c.names(bodies)
            rows = np.array([c.row(n), tangent_row(c, n)])
            rel = sk.LagrangianLinearTIR(rows, np.array([c.constant(), 0.0]))
            # resting at the start: e = 0 (no approach speed, so no rebound whatever e;
            # e = 1 would make Moreau-Jean's round-off bounce the body and lose its friction)
            e = 0.0 if c in resting else restitution(model, a, b)
            law = sk.NewtonImpactFrictionNSL(e, 0.0, friction_coefficient(model, a, b), 2)
            nsds.link(sk.Interaction(law, rel), self.ds)
        self.sim = sk.TimeStepping(nsds, sk.TimeDiscretisation(t0, STEP))
        self.sim.insertIntegrator(sk.MoreauJeanOSI(0.5))
        self.sim.insertNonSmoothProblem(sk.FrictionContact(2))
        self.n = n

    def state(self):
        q = np.array(self.ds.q(), dtype=float)
        v = np.array(self.ds.velocity(), dtype=float)
        return ([q[2 * k:2 * k + 2] for k in range(self.n)],
                [v[2 * k:2 * k + 2] for k in range(self.n)])


def tangent_row(c, n):
    h = np.zeros(2 * n)
    h[2 * c.other:2 * c.other + 2] += c.t
    if c.owner is not None:
        h[2 * c.owner:2 * c.owner + 2] -= c.t
    return h


def tangential(c, vs):
    return float(np.dot(tangent_row(c, len(vs)), np.concatenate(vs)))


def between(t0, t1, x0, x1):
    """Where the linear interpolant from (t0, x0) to (t1, x1) crosses 0, within [t0, t1]."""
    if x0 == x1:
        return t1
    return min(t1, max(t0, t0 + (t1 - t0) * x0 / (x0 - x1)))


class FrictionDriver(Driver):
    """The driver with Moreau-Jean time stepping in each segment (see the module)."""

    scheme = "moreau-jean"

    def __init__(self, model):
        Driver.__init__(self, model)
        if self.ropes:
            raise Unsupported("ropes together with friction")
        for entry in model.get("friction", []):
            if len(entry) > 3 and abs(float(entry[3]) - float(entry[2])) > 0:
                raise Unsupported("Siconos's Coulomb law has one coefficient; the kinetic and "
                                  "static coefficients differ")

    def sticking(self, c, qs, vs):
        """Whether contact C holds (touching, no normal speed to Moreau-Jean's swing)."""
        return abs(c.gap(qs)) <= GAP_TOL and abs(c.rate(vs)) <= NORMAL_TOL

    def segment(self, t0, qs, vs):
        """One Moreau-Jean segment from T0 (see SEGMENT-STEPS), its pending slide starts
        recorded at its end."""
        self.pending = {}
        self.slid = {}      # contact -> the steps it has slid, one way, until now
        try:
            return self.segment_steps(t0, qs, vs)
        finally:
            self.flush_pending()

    def segment_steps(self, t0, qs, vs):
        if self.t_end - t0 < 2 * STEP:   # less than a step left: the run ends here
            return self.t_end, qs, vs
        active = [c for c in self.contacts if c.active(qs, vs) and c not in self.excluded]
        self.last_left = []
        inactive = [c for c in self.contacts if c not in active]
        resting = {c for c in active if self.sticking(c, qs, vs)}
        seg = FrictionSegment(self.model, self.bodies, active, t0, qs, vs, self.t_end, self.springs,
                              resting)
        tp, qp, vp = t0, qs, vs
        while seg.sim.hasNextEvent():
            seg.sim.computeOneStep()
            t1 = seg.sim.nextTime()
            q1, v1 = seg.state()
            try:
                for line in self.springs:
                    line.check(q1)
            except LineLeft as e:
                self.truncated = str(e)
                return tp, qp, vp
            left = [c for c in active if not c.covers(q1)]
            entered = [c for c in inactive if c.covers(q1) and not c.covers(qp) and c.gap(q1) >= -1e-6]
            if left or entered:
                self.last_left = left
                times = [between(tp, t1, min(c.margins(qp)), min(c.margins(q1))) for c in left + entered]
                tc = min(times)
                pairs = [(":leaves",) + pair_names(c, self.bodies) for c in left
                         if self.sticking(c, qp, vp)]
                if pairs:
                    self.record(tc, pairs, qp, vp, vp)
                return t1, q1, v1
            self.step_events(active, tp, qp, vp, t1, q1, v1)
            seg.sim.nextStep()
            opened = [c for c in resting if not self.sticking(c, q1, v1)]
            tp, qp, vp = t1, q1, v1
            if opened:   # give it its own e again
                return tp, qp, vp
            if t1 >= self.t_end - 1e-12:
                break
        return tp, qp, vp

    def step_events(self, active, t0, q0, v0, t1, q1, v1):
        """The events of one step, located inside it by linear interpolation."""
        impacts = False
        for c in active:
            g0, vn0, vn1 = c.gap(q0), c.rate(v0), c.rate(v1)
            # an impulse: the approach speed jumps within a step of the gap's closing (the
            # scheme acts on the predicted gap, so the gap itself need not reach 0)
            if vn0 < -NORMAL_TOL and vn1 - vn0 > JUMP and g0 <= -vn0 * 2 * STEP + GAP_TOL:
                ti = min(t1, t0 + max(g0, 0.0) / -vn0)
                qi = [q + v * (ti - t0) for q, v in zip(q0, v0)]
                self.record(ti, [(":collision",) + pair_names(c, self.bodies)], qi, v0, v1, -vn0)
                impacts = True
        # the impulse itself comes a step after the gap closes; in the steps where any
        # normal speed jumps, the velocities change by impulses: no sliding events there
        impacts = impacts or any(abs(c.rate(v1) - c.rate(v0)) > JUMP for c in active)
        if impacts:
            return
        for c in active:
            names = pair_names(c, self.bodies)
            before, after = self.sticking(c, q0, v0), self.sticking(c, q1, v1)
            if before and not after and c.rate(v1) > NORMAL_TOL and t0 > 0:
                self.record(t0, [(":lift-off",) + names], q0, v0, v0)
            elif before and after and t0 > 2 * STEP:   # the first steps settle the initial modes
                s0, s1 = tangential(c, v0), tangential(c, v1)
                slid = self.slid.get(c, 0)   # the steps it has slid so far, one way
                self.slid[c] = slid + 1 if abs(s1) > SPEED_TOL and s0 * s1 > 0 else 0
                # a slide ends only once it has lasted CONFIRM_STEPS steps: the LCP's noise
                # can give a contact at rest a few steps of speed (a particle at rest on a
                # rough incline, make crosscheck SEED=101 #588)
                if abs(s0) > SPEED_TOL and (abs(s1) <= SPEED_TOL or s0 * s1 < 0) \
                        and c not in self.pending and slid + 1 >= CONFIRM_STEPS:
                    ts = between(t0, t1, s0, s1)
                    qs = [q + v * (ts - t0) for q, v in zip(q0, v0)]
                    self.record(ts, [(":stops-sliding",) + names], qs, v1, v1)
                elif abs(s0) <= SPEED_TOL and abs(s1) > SPEED_TOL and c not in self.pending:
                    # held until the slide lasts CONFIRM_STEPS steps: the LCP's noise can give
                    # a resting contact one step of speed (a particle at rest on a rough incline)
                    self.pending[c] = [t0, q0, v0, names, s1, 0]
        self.confirm_pending(active, q1, v1)

    def confirm_pending(self, active, q1, v1):
        """Record each pending slide start that has lasted CONFIRM_STEPS steps with the same
        direction; drop one whose contact stopped or left (noise)."""
        for c in list(self.pending):
            t0, q0, v0, names, s_start, steps = self.pending[c]
            s1 = tangential(c, v1)
            if c not in active or not self.sticking(c, q1, v1) or abs(s1) <= SPEED_TOL \
                    or s1 * s_start < 0:
                del self.pending[c]
            elif steps + 1 >= CONFIRM_STEPS:
                self.record_in_order(t0, [(":starts-sliding",) + names], q0, v0, v0)
                del self.pending[c]
            else:
                self.pending[c][5] = steps + 1

    def flush_pending(self):
        """At a segment's end, the slide starts still pending are recorded (they lasted to it)."""
        for c, (t0, q0, v0, names, s_start, steps) in list(self.pending.items()):
            self.record_in_order(t0, [(":starts-sliding",) + names], q0, v0, v0)
        self.pending = {}

    def record_in_order(self, t, pairs, qs, vs, after):
        """RECORD an event that may be earlier than the last one recorded (a confirmed slide
        start), keeping the events in time order."""
        if not self.events or self.events[-1]["time"] <= t + 1e-9 * max(1.0, abs(t)):
            self.record(t, pairs, qs, vs, after)
        else:
            self.events.append({"time": t, "pairs": list(pairs), "q": qs, "v": vs,
                                "after": after, "speed": 0.0})
            self.events.sort(key=lambda e: e["time"])
