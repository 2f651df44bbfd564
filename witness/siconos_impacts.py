"""siconos_impacts.py -- an impact applied by the witness itself, by Newton's law.

Siconos 4.4's event-driven scheme sometimes fails (an std::exception from processEvents)
after it has solved an impact, in the acceleration-level problem that follows it: two
blocks caught up with plastically while a spring drives one of them. The driver then
applies the impact here, from the state just before it, and starts its next model from
the velocities after it.

The impact is the one of Siconos's impact-level LCP: among the contacts closed at the
impact (|gap| <= TOL), impulses p >= 0 such that the normal velocities after,
u+ = u- + W p (W = J M^-1 J^T), satisfy Newton's law u+ >= -e u- where a contact
approaches (u- < 0), u+ >= 0 elsewhere, with equality wherever p > 0. The complementarity
problem is small (a few contacts) and is solved by trying the sets of contacts that push,
smallest first.
"""

import itertools

import numpy as np

TOL = 1e-7            # a contact closed at the impact: its gap within this
MAX_CONTACTS = 10     # closed contacts the enumeration takes (2^10 sets at most)


def gap_row(contact, qs, vs, n):
    """The Jacobian of CONTACT's gap over the 2 N coordinates, at (QS, VS)."""
    if hasattr(contact, "rows"):        # a contact on a circle (siconos_arcs.py)
        contact.gap(qs)
        return contact.rows(np.concatenate(qs), np.concatenate(vs))[0]
    return contact.row(n)


def newton_impact(model, bodies, contacts, qs, vs):
    """The velocities (one 2-vector per body) after the impact at (QS, VS) among CONTACTS,
    by Newton's law with each contact's restitution in MODEL; None when no closed contact
    approaches, too many are closed, or no set of pushing contacts solves the problem."""
    n = len(bodies)
    closed = [c for c in contacts if abs(c.gap(qs)) <= TOL]
    if not closed or len(closed) > MAX_CONTACTS:
        return None
    J = np.array([gap_row(c, qs, vs, n) for c in closed])
    inverse_mass = np.array([1.0 / b.mass for b in bodies for _ in (0, 1)])
    v = np.concatenate(vs)
    u = J.dot(v)
    if not (u < -1e-9).any():
        return None
    e = np.array([c.restitution(model, bodies) for c in closed])
    target = -e * np.minimum(u, 0.0)
    W = (J * inverse_mass).dot(J.T)
    scale = max(1.0, float(np.max(np.abs(u))))
    k = len(closed)
    for size in range(1, k + 1):
        for pushing in itertools.combinations(range(k), size):
            s = list(pushing)
            p_s = np.linalg.lstsq(W[np.ix_(s, s)], target[s] - u[s], rcond=None)[0]
            if (p_s < -1e-12 * scale).any():
                continue
            p = np.zeros(k)
            p[s] = np.maximum(p_s, 0.0)
            after = u + W.dot(p)
            if (np.abs(after[s] - target[s]) <= 1e-9 * scale).all() and \
                    (after >= target - 1e-9 * scale).all():
                w = v + inverse_mass * J.T.dot(p)
                return [w[2 * i:2 * i + 2] for i in range(n)]
    return None
