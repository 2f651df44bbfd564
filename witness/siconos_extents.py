"""siconos_extents.py -- the face extents of the translating witness (siconos_driver.py):
Siconos holds a body by a face's infinite line, so the driver itself finds where a body
enters or leaves a face's extent (on the cubic Hermite interpolant of two recorded states)
and rebuilds the model there; a body landing exactly at a face's end, in a corner, is held
by the face when the other face it hits stops the motion that would take it off.
"""

import numpy as np

from siconos_contacts import LOOK_AHEAD, hermite


class Extents:
    """The extent handling of Driver (a mixin)."""

    def corner_held(self, c, active, qs, vs):
        """Whether the face of C, not active, holds its body all the same: the body sits
        at the very end of C's face, touching it and approaching it, while touching and
        approaching another face (ACTIVE) that will stop its motion along that face's
        normal (a particle landing exactly in the corner of a floor and a step): its
        look-ahead is taken with the velocity those faces leave it."""
        if not hasattr(c, "other") or not c.covers(qs) or abs(c.gap(qs)) > 1e-7 \
                or c.rate(vs) >= -1e-9:
            return False
        v = vs[c.other].copy()
        stoppers = [d for d in active if getattr(d, "other", None) == c.other
                    and getattr(d, "owner", None) is None and abs(d.gap(qs)) <= 1e-7
                    and d.rate(vs) < -1e-9]
        if not stoppers:
            return False
        for d in stoppers:
            v = v - min(0.0, float(np.dot(v, d.n))) * d.n
        ahead = list(qs)
        ahead[c.other] = qs[c.other] + LOOK_AHEAD * v
        return c.covers(ahead)

    def extent_change(self, active, inactive, t0, q0, v0, t1, q1, v1):
        """The earliest time in (t0, t1] where an active contact's face stops covering its
        body, or an inactive one starts to (in front of it): (TIME Q V LEFT) or None."""
        best = None
        for c in active:
            if not c.covers(q1):
                best = self.earliest(best, c, t0, q0, v0, t1, q1, v1, True)
        for c in inactive:
            # entering a face's extent in front of it (judged where it enters: by the end
            # of the step the body may already be below the face's line, about to hit it)
            if c.covers(q1) and not c.covers(q0):
                tc = self.crossing(c, t0, q0, v0, t1, q1, v1)
                qc, _ = hermite(t0, np.array(q0), np.array(v0), t1, np.array(q1), np.array(v1), tc)
                if c.gap(list(qc)) >= -1e-6:
                    best = self.earliest(best, c, t0, q0, v0, t1, q1, v1, False)
        if best is None:
            return None
        tc = best[0]
        qc, vc = hermite(t0, np.array(q0), np.array(v0), t1, np.array(q1), np.array(v1), tc)
        qc = [np.array(x) for x in qc]
        vc = [np.array(x) for x in vc]
        left = [c for c in active if c.covers(q0) and not c.covers(q1)
                and abs(self.crossing(c, t0, q0, v0, t1, q1, v1) - tc) <= 1e-9]
        return tc, qc, vc, left

    def crossing(self, c, t0, q0, v0, t1, q1, v1):
        Q0, V0, Q1, V1 = np.array(q0), np.array(v0), np.array(q1), np.array(v1)
        inside0 = c.covers(q0)
        lo, hi = t0, t1
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            qm, _ = hermite(t0, Q0, V0, t1, Q1, V1, mid)
            m = min(c.margins(list(qm)))
            if (m >= 0) == inside0:
                lo = mid
            else:
                hi = mid
            if hi - lo <= 1e-15 * max(1.0, abs(hi)):
                break
        return 0.5 * (lo + hi)

    def earliest(self, best, c, t0, q0, v0, t1, q1, v1, leaving):
        tc = self.crossing(c, t0, q0, v0, t1, q1, v1)
        if best is None or tc < best[0]:
            return (tc, c)
        return best
