"""Centre lines of bars: straight pieces and circular arcs, sampled at equal
arc-length steps into sphere centres.

A path is a list of pieces, each a Line or an Arc, end to start. Points are
tuples (x, y, z). Tolerance: points are exact to rounding (a few ulp of the
coordinates); the first and last sphere of an open path sit exactly on the
path's given end points.
"""
import math


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    return scale(a, 1.0 / n)


class Line:
    def __init__(self, a, b):
        self.a, self.b = a, b
        self.length = norm(sub(b, a))

    def point(self, t):    # t in [0, 1]
        if t >= 1.0:
            return self.b    # the end exactly where asked
        return add(self.a, scale(sub(self.b, self.a), t))

    def end_tangent(self):
        return unit(sub(self.b, self.a))


class Arc:
    """Points centre + radius (cos u e1 + sin u e2), u in [0, angle]; e1, e2
    orthonormal, e2 the direction of travel at the start."""

    def __init__(self, centre, e1, e2, radius, angle):
        self.centre, self.e1, self.e2, self.radius, self.angle = centre, e1, e2, radius, angle
        self.length = radius * angle

    def point(self, t):
        u = self.angle * t
        return add(self.centre, scale(add(scale(self.e1, math.cos(u)), scale(self.e2, math.sin(u))),
                                      self.radius))

    def end_tangent(self):
        u = self.angle
        return add(scale(self.e1, -math.sin(u)), scale(self.e2, math.cos(u)))


def fillet_polyline(points, radius):
    """The polyline through points with every corner rounded by an arc of the
    given centre-line radius. Raises ValueError with a reason when a corner is
    a reversal or the arcs do not fit in the segments."""
    dirs = []
    for p, q in zip(points, points[1:]):
        if norm(sub(q, p)) == 0.0:
            raise ValueError("two consecutive points are the same (a zero-length segment)")
        dirs.append(unit(sub(q, p)))
    cut = [0.0] * len(points)    # tangent length taken off at each corner
    arcs = [None] * len(points)
    for i in range(1, len(points) - 1):
        u, v = dirs[i - 1], dirs[i]
        c = max(-1.0, min(1.0, dot(u, v)))
        turn = math.acos(c)
        if turn < 1e-12:
            continue    # straight on: no arc
        if math.pi - turn < 1e-9:
            raise ValueError("the polyline turns back on itself at point %d" % (i + 1))
        t = radius * math.tan(turn / 2.0)
        cut[i] = t
        w = unit(sub(v, scale(u, c)))    # towards the inside of the corner, in its plane
        start = sub(points[i], scale(u, t))
        centre = add(start, scale(w, radius))
        arcs[i] = Arc(centre, scale(w, -1.0), u, radius, turn)
    pieces = []
    for i in range(len(points) - 1):
        seg = norm(sub(points[i + 1], points[i]))
        if cut[i] + cut[i + 1] > seg * (1.0 + 1e-12):
            raise ValueError("the bends at points %d and %d do not fit in the segment between them "
                             "(%.6g needed, %.6g long)" % (i + 1, i + 2, cut[i] + cut[i + 1], seg))
        a = points[i] if i == 0 else add(points[i], scale(dirs[i], cut[i]))
        b = points[i + 1] if i + 1 == len(points) - 1 else sub(points[i + 1], scale(dirs[i], cut[i + 1]))
        if arcs[i] is not None:
            pieces.append(arcs[i])
        if norm(sub(b, a)) > 0.0:
            pieces.append(Line(a, b))
    return pieces


def hook(end, tangent, towards, radius, angle_deg, length):
    """Pieces of a hook at an open end: an arc of the given angle starting at
    `end` with direction `tangent`, turning towards `towards`, then a straight
    leg of `length`."""
    w = sub(towards, scale(tangent, dot(towards, tangent)))
    if norm(w) < 1e-12 * max(1.0, norm(towards)):
        raise ValueError("the hook direction (hook_towards) is zero or parallel to the bar's end")
    w = unit(w)
    angle = math.radians(angle_deg)
    arc = Arc(add(end, scale(w, radius)), scale(w, -1.0), tangent, radius, angle)
    a = arc.point(1.0)
    pieces = [arc]
    if length > 0.0:
        pieces.append(Line(a, add(a, scale(arc.end_tangent(), length))))
    return pieces


def reversed_pieces(pieces):
    out = []
    for p in reversed(pieces):
        if isinstance(p, Line):
            out.append(Line(p.b, p.a))
        else:
            c, s = math.cos(p.angle), math.sin(p.angle)
            e1 = add(scale(p.e1, c), scale(p.e2, s))
            e2 = sub(scale(p.e1, s), scale(p.e2, c))
            out.append(Arc(p.centre, e1, e2, p.radius, p.angle))
    return out


def total_length(pieces):
    return sum(p.length for p in pieces)


def sample(pieces, step, closed):
    """Sphere centres at equal arc-length intervals of at most `step`: both
    ends on an open path, no repeated point on a closed one. Returns
    (centres, actual interval)."""
    length = total_length(pieces)
    intervals = max(1, math.ceil(length / step * (1.0 - 1e-12)))
    if closed:
        intervals = max(3, intervals)
    count = intervals if closed else intervals + 1
    actual = length / intervals
    centres = []
    k = 0
    start = 0.0
    for index, piece in enumerate(pieces):
        last_piece = index == len(pieces) - 1
        while k < count:
            s = length * k / intervals
            if s > start + piece.length and not last_piece:
                break
            t = 1.0 if (not closed and k == count - 1) else min(1.0, (s - start) / piece.length)
            centres.append(piece.point(t))
            k += 1
        start += piece.length
    return centres, actual
