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
checks that at every step and answers :unsupported when one turns. A rope is the
unilateral constraint L - (sum of its pieces) >= 0 with Newton's law e = 0: its closing is
(:tightens ROPE ROPE), its opening (:slackens ROPE ROPE).

A model with a rotating body (an "inertia") or a hinge is simulated by siconos_rotation.py
(three degrees of freedom per body, Moreau-Jean time stepping; see there). Models with arcs
or circles (fixed, or two free round bodies), universal gravitation ("gravitation": G,
"attractors": fixed bodies with a mass) or bumpers go to siconos_arcs.ArcDriver, which adds
turning points (:turns B B) and the state at requested times ("samples": [T, ...], printed
as :samples).

Otherwise bodies translate (no rotation). Every possible contact is a face (of an obstacle or of a
free polygon body) against the support point of another free body: its gap is linear in
the positions, so each is a LagrangianLinearTIR with a NewtonImpactNSL. The driver keeps
the set of contacts whose face extent covers the body (and that the body is not behind);
when a body leaves or enters an extent, the time is found on the cubic Hermite
interpolant of the last two recorded states (exact for motion under constant forces) and
the Siconos model is rebuilt from that state.
"""

import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import numpy as np

from siconos_lines import LineLeft, Rope, Spring  # noqa: E402  (springs and ropes)
from siconos_impacts import newton_impact  # noqa: E402  (where Siconos fails after an impact)

try:
    import siconos.kernel as sk
except ImportError:  # pragma: no cover
    print('(:status :error :message "siconos is not importable by this python")')
    sys.exit(0)

TOL = 1e-8          # gap / speed tolerance (lengths and speeds are O(1) in the models)
MAX_EVENTS = 200000  # nonsmooth events in one segment (micro-rebounds of resting contacts with e = 1 too)
LOOK_AHEAD = 1e-6   # seconds: which way a body at the end of a face is moving   # Zeno sequences end well before this


def sx_number(x):
    if x == 0:
        return "0.0d0"
    return repr(float(x)).replace("e", "d") if "e" in repr(float(x)) else repr(float(x)) + "d0"


def sx_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def sx_vec(v):
    return "(%s %s)" % (sx_number(v[0]), sx_number(v[1]))


class Body:
    def __init__(self, spec):
        self.name = spec["name"]
        self.mass = float(spec["mass"])
        self.q = np.array(spec["q"], dtype=float)
        self.v = np.array(spec["v"], dtype=float)
        self.force = np.array(spec.get("force", [0.0, 0.0]), dtype=float)
        drag = spec.get("drag") or {}
        self.linear_drag = float(drag.get("linear", 0.0))        # F = -b v
        self.quadratic_drag = float(drag.get("quadratic", 0.0))  # F = -c |v| v
        shape = spec["shape"]
        self.kind = shape["kind"]
        self.r = float(shape.get("r", 0.0))
        self.vertices = [np.array(p, dtype=float) for p in shape.get("vertices", [])]

    def support(self, n):
        """The point of the shape (own frame) furthest along -n."""
        if self.kind == "point":
            return np.zeros(2)
        if self.kind == "circle":
            return -self.r * n
        return min(self.vertices, key=lambda p: float(np.dot(n, p)))

    def extent(self, t):
        """The interval of the shape's projection on the unit vector t (own frame)."""
        if self.kind == "polygon":
            values = [float(np.dot(t, p)) for p in self.vertices]
            return min(values), max(values)
        return 0.0, 0.0

    def faces(self):
        if self.kind != "polygon":
            return []
        k = len(self.vertices)
        return [(self.vertices[i], self.vertices[(i + 1) % k]) for i in range(k)]


class Contact:
    """A face of OWNER (an index of a free body, or None for a fixed obstacle) against the
    support point of the free body OTHER."""

    def __init__(self, owner, owner_name, other, a, b, infinite, bodies):
        self.owner, self.owner_name, self.other = owner, owner_name, other
        d = b - a
        length = float(np.linalg.norm(d))
        self.t = d / length
        self.n = np.array([self.t[1], -self.t[0]])   # outward: the solid is on the left
        self.a, self.b, self.infinite = a, b, infinite
        body = bodies[other]
        self.s = body.support(self.n)
        self.lo, self.hi = body.extent(self.t)

    kinds = {"close": ":collision", "open": ":lift-off"}

    def row(self, n):
        h = np.zeros(2 * n)
        h[2 * self.other:2 * self.other + 2] += self.n
        if self.owner is not None:
            h[2 * self.owner:2 * self.owner + 2] -= self.n
        return h

    def constant(self):
        return self.offset()

    def restitution(self, model, bodies):
        return restitution(model, bodies[self.other].name, self.owner_name)

    def names(self, bodies):
        return (bodies[self.other].name, self.owner_name)

    def check(self, qs):
        pass

    def key(self):
        return (self.owner, self.other, round(float(self.n[0]), 12), round(float(self.n[1]), 12),
                round(self.offset(), 12))

    def offset(self):
        return float(np.dot(self.n, self.s) - np.dot(self.n, self.a))

    def owner_q(self, qs):
        return qs[self.owner] if self.owner is not None else np.zeros(2)

    def owner_v(self, vs):
        return vs[self.owner] if self.owner is not None else np.zeros(2)

    def gap(self, qs):
        return float(np.dot(self.n, qs[self.other] - self.owner_q(qs))) + self.offset()

    def rate(self, vs):
        return float(np.dot(self.n, vs[self.other] - self.owner_v(vs)))

    def margins(self, qs):
        """Both margins of the extent overlap (positive inside)."""
        if self.infinite:
            return (1.0, 1.0)
        rel = qs[self.other] - self.owner_q(qs)
        tb = float(np.dot(self.t, rel))
        return (tb + self.hi - float(np.dot(self.t, self.a)),
                float(np.dot(self.t, self.b)) - (tb + self.lo))

    def covers(self, qs):
        return min(self.margins(qs)) >= -1e-10

    def active(self, qs, vs):
        """Whether the contact belongs to a model started at (QS, VS): the face covers the
        body a moment later (LOOK_AHEAD, so that a body at the end of a face and moving off
        it is not held), and the body is not behind the face."""
        ahead = [q + LOOK_AHEAD * v for q, v in zip(qs, vs)]
        return self.covers(ahead) and self.gap(qs) >= -1e-6


def pair_names(contact, bodies):
    return contact.names(bodies)


def make_contacts(model, bodies, curved=False):
    """The faces' contacts; two round bodies are refused unless CURVED (siconos_arcs.py
    makes their contact)."""
    contacts, seen = [], set()
    for obstacle in model.get("obstacles", []):
        for face in obstacle["faces"]:
            for j in range(len(bodies)):
                contacts.append(Contact(None, obstacle["name"], j, np.array(face["a"], float),
                                        np.array(face["b"], float), face.get("infinite", False),
                                        bodies))
    for i, owner in enumerate(bodies):
        for a, b in owner.faces():
            for j, other in enumerate(bodies):
                if i == j:
                    continue
                c = Contact(i, owner.name, j, a, b, False, bodies)
                # the same gap seen from the other body's face (two parallel faces)
                mirror = (j, i, round(-float(c.n[0]), 12), round(-float(c.n[1]), 12),
                          round(c.offset(), 12))
                if mirror in seen:
                    continue
                seen.add(c.key())
                contacts.append(c)
    for i, x in enumerate(bodies):
        for j, y in enumerate(bodies):
            if i < j and x.kind != "polygon" and y.kind != "polygon" and not curved:
                if not (x.kind == "point" and y.kind == "point"):
                    raise Unsupported("contacts between %s and %s (discs) are not linear" %
                                      (x.name, y.name))
    return contacts


class Unsupported(Exception):
    pass


def restitution(model, a, b):
    for x, y, e in model.get("restitution", []):
        if {x, y} == {a, b}:
            return float(e)
    return float(model.get("default_restitution", 0.0))


def onto_contacts(active, qs):
    """QS with each body that round-off put slightly behind an ACTIVE contact (its gap in
    [-1e-6, 0)) moved onto it along the gap's gradient: Siconos's event-driven scheme
    refuses to start with a gap below -2.2e-12 (its _TOL_ED)."""
    qs = [np.array(q, dtype=float) for q in qs]
    for c in active:
        if hasattr(c, "other"):
            gap = c.gap(qs)
            if -1e-6 <= gap < 0.0:
                n = c.normal(qs) if hasattr(c, "normal") else c.n
                qs[c.other] = qs[c.other] - gap * n
    return qs


def hermite(t0, q0, v0, t1, q1, v1, t):
    h = t1 - t0
    if h <= 0:
        return q0.copy(), v0.copy()
    s = (t - t0) / h
    h00, h10, h01, h11 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s, -2 * s**3 + 3 * s**2, s**3 - s**2
    d00, d10, d01, d11 = 6 * s**2 - 6 * s, 3 * s**2 - 4 * s + 1, -6 * s**2 + 6 * s, 3 * s**2 - 2 * s
    q = h00 * q0 + h10 * h * v0 + h01 * q1 + h11 * h * v1
    v = (d00 * q0 + d10 * h * v0 + d01 * q1 + d11 * h * v1) / h
    return q, v



def lagrangian_system(model, bodies, t0, t_end, qs, vs, springs):
    """The bodies as one linear Lagrangian system (masses, gravity and constant forces,
    springs that keep their line) in a new NonSmoothDynamicalSystem over [t0, t_end]:
    returns (nsds, ds)."""
    g = float(model.get("gravity", 0.0))
    n = len(bodies)
    nsds = sk.NonSmoothDynamicalSystem(t0, t_end)
    mass, force = np.zeros((2 * n, 2 * n)), np.zeros(2 * n)
    for k, body in enumerate(bodies):
        mass[2 * k, 2 * k] = mass[2 * k + 1, 2 * k + 1] = body.mass
        force[2 * k:2 * k + 2] = [body.force[0], body.force[1] - body.mass * g]
    stiffness = np.zeros((2 * n, 2 * n))
    for spring in springs:
        spring.add_to(stiffness, force)
    ds = sk.LagrangianLinearTIDS(list(np.concatenate(qs)), list(np.concatenate(vs)),
                                 mass, stiffness, np.zeros((2 * n, 2 * n)))
    ds.setFExtPtr(force)
    nsds.insertDynamicalSystem(ds)
    return nsds, ds

class Segment:
    """One Siconos model, from a state, with a fixed set of active contacts: one Lagrangian
    linear time-invariant system holding every free body (so that springs can couple them),
    M q'' + K q = F, and one LagrangianLinearTIR (Newton's law) per contact."""

    def __init__(self, model, bodies, contacts, t0, qs, vs, t_end, dt, springs, resting=()):
        self.bodies, self.contacts = bodies, contacts
        n = len(bodies)
        nsds, self.ds = lagrangian_system(model, bodies, t0, t_end, qs, vs, springs)
        for c in contacts:
            rel = sk.LagrangianLinearTIR(np.array([c.row(n)]), np.array([c.constant()]))
            # a contact resting at the start gets e = 0: with no approach speed Newton's law
            # gives no rebound whatever e, and e = 1 would turn Siconos's round-off into an
            # endless chatter of micro-impacts (the segment ends when such a contact opens)
            e = 0.0 if c in resting else c.restitution(model, bodies)
            inter = sk.Interaction(sk.NewtonImpactNSL(e), rel)
            nsds.link(inter, self.ds)
        td = sk.TimeDiscretisation(t0, dt)
        self.sim = sk.EventDriven(nsds, td)
        osi = sk.LsodarOSI()
        self.sim.insertIntegrator(osi)
        self.sim.insertNonSmoothProblem(sk.LCP(), sk.SICONOS_OSNSP_ED_IMPACT)
        self.sim.insertNonSmoothProblem(sk.LCP(), sk.SICONOS_OSNSP_ED_SMOOTH_ACC)
        self.em = self.sim.eventsManager()
        self.n = n

    def state(self):
        q = np.array(self.ds.q(), dtype=float)
        v = np.array(self.ds.velocity(), dtype=float)
        return ([q[2 * k:2 * k + 2] for k in range(self.n)],
                [v[2 * k:2 * k + 2] for k in range(self.n)])


class Driver:
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

    def corner_held(self, c, active, qs, vs):
        """Whether the face of C, not active, holds its body all the same: the body sits
        at the very end of C's face, touching it and approaching it, while touching and
        approaching another face (ACTIVE) that will stop its motion along that face's
        normal (a particle landing exactly in the corner of a floor and a step): its
        look-ahead is taken with the velocity those faces leave it."""
        if not hasattr(c, "other") or not c.covers(qs) or abs(c.gap(qs)) > 1e-7 \
                or c.rate(vs) >= -1e-9:
            return False
        v = vs[c.other].copy()
        stoppers = [d for d in active if getattr(d, "other", None) == c.other
                    and getattr(d, "owner", None) is None and abs(d.gap(qs)) <= 1e-7
                    and d.rate(vs) < -1e-9]
        if not stoppers:
            return False
        for d in stoppers:
            v = v - min(0.0, float(np.dot(v, d.n))) * d.n
        ahead = list(qs)
        ahead[c.other] = qs[c.other] + LOOK_AHEAD * v
        return c.covers(ahead)

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
                self.impacted, self.impact_time = closed, t1
                self.in_contact = {c for c in active if self.touching(c, q1, after)}
                return t1, q1, after
            q2, v2 = seg.state()
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

    def extent_change(self, active, inactive, t0, q0, v0, t1, q1, v1):
        """The earliest time in (t0, t1] where an active contact's face stops covering its
        body, or an inactive one starts to (in front of it): (TIME Q V LEFT) or None."""
        best = None
        for c in active:
            if not c.covers(q1):
                best = self.earliest(best, c, t0, q0, v0, t1, q1, v1, True)
        for c in inactive:
            # entering a face's extent in front of it (judged where it enters: by the end
            # of the step the body may already be below the face's line, about to hit it)
            if c.covers(q1) and not c.covers(q0):
                tc = self.crossing(c, t0, q0, v0, t1, q1, v1)
                qc, _ = hermite(t0, np.array(q0), np.array(v0), t1, np.array(q1), np.array(v1), tc)
                if c.gap(list(qc)) >= -1e-6:
                    best = self.earliest(best, c, t0, q0, v0, t1, q1, v1, False)
        if best is None:
            return None
        tc = best[0]
        qc, vc = hermite(t0, np.array(q0), np.array(v0), t1, np.array(q1), np.array(v1), tc)
        qc = [np.array(x) for x in qc]
        vc = [np.array(x) for x in vc]
        left = [c for c in active if c.covers(q0) and not c.covers(q1)
                and abs(self.crossing(c, t0, q0, v0, t1, q1, v1) - tc) <= 1e-9]
        return tc, qc, vc, left

    def crossing(self, c, t0, q0, v0, t1, q1, v1):
        Q0, V0, Q1, V1 = np.array(q0), np.array(v0), np.array(q1), np.array(v1)
        inside0 = c.covers(q0)
        lo, hi = t0, t1
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            qm, _ = hermite(t0, Q0, V0, t1, Q1, V1, mid)
            m = min(c.margins(list(qm)))
            if (m >= 0) == inside0:
                lo = mid
            else:
                hi = mid
            if hi - lo <= 1e-15 * max(1.0, abs(hi)):
                break
        return 0.5 * (lo + hi)

    def earliest(self, best, c, t0, q0, v0, t1, q1, v1, leaving):
        tc = self.crossing(c, t0, q0, v0, t1, q1, v1)
        if best is None or tc < best[0]:
            return (tc, c)
        return best


def sx_states(names, qs, key):
    return "(" + " ".join("(%s %s)" % (sx_string(n), sx_vec(q)) for n, q in zip(names, qs)) + ")"


def main():
    text = open(sys.argv[1]).read() if len(sys.argv) > 1 else sys.stdin.read()
    simulate(json.loads(text))


def simulate(model):
    """Simulate MODEL (a decoded model description) and print the s-expression answer."""
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
    except Unsupported as e:
        print("(:status :unsupported :message %s)" % sx_string(str(e)))
        return
    except Exception as e:  # the witness failed: say so, never a result
        print("(:status :error :message %s)" % sx_string("%s: %s" % (type(e).__name__, e)))
        return
    names = [b.name for b in driver.bodies]
    out = ["(:status :ok", " :scheme :%s" % getattr(driver, "scheme", "event-driven"), " :events ("]
    for ev in driver.events:
        pairs = " ".join("(%s %s %s)" % (p[0], sx_string(p[1]), sx_string(p[2]))
                         for p in ev["pairs"])
        out.append("  (:time %s :speed %s :pairs (%s) :positions %s :velocities %s :after %s)" % (
            sx_number(ev["time"]), sx_number(ev["speed"]), pairs, sx_states(names, ev["q"], 0),
            sx_states(names, ev["v"], 0), sx_states(names, ev["after"], 0)))
    out.append(" )")
    if driver.truncated:
        out.append(" :truncated %s" % sx_string(driver.truncated))
    if getattr(driver, "samples", None):
        out.append(" :samples (%s)" % " ".join(
            "(:time %s :positions %s :velocities %s)" % (
                sx_number(s["time"]), sx_states(names, s["q"], 0), sx_states(names, s["v"], 0))
            for s in driver.samples))
    out.append(" :end (:time %s :positions %s :velocities %s))" % (
        sx_number(t), sx_states(names, qs, 0), sx_states(names, vs, 0)))
    print("\n".join(out))


if __name__ == "__main__":
    main()
