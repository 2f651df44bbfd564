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
A face holds a vertex or disc only while the contact point lies within the face's extent
and in front of it (siconos_rotation_relations.py: beyond, the relation's gap is set far
open). Contacts between two free bodies are not modelled: the run is cut (:truncated)
when two come near enough to touch. Moreau-Jean keeps the relations at the velocity level;
after each step the positions are projected back onto the hinges and the contacts that
pressed (a mass-weighted Gauss-Newton step), so that a turning body does not drift off
them. Siconos 4.4 leaves the outputs (y, y') and the last impulse of an interaction it did
not keep active stale: the driver sets the outputs from which the next step activates
the relations, and reads no impulse of a contact its face no longer holds.

Events (siconos_rotation_events.py; the translating driver's format):
  :collision A B      an approach speed jumps (an impulse);
  :lift-off A B       a contact that pressed (impulse > 0) stops pressing for good (QUIET
                      steps): at the time where the normal force, extrapolated linearly
                      from the last two steps that pressed, reaches 0;
  :leaves A B         a pressing contact's point passes an end of its face (interpolated);
  :stops-sliding A B  a pressing contact's tangential speed reaches 0 (where the slip,
                      falling as in the step before, reaches 0); :starts-sliding the
                      converse;
  :tightens R R, :slackens R R   a rope's, as a contact's collision and lift-off;
  :reaches BODY "angle"  a probe: BODY's angle crosses the model's probe value.
Each event and the end add :angles ((BODY THETA) ...) and :angular-velocities, and
:hinges ((NAME (FX FY)) ...) the hinges' reaction forces (impulse / STEP). A force at a
point of a rotating body ("forces_at") keeps its world components; its torque is taken at
the step's start (explicit, first order like the scheme).
"""

import numpy as np
import siconos.kernel as sk
import siconos.numerics as sn

from siconos_ledges import corner_contacts
from siconos_rotation_events import Events
from siconos_rotation_relations import (MARGIN, STEP, Body, Contact, Face, Hinge, Rope,
                                        RopeTurned, Unsupported, friction_coefficient,
                                        restitution, rotation)


class RotationDriver(Events):
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
        # the fixed corners on the turning bodies' faces (siconos_ledges.py)
        self.contacts += corner_contacts(model, self.bodies, self.n, self.q0,
                                         friction_coefficient, restitution)
        self.hinges = [Hinge(h, self.bodies, self.n) for h in model.get("hinges", [])]
        self.ropes = [Rope(r, self.bodies, self.q0) for r in model.get("ropes", [])]
        self.has_friction = any(c.friction for c in self.contacts)
        for c in self.contacts:
            c.coulomb = self.has_friction   # one law for every contact of a FrictionContact
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
        self.sample_times = sorted(float(t) for t in model.get("samples", []))
        self.samples = []

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
        """Each relation's impulses in the last step; 0 for a contact whose face no longer
        holds it (Siconos leaves the last impulse of an interaction it drops)."""
        out = []
        for r, inter in zip(self.relations, self.inters):
            lam = np.array(inter.lambda_(1), dtype=float)
            out.append(lam if not isinstance(r, Contact) or r.front else 0.0 * lam)
        return out

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
            if self.truncated:   # an impact whose law is not AMES's (siconos_rotation_events.py)
                return t, q, v
            self.probe_events(tp, qp, vp, t, q, v, lams)
            self.observe(tp, qp, vp, t, q, v)
            self.last_hinges = self.hinge_forces(lams)
            qp, vp, tp = q, v, t
            self.refresh(q, v, lams)
            self.sim.nextStep()
            if t >= self.t_end - 1e-12:
                break
        self.flush_pending(state, qp, vp)
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
        """The relations linearised at Q again; for the contacts and ropes that did not act
        in the last step (no impulse in LAMS), their outputs y = C q + e, y' = C V set from
        them: Moreau-Jean decides which relations are active in the coming step from these
        outputs, which Siconos 4.4 leaves stale for an interaction that was not active (a
        slack rope's stale gap, about 0, kept it active: turning back, the pulley of an
        Atwood machine whose mass had landed was jerked at once, far from taut)."""
        for k, (r, inter) in enumerate(zip(self.relations, self.inters)):
            if isinstance(r, Contact) and lams is not None:
                r.update_front(q, v, lams[k][0] > 0)
            if isinstance(r, (Contact, Hinge)):
                r.refresh(q)
            if lams is not None and isinstance(r, (Contact, Rope)) and not lams[k][0] > 0:
                C, e = r.rows_at(q)
                inter.y(0)[:] = C.dot(q) + e
                inter.y(1)[:] = C.dot(v)

    def project(self, q, lams):
        """Q moved back onto the relations that hold (the hinges, the contacts and ropes that
        pressed in the step): Moreau-Jean keeps them at the velocity level only, and the gaps of
        turning bodies drift by O(STEP) over a run. A mass-weighted (Gauss-Newton)
        projection, twice; the velocities are left alone."""
        held = [r for r, lam in zip(self.relations, lams)
                if isinstance(r, Hinge) or (isinstance(r, (Contact, Rope)) and lam[0] > 0)]
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
                    gaps.append(float(C[i].dot(q) + e[i]) + (MARGIN if i == 0 and isinstance(r, (Contact, Rope)) else 0.0))
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
    out = ["(:status :ok", " :scheme :moreau-jean :step %s :collision-speed %s"
           % (sx_number(driver.step), sx_number(driver.collision_speed())), " :events ("]
    for ev in driver.events:
        pairs = " ".join("(%s %s %s)" % (p[0], sx_string(p[1]), sx_string(p[2])) for p in ev["pairs"])
        out.append("  (:time %s :pairs (%s) %s :hinges %s)" % (
            sx_number(ev["time"]), pairs, sx_state(driver, ev["q"], ev["v"]), sx_hinges(ev["hinges"])))
    out.append(" )")
    if driver.truncated:
        out.append(" :truncated %s" % sx_string(driver.truncated))
    if driver.samples:
        out.append(" :samples (%s)" % " ".join(
            "(:time %s %s)" % (sx_number(s["time"]), sx_state(driver, s["q"], s["v"]))
            for s in driver.samples))
    out.append(" :end (:time %s %s :hinges %s))" % (sx_number(t), sx_state(driver, q, v),
                                                    sx_hinges(getattr(driver, "last_hinges", []))))
    print("\n".join(out))
