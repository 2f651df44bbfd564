"""siconos_ropes.py -- ropes whose pieces turn, for the witness's event-driven drivers.

siconos_lines.Rope is linear in the positions: exact while every piece keeps the direction
of its start (a rope over pulleys with vertical pieces, or one along an incline). A piece
that turns (a hanging weight that swings, a particle pulled off the end of its incline
and swinging below the pulley) needs the rope's length constraint itself,

    g(q) = L - sum_j |P_{j+1} - P_j| >= 0,

P_j the rope's points (a free body's position plus its offset, the body translating, or a
fixed point: a pulley), with Newton's law (e = 0: the rope jerks taut plastically). It is
a Siconos LagrangianScleronomousR written here, as siconos_arcs.py's circles are: h, its
Jacobian -sum_j (u_{j-1} - u_j) over each point's body (u_j the unit vector of piece j)
and the Jacobian's time derivative (u_j' = (d_j' - u_j (u_j . d_j')) / |d_j|), which the
acceleration-level LCP needs. Its closing is (:tightens ROPE ROPE), its opening
(:slackens ROPE ROPE).

A piece that closes at its pulley (the body at its end reaching the pulley's point, the
piece's length 0) is a second unilateral relation, PieceContact: the piece's length
measured along its direction at the last output step, (P_{j+1} - P_j) . u >= 0 (its
length while the piece keeps that direction, and of the other sign once the body would
pass through the pulley, so that Lsodar's root finding, a change of sign, sees the
closing), with Newton's law and the restitution of the body and the pulley's body:
(:strikes-pulley BODY HOLDER) where it closes with an approach speed (AMES's impact of a
piece closing, src/kb/ropes.lisp; AMES's (:rope-piece-closes ROPE HOLDER BODY) matches it too;
HOLDER the
pulley's body; a closing recorded away from the pulley, a body passing by it, is
unsupported). The body is then held at the pulley along the piece's last direction, the
rope's piece of no length keeping that direction: followed while the body stays there
(CHECK cuts the run where it drifts across the piece, which a pin would hold, or leaves
the pulley). A piece between two free bodies that shrinks to no length cuts the run.
"""

import numpy as np
import siconos.kernel as sk

from siconos_forces import split
from siconos_lines import LineLeft, point_position

PIECE_FLOOR = 1e-9   # a piece shorter than this has no direction to speak of
HELD = 1e-6          # a piece shorter than this is closed: its body held at the pulley
ACROSS = 1e-9        # how far a held body may drift across its piece's direction
TOL_ED = 1e-9        # the gap below 0 Siconos's event-driven scheme lets a relation drift to


class ExactRope:
    """An inextensible rope through points, straight between them, its length constraint
    exact (see the module). The driver asks for GAP before RATE (as for a circle)."""

    kinds = {"close": ":tightens", "open": ":slackens"}

    def __init__(self, spec, n_bodies):
        self.name, self.length, self.points = spec["name"], float(spec["length"]), spec["points"]
        self.e = float(spec.get("restitution", 0.0))
        self.n_bodies = n_bodies
        self.last_q = None
        self.directions = {}    # each piece's last direction, while it had a length (CHECK)

    def positions(self, qs):
        return [point_position(p, qs) for p in self.points]

    def units(self, qs):
        """The pieces' vectors d_j and unit vectors u_j at QS."""
        ps = self.positions(qs)
        ds = [b - a for a, b in zip(ps, ps[1:])]
        lengths = [float(np.linalg.norm(d)) for d in ds]
        return ds, lengths

    def gap(self, qs):
        self.last_q = [np.array(q, dtype=float) for q in qs]
        _, lengths = self.units(qs)
        return self.length - sum(lengths)

    def rate(self, vs):
        jac, _ = self.rows(np.concatenate(self.last_q), np.concatenate(vs))
        return float(np.dot(jac, np.concatenate(vs)))

    def rows(self, q, qdot):
        """The Jacobian of the gap over every coordinate, and its time derivative."""
        qs, vs = split(q, self.n_bodies), split(qdot, self.n_bodies)
        ds, lengths = self.units(qs)
        pv = [np.zeros(2) if p.get("body") is None else vs[p["body"]] for p in self.points]
        us, udots = [], []
        for j, (d, length) in enumerate(zip(ds, lengths)):
            if length <= PIECE_FLOOR:
                # no direction: the piece's last one (Lsodar evaluates the state where a
                # piece closes at its pulley, PieceContact's root); CHECK says when the run
                # cannot go on
                us.append(self.directions.get(j, np.zeros(2)))
                udots.append(np.zeros(2))
                continue
            u = d / length
            ddot = pv[j + 1] - pv[j]
            us.append(u)
            udots.append((ddot - u * float(np.dot(u, ddot))) / length)
        m = len(us)
        jac, djac = np.zeros(2 * self.n_bodies), np.zeros(2 * self.n_bodies)
        for j, p in enumerate(self.points):
            if p.get("body") is None:
                continue
            c = (us[j - 1] if j > 0 else 0.0) - (us[j] if j < m else 0.0)
            cdot = (udots[j - 1] if j > 0 else 0.0) - (udots[j] if j < m else 0.0)
            k = p["body"]
            jac[2 * k:2 * k + 2] -= c
            djac[2 * k:2 * k + 2] -= cdot
        return jac, djac

    def relation(self):
        return RowsRelation(self)

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
        """Cut the run (LineLeft) where a piece that no PieceContact watches has no length
        (between two free bodies): it has no direction."""
        ds, lengths = self.units(qs)
        for j, length in enumerate(lengths):
            # the last direction of an accepted state (never of Lsodar's trial states,
            # which may pass a pulley before its root is found)
            if length > 1e-6:
                self.directions[j] = ds[j] / length
            a, b = self.points[j], self.points[j + 1]
            watched = [p for p in (a, b) if p.get("body") is None and p.get("holder")]
            if length <= PIECE_FLOOR and not watched:
                raise LineLeft("rope %s (piece %d) closes to no length: the witness does not "
                               "follow a piece with no direction" % (self.name, j))


class RowsRelation(sk.LagrangianScleronomousR):
    """A relation whose gap, Jacobian and its derivative a contact computes (GAP and ROWS)."""

    def __init__(self, contact):
        sk.LagrangianScleronomousR.__init__(self)
        self.contact = contact
        self.n = contact.n_bodies
        self.setJachqPtr(np.zeros((1, 2 * self.n)))
        self.qdot = np.zeros(2 * self.n)

    def computeh(self, q, z, y):
        y[0] = self.contact.gap(split(q, self.n))

    def computeJachq(self, q, z):
        jac, _ = self.contact.rows(np.array(q, dtype=float), self.qdot)
        self.jachq()[0, :] = jac

    def computeDotJachq(self, q, z, qdot):
        self.qdot = np.array(qdot, dtype=float)
        _, djac = self.contact.rows(np.array(q, dtype=float), self.qdot)
        self.dotJachq()[0, :] = djac


class PieceContact:
    """Piece J of a rope, between a fixed pulley and a free body's point, closing at the
    pulley: its length along its direction U at the last step (see the module), a
    unilateral relation with Newton's law. OTHER is the free body, HOLDER the name of the
    pulley's body."""

    kinds = {"close": ":strikes-pulley", "open": ":leaves-pulley"}

    def __init__(self, rope_spec, j, holder, model, bodies, qs):
        points = rope_spec["points"]
        a, b = points[j], points[j + 1]
        self.fixed, self.free = (a, b) if a.get("body") is None else (b, a)
        self.other = self.free["body"]
        self.holder = holder
        self.rope, self.piece = rope_spec["name"], j
        self.n_bodies = len(bodies)
        self.owner = None       # held by a fixed body (the driver's corner rules read this)
        self.u = None
        self.last_q = None
        self.closed = False     # the piece has reached its pulley (see CHECK)
        self.free_name = bodies[self.other].name
        self.refresh(qs)

    @property
    def n(self):
        """The direction in which the body's moving opens the piece (as a face's normal)."""
        return self.u

    def vector(self, qs):
        """From the pulley to the body's point."""
        return point_position(self.free, qs) - point_position(self.fixed, qs)

    def refresh(self, qs):
        """Take the piece's direction at QS (while it has one)."""
        d = self.vector(qs)
        length = float(np.linalg.norm(d))
        if length > 1e-6:
            self.u = d / length

    def gap(self, qs):
        self.last_q = [np.array(q, dtype=float) for q in qs]
        return float(np.dot(self.vector(qs), self.u))

    def rate(self, vs):
        return float(np.dot(vs[self.other], self.u))

    def rows(self, q, qdot):
        jac = np.zeros(2 * self.n_bodies)
        jac[2 * self.other:2 * self.other + 2] = self.u
        return jac, np.zeros(2 * self.n_bodies)

    def relation(self):
        return RowsRelation(self)

    def restitution(self, model, bodies):
        from siconos_contacts import restitution
        return restitution(model, bodies[self.other].name, self.holder)

    def names(self, bodies):
        return (bodies[self.other].name, self.holder)

    def covers(self, qs):
        return True

    def active(self, qs, vs):
        return True

    def margins(self, qs):
        return (1.0, 1.0)

    def check(self, qs):
        """Take the piece's direction at QS (while it has a length). A body held at its
        pulley (the piece closed: its length under HELD) is followed while it stays there:
        the piece's relation holds it along the piece's last direction only, so the run is
        cut (LineLeft) where it drifts across that direction (by ACROSS: a force across the
        piece, which a pin at the pulley would hold) or leaves the pulley (the piece opening
        again from no length has no direction)."""
        d = self.vector(qs)
        length = float(np.linalg.norm(d))
        if length <= HELD:
            across = float(np.linalg.norm(d - self.u * float(np.dot(d, self.u))))
            if across > ACROSS:
                raise LineLeft("%s, held at the pulley of rope %s (piece %d) on %s, is pulled "
                               "across the piece: the witness holds it along the piece only"
                               % (self.free_name, self.rope, self.piece, self.holder))
            self.closed = True
            return
        if self.closed:
            raise LineLeft("%s leaves the pulley of rope %s (piece %d) on %s: the witness does "
                           "not follow a piece opening from no length" % (self.free_name, self.rope,
                                                                           self.piece, self.holder))
        self.refresh(qs)


def piece_contacts(model, bodies, qs):
    """The pieces of MODEL's ropes that may close at a pulley: a piece between a fixed point
    that has a holder (the pulley's body, "holder" in the rope's point) and a free body's
    point."""
    out = []
    for spec in model.get("ropes", []):
        points = spec["points"]
        for j, (a, b) in enumerate(zip(points, points[1:])):
            fixed = [p for p in (a, b) if p.get("body") is None]
            if len(fixed) == 1 and fixed[0].get("holder") and len(fixed) < 2:
                out.append(PieceContact(spec, j, fixed[0]["holder"], model, bodies, qs))
    return out
