#!/usr/bin/env python3
"""Writes docs/benchmarks.md and its plots from a bench/run.sh output folder.

usage: report.py OUT_DIR DOCS_DIR     (standard library and gnuplot only)
"""
import csv
import datetime
import os
import platform
import statistics
import subprocess
import sys

out_dir, docs = sys.argv[1], sys.argv[2]
img_dir = os.path.join(docs, "img")
os.makedirs(img_dir, exist_ok=True)


def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return None


rows = list(csv.DictReader(open(os.path.join(out_dir, "results.tsv")), delimiter="\t"))
curves = list(csv.DictReader(open(os.path.join(out_dir, "relax.tsv")), delimiter="\t"))


def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def group(scene):
    """Median figures per (method, param, np) of one scene, in run order."""
    keys, seen = [], {}
    for r in rows:
        if r["scene"] != scene:
            continue
        k = (r["method"], r["param"], r["np"])
        if k not in seen:
            seen[k] = []
            keys.append(k)
        seen[k].append(r)
    out = []
    for k in keys:
        rs = seen[k]
        m = {f: median([num(r[f]) for r in rs]) for f in rs[0] if f not in ("scene", "method", "param")}
        m.update(method=k[0], param=k[1], np=k[2], repeats=len(rs))
        out.append(m)
    return out


def fmt(v, spec):
    return "" if v is None else format(v, spec)


def cpu_name():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


scenes = [s for s in dict.fromkeys(r["scene"] for r in rows) if not s.startswith("scaling")]
md = []
md.append("# Benchmarks: fix reinforce/invert against what a user has\n")
md.append(
    f"Measured {datetime.date.today().isoformat()} on {cpu_name()}, {os.cpu_count()} cores, "
    "a shared VM (numbers are medians of repeated runs; compare ratios, not absolute times). "
    "Regenerate with `bash bench/run.sh` (writes this page and `docs/img/`).\n"
)
md.append(
    "Times: **operation** = the operation alone: the fix's own wall time `f_ID[9]`, "
    "or the wall clock around `delete_atoms` (a `shell date` before and after it in the input), "
    "or the elapsed time of the relaxation run. **process** = the whole `mpirun lmp_reinforce` "
    "including LAMMPS start-up and reading the data file; **peak MB** = the largest resident set "
    "of one process (`/usr/bin/time`). Largest overlap: of a relocated sphere (fix), of a "
    "remaining matrix sphere with a bar (delete_atoms, relaxation), relative to rmin.\n"
)
summary = []
for scene in scenes:
    g = group(scene)
    atoms = next(r["atoms"] for r in rows if r["scene"] == scene)
    truth = next((m["targets"] for m in g if m["method"].startswith("fix") and m["targets"]), None)
    md.append(f"\n## {scene} ({int(atoms):,} spheres, {int(truth or 0)} targets)\n")
    md.append("| method | parameter | procs | runs | relocated | deleted | volume after / before | "
              "largest overlap | operation s | process s | peak MB |")
    md.append("|---|---|---|---|---|---|---|---|---|---|---|")
    for m in g:
        vol = (m["volume_after"] / m["volume_before"]) if m.get("volume_before") else None
        param = m["param"] + (" groups" if m["method"].startswith("fix") else
                              " cutoff" if m["method"].startswith("delete") else "")
        md.append(
            f"| {m['method']} | {param} | {m['np']} | {m['repeats']} | {fmt(m['relocated'], '.0f')} | "
            f"{fmt(m['deleted'], '.0f')} | {fmt(vol, '.2f')} | {fmt(m['overlap'], '.1e')} | "
            f"{fmt(m['op_seconds'], '.3f')} | {fmt(m['wall_seconds'], '.2f')} | "
            f"{fmt((m['peak_kb'] or 0) / 1024, '.0f')} |")
    fix = next((m for m in g if m["method"] == "fix closest" and m["param"] == "1000" and m["np"] == "1"), None)
    dels = [m for m in g if m["method"].startswith("delete") and m["np"] == "1"]
    relax = next((m for m in g if m["method"] == "relax"), None)
    if fix and dels:
        big = max(dels, key=lambda m: float(m["param"]))
        small = min(dels, key=lambda m: float(m["param"]))
        md.append(
            f"\n`delete_atoms overlap` with cutoff {big['param']} (r_bar + rmax) deleted "
            f"{big['deleted']:.0f} spheres for {truth:.0f} true targets; with {small['param']} "
            f"(r_bar + rmin) it deleted {small['deleted']:.0f} and left overlaps up to "
            f"{small['overlap']:.2f} rmin. The fix deleted {fix['deleted']:.0f}.")
        first = next((m for m in g if m["method"] == "fix first" and m["param"] == "1000" and m["np"] == "1"), None)
        summary.append((scene, fix, first, big, relax))
    if relax:
        md.append(
            f"\nDynamic relaxation ({relax['param']}, {relax['op_seconds']:.1f} s) ended with the "
            f"largest matrix-bar overlap at {relax['overlap']:.2e} rmin and {relax['deleted']:.0f} "
            "atoms lost (out of the box); the curve is below.")

md.append("\n## Ratios (medians, 1 process)\n")
md.append("Time ratios of the operations: below 1, the fix is faster. `closest` and `first` are the "
          "fix with 1000 groups; delete_atoms uses the cutoff r_bar + rmax (the one that removes every "
          "overlap); relaxation is the whole relaxation run, which still leaves the overlap given.\n")
md.append("| scene | closest / delete_atoms | first / delete_atoms | closest / relaxation | "
          "deleted: closest, first, delete_atoms | overlap: fix, relaxation end |")
md.append("|---|---|---|---|---|---|")
for scene, fix, first, big, relax in summary:
    rt = relax["op_seconds"] if relax else None
    md.append(
        f"| {scene} | {fix['op_seconds'] / big['op_seconds']:.2f} | "
        f"{fmt(first['op_seconds'] / big['op_seconds'] if first else None, '.2f')} | "
        f"{fmt(fix['op_seconds'] / rt if rt else None, '.4f')} | "
        f"{fix['deleted']:.0f}, {fmt(first['deleted'] if first else None, '.0f')}, {big['deleted']:.0f} | "
        f"{fix['overlap']:.0e}, {fmt(relax['overlap'] if relax else None, '.0e')} |")

md.append("\n## Relaxation: largest overlap against run time\n")
md.append("| scene | dump | seconds | atoms | matrix-bar overlap / rmin | matrix-matrix overlap / rmin |")
md.append("|---|---|---|---|---|---|")
for c in curves:
    md.append(f"| {c['scene']} | {c['chunk']} | {c['seconds']} | {c['atoms']} | {c['matrix_rebar']} | "
              f"{c['matrix_matrix']} |")


def scaling(name, x_field, x_label):
    g = group_by_atoms(name)
    md.append("\n| spheres | targets | deleted | operation s | process s | peak MB |")
    md.append("|---|---|---|---|---|---|")
    pts = []
    for m in sorted(g, key=lambda m: m[x_field] or 0):
        md.append(f"| {m['atoms']:.0f} | {m['targets']:.0f} | {m['deleted']:.0f} | "
                  f"{m['op_seconds']:.3f} | {m['wall_seconds']:.2f} | {(m['peak_kb'] or 0) / 1024:.0f} |")
        pts.append((m["atoms"], m["targets"], m["op_seconds"]))
    return pts


def group_by_atoms(name):
    """Median figures per scene size of a scaling series."""
    g = {}
    for r in rows:
        if r["scene"] == name:
            g.setdefault(r["atoms"], []).append(r)
    out = []
    for atoms, rs in g.items():
        m = {f: median([num(r[f]) for r in rs]) for f in rs[0] if f not in ("scene", "method", "param")}
        out.append(m)
    return out


md.append("\n## Scaling\n")
md.append("One bar 0.125 m long in scenes of growing size (the beam packing cut or replicated): "
          "the work (targets) stays the same while the scene grows a hundredfold.")
size_pts = scaling("scaling_size", "atoms", "spheres")
md.append("\nA growing number of bars in one scene (the beam packing replicated 2 x 4 x 1): "
          "the work grows, the scene does not.")
target_pts = scaling("scaling_targets", "targets", "targets")


def plot(script, name):
    try:
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
        return True
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"report: no plot {name}: {e}", file=sys.stderr)
        return False


# (a) error against run time, every method on one chart.
floor = 1e-16
pts_file = os.path.join(out_dir, "error_time.dat")
with open(pts_file, "w") as f:
    for scene in scenes:
        for m in group(scene):
            if m["np"] != "1" or m["method"] == "relax" or m["op_seconds"] is None:
                continue
            f.write(f"\"{scene} {m['method']} {m['param']}\" {m['op_seconds']} {max(m['overlap'] or 0, floor)}\n")
curve_file = os.path.join(out_dir, "relax_curve.dat")
with open(curve_file, "w") as f:
    for scene in scenes:
        cs = [c for c in curves if c["scene"] == scene and float(c["seconds"]) > 0]
        if cs:
            f.write(f"# {scene}\n")
            for c in cs:
                f.write(f"{c['seconds']} {max(float(c['matrix_rebar']), floor)}\n")
            f.write("\n\n")
ok_a = plot(f"""
set terminal pngcairo size 1000,650
set output '{img_dir}/error_time.png'
set logscale xy
set format y '10^{{%L}}'
set xlabel 'run time of the operation (s)'
set ylabel 'largest remaining overlap / rmin'
set key outside right
set title 'Error against run time (1 process; overlaps of 0 drawn at 1e-16)'
plot '{pts_file}' using 2:(strstrt(stringcolumn(1), 'fix') ? $3 : 1/0) with points pt 7 ps 1.5 title 'fix reinforce/invert', \\
     '{pts_file}' using 2:(strstrt(stringcolumn(1), 'delete') ? $3 : 1/0) with points pt 5 ps 1.5 title 'delete\\_atoms overlap', \\
     '{curve_file}' using 1:2 with linespoints pt 1 title 'dynamic relaxation'
""", "error_time")

# (b) time against scene size (fixed work) and against targets (fixed size).
size_file = os.path.join(out_dir, "size.dat")
with open(size_file, "w") as f:
    for a, t, s in sorted(size_pts):
        f.write(f"{a} {s}\n")
    f.write("\n\n")
    for a, t, s in sorted(target_pts, key=lambda p: p[1]):
        f.write(f"{t} {s}\n")
ok_b = plot(f"""
set terminal pngcairo size 1000,650
set output '{img_dir}/time_size.png'
set logscale xy
set xlabel 'spheres in the scene  /  targets'
set ylabel 'relocation time (s)'
set key top left
set title 'Cost follows the work (targets), not the scene size'
plot '{size_file}' index 0 using 1:2 with linespoints pt 7 title 'x = spheres, one bar (same targets)', \\
     '{size_file}' index 1 using 1:2 with linespoints pt 5 title 'x = targets, 1 to 16 bars (same scene)'
""", "time_size")

if ok_a:
    md.append("\n![error against run time](img/error_time.png)\n")
if ok_b:
    md.append("\n![time against scene size](img/time_size.png)\n")
open(os.path.join(docs, "benchmarks.md"), "w").write("\n".join(md) + "\n")
