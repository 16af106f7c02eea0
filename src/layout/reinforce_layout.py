#!/usr/bin/env python3
"""reinforce_layout: lays out reinforcement (bars, bends and hooks,
stirrups, cages, meshes, random fibres) as chains of rebar spheres for
LAMMPS and LIGGGHTS, from a short text description (docs/layout.md).

  reinforce_layout DESCRIPTION [--data FILE] [--molecules FOLDER] [--liggghts FILE]

Prints what it laid out (spheres, spacing, ripple) on stdout. Any problem
(the command line, the description, an output) stops it with one ERROR
line on stderr and status 1, nothing written (docs/layout.md lists them).
"""
import argparse
import math
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


USAGE = "reinforce_layout DESCRIPTION [--data FILE] [--molecules FOLDER] [--liggghts FILE]"


class Failure(Exception):
    """A problem that stops the command: its one line, after the ERROR prefix."""


class Arguments(argparse.ArgumentParser):
    def error(self, message):    # argparse's usage block and status 2: one line and status 1 as elsewhere
        raise Failure("%s (usage: %s)" % (message, USAGE))


def build(item):
    """An item's clumps, with numbers beyond double precision refused (a
    typo such as 1e308 for a length, not a scene)."""
    try:
        result = BUILDERS[item.kind](item)
        for c in result[0] + (result[2] if len(result) > 2 else []):
            if not (math.isfinite(W.sphere_mass(c.radius, c.density)) and
                    all(math.isfinite(abs(v) + c.radius) for p in c.centres for v in p)):
                raise OverflowError("a sphere's extent or mass beyond 1e308")
    except ArithmeticError as e:
        raise D.LayoutError(item.line, "the numbers overflow double precision (%s)" % (e.args[-1] if e.args else e))
    return result


def lay_out(items):
    """(clumps, templates, summary lines, box or None, output options)."""
    clumps, templates, summary = [], [], []
    box, options = None, {}
    first = {}    # line of the box and output items: one of each
    for item in items:
        if item.kind in ("box", "output"):
            if item.kind in first:
                item.error("a second %s item (the first is line %d)" % (item.kind, first[item.kind]))
            first[item.kind] = item.line
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
            result = build(item)
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


def read_description(path):
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise Failure("cannot read %s: %s" % (path, e.strerror or e))
    # utf-8-sig: a byte-order mark is no part of the first item. Bytes that
    # are not UTF-8 pass in comments; in a value its check refuses them.
    return data.decode("utf-8-sig", errors="surrogateescape")


def distinct_paths(args):
    """No two outputs, nor an output and the description, on one path (the
    later would replace the earlier). Devices such as /dev/null may repeat."""
    named = [("the description", args.description), ("--data", args.data),
             ("--molecules", args.molecules), ("--liggghts", args.liggghts)]
    seen = {}
    for option, path in named:
        if path is None:
            continue
        if os.path.exists(path) and not (os.path.isfile(path) or os.path.isdir(path)):
            continue
        real = os.path.realpath(path)
        if real in seen:
            raise Failure("%s and %s are the same path %s" % (seen[real], option, path))
        seen[real] = option


def run(argv, outputs):
    parser = Arguments(prog="reinforce_layout", description=__doc__.split("\n\n")[0])
    parser.add_argument("description")
    parser.add_argument("--data", help="LAMMPS data file (atom style sphere) of every rebar sphere")
    parser.add_argument("--molecules", help="folder for one LAMMPS molecule file per clump")
    parser.add_argument("--liggghts", help="LIGGGHTS file of particletemplate/multisphere sphere lists")
    args = parser.parse_args(argv)
    distinct_paths(args)
    text = read_description(args.description)
    try:
        clumps, templates, summary, box, options = lay_out(D.parse(text))
    except D.LayoutError as e:
        raise Failure("%s line %d: %s" % (args.description, e.line, e))
    if not clumps:
        raise Failure("%s lays out nothing" % args.description)
    spheres = sum(len(c.centres) for c in clumps)
    extent = bounding_box(clumps)
    report = summary + ["total: %d clumps, %d spheres" % (len(clumps), spheres),
                        "extent of the spheres: %s to %s" % (" ".join("%.6g" % v for v in extent[0]),
                                                             " ".join("%.6g" % v for v in extent[1]))]
    decimals = options.get("decimals")
    source = os.path.basename(args.description)
    if args.data is not None:
        outputs.file(args.data, lambda out: W.write_data(out, clumps, box or extent, summary, decimals, source))
        report.append("wrote %s (%d atoms)" % (args.data, spheres))
    if args.molecules is not None:
        W.write_molecules(outputs, args.molecules, templates, summary, decimals)
        report.append("wrote %d molecule files in %s" % (len(templates), args.molecules))
    if args.liggghts is not None:
        ntry = options.get("ntry", 1000000)
        outputs.file(args.liggghts, lambda out: W.write_liggghts(out, templates, summary, decimals, ntry))
        report.append("wrote %s (%d multisphere templates)" % (args.liggghts, len(templates)))
    outputs.write_in_place()
    # The report before the files go in place: a stdout that fails is an
    # error like any other. A reader gone (`| head`) is not: the files are
    # still put in place, quietly.
    try:
        sys.stdout.write("".join(line + "\n" for line in report))
        sys.stdout.flush()
    except OSError as e:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())    # nor at exit's flush
        if not isinstance(e, BrokenPipeError):
            raise Failure("cannot write standard output: %s" % (e.strerror or e))
    outputs.commit()
    return 0


def main(argv):
    outputs = W.Outputs()
    try:
        return run(argv, outputs)
    except (Failure, W.OutputError) as e:
        print("reinforce_layout: ERROR: %s" % e, file=sys.stderr)
    finally:
        outputs.discard()    # after a commit: nothing left to remove
    return 1


if __name__ == "__main__":
    # Stopped (Ctrl-C, a timeout's SIGTERM): main's clean-up runs as on an
    # error, then the status a shell gives a signal, without a traceback.
    signal.signal(signal.SIGTERM, lambda signum, frame: sys.exit(128 + signum))
    sys.stdout.reconfigure(errors="surrogateescape")    # paths as given, undecodable bytes too
    try:
        sys.exit(main(sys.argv[1:]))
    except KeyboardInterrupt:
        sys.exit(128 + signal.SIGINT)
