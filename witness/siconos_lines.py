"""siconos_lines.py -- springs and ropes for the witness's drivers.

Both are linear in the positions as long as each keeps the direction of its start (a
spring along its line, a rope's pieces straight between fixed pulleys and along the
directions they started with); CHECK raises LineLeft when one turns, and the driver cuts
its run there (a rope's turn: the run is made again with the exact rope, siconos_ropes.py). A point is {"body": INDEX, "offset": [X, Y]} (a free body's point, own
frame) or {"point": [X, Y]} (fixed).
"""

import numpy as np


class LineLeft(Exception):
    """A spring or rope turned: the run is cut at the last step where it had not."""


def point_position(point, qs):
    """A point of the model: {"body": INDEX, "offset": [X, Y]} or {"point": [X, Y]} (fixed)."""
    if point.get("body") is None:
        return np.array(point["point"], dtype=float)
    return qs[point["body"]] + np.array(point["offset"], dtype=float)


def point_constant(point):
    return np.array(point["point"] if point.get("body") is None else point["offset"], dtype=float)


def check_direction(what, d, u):
    if abs(d[0] * u[1] - d[1] * u[0]) > 1e-7 * max(1.0, float(np.linalg.norm(d))) or \
            float(np.dot(d, u)) <= 0:
        raise LineLeft("%s leaves its initial line; the witness models only springs and "
                       "ropes that keep their directions" % what)


class Spring:
    """A Hooke spring between two points, along the fixed direction U of its start: exact
    while the spring keeps that direction (checked at every step)."""

    def __init__(self, spec, qs):
        self.name, self.k, self.a, self.b = spec["name"], float(spec["k"]), spec["a"], spec["b"]
        d = point_position(self.b, qs) - point_position(self.a, qs)
        self.u = d / np.linalg.norm(d)
        self.rest = float(spec["rest"]) if spec.get("rest") is not None else float(np.linalg.norm(d))

    def add_to(self, stiffness, force):
        """F_b = -k (u.(P_b - P_a) - L0) u, F_a = -F_b, as K q and a constant force."""
        uu = self.k * np.outer(self.u, self.u)
        const = float(np.dot(self.u, point_constant(self.b) - point_constant(self.a))) - self.rest
        for point, sign in ((self.a, -1.0), (self.b, 1.0)):
            if point.get("body") is None:
                continue
            i = 2 * point["body"]
            force[i:i + 2] += -sign * self.k * const * self.u
            for other, osign in ((self.a, -1.0), (self.b, 1.0)):
                if other.get("body") is None:
                    continue
                j = 2 * other["body"]
                stiffness[i:i + 2, j:j + 2] += sign * osign * uu

    def check(self, qs):
        check_direction("spring " + self.name, point_position(self.b, qs) - point_position(self.a, qs),
                        self.u)


class Rope:
    """An inextensible rope through points (attachments and pulleys), straight between them,
    each piece along the fixed direction of its start (checked at every step): the
    unilateral constraint L - sum of the pieces' lengths >= 0, linear in the positions."""

    kinds = {"close": ":tightens", "open": ":slackens"}

    def __init__(self, spec, qs):
        self.name, self.length, self.points = spec["name"], float(spec["length"]), spec["points"]
        self.e = float(spec.get("restitution", 0.0))
        self.u = []
        for p, q in zip(self.points, self.points[1:]):
            d = point_position(q, qs) - point_position(p, qs)
            self.u.append(d / np.linalg.norm(d))
        m = len(self.u)
        self.c = [(self.u[j - 1] if j > 0 else 0.0) - (self.u[j] if j < m else 0.0)
                  for j in range(len(self.points))]

    def row(self, n):
        h = np.zeros(2 * n)
        for point, c in zip(self.points, self.c):
            if point.get("body") is not None:
                h[2 * point["body"]:2 * point["body"] + 2] -= c
        return h

    def constant(self):
        return self.length - sum(float(np.dot(c, point_constant(p))) for p, c in zip(self.points, self.c))

    def gap(self, qs):
        return float(np.dot(self.row(len(qs)), np.concatenate(qs))) + self.constant()

    def rate(self, vs):
        return float(np.dot(self.row(len(vs)), np.concatenate(vs)))

    def restitution(self, model, bodies):
        return self.e

    def names(self, bodies):
        return (self.name, self.name)

    def covers(self, qs):
        return True

    def active(self, qs, vs):
        return True

    def margins(self, qs):
        return (1.0, 1.0)

    def check(self, qs):
        for k, (p, q) in enumerate(zip(self.points, self.points[1:])):
            check_direction("rope %s (piece %d)" % (self.name, k),
                            point_position(q, qs) - point_position(p, qs), self.u[k])
