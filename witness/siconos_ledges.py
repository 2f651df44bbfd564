"""siconos_ledges.py -- the witness's fixed corners on the faces of turning bodies (issue 23):
a ledge's edge under a falling rod, a step's corner under a tumbling block.

siconos_rotation.py models a free body's vertex against a fixed face; here is the other
vertex-face contact, a corner P of a fixed body (an end of one of its finite faces) against
a straight face of a free polygon or segment (own frame, from a to b, the solid on its
left, so its outward normal n is the direction turned a quarter clockwise), as a
Contact of the same driver (the same Moreau-Jean relation, events and projection):

  gap = n_w . (P - x - R(theta) a),   n_w = R(theta) n,
  its rate -n_w . u with u = v + omega k x r the body's velocity at P, r = P - x:
  the row [m, m . (k x r)] with m = -n_w (the direction the corner pushes the body),
  and, with friction, [t_w, t_w . (k x r)], t_w = R(theta) t.

The face holds the corner only while P, seen in the body's own frame, lies within the
face's extent and in front of it (the body's own Face, whose COVERS and POSITION the
events read: a corner passing an end of the body's face is (:leaves BODY OBSTACLE)).
It holds it only in the face's region, not on its line: a corner that is not yet held and
that, one step ahead, would be behind the face but in front of a neighbouring face of the
body (sharing an end) passes outside the body around their common vertex (the body's
corner slides off the obstacle's edge past it): no contact of that face (block-step #774).
"""

import numpy as np

from siconos_rotation_relations import FAR, MARGIN, STEP, Contact, Face, perp, rotation


def body_faces(body):
    """The straight faces (A, B) of a free polygon or segment, own frame, the solid on
    the left: a polygon's edges (its vertices counter-clockwise), a segment's one side."""
    v = body.vertices
    if body.kind == "segment":
        return [(v[0], v[1])]
    if body.kind == "polygon":
        return [(v[k], v[(k + 1) % len(v)]) for k in range(len(v))]
    return []


def obstacle_corners(obstacle):
    """The corners of a fixed body: the ends of its finite faces, each once."""
    corners = []
    for spec in obstacle["faces"]:
        if spec.get("infinite"):
            continue
        for p in (spec["a"], spec["b"]):
            p = np.array(p, dtype=float)
            if not any(float(np.linalg.norm(p - c)) < 1e-12 for c in corners):
                corners.append(p)
    return corners


class CornerContact(Contact):
    """A fixed corner against a free body's straight face (see the module's header)."""

    def __init__(self, body, a, b, corner, obstacle, n_dofs, mu, e, q0, neighbours=()):
        self.corner = np.array(corner, dtype=float)
        # the body's faces sharing an end with this one, as Faces (own frame)
        self.neighbours = [Face({"a": list(na), "b": list(nb)}, obstacle) for na, nb in neighbours]
        # the body's face in its own frame: COVERS and POSITION take the corner's
        # own-frame point (POINT)
        Contact.__init__(self, body, Face({"a": list(a), "b": list(b)}, obstacle),
                         None, n_dofs, mu, e, q0)

    def arm(self, q):
        """r = P - x, world frame."""
        i = 3 * self.body.index
        return self.corner - q[i:i + 2]

    def turn(self, q):
        return rotation(q[3 * self.body.index + 2])

    def point(self, q):
        """The corner in the body's own frame (where the body's face is)."""
        return self.turn(q).T.dot(self.arm(q))

    def gap(self, q):
        return float(np.dot(self.face.n, self.point(q) - self.face.a))

    def update_front(self, q, v=None, held=False):
        """As a Contact's, and (see the module's header) not held when, not pressing, the
        corner one step ahead (Q + STEP V) is behind the face and in front of a neighbour."""
        Contact.update_front(self, q)
        if not self.front or held or v is None or not self.neighbours:
            return
        ahead = q + STEP * np.asarray(v, dtype=float)
        p = self.point(ahead)
        if self.gap(ahead) < 0 and any(float(np.dot(f.n, p - f.a)) > 0 for f in self.neighbours):
            self.front = False

    def rows_at(self, q):
        r, turn = self.arm(q), self.turn(q)
        m, t = -turn.dot(self.face.n), turn.dot(self.face.t)
        k = 2 if self.coulomb else 1
        C = np.zeros((k, self.n_dofs))
        i = 3 * self.body.index
        for row, u in enumerate([m, t][:k]):
            C[row, i:i + 2] = u
            C[row, i + 2] = float(np.dot(u, perp(r)))
        gap = self.gap(q) if self.front else FAR
        e = np.zeros(k)
        e[0] = gap - float(C[0].dot(q)) - MARGIN
        return C, e

    def tangential_speed(self, q, v):
        r, i = self.arm(q), 3 * self.body.index
        t = self.turn(q).dot(self.face.t)
        return float(np.dot(t, v[i:i + 2] + v[i + 2] * perp(r)))


def corner_contacts(model, bodies, n_dofs, q0, friction_coefficient, restitution):
    """The CornerContacts of MODEL: each corner of each obstacle against each face of each
    free turning polygon or segment among BODIES."""
    out = []
    for obstacle in model.get("obstacles", []):
        for corner in obstacle_corners(obstacle):
            for b in bodies:
                if not (b.rotating and b.kind in ("polygon", "segment")):
                    continue
                mu = friction_coefficient(model, b.name, obstacle["name"])
                e = restitution(model, b.name, obstacle["name"])
                faces = body_faces(b)
                for k, (a, bb) in enumerate(faces):
                    near = [faces[j] for j in ((k - 1) % len(faces), (k + 1) % len(faces))
                            if len(faces) > 2 and j != k]
                    out.append(CornerContact(b, a, bb, corner, obstacle["name"], n_dofs, mu, e, q0,
                                             near))
    return out

