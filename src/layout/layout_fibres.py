"""Random straight fibres in a box: isotropic or in a plane, by count or
volume fraction, optionally apart (no two closer than a diameter, axis to
axis). Python's Mersenne Twister with the given seed, drawn only through
random(): the same seed gives the same fibres, byte for byte.
"""
import math
import random

import layout_items as I
import layout_paths as P

MAX_TRIES = 1000


def segment_distance(p0, p1, q0, q1):
    """Shortest distance between segments p0-p1 and q0-q1 (exact for
    parallel and degenerate segments; clamped parameters)."""
    d1, d2, r = P.sub(p1, p0), P.sub(q1, q0), P.sub(p0, q0)
    a, e, f = P.dot(d1, d1), P.dot(d2, d2), P.dot(d2, r)
    c, b = P.dot(d1, r), P.dot(d1, d2)
    denom = a * e - b * b
    s = min(1.0, max(0.0, (b * f - c * e) / denom)) if denom > 1e-14 * a * e else 0.0
    t = (b * s + f) / e
    if t < 0.0:
        t, s = 0.0, min(1.0, max(0.0, -c / a))
    elif t > 1.0:
        t, s = 1.0, min(1.0, max(0.0, (b - c) / a))
    return P.norm(P.sub(P.add(p0, P.scale(d1, s)), P.add(q0, P.scale(d2, t))))


def fibre_volume(radius, length):
    """The spherocylinder the chain stands for, `length` tip to tip: a
    cylinder and two caps."""
    return math.pi * radius * radius * (length - 2.0 * radius) + 4.0 / 3.0 * math.pi * radius ** 3


def direction(rng, orientation, normal):
    phi = 2.0 * math.pi * rng.random()
    if orientation == "plane":
        d = [0.0, 0.0, 0.0]
        _, iu, iv = I.AXES[normal]
        d[iu], d[iv] = math.cos(phi), math.sin(phi)
        return tuple(d)
    z = 2.0 * rng.random() - 1.0    # uniform on the sphere (Archimedes)
    s = math.sqrt(max(0.0, 1.0 - z * z))
    return (s * math.cos(phi), s * math.sin(phi), z)


class Grid:
    """Fibre axes by the cell of their midpoint; cells a fibre length (tip
    to tip) wide, so any axis closer than a diameter is in the 27 cells."""

    def __init__(self, lo, cell):
        self.lo, self.cell, self.cells = lo, cell, {}

    def key(self, p):
        return tuple(int(math.floor((p[k] - self.lo[k]) / self.cell)) for k in range(3))

    def near(self, p):
        i, j, k = self.key(p)
        for di in (-1, 0, 1):
            for dj in (-1, 0, 1):
                for dk in (-1, 0, 1):
                    yield from self.cells.get((i + di, j + dj, k + dk), ())

    def add(self, p, segment):
        self.cells.setdefault(self.key(p), []).append(segment)


def build_fibres(item):
    chain = I.Chain(item)
    r = chain.radius
    lo, hi = item.get("lo"), item.get("hi")
    length = item.get("length")
    if length <= 2.0 * r:
        item.error("length (tip to tip) must be longer than the diameter %g, got %g" % (2.0 * r, length))
    axis = length - 2.0 * r    # the centre line
    edges = [hi[k] - lo[k] for k in range(3)]
    if min(edges) <= 0.0:
        item.error("the box must have hi > lo in every direction")
    orientation = item.get("orientation", "isotropic")
    normal = item.get("normal", "z")
    if "normal" in item.values and orientation != "plane":
        item.error("normal= is for orientation=plane")
    _, iu, iv = I.AXES[normal]
    span = [edges[iu], edges[iv]] if orientation == "plane" else edges
    if length > min(span):
        item.error("a fibre of length %g is longer than its box's smallest edge %g" % (length, min(span)))
    volume = edges[0] * edges[1] * edges[2]
    if "count" in item.values:
        count = item.get("count")
        if count < 1:
            item.error("count must be >= 1, got %d" % count)
    else:
        fraction = item.get("fraction")
        if not 0.0 < fraction < 1.0:
            item.error("fraction must be > 0 and < 1, got %g" % fraction)
        count = int(round(fraction * volume / fibre_volume(r, length)))
        if count < 1:
            item.error("fraction %g of this box is less than one fibre" % fraction)
    apart = item.get("apart", "no") == "yes"
    tries = item.get("tries", MAX_TRIES)
    if tries < 1:
        item.error("tries must be >= 1, got %d" % tries)
    if item.get("seed") < 0:    # Python seeds with |seed|: -5 would silently repeat 5
        item.error("seed must be >= 0, got %d" % item.get("seed"))
    rng = random.Random(item.get("seed"))
    grid = Grid(lo, length)
    template = chain.chain([P.Line((-0.5 * axis, 0.0, 0.0), (0.5 * axis, 0.0, 0.0))], closed=False)
    chain.repeated(count, len(template))
    clumps = []
    for n in range(count):
        for attempt in range(tries):
            d = direction(rng, orientation, normal)
            # Centre anywhere the whole fibre (caps included) stays in the box.
            half = [abs(d[k]) * 0.5 * axis + r for k in range(3)]
            c = tuple(lo[k] + half[k] + (edges[k] - 2.0 * half[k]) * rng.random() for k in range(3))
            a, b = P.sub(c, P.scale(d, 0.5 * axis)), P.add(c, P.scale(d, 0.5 * axis))
            if not apart or all(segment_distance(a, b, p, q) >= 2.0 * r for p, q in grid.near(c)):
                break
        else:
            item.error("fibre %d of %d found no place apart from the others in %d tries: "
                       "ask for fewer fibres or apart=no" % (n + 1, count, tries))
        grid.add(c, (a, b))
        centres = [P.add(c, P.scale(d, t[0])) for t in template]
        centres[0], centres[-1] = a, b
        clumps.append(chain.clump("fibre_l%d_%d" % (item.line, n + 1), centres))
    achieved = count * fibre_volume(r, length) / volume
    summary = chain.summary("fibres", count, count * len(template)) + (
        "; volume fraction %.6g (as spherocylinders of the length and diameter), %s" %
        (achieved, "apart" if apart else "may cross"))
    if item.get("templates", "one") == "each":
        return clumps, summary, clumps    # a molecule file and sphere list per fibre, in place
    return clumps, summary, [chain.clump("fibre_l%d" % item.line, template)]
