#!/usr/bin/env python3
"""Wall scenes of the LIGGGHTS tests (walls.sh, messages.sh): no host, no numpy.

  walls.py clip DATA_IN DATA_OUT WALL...
      Keeps the rebar (type 2) and the matrix spheres wholly on the held side
      of every wall and inside the box (a clean start: nothing touches a
      wall). --zlo Z sets the box's zlo line (a floor inside a taller box).
  walls.py check BEFORE AFTER [--tol T] [--near N] WALL...
      Every moved matrix sphere (centre or radius changed) lies wholly on the
      side of each wall where it started, at least r (1 - tol) from it, and
      the path of its centre from before to after crosses no wall. With
      --near N, at least N moved spheres end within one largest matrix
      radius of a wall (the scene tests the walls). Prints PASS or FAIL
      lines; exit status 1 on a FAIL.

  walls.py mould STL CX CY R Z0 Z1 SEGMENTS
      Writes an ASCII STL closed cylinder about the z axis through (CX, CY)
      from Z0 to Z1, as an STL mesher makes one: per segment two long slivers
      of the side spanning its height and a thin triangle of each cap's fan
      from its centre (4 * SEGMENTS triangles, vertices on the circle R).

WALL: --plane PX PY PZ NX NY NZ (held side: the normal's), --cylinder
x|y|z C1 C2 R inside|outside (C1 C2: the centre's coordinates in the other
two axes, in x y z order), --stl FILE (ASCII; spheres are held on the side
they start on).
"""
import math
import sys


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def point_segment(p, a, b):
    ab = sub(b, a)
    t = dot(sub(p, a), ab) / dot(ab, ab) if dot(ab, ab) > 0 else 0.0
    t = min(1.0, max(0.0, t))
    return norm(sub(p, (a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2])))


def point_triangle(p, tri):
    a, b, c = tri
    n = cross(sub(b, a), sub(c, a))
    nn = norm(n)
    if nn > 0:
        # Inside the prism over the triangle: the distance to its plane.
        inside = all(dot(cross(sub(v1, v0), sub(p, v0)), n) >= 0 for v0, v1 in ((a, b), (b, c), (c, a)))
        if inside:
            return abs(dot(sub(p, a), n)) / nn
    return min(point_segment(p, a, b), point_segment(p, b, c), point_segment(p, c, a))


def segment_meets_triangle(p, q, tri):
    a, b, c = tri
    n = cross(sub(b, a), sub(c, a))
    sp, sq = dot(sub(p, a), n), dot(sub(q, a), n)
    if (sp > 0 and sq > 0) or (sp < 0 and sq < 0) or sp == sq:
        return False
    t = sp / (sp - sq)
    x = (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2]))
    return all(dot(cross(sub(v1, v0), sub(x, v0)), n) >= 0 for v0, v1 in ((a, b), (b, c), (c, a)))


def read_stl(path):
    tris, cur = [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "vertex":
                cur.append(tuple(float(v) for v in w[1:4]))
                if len(cur) == 3:
                    tris.append(tuple(cur))
                    cur = []
    if not tris:
        sys.exit("walls.py: no triangle in " + path)
    return tris


class Wall:
    """clearance(x): the distance from x to the wall; crossed(a, b): the
    segment from a to b goes through it (planes and cylinders: a and b on
    different sides; a mesh: the segment meets a triangle)."""

    def __init__(self, kind, args):
        self.kind = kind
        if kind == "plane":
            v = [float(a) for a in args]
            self.p, n = tuple(v[:3]), tuple(v[3:])
            self.n = tuple(c / norm(n) for c in n)
            self.name = "plane through %s normal %s" % (self.p, self.n)
        elif kind == "cylinder":
            self.axis = "xyz".index(args[0])
            self.c = (float(args[1]), float(args[2]))
            self.r = float(args[3])
            self.inside = args[4] == "inside"
            self.name = "%s cylinder %s axis %s radius %g" % (args[4], self.c, args[0], self.r)
        else:
            self.tris = read_stl(args[0])
            self.name = "mesh %s (%d triangles)" % (args[0], len(self.tris))

    def radial(self, x):
        o = [k for k in range(3) if k != self.axis]
        return math.hypot(x[o[0]] - self.c[0], x[o[1]] - self.c[1])

    def held(self, x):    # planes and cylinders: the centre on the held side
        if self.kind == "plane":
            return dot(sub(x, self.p), self.n) >= 0
        return (self.radial(x) <= self.r) == self.inside

    def clearance(self, x):
        if self.kind == "plane":
            return abs(dot(sub(x, self.p), self.n))
        if self.kind == "cylinder":
            return abs(self.radial(x) - self.r)
        return min(point_triangle(x, t) for t in self.tris)

    def crossed(self, a, b):
        if self.kind == "stl":
            return any(segment_meets_triangle(a, b, t) for t in self.tris)
        return self.held(a) != self.held(b)


def parse_walls(args):
    walls, rest, i = [], [], 0
    sizes = {"--plane": 6, "--cylinder": 5, "--stl": 1}
    while i < len(args):
        if args[i] in sizes:
            n = sizes[args[i]]
            walls.append(Wall(args[i][2:], args[i + 1:i + 1 + n]))
            i += 1 + n
        else:
            rest.append(args[i])
            i += 1
    return walls, rest


def read_dump(path):
    """The last snapshot: {id: (type, (x, y, z), r, text)}."""
    atoms, cols, body = {}, None, False
    with open(path) as f:
        for line in f:
            if line.startswith("ITEM: ATOMS"):
                cols = line.split()[2:]
                atoms, body = {}, True
            elif line.startswith("ITEM:"):
                body = False
            elif body:
                w = line.split()
                c = {k: w[i] for i, k in enumerate(cols)}
                x = (float(c["x"]), float(c["y"]), float(c["z"]))
                atoms[int(c["id"])] = (int(c["type"]), x, float(c["radius"]),
                                       " ".join((c["x"], c["y"], c["z"], c["radius"])))
    return atoms


def clip(argv):
    walls, rest = parse_walls(argv[2:])
    zlo = rest[rest.index("--zlo") + 1] if "--zlo" in rest else None
    lines = open(argv[0]).read().split("\n")
    box = {}
    for line in lines:
        w = line.split()
        if len(w) == 4 and w[2] in ("xlo", "ylo", "zlo"):
            box[w[2][0]] = (float(zlo) if w[2] == "zlo" and zlo else float(w[0]), float(w[1]))
    out, kept, in_atoms = [], 0, False
    for line in lines:
        w = line.split()
        if line.startswith("Atoms"):
            in_atoms = True
        elif w and w[0][0].isalpha():
            in_atoms = False
        if len(w) == 4 and w[2] == "zlo" and zlo:
            line = "%s %s zlo zhi" % (zlo, w[1])
        if in_atoms and len(w) == 7:    # id type diameter density x y z
            r, x = float(w[2]) / 2, (float(w[4]), float(w[5]), float(w[6]))
            if w[1] != "2" and (
                    any(x[k] - r < box[a][0] or x[k] + r > box[a][1] for k, a in enumerate("xyz")) or
                    any(wl.clearance(x) < r or (wl.kind != "stl" and not wl.held(x)) for wl in walls)):
                continue
            kept += 1
        if w[1:] == ["atoms"]:
            line = "@ATOMS@"
        out.append(line)
    open(argv[1], "w").write("\n".join(out).replace("@ATOMS@", "%d atoms" % kept))
    print("walls.py clip: %d atoms kept" % kept)


def check(argv):
    walls, rest = parse_walls(argv[2:])
    tol = float(rest[rest.index("--tol") + 1]) if "--tol" in rest else 1e-6
    near_min = int(rest[rest.index("--near") + 1]) if "--near" in rest else 0
    before, after = read_dump(argv[0]), read_dump(argv[1])
    rmax = max(a[2] for a in before.values() if a[0] != 2)
    moved = bad = near = 0
    worst = math.inf
    for i, (t, x, r, text) in after.items():
        if t == 2 or i not in before or before[i][3] == text:
            continue
        moved += 1
        x0 = before[i][1]
        close = False
        for wl in walls:
            d = wl.clearance(x)
            worst = min(worst, (d - r) / r)
            fails = []
            if d < r * (1 - tol):
                fails.append("overlaps it: centre %.6g from it, radius %.6g" % (d, r))
            if wl.crossed(x0, x):
                fails.append("crossed it: from %s to %s" % (x0, x))
            if fails:
                bad += 1
                if bad <= 5:
                    print("atom %d and the %s: %s" % (i, wl.name, "; ".join(fails)))
            close = close or d - r < rmax
        near += close
    print("walls: %s" % "; ".join(w.name for w in walls))
    print("moved matrix spheres %d, ending within rmax %g of a wall %d, smallest gap / r %.3g" %
          (moved, rmax, near, worst))
    fail = False
    if bad:
        print("FAIL: moved spheres clear of the walls, on their side (%d bad)" % bad)
        fail = True
    else:
        print("PASS: moved spheres clear of the walls, on their side (%d moved)" % moved)
    if near < near_min:
        print("FAIL: only %d moved spheres end near a wall, expected >= %d" % (near, near_min))
        fail = True
    return 1 if fail else 0


def mould(argv):
    path = argv[0]
    cx, cy, r, z0, z1 = (float(a) for a in argv[1:6])
    segments = int(argv[6])
    if segments < 3 or not r > 0 or not z1 > z0:
        sys.exit("walls.py mould: need SEGMENTS >= 3, R > 0, Z1 > Z0")
    rim = [(cx + r * math.cos(2 * math.pi * i / segments), cy + r * math.sin(2 * math.pi * i / segments))
           for i in range(segments)]
    tris = []
    for i in range(segments):
        (x0, y0), (x1, y1) = rim[i], rim[(i + 1) % segments]
        # Counter-clockwise seen from outside: normals point out of the mould.
        tris.append(((x0, y0, z0), (x1, y1, z0), (x1, y1, z1)))
        tris.append(((x0, y0, z0), (x1, y1, z1), (x0, y0, z1)))
        tris.append(((cx, cy, z0), (x1, y1, z0), (x0, y0, z0)))
        tris.append(((cx, cy, z1), (x0, y0, z1), (x1, y1, z1)))
    with open(path, "w") as f:
        f.write("solid mould\n")
        for a, b, c in tris:
            n = cross(sub(b, a), sub(c, a))
            n = tuple(v / norm(n) for v in n)
            f.write("  facet normal %.17g %.17g %.17g\n    outer loop\n" % n)
            for v in (a, b, c):
                f.write("      vertex %.17g %.17g %.17g\n" % v)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid mould\n")
    print("walls.py mould: %d triangles in %s" % (len(tris), path))


if __name__ == "__main__":
    if len(sys.argv) < 4 or sys.argv[1] not in ("clip", "check", "mould"):
        sys.exit(__doc__)
    if sys.argv[1] == "clip":
        clip(sys.argv[2:])
    elif sys.argv[1] == "mould":
        mould(sys.argv[2:])
    else:
        sys.exit(check(sys.argv[2:]))
