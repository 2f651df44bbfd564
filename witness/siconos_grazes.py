"""siconos_grazes.py -- the witness's least gaps near given times (contacts reached with no
approach speed).

A contact reached with no approach speed (a light mass of an Atwood machine coming back to
the floor exactly at rest) is a double root of its gap: Lsodar's root finding, a change of
sign, cannot see it, and the witness has no event there. The comparator then checks AMES's
event against the witness's trajectory instead (src/witness/compare-grazes.lisp): the
driver records its states (TRACE, at every output step and on both sides of each event) and
reports, at each time the model asks for ("samples"), the state there and, for every pair
of a body and an obstacle or body whose gap comes near zero, the least gap of that pair
within WINDOW of the time, where it is least, and its rate there:

  :grazes ((:time T :positions (...) :velocities (...)
            :pairs (("A" "B" LEAST-GAP AT RATE) ...)) ...)

Between two recorded states the motion is the cubic Hermite interpolant (exact under
constant forces); the least gap is found by sampling it and a golden section.
"""

import math

import numpy as np

from siconos_contacts import hermite

WINDOW = 0.01      # s each side of the time asked for
NEAR = 1e-3        # pairs whose least gap is below this are reported


class Trace:
    """The driver's recorded states (a mixin of siconos_driver.Driver)."""

    def trace(self, t, qs, vs):
        """Record the state (T QS VS), when the model asks for states at given times."""
        if not self.model.get("samples"):
            return
        if not hasattr(self, "trajectory"):
            self.trajectory = []
        self.trajectory.append((float(t), [np.array(q, dtype=float) for q in qs],
                                [np.array(v, dtype=float) for v in vs]))

    def intervals(self, lo, hi):
        """The recorded smooth intervals ((t0 q0 v0) (t1 q1 v1)) meeting [LO, HI]."""
        path = getattr(self, "trajectory", [])
        return [(a, b) for a, b in zip(path, path[1:])
                if b[0] > a[0] + 1e-12 and b[0] >= lo and a[0] <= hi]

    def state_at(self, t):
        """The recorded motion's state at T (the last interval holding it), or None."""
        found = None
        for a, b in self.intervals(t, t):
            if a[0] - 1e-12 <= t <= b[0] + 1e-12:
                found = (a, b)
        if found is None:
            return None
        (t0, q0, v0), (t1, q1, v1) = found
        q, v = hermite(t0, np.array(q0), np.array(v0), t1, np.array(q1), np.array(v1), t)
        return [np.array(x) for x in q], [np.array(x) for x in v]

    def pair_gap(self, pair, qs):
        """The least gap of the contacts of PAIR (two names, either order) whose faces cover
        the body at QS, or None."""
        gaps = []
        for c in self.contacts:
            if not hasattr(c, "other") or not hasattr(c, "names"):
                continue
            if set(c.names(self.bodies)) != set(pair) or not c.covers(qs):
                continue
            gaps.append((c.gap(qs), c))
        return min(gaps, key=lambda x: x[0]) if gaps else None

    def least_gap(self, pair, t):
        """(GAP AT RATE): the least gap of PAIR within WINDOW of T on the recorded motion."""
        best = None
        for (t0, q0, v0), (t1, q1, v1) in self.intervals(t - WINDOW, t + WINDOW):
            lo, hi = max(t0, t - WINDOW), min(t1, t + WINDOW)
            if hi < lo:
                continue

            def gap(s):
                q, _ = hermite(t0, np.array(q0), np.array(v0), t1, np.array(q1), np.array(v1), s)
                found = self.pair_gap(pair, [np.array(x) for x in q])
                return math.inf if found is None else found[0]
            n = 64
            times = [lo + (hi - lo) * k / n for k in range(n + 1)]
            values = [gap(s) for s in times]
            k = min(range(n + 1), key=lambda i: values[i])
            a, b = times[max(0, k - 1)], times[min(n, k + 1)]
            ratio = (math.sqrt(5) - 1) / 2
            for _ in range(100):
                c, d = b - ratio * (b - a), a + ratio * (b - a)
                if gap(c) < gap(d):
                    b = d
                else:
                    a = c
                if b - a <= 1e-14 * max(1.0, abs(b)):
                    break
            s = 0.5 * (a + b)
            g = min((gap(s), s), (values[k], times[k]))
            if g[0] < math.inf and (best is None or g[0] < best[0]):
                best = (g[0], g[1], t0, q0, v0, t1, q1, v1)
        if best is None:
            return None
        g, s, t0, q0, v0, t1, q1, v1 = best
        q, v = hermite(t0, np.array(q0), np.array(v0), t1, np.array(q1), np.array(v1), s)
        qs, vs = [np.array(x) for x in q], [np.array(x) for x in v]
        _, c = self.pair_gap(pair, qs)
        return g, s, c.rate(vs)

    def grazes(self, times):
        """For each time of TIMES: (T QS VS PAIRS), PAIRS ((A B GAP AT RATE) ...) the pairs
        whose least gap within WINDOW is below NEAR."""
        pairs = sorted({tuple(c.names(self.bodies)) for c in self.contacts
                        if hasattr(c, "other") and hasattr(c, "names")})
        out = []
        for t in times:
            state = self.state_at(t)
            if state is None:
                continue
            near = []
            for pair in pairs:
                found = self.least_gap(pair, t)
                if found is not None and found[0] < NEAR:
                    near.append(pair + found)
            out.append((t, state[0], state[1], near))
        return out
