#!/usr/bin/env python3
"""reinforce_layout: lays out reinforcement (bars, bends and hooks,
stirrups, cages, meshes, random fibres) as chains of rebar spheres for
LAMMPS and LIGGGHTS, from a short text description (docs/layout.md).

  reinforce_layout DESCRIPTION [--data FILE] [--molecules FOLDER] [--liggghts FILE]

Prints what it laid out (spheres, spacing, ripple) on stdout; a bad
description stops it with one ERROR line naming the line, status 1.
"""
import argparse
import os
import signal
import sys

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))

import layout_description as D  # noqa: E402
import layout_fibres  # noqa: E402
import layout_items  # noqa: E402
import layout_writers as W  # noqa: E402

BUILDERS = {"bar": layout_items.build_bar, "polyline": layout_items.build_polyline,
            "stirrups": layout_items.build_stirrups, "cage": layout_items.build_cage,
            "mesh": layout_items.build_mesh, "fibres": layout_fibres.build_fibres}


def lay_out(items):
    """(clumps, templates, summary lines, box or None, output options)."""
    clumps, templates, summary = [], [], []
    box, options = None, {}
    for item in items:
        if item.kind == "box":
            lo, hi = item.get("lo"), item.get("hi")
            if any(hi[k] <= lo[k] for k in range(3)):
                item.error("the box must have hi > lo in every direction")
            box = (lo, hi)
        elif item.kind == "output":
            if item.get("decimals") is not None and not 0 <= item.get("decimals") <= 17:
                item.error("decimals must be 0 to 17, got %d" % item.get("decimals"))
            if item.get("ntry") is not None and item.get("ntry") < 1:
                item.error("ntry must be >= 1, got %d" % item.get("ntry"))
            options.update(item.values)
        else:
            result = BUILDERS[item.kind](item)
            names = set(c.name for c in clumps + templates)
            for c in result[0] + (result[2] if len(result) > 2 else []):
                if c.name in names:
                    item.error("the name %s is taken by an earlier item" % c.name)
            clumps += result[0]
            summary += result[1].split("\n")
            templates += result[2] if len(result) > 2 else result[0]
    return clumps, templates, summary, box, options


def bounding_box(clumps):
    lo = [min(p[k] - c.radius for c in clumps for p in c.centres) for k in range(3)]
    hi = [max(p[k] + c.radius for c in clumps for p in c.centres) for k in range(3)]
    return tuple(lo), tuple(hi)


def main(argv):
    parser = argparse.ArgumentParser(prog="reinforce_layout", description=__doc__.split("\n\n")[0])
    parser.add_argument("description")
    parser.add_argument("--data", help="LAMMPS data file (atom style sphere) of every rebar sphere")
    parser.add_argument("--molecules", help="folder for one LAMMPS molecule file per clump")
    parser.add_argument("--liggghts", help="LIGGGHTS file of particletemplate/multisphere sphere lists")
    args = parser.parse_args(argv)
    try:
        with open(args.description) as f:
            text = f.read()
    except OSError as e:
        print("reinforce_layout: ERROR: cannot read %s: %s" % (args.description, e.strerror), file=sys.stderr)
        return 1
    try:
        clumps, templates, summary, box, options = lay_out(D.parse(text))
    except D.LayoutError as e:
        print("reinforce_layout: ERROR: %s line %d: %s" % (args.description, e.line, e), file=sys.stderr)
        return 1
    if not clumps:
        print("reinforce_layout: ERROR: %s lays out nothing" % args.description, file=sys.stderr)
        return 1
    for line in summary:
        print(line)
    spheres = sum(len(c.centres) for c in clumps)
    print("total: %d clumps, %d spheres" % (len(clumps), spheres))
    extent = bounding_box(clumps)
    print("extent of the spheres: %s to %s" % (" ".join("%.6g" % v for v in extent[0]),
                                               " ".join("%.6g" % v for v in extent[1])))
    decimals = options.get("decimals")
    source = os.path.basename(args.description)
    if args.data:
        W.write_data(args.data, clumps, box or extent, summary, decimals, source)
        print("wrote %s (%d atoms)" % (args.data, spheres))
    if args.molecules:
        W.write_molecules(args.molecules, templates, summary, decimals)
        print("wrote %d molecule files in %s" % (len(templates), args.molecules))
    if args.liggghts:
        W.write_liggghts(args.liggghts, templates, summary, decimals, options.get("ntry", 1000000))
        print("wrote %s (%d multisphere templates)" % (args.liggghts, len(templates)))
    return 0


if __name__ == "__main__":
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)    # `| head`: stop quietly, as a shell tool does
    sys.exit(main(sys.argv[1:]))
