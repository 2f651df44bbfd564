"""siconos_arcs.py -- the witness for arcs, circles, universal gravitation and bumpers.

The event-driven driver (siconos_driver.Driver) with what is not linear in the positions:

- a point or disc against a fixed arc or circle (inside a loop or bowl, on a dome or a
  planet), or two free discs (or a disc and a point) against each other: each contact's gap
  is a distance to a centre, +(|p - c| - R) outside the circle or -(|p - c| - R) inside
  it, a LagrangianScleronomousR written here (h, its Jacobian and the Jacobian's time
  derivative, which Siconos's acceleration-level LCP needs), with Newton's law; an arc's
  angular extent is handled like a face's extent (the particle leaving a quarter circle at
  its end :leaves it);
- universal gravitation between every two bodies with mass (free, or fixed attractors),
  and drag (linear -b v, quadratic -c |v| v, per body): the bodies are one LagrangianDS
  whose internal force FInt(q, v) is computed here;
- bumpers: a spring with a free end that only pushes. A body whose support point along
  -u reaches the free end (P + L0 u) starts pressing it, (:contact BODY BUMPER); from
  then on the bumper is a linear spring on that point, k (L0 - u.(x - P)) u, until its
  compression returns to zero, (:leaves BODY BUMPER). Both times are found on the cubic
  Hermite interpolant of two output steps (exact before the contact, where the force is
  constant; the step is STEP while springs act).

Besides the events of the driver it reports (:turns BODY BODY) where a body's velocity
passes through zero and reverses (a turning point of one-degree-of-freedom motion), and
the states at the times the model asks for ("samples"), so that a state that lasts
forever can be compared at a few times.

The dynamical system of gravitation and drag and the bumpers are in siconos_forces.py.

Lsodar finds a lift-off from an arc as a root of the contact force, computed by the
acceleration-level LCP: to about 1e-7 relative (the comparator's *CURVED-TOLERANCE*).
"""

import math

import numpy as np
import siconos.kernel as sk

from siconos_driver import Contact, Driver, Segment, Unsupported, hermite, lagrangian_system, make_contacts, \
    restitution
from siconos_forces import Bumper, GravitationDS, nonlinear_forces_p, split

STEP = 0.002        # the output step (s): turning points and bumpers are found on it


class CircleContact:
    """The free body OTHER against a circle: a fixed arc (OWNER None, CENTRE in the world)
    or a free disc OWNER (its centre its position). INSIDE: the body moves inside the
    circle (a loop, a bowl). RANGE: the arc's angles (from, to), or None for a whole
    circle. The gap's rate and normal depend on the positions: RATE uses those of the last
    GAP (the driver always asks for the gap first)."""

    kinds = {"close": ":collision", "open": ":lift-off"}

    def __init__(self, owner, owner_name, other, centre, radius, inside, angles, bodies):
        self.owner, self.owner_name, self.other = owner, owner_name, other
        self.centre = np.array(centre, dtype=float)
        self.inside = inside
        self.sign = -1.0 if inside else 1.0
        rb = bodies[other].r
        self.radius = radius - rb if inside else radius + rb
        self.angles = angles
        self.n_bodies = len(bodies)
        self.last_q = None

    def rel(self, qs):
        owner = qs[self.owner] if self.owner is not None else np.zeros(2)
        return qs[self.other] - owner - self.centre

    def normal(self, qs):
        p = self.rel(qs)
        return self.sign * p / float(np.linalg.norm(p))

    def gap(self, qs):
        self.last_q = [np.array(q) for q in qs]
        return self.sign * (float(np.linalg.norm(self.rel(qs))) - self.radius)

    def rate(self, vs):
        n = self.normal(self.last_q)
        owner = vs[self.owner] if self.owner is not None else np.zeros(2)
        return float(np.dot(n, vs[self.other] - owner))

    def margins(self, qs):
        if self.angles is None:
            return (1.0, 1.0)
        a1, a2 = self.angles
        mid = 0.5 * (a1 + a2)
        p = self.rel(qs)
        angle = mid + math.remainder(math.atan2(p[1], p[0]) - mid, 2 * math.pi)
        return (self.radius * (angle - a1), self.radius * (a2 - angle))

    def covers(self, qs):
        return min(self.margins(qs)) >= -1e-10

    def active(self, qs, vs):
        ahead = [q + 1e-6 * v for q, v in zip(qs, vs)]
        return self.covers(ahead) and self.gap(qs) >= -1e-6

    def restitution(self, model, bodies):
        return restitution(model, bodies[self.other].name, self.owner_name)

    def names(self, bodies):
        return (bodies[self.other].name, self.owner_name)

    def key(self):
        return ("circle", self.owner, self.other, tuple(self.centre), self.radius, self.inside)

    def check(self, qs):
        pass

    def rows(self, q, qdot):
        """The Jacobian of the gap and its time derivative, as rows over every coordinate."""
        qs, vs = split(q, self.n_bodies), split(qdot, self.n_bodies)
        p = self.rel(qs)
        d = float(np.linalg.norm(p))
        n = p / d
        owner_v = vs[self.owner] if self.owner is not None else np.zeros(2)
        pdot = vs[self.other] - owner_v
        ndot = (pdot - n * float(np.dot(n, pdot))) / d
        jac, djac = np.zeros(2 * self.n_bodies), np.zeros(2 * self.n_bodies)
        for index, sign in ((self.other, 1.0), (self.owner, -1.0)):
            if index is not None:
                jac[2 * index:2 * index + 2] += self.sign * sign * n
                djac[2 * index:2 * index + 2] += self.sign * sign * ndot
        return jac, djac

    def relation(self):
        return CircleRelation(self)


class CircleRelation(sk.LagrangianScleronomousR):
    """A CircleContact's gap as a Siconos relation: h(q), its Jacobian and the Jacobian's
    derivative (computed in CONTACT.rows)."""

    def __init__(self, contact):
        sk.LagrangianScleronomousR.__init__(self)
        self.contact = contact
        self.n = contact.n_bodies
        self.setJachqPtr(np.zeros((1, 2 * self.n)))
        self.qdot = np.zeros(2 * self.n)

    def computeh(self, q, z, y):
        c = self.contact
        qs = split(q, self.n)
        y[0] = c.sign * (float(np.linalg.norm(c.rel(qs))) - c.radius)

    def computeJachq(self, q, z):
        jac, _ = self.contact.rows(q, self.qdot)
        self.jachq()[0, :] = jac

    def computeDotJachq(self, q, z, qdot):
        self.qdot = np.array(qdot, dtype=float)
        _, djac = self.contact.rows(q, self.qdot)
        self.dotJachq()[0, :] = djac


class ArcSegment(Segment):
    """A Segment whose contacts may be CircleContacts and whose bodies may attract each
    other (GravitationDS)."""

    def __init__(self, model, bodies, contacts, t0, qs, vs, t_end, dt, springs, resting=()):
        self.bodies, self.contacts = bodies, contacts
        n = len(bodies)
        self.n = n
        nsds, linear = lagrangian_system(model, bodies, t0, t_end, qs, vs, springs)
        self.ds = linear
        if nonlinear_forces_p(model):
            nsds = sk.NonSmoothDynamicalSystem(t0, t_end)
            attractors = [(np.array(a["q"], dtype=float), float(a["mass"]))
                          for a in model.get("attractors", [])]
            self.ds = GravitationDS(list(np.concatenate(qs)), list(np.concatenate(vs)),
                                    np.array(linear.mass(), dtype=float), np.array(linear.K(), dtype=float),
                                    [b.mass for b in bodies], float(model.get("gravitation") or 0.0),
                                    attractors, [b.linear_drag for b in bodies],
                                    [b.quadratic_drag for b in bodies])
            self.ds.setFExtPtr(np.array(linear.fExt(), dtype=float))
            nsds.insertDynamicalSystem(self.ds)
        self.relations = []
        for c in contacts:
            if hasattr(c, "relation"):
                rel = c.relation()
            else:
                rel = sk.LagrangianLinearTIR(np.array([c.row(n)]), np.array([c.constant()]))
            self.relations.append(rel)   # the Python relations must outlive the segment
            e = 0.0 if c in resting else c.restitution(model, bodies)
            nsds.link(sk.Interaction(sk.NewtonImpactNSL(e), rel), self.ds)
        self.sim = sk.EventDriven(nsds, sk.TimeDiscretisation(t0, dt))
        self.sim.insertIntegrator(sk.LsodarOSI())
        self.sim.insertNonSmoothProblem(sk.LCP(), sk.SICONOS_OSNSP_ED_IMPACT)
        self.sim.insertNonSmoothProblem(sk.LCP(), sk.SICONOS_OSNSP_ED_SMOOTH_ACC)
        self.em = self.sim.eventsManager()
        self.nsds = nsds


def arc_contacts(model, bodies):
    """The CircleContacts: every free body against every fixed arc, and every two free
    bodies that are not polygons (discs, or a disc and a point)."""
    contacts = []
    for obstacle in model.get("obstacles", []):
        for arc in obstacle.get("arcs", []):
            angles = None if arc.get("whole") else (float(arc["from"]), float(arc["to"]))
            for j, body in enumerate(bodies):
                if body.kind == "polygon":
                    raise Unsupported("a polygon against an arc")
                contacts.append(CircleContact(None, obstacle["name"], j, arc["center"],
                                              float(arc["radius"]), arc["solid"] == "outside",
                                              angles, bodies))
    for i, x in enumerate(bodies):
        for j, y in enumerate(bodies):
            if i < j and "polygon" not in (x.kind, y.kind) and (x.kind, y.kind) != ("point", "point"):
                rx = x.r
                contacts.append(CircleContact(i, x.name, j, [0.0, 0.0], rx, False, None, bodies))
    return contacts


def curved_model_p(model):
    """Whether MODEL needs this driver: arcs, gravitation, drag, bumpers or two round bodies."""
    round_bodies = [b for b in model.get("bodies", []) if b["shape"]["kind"] == "circle"]
    return bool(any(o.get("arcs") for o in model.get("obstacles", [])) or nonlinear_forces_p(model)
                or model.get("bumpers") or len(round_bodies) >= 2 or
                (round_bodies and len(model.get("bodies", [])) >= 2 and
                 any(b["shape"]["kind"] == "point" for b in model["bodies"])))


class ArcDriver(Driver):
    """The event-driven driver with circle contacts, gravitation, bumpers, turning points
    and samples (see the module)."""

    segment_class = ArcSegment

    def __init__(self, model):
        if model.get("friction"):
            raise Unsupported("friction together with arcs, gravitation or bumpers")
        Driver.__init__(self, model)
        self.base_springs = list(self.springs)
        self.bumpers = [Bumper(spec, self.bodies) for spec in model.get("bumpers", [])]
        qs = [b.q.copy() for b in self.bodies]
        for bumper in self.bumpers:
            for j in range(len(self.bodies)):
                if bumper.gap(j, qs) < -1e-12:
                    bumper.engaged.add(j)
        self.dt = min(self.dt, STEP)
        self.scheme = "curved" if any(isinstance(c, CircleContact) for c in self.contacts) \
            else "event-driven"
        self.sample_times = sorted(float(t) for t in model.get("samples", []))
        self.samples = []

    def make_contacts(self, model):
        return make_contacts(model, self.bodies, curved=True) + arc_contacts(model, self.bodies)

    def segment(self, t0, qs, vs):
        self.segment_start = t0
        self.springs = self.base_springs + self.bumpers
        if nonlinear_forces_p(self.model):
            vs = self.settled(qs, vs)
        return Driver.segment(self, t0, qs, vs)

    def settled(self, qs, vs):
        """VS with the normal speed of each body touching a fixed face or arc (gap and speed
        under 1e-7: the end of a Zeno sequence of impacts) set to 0. Under gravitation or
        drag Siconos 4.4 fails on an impact with no approach speed to speak of (an
        std::exception in processEvents), and IMPACT (above) applies only those with one;
        a model that starts with the contact closed runs."""
        vs = [np.array(v, dtype=float) for v in vs]
        for c in self.contacts:
            if getattr(c, "owner", 0) is None and abs(c.gap(qs)) <= 1e-7:
                rate = c.rate(vs)
                if 0.0 < abs(rate) <= 1e-7:
                    n = c.normal(qs) if isinstance(c, CircleContact) else c.n
                    vs[c.other] = vs[c.other] - rate * n
        return vs

    def extent_change(self, active, inactive, t0, q0, v0, t1, q1, v1):
        change = Driver.extent_change(self, active, inactive, t0, q0, v0, t1, q1, v1)
        bumped = self.bumper_change(t0, q0, v0, t1, q1, v1)
        if bumped is not None and (change is None or bumped[0] < change[0] - 1e-12):
            tc, bumper, j, engage = bumped
            qc, vc = self.interpolate(t0, q0, v0, t1, q1, v1, tc)
            self.observe(t0, q0, v0, t1, q1, v1, tc)
            kind = ":contact" if engage else ":leaves"
            self.record(tc, [(kind, self.bodies[j].name, bumper.name)], qc, vc, vc)
            (bumper.engaged.add if engage else bumper.engaged.discard)(j)
            return tc, qc, vc, []
        self.observe(t0, q0, v0, t1, q1, v1, change[0] if change else t1)
        if change is None and nonlinear_forces_p(self.model):
            return self.impact(active, t1, q1, v1)
        return change

    def impact(self, active, t, qs, vs):
        """Under gravitation or drag, Siconos 4.4's impact with e = 0 fails (an
        std::exception in processEvents when the forces depend on the state; a model that
        starts with the contact closed runs): the impact of a contact (on a circle or a
        face) closing at T is applied here by Newton's law, and the next model starts just
        after it. None when no such contact closes at T."""
        closing = [c for c in active if isinstance(c, (CircleContact, Contact))
                   and abs(c.gap(qs)) <= 1e-7 and c.rate(vs) < -1e-9]
        if not closing:
            return None
        if len(closing) > 1:
            raise Unsupported("several contacts closing at once under gravitation or drag")
        c = closing[0]
        n = len(self.bodies)
        if isinstance(c, CircleContact):
            jac, _ = c.rows(np.concatenate(qs), np.concatenate(vs))
        else:
            jac = c.row(n)
        inverse_mass = np.array([1.0 / b.mass for b in self.bodies for _ in (0, 1)])
        rate = float(np.dot(jac, np.concatenate(vs)))
        e = c.restitution(self.model, self.bodies)
        impulse = -(1.0 + e) * rate / float(np.dot(jac * inverse_mass, jac))
        after = split(np.concatenate(vs) + inverse_mass * jac * impulse, n)
        self.record(t, [(":collision",) + c.names(self.bodies)], qs, vs, after, -rate)
        return t, [np.array(q) for q in qs], after, []

    def lift_offs(self, opened, tp, vs):
        """As the driver's, but a contact that an impact at TP left closed with no approach
        speed and that the forces open at once (a block thrown back by the bumper it
        pressed against the wall) never held: no lift-off, the impact is its end."""
        last = self.events[-1] if self.events else None
        smooth = self.smooth_event
        if opened and last and abs(last["time"] - tp) <= 1e-9 and \
                any(p[0] == ":collision" for p in last["pairs"]) and \
                not (smooth and smooth[0] >= tp - 1e-12):
            return
        # leaving a circle tangentially, the gap grows as tau^3: the contact may look
        # closed (gap and rate under 1e-7) for some steps after Siconos's lift-off event
        # (the root of the contact force), which is the lift-off
        if opened and tp > 0 and smooth and smooth[0] < tp - 1e-12 and \
                smooth[0] > max(self.segment_start, last["time"] if last else 0.0) and \
                any(isinstance(c, CircleContact) for c in opened):
            t, q, v = smooth
            self.record(t, [(c.kinds["open"],) + c.names(self.bodies) for c in opened], q, v, v)
            return
        Driver.lift_offs(self, opened, tp, vs)

    def interpolate(self, t0, q0, v0, t1, q1, v1, t):
        q, v = hermite(t0, np.array(q0), np.array(v0), t1, np.array(q1), np.array(v1), t)
        return [np.array(x) for x in q], [np.array(x) for x in v]

    def bumper_change(self, t0, q0, v0, t1, q1, v1):
        """The earliest bumper engaged or released in (t0, t1]: (TIME BUMPER BODY ENGAGE)."""
        best = None
        for bumper in self.bumpers:
            for j in range(len(self.bodies)):
                g0, g1 = bumper.gap(j, q0), bumper.gap(j, q1)
                engaged = j in bumper.engaged
                # engaged: the gap falls from above 0 to 0 or below; released: it rises
                # from below 0 to 0 or above (a rebuild at a crossing leaves it ~0)
                if (not engaged and g0 > 1e-12 and g1 <= 1e-12) or \
                        (engaged and g0 < -1e-12 and g1 >= -1e-12):
                    tc = self.root(lambda qs: bumper.gap(j, qs), t0, q0, v0, t1, q1, v1)
                    if best is None or tc < best[0]:
                        best = (tc, bumper, j, not engaged)
        return best

    def root(self, f, t0, q0, v0, t1, q1, v1):
        """Where F (of the positions) changes sign on the Hermite interpolant in (t0, t1]."""
        lo, hi = t0, t1
        f_lo = f(q0)
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            qm, _ = self.interpolate(t0, q0, v0, t1, q1, v1, mid)
            if (f(qm) > 0) == (f_lo > 0) and f(qm) != 0:
                lo = mid
            else:
                hi = mid
            if hi - lo <= 1e-15 * max(1.0, abs(hi)):
                break
        return 0.5 * (lo + hi)

    def observe(self, t0, q0, v0, t1, q1, v1, until):
        """The turning points and the samples in (t0, until]."""
        while self.sample_times and self.sample_times[0] <= until:
            ts = self.sample_times.pop(0)
            if ts >= t0:
                qs, vs = self.interpolate(t0, q0, v0, t1, q1, v1, ts)
                self.samples.append({"time": ts, "q": qs, "v": vs})
        for k, body in enumerate(self.bodies):
            if float(np.dot(v0[k], v1[k])) >= 0:
                continue
            speed = max(1.0, float(np.linalg.norm(v0[k])), float(np.linalg.norm(v1[k])))
            tm = self.slowest(k, t0, q0, v0, t1, q1, v1)
            qm, vm = self.interpolate(t0, q0, v0, t1, q1, v1, tm)
            if tm <= until and float(np.linalg.norm(vm[k])) <= 1e-5 * speed:
                self.record(tm, [(":turns", body.name, body.name)], qm, vm, vm)

    def slowest(self, k, t0, q0, v0, t1, q1, v1):
        """Where body K's speed is least in [t0, t1] (golden section on the interpolant)."""
        def speed(t):
            return float(np.linalg.norm(self.interpolate(t0, q0, v0, t1, q1, v1, t)[1][k]))
        a, b = t0, t1
        ratio = (math.sqrt(5) - 1) / 2
        for _ in range(200):
            c, d = b - ratio * (b - a), a + ratio * (b - a)
            if speed(c) < speed(d):
                b = d
            else:
                a = c
            if b - a <= 1e-15 * max(1.0, abs(b)):
                break
        return 0.5 * (a + b)
