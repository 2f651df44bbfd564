"""siconos_rotation.py -- the witness for models with rotating bodies (issue 23).

A body with an "inertia" (about its centre of mass, its reference point) is a Lagrangian
system with three degrees of freedom (x, y, theta): mass matrix diag(m, m, I), gravity
and constant forces at the centre of mass. The whole model is one LagrangianLinearTIDS
(3 coordinates per free body; a body without inertia keeps theta = 0: its row of the
mass matrix is 1 and nothing acts on it). Every relation is written as Siconos's
LagrangianLinearTIR y = C q + e, and the relations whose gap depends on theta (a vertex
of a turning polygon on a face, a hinge) are linearised again at the start of every step
(C the Jacobian of the gap at q_k, e = h(q_k) - C q_k): this is what Moreau-Jean's scheme
does with a non-linear relation (it uses the Jacobian at q_k and the gap predicted from
q_k), done here because Siconos 4.4's Python relations with non-linear h crash (a
segmentation fault in LagrangianScleronomousR's director), and the one-step problem is
told to assemble its matrix again (setHasBeenUpdated(False)).

The scheme is Moreau-Jean time stepping (MoreauJeanOSI, theta 1/2) with the fixed step
STEP (the model's "step" may set another): first order, so results are compared with
closed forms to a tolerance of order STEP (a few STEP relative for times and speeds;
the tests say which). The one-step problem is an MLCP (unilateral contacts with Newton's
law, hinges as EqualityConditionNSL), or a 2-D FrictionContact problem when the model
has friction (hinges with friction are refused: Siconos's GenericMechanical problem is
three-dimensional).

Relations (world frame, n the outward normal of a face, t its direction a -> b):
  - a vertex p (own frame) of a free polygon or segment against a fixed face:
      gap = n . (x + R(theta) p - a); rows [n, n . (k x R p)] and, with friction,
      [t, t . (k x R p)];
  - a free disc of radius r against a fixed face: gap = n . (x - a) - r; rows [n, 0],
      [t, t . (k x (-r n))] = [t, -r] (rolling is the tangential speed 0);
  - a free point against a fixed face (a particle): gap = n . (x - a);
  - a hinge: the body's point p is the fixed point P: x + R(theta) p - P = 0 (2 rows);
  - a rope: as in siconos_lines (straight pieces that keep their directions), with an end
      "wound" on a body's circle of radius |p| about its centre: that end is the tangent
      point T = x + d (d fixed in the world while the rope keeps its direction) on the side
      of the body's point p, and the body turning pays the rope out at the rate
      omega (k x d) . u (u from T toward the previous point): the gap L - sum of the
      pieces gains (k x d) . u (theta - theta0).
A finite face holds a vertex or disc only while the contact point lies within it (beyond
it, the relation's gap is set far open). Contacts between two free bodies are not
modelled (refused when both have an extent).

Events (besides those of the translating driver's format):
  :collision A B      an approach speed jumps (an impulse);
  :lift-off A B       a contact that pressed (impulse > 0) stops pressing: the time where
                      the normal force, extrapolated linearly from the last two steps that
                      pressed, reaches 0;
  :stops-sliding A B  a pressing contact's tangential speed reaches 0 (linear
                      interpolation inside the step); :starts-sliding the converse;
  :reaches BODY "angle"  a probe: BODY's angle crosses the model's probe value.
Each event and the end add :angles ((BODY THETA) ...) and :angular-velocities, and
:hinges ((NAME (FX FY)) ...) the hinges' reaction forces (impulse / STEP).
"""

import math

import numpy as np
import siconos.kernel as sk
import siconos.numerics as sn

STEP = 1e-3
GAP_TOL = 1e-6
SPEED_TOL = 1e-6
MARGIN = 1e-6     # a resting contact stays in the index set: its gap is seen this much closer
FAR = 1e3          # the gap given to a relation whose face does not cover its contact point
JUMP = 1e-2
QUIET = 20        # steps a contact stays open before its opening is a lift-off


class Unsupported(Exception):
    pass


def perp(d):
    """k x d: d turned a quarter counter-clockwise."""
    return np.array([-d[1], d[0]])


def rotation(theta):
    c, s = math.cos(theta), math.sin(theta)
    return np.array([[c, -s], [s, c]])


class Body:
    def __init__(self, spec, index):
        self.index, self.name = index, spec["name"]
        self.mass = float(spec["mass"])
        self.inertia = spec.get("inertia")
        self.rotating = self.inertia is not None
        self.inertia = float(self.inertia) if self.rotating else 1.0
        self.q = np.array(list(spec["q"]) + [float(spec.get("theta", 0.0))], dtype=float)
        self.v = np.array(list(spec["v"]) + [float(spec.get("omega", 0.0))], dtype=float)
        self.force = np.array(spec.get("force", [0.0, 0.0]), dtype=float)
        self.forces_at = [(np.array(f["point"], float), np.array(f["force"], float))
                          for f in spec.get("forces_at", [])]
        shape = spec["shape"]
        self.kind = shape["kind"]
        self.r = float(shape.get("r", 0.0))
        self.vertices = [np.array(p, dtype=float) for p in shape.get("vertices", [])]
        if not self.rotating and self.kind not in ("point", "circle", "polygon"):
            raise Unsupported("a translating body of shape %s" % self.kind)

    def dofs(self):
        return slice(3 * self.index, 3 * self.index + 3)


class Face:
    def __init__(self, spec, name):
        self.name = name
        self.a, self.b = np.array(spec["a"], float), np.array(spec["b"], float)
        d = self.b - self.a
        self.length = float(np.linalg.norm(d))
        self.t = d / self.length
        self.n = np.array([self.t[1], -self.t[0]])   # outward: the solid is on the left
        self.infinite = bool(spec.get("infinite", False))

    def covers(self, point):
        if self.infinite:
            return True
        s = float(np.dot(self.t, point - self.a))
        return -1e-9 <= s <= self.length + 1e-9


class Relation:
    """One Siconos interaction: rows C (over all coordinates) and constant e, refreshed
    from the state at every step by REFRESH."""

    friction = False
    equality = False

    def rows_at(self, q):
        raise NotImplementedError

    def make(self, q):
        C, e = self.rows_at(q)
        self.rel = sk.LagrangianLinearTIR(C, e)
        return self.rel

    def refresh(self, q):
        C, e = self.rows_at(q)
        # in place: the interaction keeps the matrices it was built with
        self.rel.jachq()[:, :] = C
        self.rel.e()[:] = e


class Contact(Relation):
    """A free body's vertex, disc or point against a fixed face."""

    def __init__(self, body, face, vertex, n_dofs, mu, e, q0):
        self.body, self.face, self.vertex = body, face, vertex
        self.n_dofs, self.mu, self.e = n_dofs, mu, e
        self.friction = mu is not None
        self.names = (body.name, face.name)
        self.front = False
        self.update_front(q0)

    def update_front(self, q):
        """Whether the face may hold the contact in the coming step: its point lies within
        the face's extent, and in front of the face (or it was already held: a contact
        in force may sink by round-off). A point behind a face's line (the body beside a
        convex obstacle, seen from a face that looks away) is never held by it."""
        point = self.point(q)
        if not self.face.covers(point):
            self.front = False
        elif self.gap(q) >= -GAP_TOL:
            self.front = True

    def offset(self, q):
        """The contact point's offset from the body's centre, world frame."""
        b = self.body
        if b.kind == "circle":
            return -b.r * self.face.n
        if self.vertex is None:
            return np.zeros(2)
        return rotation(q[3 * b.index + 2]).dot(self.vertex)

    def point(self, q):
        return q[3 * self.body.index:3 * self.body.index + 2] + self.offset(q)

    def gap(self, q):
        return float(np.dot(self.face.n, self.point(q) - self.face.a))

    def rows_at(self, q):
        d = self.offset(q)
        k = 2 if self.friction else 1
        C = np.zeros((k, self.n_dofs))
        i = 3 * self.body.index
        for row, u in enumerate([self.face.n, self.face.t][:k]):
            C[row, i:i + 2] = u
            C[row, i + 2] = float(np.dot(u, perp(d))) if self.body.rotating else 0.0
        gap = self.gap(q) if self.front else FAR
        e = np.zeros(k)
        e[0] = gap - float(C[0].dot(q)) - MARGIN
        return C, e

    def law(self):
        if self.friction:
            return sk.NewtonImpactFrictionNSL(self.e, 0.0, self.mu, 2)
        return sk.NewtonImpactNSL(self.e)

    def normal_speed(self, q, v):
        C, _ = self.rows_at(q)
        return float(C[0].dot(v))

    def tangential_speed(self, q, v):
        d = self.offset(q)
        i = 3 * self.body.index
        w = v[i + 2] if self.body.rotating else 0.0
        return float(np.dot(self.face.t, v[i:i + 2] + w * perp(d)))


class Hinge(Relation):
    equality = True

    def __init__(self, spec, bodies, n_dofs):
        self.name = spec["name"]
        self.body = bodies[spec["body"]]
        self.p = np.array(spec["offset"], float)
        self.at = np.array(spec["point"], float)
        self.n_dofs = n_dofs
        self.names = (self.name, self.name)

    def rows_at(self, q):
        i = 3 * self.body.index
        d = rotation(q[i + 2]).dot(self.p)
        C = np.zeros((2, self.n_dofs))
        C[0, i], C[1, i + 1] = 1.0, 1.0
        C[:, i + 2] = perp(d)
        h = q[i:i + 2] + d - self.at
        return C, h - C.dot(q)

    def law(self):
        return sk.EqualityConditionNSL(2)


class Rope(Relation):
    """A rope through points ({"body": I, "offset": [X, Y], "wound": BOOL} or {"point":
    [X, Y]}), straight pieces that keep their directions, unilateral (taut or slack)."""

    def __init__(self, spec, bodies, q0):
        self.name, self.length = spec["name"], float(spec["length"])
        self.points, self.bodies = spec["points"], bodies
        self.names = (self.name, self.name)
        self.n_dofs = 3 * len(bodies)
        self.e = 0.0
        # each end's world offset from its body's centre (a wound end: the tangent point)
        self.offsets = [None] * len(self.points)
        for j, p in enumerate(self.points):
            if p.get("body") is not None:
                theta = q0[3 * p["body"] + 2]
                self.offsets[j] = rotation(theta).dot(np.array(p["offset"], float))
        for j, p in enumerate(self.points):
            if p.get("wound"):
                i = j - 1 if j > 0 else 1
                self.offsets[j] = self.tangent(j, self.position(self.points[i], q0, i), q0)
        self.u = []
        for p, r in zip(self.points, self.points[1:]):
            d = self.position(r, q0) - self.position(p, q0)
            self.u.append(d / np.linalg.norm(d))
        self.theta0 = {}
        self.turn = {}
        for j, p in enumerate(self.points):
            if p.get("wound"):
                u = -self.u[j - 1] if j > 0 else self.u[0]   # from T toward its neighbour
                self.turn[j] = float(np.dot(perp(self.offsets[j]), u))
                self.theta0[j] = q0[3 * p["body"] + 2]

    def index_of(self, point):
        return self.points.index(point)

    def position(self, point, q, j=None):
        if point.get("body") is None:
            return np.array(point["point"], float)
        j = self.index_of(point) if j is None else j
        i = 3 * point["body"]
        return q[i:i + 2] + self.offsets[j]

    def tangent(self, j, towards, q0):
        """The tangent point (offset from the centre) of end J's circle, seen from the
        point TOWARDS, on the side of the end's own point."""
        p = self.points[j]
        i = 3 * p["body"]
        centre = q0[i:i + 2]
        own = self.offsets[j]
        radius = float(np.linalg.norm(own))
        w = towards - centre
        dist = float(np.linalg.norm(w))
        if dist <= radius:
            raise Unsupported("rope %s: its wound end's circle holds the rope's next point" % self.name)
        alpha = math.acos(radius / dist)
        base = math.atan2(w[1], w[0])
        candidates = [radius * np.array([math.cos(base + s * alpha), math.sin(base + s * alpha)])
                      for s in (1.0, -1.0)]
        return min(candidates, key=lambda c: float(np.linalg.norm(c - own)))

    def rows_at(self, q):
        C = np.zeros((1, self.n_dofs))
        m = len(self.u)
        const = self.length
        for j, p in enumerate(self.points):
            c = (self.u[j - 1] if j > 0 else 0.0) - (self.u[j] if j < m else 0.0)
            if p.get("body") is None:
                const -= float(np.dot(c, np.array(p["point"], float)))
            else:
                i = 3 * p["body"]
                C[0, i:i + 2] -= c
                const -= float(np.dot(c, self.offsets[j]))
            if j in self.turn:
                C[0, 3 * p["body"] + 2] += self.turn[j]
                const -= self.turn[j] * self.theta0[j]
        return C, np.array([const])

    def law(self):
        return sk.NewtonImpactNSL(0.0)

    def check(self, q):
        for k, (p, r) in enumerate(zip(self.points, self.points[1:])):
            d = self.position(r, q, k + 1) - self.position(p, q, k)
            u = self.u[k]
            if abs(d[0] * u[1] - d[1] * u[0]) > 1e-6 * max(1.0, float(np.linalg.norm(d))) or \
                    float(np.dot(d, u)) <= 0:
                raise RopeTurned("rope %s (piece %d) leaves its initial line" % (self.name, k))


class RopeTurned(Exception):
    pass


def friction_coefficient(model, a, b):
    for entry in model.get("friction", []):
        if {entry[0], entry[1]} == {a, b}:
            if len(entry) > 3 and abs(float(entry[3]) - float(entry[2])) > 0:
                raise Unsupported("Siconos's Coulomb law has one coefficient; the kinetic and "
                                  "static coefficients differ")
            return float(entry[2])
    return None


def restitution(model, a, b):
    for x, y, e in model.get("restitution", []):
        if {x, y} == {a, b}:
            return float(e)
    return float(model.get("default_restitution", 0.0))


class RotationDriver:
    scheme = "moreau-jean"

    def __init__(self, model):
        self.model = model
        self.bodies = [Body(b, k) for k, b in enumerate(model["bodies"])]
        self.n = 3 * len(self.bodies)
        self.step = float(model.get("step", STEP))
        self.t_end = float(model["t_end"])
        self.q0 = np.concatenate([b.q for b in self.bodies])
        self.v0 = np.concatenate([b.v for b in self.bodies])
        self.check_pairs()
        self.contacts = []
        for obstacle in model.get("obstacles", []):
            for spec in obstacle["faces"]:
                face = Face(spec, obstacle["name"])
                for b in self.bodies:
                    mu = friction_coefficient(model, b.name, face.name)
                    e = restitution(model, b.name, face.name)
                    vertices = b.vertices if b.kind in ("polygon", "segment") else [None]
                    for p in vertices:
                        self.contacts.append(Contact(b, face, p, self.n, mu, e, self.q0))
        self.hinges = [Hinge(h, self.bodies, self.n) for h in model.get("hinges", [])]
        self.ropes = [Rope(r, self.bodies, self.q0) for r in model.get("ropes", [])]
        self.has_friction = any(c.friction for c in self.contacts)
        if self.has_friction and self.hinges:
            raise Unsupported("a hinge together with friction (Siconos's GenericMechanical "
                              "problem is three-dimensional)")
        if self.has_friction and self.ropes:
            raise Unsupported("ropes together with friction")
        if model.get("springs"):
            raise Unsupported("springs on rotating bodies")
        self.probes = [(self.body_named(p["body"]), float(p["angle"]))
                       for p in model.get("probes", [])]
        self.events = []
        self.truncated = None

    def body_named(self, name):
        for b in self.bodies:
            if b.name == name:
                return b
        raise Unsupported("a probe on %s, which is no free body" % name)

    def check_pairs(self):
        """The pairs of free bodies that could touch, with the sum of their reaches (the
        largest distance of a shape's point from its centre)."""
        def reach(b):
            if b.kind == "circle":
                return b.r
            return max([float(np.linalg.norm(p)) for p in b.vertices] + [0.0])
        self.pairs = [(a, b, reach(a) + reach(b)) for k, a in enumerate(self.bodies)
                      for b in self.bodies[k + 1:] if not (a.kind == "point" and b.kind == "point")]

    def pair_met(self, q):
        """A description of two free bodies near enough to touch (contacts between free
        bodies are not modelled: the run is cut there), or None."""
        for a, b, reach in self.pairs:
            d = q[3 * a.index:3 * a.index + 2] - q[3 * b.index:3 * b.index + 2]
            if float(np.linalg.norm(d)) <= reach:
                return "%s and %s may touch; the witness does not model contacts between " \
                       "free bodies" % (a.name, b.name)
        return None

    def build(self):
        nsds = sk.NonSmoothDynamicalSystem(0.0, self.t_end)
        g = float(self.model.get("gravity", 0.0))
        mass, force = np.zeros((self.n, self.n)), np.zeros(self.n)
        for b in self.bodies:
            i = 3 * b.index
            mass[i, i] = mass[i + 1, i + 1] = b.mass
            mass[i + 2, i + 2] = b.inertia
            force[i:i + 2] = [b.force[0], b.force[1] - b.mass * g]
        self.mass, self.base_force = mass, force
        self.ds = sk.LagrangianLinearTIDS(list(self.q0), list(self.v0), mass)
        self.ds.setFExtPtr(force.copy())
        nsds.insertDynamicalSystem(self.ds)
        self.relations = self.contacts + self.hinges + self.ropes
        self.inters = []
        for r in self.relations:
            inter = sk.Interaction(r.law(), r.make(self.q0))
            nsds.link(inter, self.ds)
            self.inters.append(inter)
        self.sim = sk.TimeStepping(nsds, sk.TimeDiscretisation(0.0, self.step))
        self.sim.insertIntegrator(sk.MoreauJeanOSI(0.5))
        if self.has_friction:
            self.osnsp = sk.FrictionContact(2)
            # the Coulomb problem solved to round-off (the default tolerance, 1e-4, leaves
            # a block sliding flat on two corners turning at 1e-6 rad/s)
            options = self.osnsp.numericsSolverOptions()
            options.dparam[sn.SICONOS_DPARAM_TOL] = 1e-12
            options.iparam[sn.SICONOS_IPARAM_MAX_ITER] = 1000
        else:
            self.osnsp = sk.MLCP()
        self.sim.insertNonSmoothProblem(self.osnsp)

    def impulses(self):
        """Each relation's impulse of the last step (its normal component)."""
        out = []
        for inter in self.inters:
            lam = np.array(inter.lambda_(1), dtype=float)
            out.append(lam)
        return out

    def record(self, t, pairs, q, v, hinges=None):
        self.events.append({"time": t, "pairs": pairs, "q": q.copy(), "v": v.copy(),
                            "hinges": hinges})

    def run(self):
        self.build()
        qp, vp, tp = self.q0.copy(), self.v0.copy(), 0.0
        state = {}
        while self.sim.hasNextEvent():
            self.refresh(qp, vp)
            self.apply_forces(qp)
            self.osnsp.setHasBeenUpdated(False)
            self.sim.computeOneStep()
            t = self.sim.nextTime()
            q = np.array(self.ds.q(), dtype=float)
            v = np.array(self.ds.velocity(), dtype=float)
            try:
                for rope in self.ropes:
                    rope.check(q)
            except RopeTurned as e:
                self.truncated = str(e)
                return tp, qp, vp
            met = self.pair_met(q)
            if met:
                self.truncated = met
                return tp, qp, vp
            lams = self.impulses()
            q = self.project(q, lams)
            self.contact_events(tp, qp, vp, t, q, v, lams, state)
            self.probe_events(tp, qp, vp, t, q, v, lams)
            self.last_hinges = self.hinge_forces(lams)
            qp, vp, tp = q, v, t
            self.refresh(q, v, lams)
            self.sim.nextStep()
            if t >= self.t_end - 1e-12:
                break
        return tp, qp, vp

    def apply_forces(self, q):
        """The external forces for the coming step: gravity and the forces at the centres,
        and each force at a point of a rotating body with its torque (R(theta) p) x F at Q
        (explicit, first order like the scheme)."""
        if not any(b.forces_at for b in self.bodies):
            return
        f = self.base_force.copy()
        for b in self.bodies:
            i = 3 * b.index
            for p, force in b.forces_at:
                d = rotation(q[i + 2]).dot(p)
                f[i:i + 2] += force
                f[i + 2] += d[0] * force[1] - d[1] * force[0]
        self.ds.fExt()[:] = f

    def refresh(self, q, v, lams=None):
        """The relations linearised at Q again; for those that did not act in the last step
        (no impulse in LAMS), their outputs y = C q + e, y' = C V set from them: Moreau-Jean
        decides which relations are active in the coming step from these outputs, which
        Siconos 4.4 leaves stale for an interaction that was not active."""
        for k, (r, inter) in enumerate(zip(self.relations, self.inters)):
            if isinstance(r, Contact) and lams is not None:
                r.update_front(q)
            if isinstance(r, (Contact, Hinge)):
                r.refresh(q)
            if lams is not None and isinstance(r, Contact) and not lams[k][0] > 0:
                C, e = r.rows_at(q)
                inter.y(0)[:] = C.dot(q) + e
                inter.y(1)[:] = C.dot(v)

    def project(self, q, lams):
        """Q moved back onto the relations that hold (the hinges, the contacts that pressed
        in the step): Moreau-Jean keeps them at the velocity level only, and the gaps of
        turning bodies drift by O(STEP) over a run. A mass-weighted (Gauss-Newton)
        projection, twice; the velocities are left alone."""
        held = [r for r, lam in zip(self.relations, lams)
                if isinstance(r, Hinge) or (isinstance(r, Contact) and lam[0] > 0)]
        if not held:
            return q
        inverse = 1.0 / np.diag(self.mass)
        for _ in range(2):
            rows, gaps = [], []
            for r in held:
                C, e = r.rows_at(q)
                k = 2 if isinstance(r, Hinge) else 1
                for i in range(k):
                    rows.append(C[i])
                    gaps.append(float(C[i].dot(q) + e[i]) + (MARGIN if i == 0 and isinstance(r, Contact) else 0.0))
            C, g = np.array(rows), np.array(gaps)
            A = (C * inverse).dot(C.T)
            q = q - inverse * C.T.dot(np.linalg.lstsq(A, g, rcond=None)[0])
        self.ds.setQPtr(q.copy())   # a copy: Siconos writes into the vector it is given
        return q

    def hinge_forces(self, lams):
        out = []
        for r, lam in zip(self.relations, lams):
            if isinstance(r, Hinge):
                out.append((r.name, lam[:2] / self.step))
        return out

    def contact_events(self, tp, qp, vp, t, q, v, lams, state):
        """The events of contacts in the step from (TP, QP, VP) to (T, Q, V), LAMS the
        relations' impulses; STATE holds each contact's history (pressing or not, its last
        two forces, a pending lift-off)."""
        h = self.step
        collide = max(0.05, 20.0 * float(self.model.get("gravity", 0.0)) * h)
        for k, (r, lam) in enumerate(zip(self.relations, lams)):
            if not isinstance(r, Contact):
                continue
            s = state.setdefault(k, {"pressing": False, "forces": [], "pending": None})
            force = float(lam[0]) / h
            pressing = force > 1e-9
            vn0, vn1 = r.normal_speed(qp, vp), r.normal_speed(q, v)
            if pressing and not s["pressing"] and vn0 < -collide and vn1 - vn0 > JUMP:
                self.record(t, [(":collision",) + r.names], qp, vp)
            if s["pending"] is not None:
                if pressing:                      # it pressed again: no lift-off
                    s["pending"] = None
                elif t - s["pending"][0] >= QUIET * h or t >= self.t_end - 1e-12:
                    self.record(*s["pending"][1:])
                    s["pending"] = None
            elif s["pressing"] and not pressing and tp > 2 * h:
                tz, f = tp, 0.0
                if len(s["forces"]) == 2 and s["forces"][0] > s["forces"][1]:
                    f0, f1 = s["forces"]   # the force falls from f0 (at tp - h) to f1 (at tp)
                    f = min(1.0, f1 / (f0 - f1))
                    tz = tp + f * h
                s["pending"] = (t, tz, [(":lift-off",) + r.names], qp + f * (q - qp),
                                vp + f * (v - vp))
            # the contact point's tangential speed as the step saw it: its point at QP (where
            # the relation was linearised) moving with the new velocities V, 0 when it sticks
            s1 = r.tangential_speed(qp, v) if r.friction else 0.0
            s0 = s.get("slip")
            s["slip"] = s1
            if pressing and r.friction and s["pressing"] and tp > 2 * h and s0 is not None:
                if abs(s0) > SPEED_TOL and (abs(s1) <= SPEED_TOL or s0 * s1 < 0):
                    f = s0 / (s0 - s1)
                    self.record(tp + f * h, [(":stops-sliding",) + r.names], qp + f * (q - qp),
                                vp + f * (v - vp))
                elif abs(s0) <= SPEED_TOL and abs(s1) > SPEED_TOL:
                    self.record(tp, [(":starts-sliding",) + r.names], qp, vp)
            s["forces"] = (s["forces"] + [force])[-2:] if pressing else []
            s["pressing"] = pressing

    def probe_events(self, tp, qp, vp, t, q, v, lams):
        for b, angle in self.probes:
            i = 3 * b.index + 2
            a0, a1 = qp[i] - angle, q[i] - angle
            if a0 != 0 and a0 * a1 <= 0:
                f = a0 / (a0 - a1)
                hinges = [(name, fv) for name, fv in self.hinge_forces(lams)]
                self.record(tp + f * (t - tp), [(":reaches", b.name, "angle")],
                            qp + f * (q - qp), vp + f * (v - vp), hinges)


def sx_number(x):
    return repr(float(x)).replace("e", "d") if "e" in repr(float(x)) else repr(float(x)) + "d0"


def sx_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def sx_state(driver, q, v):
    """The keys of a state: positions, velocities, angles, angular velocities."""
    def each(f):
        return "(" + " ".join("(%s %s)" % (sx_string(b.name), f(b)) for b in driver.bodies) + ")"
    vec = lambda x, i: "(%s %s)" % (sx_number(x[3 * i]), sx_number(x[3 * i + 1]))
    return ":positions %s :velocities %s :angles %s :angular-velocities %s" % (
        each(lambda b: vec(q, b.index)), each(lambda b: vec(v, b.index)),
        each(lambda b: sx_number(q[3 * b.index + 2])), each(lambda b: sx_number(v[3 * b.index + 2])))


def sx_hinges(forces):
    return "(" + " ".join("(%s (%s %s))" % (sx_string(name), sx_number(f[0]), sx_number(f[1]))
                          for name, f in forces or []) + ")"


def main_rotation(model):
    """Simulate MODEL (with rotating bodies or hinges) and print the s-expression answer."""
    try:
        driver = RotationDriver(model)
        t, q, v = driver.run()
        driver.events.sort(key=lambda event: event["time"])   # lift-offs are known late
    except Unsupported as e:
        print("(:status :unsupported :message %s)" % sx_string(str(e)))
        return
    except Exception as e:  # the witness failed: say so, never a result
        print("(:status :error :message %s)" % sx_string("%s: %s" % (type(e).__name__, e)))
        return
    out = ["(:status :ok", " :scheme :moreau-jean :step %s" % sx_number(driver.step), " :events ("]
    for ev in driver.events:
        pairs = " ".join("(%s %s %s)" % (p[0], sx_string(p[1]), sx_string(p[2])) for p in ev["pairs"])
        out.append("  (:time %s :pairs (%s) %s :hinges %s)" % (
            sx_number(ev["time"]), pairs, sx_state(driver, ev["q"], ev["v"]), sx_hinges(ev["hinges"])))
    out.append(" )")
    if driver.truncated:
        out.append(" :truncated %s" % sx_string(driver.truncated))
    out.append(" :end (:time %s %s :hinges %s))" % (sx_number(t), sx_state(driver, q, v),
                                                    sx_hinges(getattr(driver, "last_hinges", []))))
    print("\n".join(out))
