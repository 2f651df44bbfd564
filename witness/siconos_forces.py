"""siconos_forces.py -- the forces of the witness's arcs driver (siconos_arcs.py) that are
not constant: universal gravitation and drag (a LagrangianDS whose FInt is computed here)
and bumpers (springs that only push, engaged and released by the driver)."""

import numpy as np
import siconos.kernel as sk


def split(q, n):
    """The coordinates Q of N bodies as N points."""
    return [np.array(q[2 * k:2 * k + 2], dtype=float) for k in range(n)]


class GravitationDS(sk.LagrangianDS):
    """Every free body as one LagrangianDS: M q'' + FInt(q, v) = FExt, FExt the constant
    forces (gravity, pushes, springs' constant parts), FInt = K q minus universal
    gravitation (between free bodies and towards the fixed attractors; BIG_G 0 for none)
    plus drag: b_k v_k + c_k |v_k| v_k on body k (LINEAR and QUADRATIC, one per body)."""

    def __init__(self, q, v, mass, stiffness, masses, big_g, attractors, linear=None, quadratic=None):
        sk.LagrangianDS.__init__(self, q, v, mass)
        self.k, self.masses, self.big_g, self.attractors = stiffness, masses, big_g, attractors
        n = len(masses)
        self.linear = list(linear) if linear is not None else [0.0] * n
        self.quadratic = list(quadratic) if quadratic is not None else [0.0] * n
        self.setFIntPtr(np.zeros(len(q)))

    def pull(self, q):
        n = len(self.masses)
        f = np.zeros(2 * n)
        if not self.big_g:
            return f
        qs = split(q, n)
        for i in range(n):
            for j in range(i + 1, n):
                d = qs[j] - qs[i]
                force = self.big_g * self.masses[i] * self.masses[j] * d / float(np.linalg.norm(d)) ** 3
                f[2 * i:2 * i + 2] += force
                f[2 * j:2 * j + 2] -= force
            for centre, mass in self.attractors:
                d = centre - qs[i]
                f[2 * i:2 * i + 2] += self.big_g * self.masses[i] * mass * d / float(np.linalg.norm(d)) ** 3
        return f

    def drag(self, v):
        """The drag forces' opposite, b v + c |v| v per body."""
        f = np.zeros(len(v))
        for k, (b, c) in enumerate(zip(self.linear, self.quadratic)):
            vk = v[2 * k:2 * k + 2]
            f[2 * k:2 * k + 2] = b * vk + c * float(np.linalg.norm(vk)) * vk
        return f

    def computeFInt(self, time, q=None, v=None):
        q = np.array(self.q() if q is None else q, dtype=float)
        v = np.array(self.velocity() if v is None else v, dtype=float)
        self.fInt()[:] = self.k.dot(q) - self.pull(q) + self.drag(v)


def nonlinear_forces_p(model):
    """Whether MODEL has forces that depend on the state besides springs: universal
    gravitation or drag."""
    return bool(model.get("gravitation") or any(b.get("drag") for b in model.get("bodies", [])))


class Bumper:
    """A bumper (see the module): attached at the fixed POINT, free end at REST along the
    unit U; ENGAGED the bodies pressing it."""

    def __init__(self, spec, bodies):
        self.name, self.k, self.rest = spec["name"], float(spec["k"]), float(spec["rest"])
        self.point = np.array(spec["point"], dtype=float)
        u = np.array(spec["toward"], dtype=float)
        self.u = u / float(np.linalg.norm(u))
        self.support = [body.support(self.u) for body in bodies]   # furthest along -u
        self.engaged = set()

    def gap(self, j, qs):
        """Body J's distance to the free end along u (negative: the compression)."""
        return float(np.dot(self.u, qs[j] + self.support[j] - self.point)) - self.rest

    def add_to(self, stiffness, force):
        """k (L0 - u.(x_j + s_j - P)) u on each engaged body j, as K q and a constant force."""
        for j in self.engaged:
            stiffness[2 * j:2 * j + 2, 2 * j:2 * j + 2] += self.k * np.outer(self.u, self.u)
            force[2 * j:2 * j + 2] += self.k * (self.rest + float(np.dot(self.u, self.point - self.support[j]))) * self.u

    def check(self, qs):
        pass
