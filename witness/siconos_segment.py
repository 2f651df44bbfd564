"""siconos_segment.py -- one Siconos model of the translating witness (siconos_driver.py):
the free bodies as one linear Lagrangian system, a Newton impact law per active contact,
Siconos's event-driven scheme (LsodarOSI, LCPs at the impact and acceleration levels).
"""

import numpy as np
import siconos.kernel as sk


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
