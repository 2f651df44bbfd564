"""siconos_sexp.py -- the witness's answer as an s-expression (see siconos_driver.py for its
format): numbers as Lisp double-floats, names as strings, states as ((NAME (X Y)) ...).
"""


def sx_number(x):
    if x == 0:
        return "0.0d0"
    return repr(float(x)).replace("e", "d") if "e" in repr(float(x)) else repr(float(x)) + "d0"


def sx_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def sx_vec(v):
    return "(%s %s)" % (sx_number(v[0]), sx_number(v[1]))


def sx_states(names, qs, key):
    return "(" + " ".join("(%s %s)" % (sx_string(n), sx_vec(q)) for n, q in zip(names, qs)) + ")"


def print_answer(driver, t, qs, vs):
    """Print the s-expression answer of DRIVER (a translating driver that ran: its events,
    truncation and samples) ending at time T in the state (QS, VS)."""
    names = [b.name for b in driver.bodies]
    out = ["(:status :ok", " :scheme :%s" % getattr(driver, "scheme", "event-driven"), " :events ("]
    for ev in driver.events:
        pairs = " ".join("(%s %s %s)" % (p[0], sx_string(p[1]), sx_string(p[2]))
                         for p in ev["pairs"])
        out.append("  (:time %s :speed %s :pairs (%s) :positions %s :velocities %s :after %s)" % (
            sx_number(ev["time"]), sx_number(ev["speed"]), pairs, sx_states(names, ev["q"], 0),
            sx_states(names, ev["v"], 0), sx_states(names, ev["after"], 0)))
    out.append(" )")
    if driver.truncated:
        out.append(" :truncated %s" % sx_string(driver.truncated))
    if getattr(driver, "samples", None):
        out.append(" :samples (%s)" % " ".join(
            "(:time %s :positions %s :velocities %s)" % (
                sx_number(s["time"]), sx_states(names, s["q"], 0), sx_states(names, s["v"], 0))
            for s in driver.samples))
    grazes = driver.grazes(driver.model.get("samples", [])) if hasattr(driver, "grazes") else []
    if grazes:   # siconos_grazes.py
        out.append(" :grazes (%s)" % " ".join(
            "(:time %s :positions %s :velocities %s :pairs (%s))" % (
                sx_number(t), sx_states(names, q, 0), sx_states(names, v, 0),
                " ".join("(%s %s %s %s %s)" % (sx_string(a), sx_string(b), sx_number(g),
                                               sx_number(at), sx_number(rate))
                         for a, b, g, at, rate in pairs))
            for t, q, v, pairs in grazes))
    out.append(" :end (:time %s :positions %s :velocities %s))" % (
        sx_number(t), sx_states(names, qs, 0), sx_states(names, vs, 0)))
    print("\n".join(out))
