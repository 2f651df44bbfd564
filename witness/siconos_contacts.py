"""siconos_contacts.py -- the translating witness's bodies and their contacts with faces
(siconos_driver.py describes the model): each free body's shape, support point and extent
along a direction; each contact a face (of a fixed obstacle, or of a free polygon) against
the support point of a free body, whose gap is linear in the positions and which holds the
body only within the face's extent; the cubic Hermite interpolant on which the driver finds
where a body enters or leaves an extent.
"""

import numpy as np

LOOK_AHEAD = 1e-6   # seconds: which way a body at the end of a face is moving   # Zeno sequences end well before this


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
