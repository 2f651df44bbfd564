"""siconos_rotation_events.py -- the events the witness for rotating bodies reports
(siconos_rotation.py lists them): found from each step's impulses and velocities.
"""

from siconos_rotation_relations import JUMP, QUIET, SPEED_TOL, Contact, Rope


class Events:
    """The event finding of RotationDriver (a mixin: it uses the driver's step, model,
    relations, probes, t_end and hinge_forces)."""

    def record(self, t, pairs, q, v, hinges=None):
        self.events.append({"time": t, "pairs": pairs, "q": q.copy(), "v": v.copy(),
                            "hinges": hinges})


    def collision_speed(self):
        """The approach speed above which a contact's closing is a collision (slower, the
        contact just starts pressing): a few times what gravity adds in a step."""
        return max(0.05, 20.0 * float(self.model.get("gravity", 0.0)) * self.step)

    def contact_events(self, tp, qp, vp, t, q, v, lams, state):
        """The events of contacts in the step from (TP, QP, VP) to (T, Q, V), LAMS the
        relations' impulses; STATE holds each contact's history (pressing or not, its last
        two forces, a pending lift-off)."""
        h = self.step
        collide = self.collision_speed()
        for k, (r, lam) in enumerate(zip(self.relations, lams)):
            if not isinstance(r, (Contact, Rope)):
                continue
            s = state.setdefault(k, {"pressing": False, "forces": [], "pending": None, "left": False})
            force = float(lam[0]) / h
            pressing = force > 1e-9
            vn0, vn1 = r.normal_speed(qp, vp), r.normal_speed(q, v)
            if pressing and not s["pressing"] and vn0 < -collide and vn1 - vn0 > JUMP:
                self.record(t, [(r.kinds["close"],) + r.names], qp, vp)
                if getattr(r, "friction", 0.0) and abs(r.tangential_speed(qp, vp)) > SPEED_TOL:
                    # Siconos's impact law is Newton-Coulomb (a tangential impulse up to mu
                    # times the normal one); AMES's impacts are frictionless: what follows
                    # an impact that slides on a rough contact is not witnessed
                    self.truncated = "an impact of %s on %s while sliding on a rough contact: " \
                        "Siconos's impacts have Coulomb friction, AMES's none" % r.names
            if isinstance(r, Contact) and r.front and (pressing or s["pressing"]) \
                    and not r.face.covers(r.point(q)):
                self.leaves(r, tp, qp, vp, q, v)   # off the end of its face: not a lift-off
                s["left"] = True
            elif pressing:
                s["left"] = False
            if s["left"]:
                s["pending"] = None
            elif s["pending"] is not None:
                if pressing:                      # it pressed again: no lift-off
                    s["pending"] = None
                elif t - s["pending"][0] >= QUIET * h or t >= self.t_end - 1e-12:
                    self.record(*s["pending"][1:])
                    s["pending"] = None
            elif s["pressing"] and not pressing and tp > 2 * h:
                tz, f = tp, 0.0
                if len(s["forces"]) == 2 and s["forces"][0] > s["forces"][1]:
                    f0, f1 = s["forces"]   # the force falls from f0 (at tp - h) to f1 (at tp)
                    f = min(1.0, f1 / (f0 - f1))
                    tz = tp + f * h
                s["pending"] = (t, tz, [(r.kinds["open"],) + r.names], qp + f * (q - qp),
                                vp + f * (v - vp))
            # the contact point's tangential speed as the step saw it: its point at QP (where
            # the relation was linearised) moving with the new velocities V, 0 when it sticks
            s1 = r.tangential_speed(qp, v) if r.friction else 0.0   # ropes have no friction
            s0, s_1 = s.get("slip"), s.get("slip before")
            s["slip"], s["slip before"] = s1, s0
            if pressing and r.friction and s["pressing"] and tp > 2 * h and s0 is not None:
                if abs(s0) > SPEED_TOL and (abs(s1) <= SPEED_TOL or s0 * s1 < 0):
                    if abs(s1) <= SPEED_TOL and s_1 is not None and s_1 * s0 > 0 and abs(s_1) > abs(s0):
                        # stuck by the end of the step: where the slip, falling as in the
                        # step before, reached 0 (exact under a constant friction); from then
                        # on the body moved with the step's end velocities V
                        f = min(1.0, s0 / (s_1 - s0))
                        self.record(tp + f * h, [(":stops-sliding",) + r.names],
                                    q - (1.0 - f) * h * v, v)
                    else:
                        f = s0 / (s0 - s1)
                        self.record(tp + f * h, [(":stops-sliding",) + r.names], qp + f * (q - qp),
                                    vp + f * (v - vp))
                elif abs(s0) <= SPEED_TOL and abs(s1) > SPEED_TOL:
                    self.record(tp, [(":starts-sliding",) + r.names], qp, vp)
            s["forces"] = (s["forces"] + [force])[-2:] if pressing else []
            s["pressing"] = pressing

    def leaves(self, r, tp, qp, vp, q, v):
        """Record (:leaves BODY FACE): the contact R's point passed an end of its face
        between TP and TP + STEP (linear interpolation of where it projects)."""
        s0, s1 = r.face.position(r.point(qp)), r.face.position(r.point(q))
        end = 0.0 if s1 < 0.0 else r.face.length
        f = min(1.0, max(0.0, (end - s0) / (s1 - s0))) if s1 != s0 else 1.0
        self.record(tp + f * self.step, [(":leaves",) + r.names], qp + f * (q - qp),
                    vp + f * (v - vp))

    def probe_events(self, tp, qp, vp, t, q, v, lams):
        for b, angle in self.probes:
            i = 3 * b.index + 2
            a0, a1 = qp[i] - angle, q[i] - angle
            if a0 != 0 and a0 * a1 <= 0:
                f = a0 / (a0 - a1)
                hinges = [(name, fv) for name, fv in self.hinge_forces(lams)]
                self.record(tp + f * (t - tp), [(":reaches", b.name, "angle")],
                            qp + f * (q - qp), vp + f * (v - vp), hinges)

    def flush_pending(self, state, q, v):
        """The lift-offs still pending when the run reaches its horizon (quiet since, but
        for fewer than QUIET steps) whose contact is opening at the end (Q, V: its normal
        speed positive): recorded. One whose bodies still approach is no lift-off (a
        contact that did not press in the last step only)."""
        for k, s in state.items():
            if s.get("pending") is not None:
                if self.relations[k].normal_speed(q, v) > SPEED_TOL:
                    self.record(*s["pending"][1:])
                s["pending"] = None

    def observe(self, tp, qp, vp, t, q, v):
        """The samples the model asks for in (TP, T] (linear interpolation inside the step),
        and the turning points of the rotating bodies: where a body's angular velocity
        changes sign (interpolated), (:turns BODY BODY)."""
        while self.sample_times and self.sample_times[0] <= t:
            ts = self.sample_times.pop(0)
            if ts >= tp:
                f = (ts - tp) / (t - tp)
                self.samples.append({"time": ts, "q": qp + f * (q - qp), "v": vp + f * (v - vp)})
        for b in self.bodies:
            i = 3 * b.index + 2
            w0, w1 = vp[i], v[i]
            if b.rotating and w0 * w1 < 0.0 and abs(w0 - w1) > 1e-9:   # not round-off about rest
                f = w0 / (w0 - w1)
                self.record(tp + f * (t - tp), [(":turns", b.name, b.name)],
                            qp + f * (q - qp), vp + f * (v - vp))
