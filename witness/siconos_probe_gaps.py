"""siconos_probe_gaps.py -- the gap of a pair along a motion given to the witness (not
simulated): AMES's own motion over a state, to say whether a strike the first-order witness
finds is a graze below its resolution (src/witness/compare-grazes.lisp).

The model (as for siconos_rotation.py) has "gap_probe": {"pair": [A, B], "motion":
[[T, [[X, Y, THETA, VX, VY, OMEGA] per free body, in the model's order]], ...]}; the answer
is

  (:status :ok :least-gap G :at T :speed V)

G the least gap of the pair's contacts (the rotation witness's relations: a body's vertex or
disc or point on a fixed face, a fixed corner on a body's face) whose faces cover their
contact points from in front (as the driver's relations), over the motion's samples
after its start (the least of each gap's minima: a contact the state starts with that
opens at once is no approach) (an upper bound of the motion's least gap:
sampled), T where, and V the largest speed of the bodies' material points at those
contacts over the motion (the witness's error of position over a step is of order V times
its step); or (:status :unsupported :message ...) when the pair has no such contact.
"""

import numpy as np

from siconos_rotation_relations import GAP_TOL, perp


def probe_gaps(model):
    from siconos_rotation import RotationDriver
    probe = model["gap_probe"]
    pair = set(probe["pair"])
    driver = RotationDriver(model)
    contacts = [c for c in driver.contacts if set(c.names) == pair]
    if not contacts:
        return '(:status :unsupported :message "no contact of that pair")'
    best, speed = None, 0.0
    front, series = {}, {}
    for t, states in probe["motion"]:
        q = np.array([x for s in states for x in s[:3]], dtype=float)
        v = np.array([x for s in states for x in s[3:6]], dtype=float)
        for c in contacts:
            # as the driver's relations: a contact counts while its face covers its point,
            # from a sample where it is in front of the face (a point that enters the
            # extent behind the face's line is beside the obstacle, not in it); a point
            # that then sinks behind the face keeps counting (a negative gap)
            if not c.face.covers(c.point(q)):
                front[c] = False
            elif c.gap(q) >= -GAP_TOL:
                front[c] = True
            if not front.get(c):
                continue
            i = 3 * c.body.index
            world = c.corner if hasattr(c, "corner") else c.point(q)
            w = v[i:i + 2] + (v[i + 2] * perp(world - q[i:i + 2]) if c.body.rotating else 0.0)
            speed = max(speed, float(np.linalg.norm(w)))
            series.setdefault(c, []).append((c.gap(q), t))
    # the least of the gaps' minima after the state's start (a contact the state starts
    # with and that opens at once is no approach): a sample below its neighbours, or the
    # last one where a gap still falls
    for c, gaps in series.items():
        for k in range(1, len(gaps)):
            g, t = gaps[k]
            if g <= gaps[k - 1][0] and (k == len(gaps) - 1 or g <= gaps[k + 1][0]):
                if best is None or g < best[0]:
                    best = (g, t)
    if best is None:
        return '(:status :unsupported :message "the pair\'s faces never cover its points")'
    from siconos_sexp import sx_number
    return "(:status :ok :least-gap %s :at %s :speed %s)" % (sx_number(best[0]), sx_number(best[1]),
                                                             sx_number(speed))
