#!/usr/bin/env python3
"""What a host read back against what reinforce_layout wrote (host_read.sh).
    check_read.py lammps|liggghts BARS.data CLUMP.mol READ.dump LOG
lammps: the dump holds every sphere of the data file (type 1, rebar) as
written, and the clump's spheres (type 3) where the data file has them, to
1e-12 of the box; the log's clump mass is the molecule's.
liggghts: the dump holds the clump's spheres only, in the molecule file's
shape (each sphere's offset from the clump's mean) to 1e-9 of the box."""
import re
import sys

host, data, mol, dump, log = sys.argv[1:6]
BOX = 0.4


def data_atoms(path):
    body = open(path).read().split("Atoms # sphere", 1)[1]
    return [tuple(float(v) for v in line.split()[2:]) for line in body.splitlines() if line.strip()]


def dump_atoms(path):
    lines = open(path).read().split("ITEM: ATOMS", 1)[1].splitlines()
    cols = lines[0].split()
    rows = [dict(zip(cols, line.split())) for line in lines[1:] if line.strip()]
    return [(int(r["type"]), float(r["radius"]), tuple(float(r[k]) for k in "xyz"), float(r["mass"])) for r in rows]


def section(text, name):
    block = re.search(r"\n%s\n\n(.*?)(\n\n|\Z)" % name, text, re.S).group(1)
    return [line.split()[1:] for line in block.splitlines()]


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


mol_text = open(mol).read()
coords = [tuple(float(v) for v in r) for r in section(mol_text, "Coords")]
mol_mass = sum(float(r[0]) for r in section(mol_text, "Masses"))
mol_radius = 0.5 * float(section(mol_text, "Diameters")[0][0])
centre = tuple(float(v) for v in re.search(r"# centre (\S+) (\S+) (\S+):", mol_text).groups())
read = dump_atoms(dump)
clump = [a for a in read if a[0] == (3 if host == "lammps" else 1)]
if len(clump) != len(coords):
    fail("%d spheres of the clump read, the molecule has %d" % (len(clump), len(coords)))
if any(abs(a[1] - mol_radius) > 1e-15 for a in clump):
    fail("a clump sphere has a radius other than %r" % mol_radius)
if host == "lammps":
    written = data_atoms(data)
    rebar = [a for a in read if a[0] == 1]
    worst = max(max(abs(a[2][k] - w[2 + k]) for k in range(3)) for a, w in zip(rebar, written))
    if len(rebar) != len(written) or worst > 1e-12 * BOX:
        fail("rebar read: %d of %d atoms, largest difference %g" % (len(rebar), len(written), worst))
    print("PASS: read_data add append: %d rebar spheres as written" % len(rebar))
    expected = [tuple(centre[k] + c[k] for k in range(3)) for c in coords]
    pool = {tuple(round(w[2 + k] / 1e-9) for k in range(3)): w for w in written}
    worst = 0.0
    for a in clump:
        w = pool.get(tuple(round(a[2][k] / 1e-9) for k in range(3)))
        if w is None:
            fail("clump sphere at %s is not a sphere of the data file" % (a[2],))
        worst = max(worst, max(abs(a[2][k] - w[2 + k]) for k in range(3)))
    if worst > 1e-12 * BOX:
        fail("clump placed %g from the data file's spheres" % worst)
    mass = float(re.search(r"^REBAR \d+ CLUMP \d+ MASS (\S+)", open(log).read(), re.M).group(1))
    if abs(mass - mol_mass) > 1e-12 * mol_mass:
        fail("clump mass %r, the molecule's %r" % (mass, mol_mass))
    print("PASS: molecule %s: %d spheres placed where the data file has them (largest difference %.2g), "
          "fix rigid on it, mass %.6g" % (mol, len(clump), worst, mass))
else:
    mean = [sum(a[2][k] for a in clump) / len(clump) for k in range(3)]
    worst = max(max(abs(a[2][k] - mean[k] - c[k]) for k in range(3)) for a, c in zip(clump, coords))
    if worst > 1e-9 * BOX:
        fail("the clump's shape differs from the template's by %g" % worst)
    print("PASS: multisphere template of %s: %d spheres, the shape kept (largest difference %.2g)"
          % (mol, len(clump), worst))
