"""The three outputs: a LAMMPS data file (atom style sphere, for
`read_data FILE add append group rebar`), a LAMMPS molecule file per
clump (for `create_atoms ... mol` and `fix rigid`), and LIGGGHTS
`particletemplate/multisphere` sphere lists (as string variables).
Coordinates are written with full precision (the shortest text that reads
back as the same double), or rounded to `decimals` when the description
asks.
"""
import math
import os


def formatter(decimals):
    if decimals is None:
        return repr
    return lambda v: "%.*f" % (decimals, v)


def sphere_mass(radius, density):
    return density * 4.0 / 3.0 * math.pi * radius ** 3


def centre_of(centres):
    n = float(len(centres))
    return tuple(sum(c[k] for c in centres) / n for k in range(3))


def comments(summary):
    return "".join("# %s\n" % line for line in summary)


def write_data(path, clumps, box, summary, decimals, source):
    f = formatter(decimals)
    atoms = sum(len(c.centres) for c in clumps)
    with open(path, "w") as out:
        out.write("reinforce_layout: %d rebar spheres in %d clumps from %s\n" % (atoms, len(clumps), source))
        out.write(comments(summary))
        out.write("\n%d atoms\n%d atom types\n\n" % (atoms, max(c.type for c in clumps)))
        for k, name in enumerate("xyz"):
            out.write("%s %s %slo %shi\n" % (f(box[0][k]), f(box[1][k]), name, name))
        out.write("\nAtoms # sphere\n\n")
        n = 0
        for c in clumps:
            d = f(2.0 * c.radius)
            for x, y, z in c.centres:
                n += 1
                out.write("%d %d %s %s %s %s %s\n" % (n, c.type, d, f(c.density), f(x), f(y), f(z)))


def relative(clump):
    centre = centre_of(clump.centres)
    return centre, [tuple(p[k] - centre[k] for k in range(3)) for p in clump.centres]


def write_molecules(folder, clumps, summary, decimals):
    f = formatter(decimals)
    os.makedirs(folder, exist_ok=True)
    names = []
    for c in clumps:
        centre, coords = relative(c)
        path = os.path.join(folder, c.name + ".mol")
        mass = sphere_mass(c.radius, c.density)
        with open(path, "w") as out:
            out.write("reinforce_layout: %s, %d spheres, coordinates relative to its centre\n" % (c.name, len(coords)))
            out.write("# centre %s %s %s: create_atoms 0 single %s %s %s mol ID SEED rotate 0 0 0 1 units box\n"
                      % ((f(centre[0]), f(centre[1]), f(centre[2])) * 2))
            out.write("# puts it where the description laid it\n")
            out.write(comments(summary))
            out.write("\n%d atoms\n\nCoords\n\n" % len(coords))
            for i, (x, y, z) in enumerate(coords, start=1):
                out.write("%d %s %s %s\n" % (i, f(x), f(y), f(z)))
            out.write("\nTypes\n\n")
            out.write("".join("%d %d\n" % (i, c.type) for i in range(1, len(coords) + 1)))
            out.write("\nDiameters\n\n")
            out.write("".join("%d %s\n" % (i, f(2.0 * c.radius)) for i in range(1, len(coords) + 1)))
            out.write("\nMasses\n\n")
            out.write("".join("%d %r\n" % (i, mass) for i in range(1, len(coords) + 1)))
        names.append(path)
    return names


def write_liggghts(path, clumps, summary, decimals, ntry):
    f = formatter(decimals)
    with open(path, "w") as out:
        out.write("# reinforce_layout: LIGGGHTS particletemplate/multisphere sphere lists, one string\n")
        out.write("# variable per clump, relative to the clump's centre (x y z r per sphere):\n")
        out.write("#   fix ID all particletemplate/multisphere SEED atom_type T density constant D ${NAME} type 1\n")
        out.write(comments(summary))
        for c in clumps:
            centre, coords = relative(c)
            spheres = " ".join("%s %s %s %s" % (f(x), f(y), f(z), f(c.radius)) for x, y, z in coords)
            out.write("# %s: centre %s %s %s\n" % (c.name, f(centre[0]), f(centre[1]), f(centre[2])))
            out.write('variable %s string "nspheres %d ntry %d spheres %s"\n' % (c.name, len(coords), ntry, spheres))
