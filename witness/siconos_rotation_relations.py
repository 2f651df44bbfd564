"""siconos_rotation_relations.py -- the bodies, faces and relations of the witness for rotating
bodies (siconos_rotation.py): each relation a LagrangianLinearTIR y = C q + e over the
model's coordinates (x, y, theta per free body), made again from the state at every step
(ROWS_AT) where it depends on theta. See siconos_rotation.py for the scheme and the list
of relations.
"""

import math

import numpy as np
import siconos.kernel as sk

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

    def position(self, point):
        """Where POINT projects along the face, from a (0) to b (its length)."""
        return float(np.dot(self.t, point - self.a))

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
    kinds = {"close": ":collision", "open": ":lift-off"}

    def normal_speed(self, q, v):
        C, _ = self.rows_at(q)
        return float(C[0].dot(v))

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
        # a frictionless contact in a model with friction is a Coulomb contact with mu = 0:
        # Siconos's FrictionContact problem takes only contacts of that law (coulomb)
        self.coulomb = self.friction
        self.names = (body.name, face.name)
        self.front = False
        self.update_front(q0)

    def update_front(self, q, v=None, held=False):
        """Whether the face may hold the contact in the coming step: its point lies within
        the face's extent, and in front of the face (or it was already held: a contact
        in force may sink by round-off). A point behind a face's line (the body beside a
        convex obstacle, seen from a face that looks away) is never held by it. V (the
        velocities) and HELD (whether it pressed in the last step) serve the relations
        that look ahead (siconos_ledges.py)."""
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
        k = 2 if self.coulomb else 1
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
        if self.coulomb:
            return sk.NewtonImpactFrictionNSL(self.e, 0.0, self.mu or 0.0, 2)
        return sk.NewtonImpactNSL(self.e)

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
        # seen MARGIN closer, as a contact's gap: a taut rope stays in the index set (at
        # exactly 0 round-off lets it go slack for a step, then catch its bodies again)
        return C, np.array([const - MARGIN])

    kinds = {"close": ":tightens", "open": ":slackens"}

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
