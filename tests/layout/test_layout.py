"""Geometry of what reinforce_layout writes, checked on its data file (the
expected values computed here from the description, independently of the
command's code). Run by ctest one class at a time:
    REINFORCE_LAYOUT=build/src/layout/reinforce_layout python3 -m unittest -v test_layout.Spacing
"""
import math
import os
import random
import re
import signal
import stat
import subprocess
import tempfile
import threading
import time
import unittest

from layout_output import COMMAND, TIMEOUT, atoms, command, lay_out, run, snapshot

EXACT = 1e-12    # relative: rounding of a few operations


def read(path, mode="r"):
    with open(path, mode) as f:
        return f.read()


def dist(a, b):
    return math.sqrt(sum((a[k] - b[k]) ** 2 for k in range(3)))


def ray_reach(origin, direction, centres, radius):
    """How far the union of spheres reaches along a ray (0 if it misses)."""
    best = 0.0
    for c in centres:
        w = [origin[k] - c[k] for k in range(3)]
        b = sum(w[k] * direction[k] for k in range(3))
        q = b * b - (sum(v * v for v in w) - radius * radius)
        if q >= 0.0:
            best = max(best, -b + math.sqrt(q))
    return best


class Spacing(unittest.TestCase):
    """Spacing and ripple as asked: the largest spacing whose envelope dips
    at most smoothness * r, the fewest spheres that keep it, and the
    envelope measured on the written spheres."""

    def check(self, r, q, length, x0=0.0):
        text = "bar from=%r,0,0 to=%r,0,0 diameter=%r smoothness=%r\n" % (x0, x0 + length, 2 * r, q)
        centres, radii, out = lay_out(text)
        gaps = [dist(a, b) for a, b in zip(centres, centres[1:])]
        s_max = 2 * r * math.sqrt(1 - (1 - q) ** 2)
        self.assertTrue(all(g <= s_max * (1 + EXACT) for g in gaps), "spacing above the smoothness's")
        self.assertGreater(length / (len(centres) - 2), s_max, "one sphere fewer would do")
        self.assertLess(max(gaps) - min(gaps), EXACT * length)
        # The envelope between the first two spheres, probed across.
        worst = min(ray_reach((x0 + gaps[0] * t / 50, 0, 0), (0, 0, 1), centres[:3], r) for t in range(51))
        ripple = 1 - worst / r
        self.assertLessEqual(ripple, q * (1 + 1e-9))
        self.assertAlmostEqual(ripple, 1 - math.sqrt(1 - (gaps[0] / (2 * r)) ** 2), delta=1e-9)
        said = re.search(r"spacing ([0-9.e+-]+) to ([0-9.e+-]+).*largest ripple ([0-9.e+-]+)", out)
        self.assertIsNotNone(said, out)
        self.assertAlmostEqual(float(said.group(1)), gaps[0], delta=1e-5 * gaps[0])
        self.assertAlmostEqual(float(said.group(3)), ripple, delta=1e-3 * ripple)
        self.assertTrue(all(x == r for x in radii))

    def test_smooth(self):
        self.check(0.005, 0.01, 0.49)

    def test_rough(self):
        self.check(0.005, 0.357, 0.49)

    def test_tiny_and_far(self):    # micro units, far from the origin (a metre: 1e6 radii)
        self.check(1e-6, 0.05, 3e-4, 1.0)

    def test_spacing_key_is_a_largest_spacing(self):
        centres, _, out = lay_out("bar from=0.005,0.04,0.04 to=0.495,0.04,0.04 diameter=0.01 spacing=0.00766\n")
        self.assertEqual(len(centres), 65)
        self.assertIn("spacing 0.00765625", out)

    def test_header_says_the_spacing(self):
        status, out, err, folder = run("bar from=0,0,0 to=1,0,0 diameter=0.1 smoothness=0.1\n", "data")
        header = read(os.path.join(folder, "rebar.data")).split("atoms")[0]
        self.assertRegex(header, r"# line 1 bar: .*spacing [0-9.]+ to [0-9.]+ \(smoothness 0.1 asked\)")


class Ends(unittest.TestCase):
    """The first and last sphere exactly at the ends asked; hooks ending
    where their bend radius and leg put them."""

    def test_straight_ends_exact(self):
        a, b = (0.1, -0.2, 0.3), (0.7, 0.4, -0.05)
        centres, _, _ = lay_out("bar from=%r,%r,%r to=%r,%r,%r diameter=0.02\n" % (a + b))
        self.assertEqual(centres[0], a)
        self.assertEqual(centres[-1], b)

    def hook_end(self, angle, leg):
        d, mandrel = 0.01, 0.03
        rc = mandrel + d / 2
        text = ("bar from=0,0,0 to=1,0,0 diameter=%r bend=%r hook_end=%d hook_length=%r hook_towards=0,0,1\n"
                % (d, mandrel, angle, leg))
        centres, _, _ = lay_out(text)
        t = math.radians(angle)
        arc_end = (1 + rc * math.sin(t), 0, rc * (1 - math.cos(t)))
        return centres, [arc_end[0] + leg * math.cos(t), 0, arc_end[2] + leg * math.sin(t)]

    def test_hooks(self):
        for angle in (90, 135, 180):
            centres, expected = self.hook_end(angle, 0.1)
            self.assertLess(dist(centres[-1], expected), 1e-12, "hook %d" % angle)
            self.assertEqual(centres[0], (0.0, 0.0, 0.0))

    def test_hook_at_start_mirrors_the_end(self):
        text = "bar from=0,0,0 to=1,0,0 diameter=0.01 hook_start=180 hook_length=0.05 hook_towards=0,1,0\n"
        centres, _, _ = lay_out(text)
        rc = 0.02 + 0.005
        self.assertLess(dist(centres[0], (0.05, 2 * rc, 0)), 1e-12)
        self.assertEqual(centres[-1], (1.0, 0.0, 0.0))


class Bends(unittest.TestCase):
    """A polyline's corner is an arc: centres on it at mandrel + bar radius
    from the bend's centre, the straight parts on their lines, and the
    ripple on the outside of the bend within the smoothness."""

    def test_right_angle(self):
        d, mandrel, q = 0.01, 0.02, 0.05
        rc = mandrel + d / 2
        text = "polyline points=0,0,0;0.3,0,0;0.3,0.2,0 bend=%r diameter=%r smoothness=%r\n" % (mandrel, d, q)
        centres, _, _ = lay_out(text)
        centre = (0.3 - rc, rc, 0.0)
        on_arc = 0
        for c in centres:
            self.assertEqual(c[2], 0.0)
            if c[0] > 0.3 - rc + 1e-12 and c[1] < rc - 1e-12:
                on_arc += 1
                self.assertAlmostEqual(dist(c, centre), rc, delta=1e-12)
            elif c[1] < rc - 1e-12:
                self.assertEqual(c[1], 0.0) if c[0] < 0.3 - rc - 1e-9 else None
            else:
                self.assertAlmostEqual(c[0], 0.3, delta=1e-12)
        self.assertGreater(on_arc, 3)
        # No sphere near the kink's corner: the path is rounded.
        self.assertGreater(min(dist(c, (0.3, 0, 0)) for c in centres), rc * (math.sqrt(2) - 1) * 0.99)
        # The envelope on the outside of the bend, probed radially.
        worst = 1.0
        for k in range(1, 200):
            a = -math.pi / 2 + (math.pi / 2) * k / 200
            n = (math.cos(a), math.sin(a), 0.0)
            o = (centre[0] + rc * n[0], centre[1] + rc * n[1], 0.0)
            worst = min(worst, ray_reach(o, n, centres, d / 2) / (d / 2))
        self.assertGreaterEqual(worst, 1 - q - 1e-9)

    def test_corners_in_3d_and_straight_on(self):
        text = "polyline points=0,0,0;0.1,0,0;0.2,0,0;0.2,0.1,0.1 bend=0.01 diameter=0.005\n"
        centres, _, _ = lay_out(text)
        self.assertEqual(centres[0], (0.0, 0.0, 0.0))
        self.assertEqual(centres[-1], (0.2, 0.1, 0.1))
        gaps = [dist(a, b) for a, b in zip(centres, centres[1:])]
        self.assertLess(max(gaps), 0.005)


class Cage(unittest.TestCase):
    """Stirrups closed and at their spacing; the longitudinal bars inside
    the stirrups' corners, touching the inner corner."""

    TEXT = ("cage axis=x from=0.03 to=0.47 centre=0.1,0.125 width=0.2 height=0.25 cover=0.02 "
            "diameter=%r stirrup_diameter=0.006 every=0.07 stirrups_from=0.04 bars_bottom=3 bars_top=2 "
            "stirrup_bend=%r smoothness=0.02\n")

    def lay(self, db, mandrel):
        centres, radii, _ = lay_out(self.TEXT % (db, mandrel))
        stirrup = [c for c, r in zip(centres, radii) if r == 0.003]
        bars = [c for c, r in zip(centres, radii) if r == db / 2]
        return stirrup, bars

    def check(self, db, mandrel):
        stirrup, bars = self.lay(db, mandrel)
        rs, rb = 0.003, db / 2
        planes = sorted(set(c[0] for c in stirrup))
        self.assertEqual(planes, [0.04 + 0.07 * k for k in range(7)])
        first = [c for c in stirrup if c[0] == planes[0]]
        gaps = [dist(a, b) for a, b in zip(first, first[1:] + first[:1])]    # closed loop
        # Equal arc-length steps: the closing step (on the bottom leg) as
        # long as the first, the chords on the corners shorter.
        self.assertAlmostEqual(gaps[-1], gaps[0], delta=1e-12)
        self.assertLessEqual(max(gaps), gaps[0] * (1 + 1e-12))
        # Outer size of the stirrup: section minus cover.
        self.assertAlmostEqual(max(c[1] for c in first) - min(c[1] for c in first) + 2 * rs, 0.16, delta=1e-12)
        self.assertAlmostEqual(max(c[2] for c in first) - min(c[2] for c in first) + 2 * rs, 0.21, delta=1e-12)
        axes = sorted(set((c[1], c[2]) for c in bars))
        self.assertEqual(len(axes), 5)
        ys = [a[0] for a in axes]
        corner = [a for a in axes if a[0] in (min(ys), max(ys))]
        self.assertEqual(len(corner), 4)
        for y, z in corner:
            near = min(math.hypot(c[1] - y, c[2] - z) for c in first)
            # touching: the centres rb + rs apart, the chords only shorten it
            self.assertGreaterEqual(near, (rb + rs) * (1 - 1e-12))
            self.assertLess(near, rb + rs + 0.02 * rs * 2)
            self.assertTrue(min(c[1] for c in first) < y < max(c[1] for c in first))
            self.assertTrue(min(c[2] for c in first) < z < max(c[2] for c in first))
            # in the corner: nearer the corner than the section's middle
            self.assertGreater(abs(y - 0.1), 0.05)
            self.assertGreater(abs(z - 0.125), 0.07)

    def test_stirrups_item(self):
        text = "stirrups axis=z from=0.1 to=0.5 every=0.15 centre=0.2,0.3 width=0.1 height=0.2 diameter=0.008\n"
        centres, _, out = lay_out(text)
        self.assertEqual(sorted(set(c[2] for c in centres)), [0.1, 0.25, 0.4])
        self.assertIn("3 stirrups", out)
        xs, ys = [c[0] for c in centres], [c[1] for c in centres]
        self.assertAlmostEqual(max(xs) - min(xs) + 0.008, 0.1, delta=1e-12)
        self.assertAlmostEqual(max(ys) - min(ys) + 0.008, 0.2, delta=1e-12)
        self.assertAlmostEqual((max(xs) + min(xs)) / 2, 0.2, delta=1e-12)

    def test_bar_on_the_corner_arc(self):    # the corner's inner radius holds the bar
        self.check(0.012, 0.02)

    def test_bar_on_both_legs(self):    # a tight corner: the bar rests on both legs
        self.check(0.02, 0.006)


class Mesh(unittest.TestCase):
    def test_two_families(self):
        text = "mesh corner=0,0,0.1 a=0.4,0,0 b=0,0.3,0 every_a=0.1 every_b=0.1 diameter=0.008 diameter_b=0.006\n"
        centres, radii, _ = lay_out(text)
        a_bars = sorted(set(c[1] for c, r in zip(centres, radii) if r == 0.004))
        b_bars = sorted(set(c[0] for c, r in zip(centres, radii) if r == 0.003))
        self.assertEqual(len(a_bars), 4)
        self.assertEqual(len(b_bars), 5)
        self.assertTrue(all(c[2] == 0.1 for c, r in zip(centres, radii) if r == 0.004))
        self.assertTrue(all(abs(c[2] - 0.107) < 1e-15 for c, r in zip(centres, radii) if r == 0.003))


def segment_distance_search(p0, p1, q0, q1):
    """Distance between segments by golden-section search over the first
    segment (distance to the second is convex along it)."""
    def to_second(s):
        p = [p0[k] + (p1[k] - p0[k]) * s for k in range(3)]
        d = [q1[k] - q0[k] for k in range(3)]
        t = sum((p[k] - q0[k]) * d[k] for k in range(3)) / sum(v * v for v in d)
        t = min(1.0, max(0.0, t))
        return dist(p, [q0[k] + d[k] * t for k in range(3)])
    lo, hi = 0.0, 1.0
    g = (math.sqrt(5) - 1) / 2
    for _ in range(80):
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        if to_second(a) < to_second(b):
            hi = b
        else:
            lo = a
    return min(to_second(0.5 * (lo + hi)), to_second(0.0), to_second(1.0))


class Fibres(unittest.TestCase):
    """Random fibres: inside their box, at their volume fraction, isotropic
    or in a plane, apart when asked, the same bytes from the same seed."""
    LO, HI = (0.0, 0.0, 0.0), (0.1, 0.08, 0.06)

    def fibres(self, extra, length=0.03, d=0.002):
        text = "fibres lo=0,0,0 hi=0.1,0.08,0.06 length=%r diameter=%r %s\n" % (length, d, extra)
        centres, radii, out = lay_out(text)
        n = int(re.search(r"fibres: (\d+) fibres", out).group(1))
        per = len(centres) // n
        self.assertEqual(per * n, len(centres))
        return [centres[k * per:(k + 1) * per] for k in range(n)], radii[0], out

    def test_inside_the_box(self):
        fibres, r, _ = self.fibres("count=300 seed=3")
        for f in fibres:
            for c in f:
                for k in range(3):
                    self.assertGreaterEqual(c[k] - r, self.LO[k])
                    self.assertLessEqual(c[k] + r, self.HI[k])
            self.assertAlmostEqual(dist(f[0], f[-1]) + 2 * r, 0.03, delta=1e-12)

    def test_volume_fraction(self):
        fraction, length, d = 0.02, 0.03, 0.002
        fibres, r, out = self.fibres("fraction=%r seed=11" % fraction, length, d)
        volume = 0.1 * 0.08 * 0.06
        one = math.pi * r * r * (length - d) + 4 / 3 * math.pi * r ** 3
        self.assertLessEqual(abs(len(fibres) * one - fraction * volume), 0.5 * one)
        # Measured: points at random, the share inside a sphere of a fibre.
        rng = random.Random(1)
        n, inside = 20000, 0
        cells = {}
        for f in fibres:
            for c in f:
                cells.setdefault(tuple(int(c[k] / 0.004) for k in range(3)), []).append(c)
        for _ in range(n):
            p = (0.1 * rng.random(), 0.08 * rng.random(), 0.06 * rng.random())
            key = tuple(int(p[k] / 0.004) for k in range(3))
            if any(dist(p, c) <= r for i in (-1, 0, 1) for j in (-1, 0, 1) for k in (-1, 0, 1)
                   for c in cells.get((key[0] + i, key[1] + j, key[2] + k), ())):
                inside += 1
        sigma = math.sqrt(fraction * (1 - fraction) / n)
        # The chain is smaller than the spherocylinder by its ripple (<= 5%).
        self.assertLess(abs(inside / n - fraction), 4 * sigma + 0.05 * fraction)

    def test_isotropic(self):
        fibres, _, _ = self.fibres("count=400 seed=5", 0.01, 0.001)
        cosines = [abs(f[-1][2] - f[0][2]) / dist(f[0], f[-1]) for f in fibres]
        mean = sum(cosines) / len(cosines)    # uniform on the sphere: |cos| has mean 1/2, sd 1/sqrt(12)
        self.assertLess(abs(mean - 0.5), 4 / math.sqrt(12 * len(cosines)))

    def test_in_a_plane(self):
        fibres, _, _ = self.fibres("count=50 seed=5 orientation=plane normal=y", 0.02, 0.001)
        for f in fibres:
            self.assertLess(abs(f[-1][1] - f[0][1]), 1e-12)

    def test_apart(self):
        fibres, r, out = self.fibres("fraction=0.03 seed=7 apart=yes", 0.03, 0.002)
        self.assertIn("apart", out)
        closest = 1.0
        for i, f in enumerate(fibres):
            for g in fibres[i + 1:]:
                if dist(f[len(f) // 2], g[len(g) // 2]) < 0.03:
                    closest = min(closest, segment_distance_search(f[0], f[-1], g[0], g[-1]))
        self.assertGreaterEqual(closest, 2 * r * (1 - 1e-9))

    def test_without_apart_they_cross(self):    # the test above can fail
        fibres, r, _ = self.fibres("fraction=0.03 seed=7", 0.03, 0.002)
        closest = min(segment_distance_search(f[0], f[-1], g[0], g[-1])
                      for i, f in enumerate(fibres) for g in fibres[i + 1:]
                      if dist(f[len(f) // 2], g[len(g) // 2]) < 0.03)
        self.assertLess(closest, 2 * r)

    def test_same_seed_same_bytes(self):
        text = "fibres lo=0,0,0 hi=0.1,0.1,0.1 length=0.03 diameter=0.001 count=100 seed=42 apart=yes\n"
        written = []
        for _ in range(2):
            status, _, err, folder = run(text, "data", "liggghts")
            self.assertEqual(status, 0, err)
            written.append(read(os.path.join(folder, "rebar.data"), "rb"))
        self.assertEqual(written[0], written[1])
        _, _, _, folder = run(text.replace("seed=42", "seed=43"), "data")
        self.assertNotEqual(read(os.path.join(folder, "rebar.data"), "rb"), written[0])


DOCS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "layout.md")
ALL_OUTPUTS = ("data", "molecules", "liggghts")
GOOD = "bar from=0,0,0 to=1,0,0 diameter=0.01\n"    # one clump, bar_l1


def refused(test, status, out, err, gist):
    """Status 1, nothing on stdout, one ERROR line on stderr holding gist;
    returns the line."""
    test.assertEqual(status, 1, err)
    test.assertEqual(out, "")
    lines = err.splitlines()
    test.assertEqual(len(lines), 1, err)
    test.assertTrue(lines[0].startswith("reinforce_layout: ERROR: "), lines[0])
    test.assertIn(gist, lines[0])
    return lines[0]


def documented():
    """The examples of docs/layout.md's Errors tables: the backquoted text
    of each row's last cell."""
    section = read(DOCS).split("\n## Errors\n", 1)[1].split("\n## ", 1)[0]
    rows = [line for line in section.splitlines() if line.startswith("| ") and not line.startswith("| refused")]
    return set(g for row in rows for g in re.findall(r"`([^`]*)`", row.rsplit(" | ", 1)[1]))


class BadDescriptions(unittest.TestCase):
    """A bad description: status 1, one ERROR line on stderr naming the
    item's line and the fault, nothing on stdout, and nothing written of
    any output. One case per check of docs/layout.md's Errors tables; the
    faulty item is the case's last line."""
    CASES = [
        # the text
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 =3", "expected key=value"),
        ("rod from=0,0,0 to=1,0,0", "unknown item 'rod'"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 colour=red", "unknown key 'colour'"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 diameter=0.02", "key 'diameter' given twice"),
        ("bar to=1,0,0 diameter=0.01", "bar needs from="),
        ("bar from=0,0,0 to=1,0,0", "bar needs diameter="),
        ("cage axis=x from=0 to=1 centre=0,0 width=0.3 height=0.3 cover=0.02 every=0.5 diameter=0.01",
         "cage needs stirrup_diameter="),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 type=1_0", "expected a number, got '1_0'"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 type=0x10", "expected a number, got '0x10'"),
        ("bar from=0,0,0 to=1,0,0 diameter=\u0661", "expected a number, got '\u0661'"),    # an Arabic-Indic 1
        ("bar from=0,0,0 to=1,0,0 diameter=one", "expected a number, got 'one'"),
        ("bar from=0,0,0 to=nan,0,0 diameter=0.01", "expected a finite number, got 'nan'"),
        ("bar from=0,0,0 to=1,0,0 diameter=inf", "expected a finite number, got 'inf'"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 spacing=-1e400", "expected a finite number"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 type=1.5", "expected a whole number"),
        ("bar from=0,0,0 to=1,0 diameter=0.01", "expected 3 comma-separated numbers"),
        ("polyline points=0,0,0 diameter=0.01", "expected at least two points"),
        ("stirrups axis=w from=0 to=1 every=0.5 centre=0,0 width=0.1 height=0.1 diameter=0.01",
         "expected one of x, y, z"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 name=1st", "a name is a letter then letters, digits or _"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 hook_end=45", "a hook is 90, 135, 180 or none"),
        ("fibres lo=0,0,0 hi=1,1,1 length=0.1 diameter=0.01 count=5 fraction=0.01 seed=1",
         "give count= or fraction=, not both"),
        ("fibres lo=0,0,0 hi=1,1,1 length=0.1 diameter=0.01 seed=1", "fibres need count= or fraction="),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 spacing=0.005 smoothness=0.1",
         "give spacing= or smoothness=, not both"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 &", "the item ends with & but no line follows"),
        ("defaults diameter=0.01 name=top", "name= is for one item, not for defaults"),
        ("box lo=0,0,0 hi=1,1,1\nbox lo=0,0,0 hi=2,2,2", "a second box item (the first is line 3)"),
        ("output decimals=3\nbar from=0,0,0 to=1,0,0 diameter=0.01\noutput ntry=10", "a second output item"),
        # the items
        ("box lo=0,0,0 hi=1,0,1", "the box must have hi > lo in every direction"),
        ("fibres lo=0,0,0 hi=1,1,-1 length=0.1 diameter=0.01 count=5 seed=1",
         "the box must have hi > lo in every direction"),
        ("output decimals=18", "decimals must be 0 to 17"),
        ("output ntry=0", "ntry must be >= 1"),
        (GOOD + "bar from=0,1,0 to=1,1,0 diameter=0.01 name=top\nbar from=0,2,0 to=1,2,0 diameter=0.01 name=top",
         "the name top is taken by an earlier item"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 name=bar_l4\n" + GOOD.strip(),
         "the name bar_l4 is taken by an earlier item"),
        ("bar from=0,0,0 to=1,0,0 diameter=-0.01", "diameter must be > 0"),
        ("cage axis=x from=0 to=1 centre=0,0 width=0.3 height=0.3 cover=0.02 every=0.5 diameter=0.01 "
         "stirrup_diameter=0", "stirrup_diameter must be > 0"),
        ("mesh corner=0,0,0 a=1,0,0 b=0,1,0 every_a=0.5 every_b=0.5 diameter=0.01 diameter_b=-0.01",
         "diameter_b must be > 0"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 type=0", "type must be >= 1"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 density=0", "density must be > 0"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 spacing=0.02", "spacing must be > 0 and < the diameter"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 smoothness=1.5", "smoothness must be > 0 and < 1"),
        ("polyline points=0,0,0;1,0,0;1,1,0 diameter=0.01 bend=0.002",
         "bend: the mandrel radius 0.002 is tighter than the bar"),
        ("cage axis=x from=0 to=1 centre=0,0 width=0.3 height=0.3 cover=0.02 every=0.5 diameter=0.01 "
         "stirrup_diameter=0.006 stirrup_bend=0.001", "stirrup_bend: the mandrel radius 0.001 is tighter than the bar"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 hook_end=90 hook_length=-0.1", "hook_length must be >= 0"),
        ("bar from=0,0,0 to=0,0,1 diameter=0.01 hook_end=90", "is zero or parallel to the bar's end"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 hook_start=180 hook_towards=0,0,0",
         "is zero or parallel to the bar's end"),
        ("bar from=0,0,0 to=0,0,0 diameter=0.01", "zero-length bar"),
        ("polyline points=0,0,0;0,0,0;1,0,0 diameter=0.01", "zero-length segment"),
        ("polyline points=0,0,0;1,0,0;0,0,0 diameter=0.01", "turns back on itself"),
        ("polyline points=0,0,0;0.05,0,0;0.05,0.05,0 diameter=0.01 bend=0.1", "do not fit in the segment"),
        ("stirrups axis=x from=0 to=1 every=0 centre=0,0 width=0.1 height=0.1 diameter=0.01", "every must be > 0"),
        ("mesh corner=0,0,0 a=1,0,0 b=0,1,0 every_a=-0.5 every_b=0.5 diameter=0.01", "every_a must be > 0"),
        ("stirrups axis=x from=1 to=0 every=0.5 centre=0,0 width=0.1 height=0.1 diameter=0.01",
         "to (0) must not be below from (1)"),
        ("cage axis=x from=0 to=1 centre=0,0 width=0.3 height=0.3 cover=0.02 every=0.1 diameter=0.01 "
         "stirrup_diameter=0.006 stirrups_from=0.3 stirrups_to=0.1",
         "stirrups_to (0.1) must not be below stirrups_from (0.3)"),
        ("stirrups axis=x from=0 to=1 every=0.5 centre=0,0 width=0.03 height=0.1 diameter=0.01",
         "is too small for its bends"),
        ("cage axis=x from=1 to=1 centre=0,0 width=0.3 height=0.3 cover=0.02 every=0.5 diameter=0.01 "
         "stirrup_diameter=0.006", "zero-length cage"),
        ("cage axis=x from=0 to=1 centre=0,0 width=0.1 height=0.1 cover=0.06 every=0.1 diameter=0.01 "
         "stirrup_diameter=0.006", "leaves no room"),
        ("cage axis=x from=0 to=1 centre=0,0 width=0.3 height=0.3 cover=0.02 every=0.5 diameter=0.01 "
         "stirrup_diameter=0.006 bars_top=1", "bars_bottom and bars_top must be >= 2"),
        ("cage axis=x from=0 to=1 centre=0,0 width=0.3 height=0.3 cover=0.02 every=0.5 diameter=0.01 "
         "stirrup_diameter=0.006 bars_bottom=30", "do not fit side by side"),
        ("cage axis=x from=0 to=1 centre=0,0 width=0.3 height=0.3 cover=0.02 every=0.5 diameter=0.01 "
         "stirrup_diameter=0.006 bars_bottom=1e9", "do not fit side by side"),    # refused before it is laid out
        ("mesh corner=0,0,0 a=0,0,0 b=0,1,0 every_a=0.5 every_b=0.5 diameter=0.01", "zero-length mesh side"),
        ("mesh corner=0,0,0 a=1,0,0 b=2,0,0 every_a=0.1 every_b=0.1 diameter=0.01", "a and b are parallel"),
        ("fibres lo=0,0,0 hi=1,1,1 length=0.01 diameter=0.01 count=5 seed=1", "must be longer than the diameter"),
        ("fibres lo=0,0,0 hi=1,1,1 length=0.1 diameter=0.01 count=5 seed=1 normal=y",
         "normal= is for orientation=plane"),
        ("fibres lo=0,0,0 hi=0.02,0.1,0.1 length=0.03 diameter=0.001 count=5 seed=1",
         "is longer than its box's smallest edge"),
        ("fibres lo=0,0,0 hi=1,1,0.02 length=0.03 diameter=0.001 count=5 seed=1 orientation=plane normal=x",
         "is longer than its box's smallest edge"),
        ("fibres lo=0,0,0 hi=1,1,1 length=0.1 diameter=0.01 count=0 seed=1", "count must be >= 1"),
        ("fibres lo=0,0,0 hi=1,1,1 length=0.1 diameter=0.01 fraction=1 seed=1", "fraction must be > 0 and < 1"),
        ("fibres lo=0,0,0 hi=1,1,1 length=0.1 diameter=0.01 fraction=1e-9 seed=1", "is less than one fibre"),
        ("fibres lo=0,0,0 hi=1,1,1 length=0.1 diameter=0.01 count=5 seed=1 tries=0", "tries must be >= 1"),
        ("fibres lo=0,0,0 hi=1,1,1 length=0.1 diameter=0.01 count=5 seed=-1", "seed must be >= 0"),
        ("fibres lo=0,0,0 hi=0.1,0.1,0.1 length=0.05 diameter=0.01 count=5000 seed=1 apart=yes tries=20",
         "found no place apart"),
        ("bar from=0,0,0 to=1,0,0 diameter=0.01 smoothness=1e-300", "would need more than 10000000 spheres"),
        ("stirrups axis=x from=0 to=1000 every=0.001 centre=0,0 width=0.1 height=0.1 diameter=0.01",
         "spheres in one item"),
        ("fibres lo=0,0,0 hi=1,1,1 length=0.1 diameter=0.01 count=20000000 seed=1", "spheres in one item"),
        ("stirrups axis=x from=0 to=1 every=1e-300 centre=0,0 width=0.1 height=0.1 diameter=0.01",
         "repeats more than 10000000 times"),
        ("bar from=0,0,0 to=1,0,0 diameter=1e308", "the numbers overflow double precision"),
        ("stirrups axis=x from=0 to=1 every=1 centre=0,0 width=1e308 height=1e308 diameter=0.01",
         "the numbers overflow double precision"),
        ("fibres lo=-1e308,-1e308,-1e308 hi=1e308,1e308,1e308 length=0.1 diameter=0.01 fraction=0.5 seed=1",
         "the numbers overflow double precision"),
    ]
    NOTHING = ["", "# only a comment\n", "box lo=0,0,0 hi=1,1,1\noutput decimals=3\ndefaults diameter=0.01\n"]

    def test_each(self):
        for text, gist in self.CASES:
            with self.subTest(text=text):
                status, out, err, folder = run("# a comment line\n\n" + text + "   # trailing comment\n", *ALL_OUTPUTS)
                line = refused(self, status, out, err, gist)
                where = r"^reinforce_layout: ERROR: \S*description.txt line %d: " % (3 + text.count("\n"))
                self.assertRegex(line, where)
                self.assertEqual(os.listdir(folder), ["description.txt"])

    def test_nothing_laid_out(self):
        for text in self.NOTHING:
            with self.subTest(text=text):
                status, out, err, folder = run(text, *ALL_OUTPUTS)
                refused(self, status, out, err, "description.txt lays out nothing")
                self.assertEqual(os.listdir(folder), ["description.txt"])

    def test_every_documented_check_tested(self):
        """Each example of the Errors tables is in a case's gist, and each
        case's gist holds one of them."""
        tested = set(g for _, g in self.CASES) | {"description.txt lays out nothing", BadOutputs.STDOUT}
        tested |= set(g for _, g, _ in BadArguments.CASES) | set(g for _, g, _ in BadOutputs.CASES)
        docs = documented()
        self.assertGreater(len(docs), 50)
        self.assertEqual(sorted(d for d in docs if not any(d in t for t in tested)), [], "documented, not tested")
        self.assertEqual(sorted(t for t in tested if not any(d in t for d in docs)), [], "tested, not documented")

    def test_continued_item_names_its_first_line(self):
        status, _, err, _ = run("# two items\nbar from=0,0,0 &\n  # a comment inside\n  to=1,0,0 diameter=0.01\n"
                                "bar from=0,0,0 &\n    to=1,0,0 &\n    diameter=-1\n")
        self.assertEqual(status, 1)
        self.assertIn("line 5: diameter must be > 0", err)
        status, _, err, _ = run("bar from=0,0,0 to=1,0,0 diameter=0.01 &\n")
        self.assertIn("line 1: the item ends with & but no line follows", err)

    def test_good_lines_before_a_bad_one(self):
        status, _, err, _ = run("bar from=0,0,0 to=1,0,0 diameter=0.01\nbar from=0,0,0 to=1,0,0 diameter=0\n")
        self.assertEqual(status, 1)
        self.assertIn("line 2: diameter must be > 0", err)

    def test_numbers_in_every_notation_taken(self):    # the check that refuses 1_0 and 0x10 takes these
        status, _, err, folder = run("bar from=-0,+.5,0. to=1e0,5E-1,0 diameter=1.e-2 type=2 density=7.8e3\n", "data")
        self.assertEqual(status, 0, err)
        rows = atoms(os.path.join(folder, "rebar.data"))
        self.assertEqual(rows[0], (2, 0.01, 0.0, 0.5, 0.0))
        self.assertEqual(rows[-1][2:], (1.0, 0.5, 0.0))

    def test_byte_order_mark_and_latin1_comment(self):
        folder = tempfile.mkdtemp(prefix="layout_test.")
        with open(os.path.join(folder, "d.layout"), "wb") as f:
            f.write(b"\xef\xbb\xbf# B\xfcgel\n" + GOOD.encode())
        status, out, err = command(["d.layout"], folder)
        self.assertEqual(status, 0, err)
        self.assertIn("line 2 bar: 1 bar", out)


class BadArguments(unittest.TestCase):
    """A bad command line: status 1 (not argparse's 2), one ERROR line
    naming it, nothing on stdout, and nothing written or changed."""
    # (arguments, gist as documented, what else the line names)
    CASES = [
        ([], "the following arguments are required: description", "usage: reinforce_layout DESCRIPTION"),
        (["description.txt", "--colour", "red", "--data", "rebar.data"], "unrecognized arguments:", "--colour red"),
        (["description.txt", "other.txt", "--data", "rebar.data"], "unrecognized arguments:", "other.txt"),
        (["description.txt", "--data"], "expected one argument", "--data"),
        (["missing.txt", "--data", "rebar.data"], "cannot read", "missing.txt: No such file or directory"),
        (["adir", "--data", "rebar.data"], "cannot read", "adir: Is a directory"),
        (["description.txt", "--data", "description.txt"], "are the same path", "the description and --data"),
        (["description.txt", "--data", "out", "--liggghts", "./out"], "are the same path", "--data and --liggghts"),
        (["description.txt", "--molecules", "mol", "--liggghts", "adir/../mol"], "are the same path",
         "--molecules and --liggghts"),
    ]

    def test_each(self):
        for args, gist, detail in self.CASES:
            with self.subTest(args=args):
                folder = tempfile.mkdtemp(prefix="layout_test.")
                with open(os.path.join(folder, "description.txt"), "w") as f:
                    f.write(GOOD)
                os.mkdir(os.path.join(folder, "adir"))
                before = snapshot(folder)
                status, out, err = command(args, folder)
                self.assertIn(detail, refused(self, status, out, err, gist))
                self.assertEqual(snapshot(folder), before)

    def test_help_is_no_error(self):
        status, out, err = command(["--help"], tempfile.gettempdir())
        self.assertEqual((status, err), (0, ""))
        self.assertIn("usage: reinforce_layout", out)


class BadOutputs(unittest.TestCase):
    """An output that cannot be written: status 1, one ERROR line naming
    it, nothing on stdout, and no output written, none half written, none
    changed (an existing file keeps its bytes, a --molecules folder made
    for the run is gone again)."""
    # Arguments after the description, run in a folder holding afile, an
    # empty folder adir, old.data, and mol/ with keep.txt and a folder
    # where bar_l1.mol would go; the outputs before the failing one are
    # written first (data, molecules, liggghts, in that order).
    CASES = [
        (["--data", "missing/dir/x.data", "--liggghts", "t.liggghts"], "cannot write",
         "missing/dir/x.data: No such file or directory"),
        (["--data", "adir", "--molecules", "newmol"], "cannot write", "adir: Is a directory"),
        (["--data", "new.data", "--liggghts", "adir"], "cannot write", "adir: Is a directory"),
        (["--data", "afile/x.data"], "cannot write", "afile/x.data: Not a directory"),
        (["--data", "newdir/", "--molecules", "newmol"], "cannot write", "newdir/: Is a directory"),
        (["--liggghts", "", "--data", "new.data"], "cannot write", "write : No such file or directory"),
        (["--data", "new.data", "--liggghts", "missing/t.liggghts"], "cannot write",
         "missing/t.liggghts: No such file or directory"),
        (["--molecules", "afile", "--data", "new.data"], "cannot write", "afile: Not a directory"),
        (["--molecules", "afile/sub/mol"], "cannot write", "afile: Not a directory"),
        (["--data", "new.data", "--molecules", "mol"], "cannot write", "mol/bar_l1.mol: Is a directory"),
        (["--data", "new.data", "--molecules", "new/deeper/mol", "--liggghts", "adir"], "cannot write",
         "adir: Is a directory"),
        (["--data", "old.data", "--molecules", "newmol", "--liggghts", "missing/t.liggghts"], "cannot write",
         "missing/t.liggghts"),
    ]
    STDOUT = "cannot write standard output"

    def setUp(self):    # also for each case: one that wrote would spoil the next
        self.folder = tempfile.mkdtemp(prefix="layout_test.")
        for name, text in (("description.txt", GOOD), ("afile", "a file\n"), ("old.data", "old data\n"),
                           ("mol/keep.txt", "kept\n")):
            os.makedirs(os.path.dirname(os.path.join(self.folder, name)), exist_ok=True)
            with open(os.path.join(self.folder, name), "w") as f:
                f.write(text)
        os.mkdir(os.path.join(self.folder, "adir"))
        os.mkdir(os.path.join(self.folder, "mol", "bar_l1.mol"))
        self.before = snapshot(self.folder)

    def test_each(self):
        for args, gist, detail in self.CASES:
            with self.subTest(args=args):
                self.setUp()
                status, out, err = command(["description.txt"] + args, self.folder)
                self.assertIn(detail, refused(self, status, out, err, gist))
                self.assertEqual(snapshot(self.folder), self.before)

    def test_absolute_missing_folder(self):
        target = os.path.join(self.folder, "nonexistent", "dir", "x.data")
        status, out, err = command(["description.txt", "--data", target, "--molecules", "newmol"], self.folder)
        self.assertIn(target + ": No such file or directory", refused(self, status, out, err, "cannot write"))
        self.assertEqual(snapshot(self.folder), self.before)

    def test_write_error(self):
        """A pipe whose reader goes away: the write itself fails."""
        pipe = os.path.join(self.folder, "pipe")
        os.mkfifo(pipe)
        reader = threading.Thread(target=lambda: open(pipe, "rb").close(), daemon=True)
        reader.start()
        # 30,000 spheres: more than a pipe holds, so a write meets the closed end
        text = "bar from=0,0,0 to=100,0,0 diameter=0.01 spacing=0.0033\n"
        with open(os.path.join(self.folder, "description.txt"), "w") as f:
            f.write(text)
        before = snapshot(self.folder)
        status, out, err = command(["description.txt", "--data", "new.data", "--molecules", "newmol",
                                    "--liggghts", "pipe"], self.folder)
        self.assertIn("pipe: Broken pipe", refused(self, status, out, err, "cannot write"))
        self.assertEqual(snapshot(self.folder), before)
        self.assertTrue(stat.S_ISFIFO(os.stat(pipe).st_mode))

    def test_stopped_leaves_nothing(self):
        """Stopped while it waits to write a pipe nobody reads (the data
        file staged by then): no temporary file left, no traceback."""
        for signum in (signal.SIGTERM, signal.SIGINT):
            with self.subTest(signal=signum):
                self.setUp()
                os.mkfifo(os.path.join(self.folder, "pipe"))
                before = snapshot(self.folder)
                p = subprocess.Popen([COMMAND, "description.txt", "--data", "new.data", "--molecules", "newmol",
                                      "--liggghts", "pipe"], cwd=self.folder, stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE)
                waited = 0.0
                while not any(n.startswith(".new.data.") for n in os.listdir(self.folder)) and waited < TIMEOUT:
                    time.sleep(0.05)
                    waited += 0.05
                p.send_signal(signum)
                out, err = p.communicate(timeout=TIMEOUT)
                self.assertEqual((p.returncode, out, err), (128 + signum, b"", b""))
                self.assertEqual(snapshot(self.folder), before)

    def test_standard_output_full(self):
        if not os.path.exists("/dev/full"):
            self.skipTest("no /dev/full")
        with open("/dev/full", "w") as full:
            status, _, err = command(["description.txt", "--data", "new.data", "--molecules", "newmol"], self.folder,
                                     stdout=full)
        self.assertIn("No space left on device", refused(self, status, "", err, self.STDOUT))
        self.assertEqual(snapshot(self.folder), self.before)


class Outputs(unittest.TestCase):
    """The molecule file and the LIGGGHTS sphere list hold the data file's
    spheres, relative to the clump's centre; clumps named as asked."""

    def test_names(self):
        text = ("bar from=0,0,0 to=1,0,0 diameter=0.01 name=top\n"
                "cage axis=x from=0 to=1 centre=0.1,0.1 width=0.2 height=0.2 cover=0.02 every=0.5 "
                "diameter=0.012 stirrup_diameter=0.006 name=beam\n"
                "fibres lo=0,0,0 hi=0.1,0.1,0.1 length=0.03 diameter=0.001 count=3 seed=1\n")
        status, _, err, folder = run(text, "molecules", "liggghts")
        self.assertEqual(status, 0, err)
        self.assertEqual(sorted(os.listdir(os.path.join(folder, "mol"))),
                         ["beam_bar_1.mol", "beam_bar_2.mol", "beam_bar_3.mol", "beam_bar_4.mol",
                          "beam_stirrup_1.mol", "beam_stirrup_2.mol", "beam_stirrup_3.mol", "fibre_l3.mol",
                          "top.mol"])
        variables = re.findall(r"^variable (\S+) string", read(os.path.join(folder, "templates.liggghts")), re.M)
        self.assertEqual(len(variables), 9)
        status, _, err, folder = run(text.replace("seed=1", "seed=1 templates=each"), "molecules")
        self.assertEqual(sorted(f for f in os.listdir(os.path.join(folder, "mol")) if f.startswith("fibre")),
                         ["fibre_l3_1.mol", "fibre_l3_2.mol", "fibre_l3_3.mol"])
        status, _, err, _ = run(text + "bar from=0,1,0 to=1,1,0 diameter=0.01 name=top\n", "data")
        self.assertEqual(status, 1)
        self.assertIn("line 4: the name top is taken by an earlier item", err)

    def test_molecule_and_template(self):
        text = "bar from=0.1,0.2,0.3 to=0.5,0.2,0.3 diameter=0.01 density=7850 hook_end=90\n"
        status, _, err, folder = run(text, "data", "molecules", "liggghts")
        self.assertEqual(status, 0, err)
        rows = atoms(os.path.join(folder, "rebar.data"))
        centre = [sum(r[2 + k] for r in rows) / len(rows) for k in range(3)]
        mol = read(os.path.join(folder, "mol", "bar_l1.mol"))
        coords = re.search(r"Coords\n\n(.*?)\n\n", mol, re.S).group(1).splitlines()
        self.assertEqual(len(coords), len(rows))
        for line, row in zip(coords, rows):
            v = [float(x) for x in line.split()[1:]]
            self.assertLess(dist([v[k] + centre[k] for k in range(3)], row[2:]), 1e-15)
        masses = re.search(r"Masses\n\n(.*)", mol, re.S).group(1).split()
        self.assertAlmostEqual(float(masses[1]), 7850 * 4 / 3 * math.pi * 0.005 ** 3, delta=1e-15)
        lig = read(os.path.join(folder, "templates.liggghts"))
        m = re.search(r'variable bar_l1 string "nspheres (\d+) ntry 1000000 spheres ([^"]*)"', lig)
        self.assertEqual(int(m.group(1)), len(rows))
        values = [float(x) for x in m.group(2).split()]
        for k, row in enumerate(rows):
            self.assertLess(dist([values[4 * k + j] + centre[j] for j in range(3)], row[2:]), 1e-15)
            self.assertEqual(values[4 * k + 3], 0.005)

    def test_nothing_beside_the_outputs(self):    # the temporary files are gone, the old files replaced
        folder = tempfile.mkdtemp(prefix="layout_test.")
        with open(os.path.join(folder, "description.txt"), "w") as f:
            f.write(GOOD)
        os.mkdir(os.path.join(folder, "mol"))
        for name in ("rebar.data", "mol/bar_l1.mol", "mol/other.mol"):
            with open(os.path.join(folder, name), "w") as f:
                f.write("old\n")
        os.chmod(os.path.join(folder, "rebar.data"), 0o640)
        status, out, err = command(["description.txt", "--data", "rebar.data", "--molecules", "mol",
                                    "--liggghts", "t.liggghts"], folder)
        self.assertEqual(status, 0, err)
        self.assertEqual(sorted(snapshot(folder)), ["description.txt", "mol", "mol/bar_l1.mol", "mol/other.mol",
                                                    "rebar.data", "t.liggghts"])
        self.assertEqual(read(os.path.join(folder, "mol", "other.mol")), "old\n")
        self.assertIn("Coords", read(os.path.join(folder, "mol", "bar_l1.mol")))
        self.assertEqual(len(atoms(os.path.join(folder, "rebar.data"))), 322)
        self.assertEqual(stat.S_IMODE(os.stat(os.path.join(folder, "rebar.data")).st_mode), 0o640)
        self.assertIn("wrote rebar.data (322 atoms)", out)

    def test_pipe_written_in_place(self):    # renamed over, a pipe (or /dev/null) would become a file
        folder = tempfile.mkdtemp(prefix="layout_test.")
        with open(os.path.join(folder, "description.txt"), "w") as f:
            f.write(GOOD)
        pipe = os.path.join(folder, "pipe")
        os.mkfifo(pipe)
        got = []
        reader = threading.Thread(target=lambda: got.append(read(pipe)), daemon=True)
        reader.start()
        status, _, err = command(["description.txt", "--data", "rebar.data", "--liggghts", "pipe"], folder)
        reader.join(TIMEOUT)
        self.assertEqual(status, 0, err)
        self.assertTrue(stat.S_ISFIFO(os.stat(pipe).st_mode))
        self.assertRegex(got[0] if got else "", r'variable bar_l1 string "nspheres 322 ')
        self.assertEqual(sorted(os.listdir(folder)), ["description.txt", "pipe", "rebar.data"])

    def test_reader_gone_files_written(self):    # `| head`: no error, the files still in place
        folder = tempfile.mkdtemp(prefix="layout_test.")
        with open(os.path.join(folder, "description.txt"), "w") as f:
            f.write(GOOD)
        p = subprocess.Popen([COMMAND, "description.txt", "--data", "rebar.data"], cwd=folder,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        p.stdout.close()
        err = p.stderr.read()
        self.assertEqual((p.wait(TIMEOUT), err), (0, b""))
        self.assertEqual(len(atoms(os.path.join(folder, "rebar.data"))), 322)


if __name__ == "__main__":
    unittest.main()
