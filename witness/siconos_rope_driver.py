"""siconos_rope_driver.py -- the event-driven driver with exact ropes (siconos_ropes.py):
siconos_arcs.ArcDriver (nonlinear relations, samples) with each rope's length constraint
exact, its pieces' closings at their pulleys, a taut rope kept on its length where a model
is rebuilt, and the turning points of swings: where a taut piece from a fixed point to a
free body's point changes the sense it turns in, (:turns BODY BODY) (AMES's rope swing,
src/kb/rope-swing.lisp). siconos_driver.simulate runs it where a rope of the linear driver
turned or closed.
"""

import numpy as np

from siconos_forces import split
from siconos_lines import point_position
from siconos_ropes import ExactRope, PieceContact, TOL_ED, piece_contacts

OUTPUT_STEP = 5e-4  # s
SNAP_RATE = 1e-4    # a taut rope's rate at a rebuild set to 0 below this (the comparator's
                    # *SETTLE-SPEED*: slower impacts are round-off, not events)


def swing_piece(rope, j):
    """The free end of ROPE's piece J when the piece runs from a fixed point to a free
    body's point (a swing), else None."""
    a, b = rope.points[j], rope.points[j + 1]
    if a.get("body") is None and b.get("body") is not None:
        return b
    if b.get("body") is None and a.get("body") is not None:
        return a
    return None


def swing_rate(rope, j, qs, vs):
    """(B - A) x (B' - A') of ROPE's piece J (A fixed): its angle's rate times its length
    squared."""
    free = swing_piece(rope, j)
    fixed = rope.points[j] if free is rope.points[j + 1] else rope.points[j + 1]
    d = point_position(free, qs) - point_position(fixed, qs)
    w = vs[free["body"]]
    return float(d[0] * w[1] - d[1] * w[0])


def swing_noise(rope, j, qs, vs):
    """The round-off of ROPE's piece J's swing rate at (QS VS): 1e-10 |d| max(1, |v|)."""
    free = swing_piece(rope, j)
    fixed = rope.points[j] if free is rope.points[j + 1] else rope.points[j + 1]
    d = point_position(free, qs) - point_position(fixed, qs)
    return 1e-10 * float(np.linalg.norm(d)) * max(1.0, float(np.linalg.norm(vs[free["body"]])))


def turning_rope_driver(model):
    """The event-driven driver (siconos_arcs.ArcDriver: turning points, samples, nonlinear
    relations) with MODEL's ropes exact and their pieces' closings at pulleys; used where a
    rope of the linear driver turned (siconos_driver.simulate)."""
    from siconos_arcs import ArcDriver, ArcSegment
    from siconos_contacts import Unsupported

    class RopeSegment(ArcSegment):
        """An ArcSegment that lets a taut rope's gap drift by TOL_ED (Siconos stops at a gap
        below -2.2e-12 otherwise: Lsodar keeps a nonlinear relation at the acceleration level
        only, and the rope's length drifts by round-off over a swing)."""

        def __init__(self, *args, **kwargs):
            ArcSegment.__init__(self, *args, **kwargs)
            self.sim.setToleranceED(TOL_ED)

    class TurningRopeDriver(ArcDriver):
        segment_class = RopeSegment

        def __init__(self, model):
            ArcDriver.__init__(self, model)
            linear = set(self.ropes)
            qs = [b.q.copy() for b in self.bodies]
            n = len(self.bodies)
            self.ropes = [ExactRope(spec, n) for spec in model.get("ropes", [])] + \
                piece_contacts(model, self.bodies, qs)
            self.contacts = [c for c in self.contacts if c not in linear] + self.ropes
            self.scheme = "curved"     # nonlinear relations: the comparator's tolerance for them
            # the output step: turning points and extents are found on the cubic interpolant
            # of two outputs, whose velocities are off by O(h^3) in a fast swing
            self.dt = min(self.dt, OUTPUT_STEP)
            self.swing_sense = {}
            self.swings = [(rope, j) for rope in self.ropes if isinstance(rope, ExactRope)
                           for j in range(len(rope.points) - 1) if swing_piece(rope, j)]

        def segment(self, t0, qs, vs):
            return ArcDriver.segment(self, t0, *self.onto_ropes(qs, vs))

        def onto_ropes(self, qs, vs):
            """QS and VS with each taut rope (its gap within 1e-6, its rate within 1e-6, or
            SNAP_RATE when it was taut at the last step) put back on its length and its rate
            to 0, mass-weighted along its gradient: a model rebuilt from a state interpolated
            between output steps (an extent crossed) would find the rope a little open or
            opening and let it slacken for an instant."""
            n = len(self.bodies)
            inverse = np.array([1.0 / b.mass for b in self.bodies for _ in (0, 1)])
            q, v = np.concatenate(qs), np.concatenate(vs)
            for rope in self.ropes:
                if not isinstance(rope, ExactRope):
                    continue
                for _ in range(2):
                    gap = rope.gap(split(q, n))
                    jac, _ = rope.rows(q, v)
                    w = float(np.dot(jac * inverse, jac))
                    if abs(gap) > 1e-6 or w <= 0:
                        break
                    q = q - gap * inverse * jac / w
                jac, _ = rope.rows(q, v)
                w = float(np.dot(jac * inverse, jac))
                rate = float(np.dot(jac, v))
                # a rope taut at the last step keeps its rate 0 (the interpolated state's
                # velocities are off by up to ~1e-6 in a fast swing: O(h^3) of the cubic)
                if abs(rope.gap(split(q, n))) <= 1e-9 and w > 0 and \
                        (abs(rate) <= 1e-6 or (rope in self.in_contact and abs(rate) <= SNAP_RATE)):
                    v = v - rate * inverse * jac / w
            return split(q, n), split(v, n)

        def observe(self, t0, q0, v0, t1, q1, v1, until):
            """The samples in (t0, until], and the turning points of the swings: where a taut
            piece from a fixed point to a free body's point changes the sense it turns in
            (its angle's rate, d x d', changes sign: AMES's (:turns BODY)). A body's velocity
            reversing is no event here (a weight that rises and falls back on a rope)."""
            while self.sample_times and self.sample_times[0] <= until:
                ts = self.sample_times.pop(0)
                if ts >= t0:
                    qs, vs = self.interpolate(t0, q0, v0, t1, q1, v1, ts)
                    self.samples.append({"time": ts, "q": qs, "v": vs})
            for rope, j in self.swings:
                if abs(rope.gap(q0)) > 1e-7 or abs(rope.gap(q1)) > 1e-7:
                    self.swing_sense.pop((id(rope), j), None)   # slack: no swing
                    continue
                s0, s1 = swing_rate(rope, j, q0, v0), swing_rate(rope, j, q1, v1)
                # the sense of a swing is its rate's sign where the rate is more than
                # round-off (a piece along a slope or hanging still has none): a turn is a
                # change of that sense, not of the round-off's sign
                if abs(s1) <= swing_noise(rope, j, q1, v1):
                    continue
                last = self.swing_sense.get((id(rope), j))
                self.swing_sense[(id(rope), j)] = s1 > 0
                if last is None or last == (s1 > 0):
                    continue
                if s0 * s1 >= 0:     # the rate crossed 0 within round-off of T0
                    name = self.bodies[swing_piece(rope, j)["body"]].name
                    self.record(t0, [(":turns", name, name)], q0, v0, v0)
                    continue
                lo, hi = t0, t1
                for _ in range(200):
                    mid = 0.5 * (lo + hi)
                    qm, vm = self.interpolate(t0, q0, v0, t1, q1, v1, mid)
                    if (swing_rate(rope, j, qm, vm) > 0) == (s0 > 0):
                        lo = mid
                    else:
                        hi = mid
                    if hi - lo <= 1e-15 * max(1.0, abs(hi)):
                        break
                tm = 0.5 * (lo + hi)
                if tm <= until:
                    qm, vm = self.interpolate(t0, q0, v0, t1, q1, v1, tm)
                    name = self.bodies[swing_piece(rope, j)["body"]].name
                    self.record(tm, [(":turns", name, name)], qm, vm, vm)

        def record(self, t, pairs, qs, vs, after, speed=0.0):
            # a piece's relation is its length only along its last direction: a closing
            # recorded away from the pulley is a body passing by it, which is not modelled
            for c in self.ropes:
                if isinstance(c, PieceContact) and \
                        (c.kinds["close"],) + c.names(self.bodies) in [tuple(p) for p in pairs] and \
                        float(np.linalg.norm(c.vector(qs))) > 1e-6:
                    raise Unsupported("%s passes by the pulley of rope %s (piece %d) at %g m "
                                      "from it" % (self.bodies[c.other].name, c.rope, c.piece,
                                                   float(np.linalg.norm(c.vector(qs)))))
            ArcDriver.record(self, t, pairs, qs, vs, after, speed)

    return TurningRopeDriver(model)
