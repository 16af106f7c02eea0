"""The sections of docs/benchmarks.md on cost (bench/report.py writes the page): parallel speedup and its model of
larger runs, rebar radius and search gap, relaxation, scaling, and the figures of error and time.
"""
import os

import plot
from results import DEFAULTS, compared_scenes, find, fmt, num, summarize, table


def exchange_slope(run):
    """The exchange's cost per partner and round (s): least-squares slope of exchange_cost's microseconds."""
    ex = [(k, t) for k, t in run.exchange if k is not None and t is not None]
    if len(ex) < 2:
        return None
    kx, ty = sum(k for k, _ in ex) / len(ex), sum(t for _, t in ex) / len(ex)
    return sum((k - kx) * (t - ty) for k, t in ex) / sum((k - kx) ** 2 for k, _ in ex) * 1e-6


def speedup(run):
    md = ["\n## Parallel speedup\n"]
    pairs = [(s[8:], find(run.group(s, "1"), DEFAULTS), find(run.group(s, "2"), DEFAULTS))
             for s in run.scenes() if s.startswith("speedup_")]
    pairs = [p for p in pairs if p[1] and p[2]]
    if not pairs:
        return md + ["Not run."]
    md.append("The fix with its defaults on 1 and 2 processes, the two alternating in every repeat (one harness run); "
              "time = `f_ID[9]` (the largest over processes). **rounds** = `f_ID[17]`, the rounds of the schedule by "
              "space that had work (one per colour of blocks with targets, and with `size keep` per class of radius; "
              "the atoms are migrated once per invocation, each process updates its own view between rounds). "
              "**busiest** = the targets of the busiest process summed over the rounds, and **balance** = targets / "
              "(busiest x processes), both from the fix's schedule log line (1 = even).\n")
    md += table(["scene", "spheres", "targets", "rounds", "runs", "1 process s", "2 processes s", "speedup (1 / 2)",
                 "busiest (2 processes)", "balance", "deleted 1, 2"],
                [[name, f"{one['atoms']:,.0f}", f"{one['targets']:.0f}", f"{one['rounds']:.0f}", one["repeats"],
                  f"{one['op_seconds']:.3f}", f"{two['op_seconds']:.3f}", f"{one['op_seconds'] / two['op_seconds']:.2f}",
                  fmt(two.get("busiest"), ".0f"), fmt(two.get("balance"), ".2f"),
                  f"{one['deleted']:.0f}, {two['deleted']:.0f}"] for name, one, two in pairs])
    m = exchange_slope(run)
    if m is None:
        return md
    md.append("\n**Model of larger runs** (this machine has 2 cores). With T1 and T2 the medians on 1 and 2 processes, "
              "N the targets, R the rounds and B the blocks with targets summed over the rounds (the fix's schedule "
              "line): the per-target cost c = T1 / N; the per-round overhead o = max(0, T2 - T1 / 2) / R, i.e. "
              "everything the second process did not halve is charged to the rounds (ghost exchange, view over the "
              "ghosts, waiting, one partner's messages); W = B / R, the processes a round can keep busy on average "
              "(one per block); and m, the cost of one more partner per round, measured by `exchange_cost` (a round's "
              f"post and collect with 1 to 26 partners, 2 processes): {m * 1e6:.2f} microseconds. The model is T(P) = "
              "c N / min(P, W) + R (o + m (k(P) - 1)) for P of 2 or more, with k(P) = min(P - 1, 26) partners: each "
              "round's results go point to point to the processes near enough to matter (docs/design.md, "
              "\"Partners\"), at most the 26 neighbours of a regular grid. m is for shared memory; a network's latency "
              "of a few microseconds per message adds R x 26 x that, about a millisecond. It assumes the blocks of a "
              "round spread over the processes and R stays as measured (fixed by space, not by P); o is charged whole "
              "at every P, although its ghost part shrinks with the subdomains.\n")
    ps, body = [1, 2, 8, 32, 128, 512], []
    for name, one, two in pairs:
        n, r = one["targets"], max(one["rounds"] or 1, 1)
        c, o = one["op_seconds"] / n, max(0.0, two["op_seconds"] - one["op_seconds"] / 2) / r
        w = (two.get("blocks") or one.get("blocks") or r) / r
        model = [c * n if p == 1 else c * n / min(p, w) + r * (o + m * (min(p - 1, 26) - 1)) for p in ps]
        body.append([name, f"{c * 1e3:.3f}", f"{o * 1e3:.2f}", f"{w:.1f}"] + [f"{t:.3f}" for t in model])
    return md + table(["scene", "c (ms / target)", "o (ms / round)", "W (blocks / round)"]
                      + [f"T({p}) s" for p in ps], body)


def rbar_and_gap(run):
    md, rb, gp = ["\n## Cost against rebar radius and search gap\n"], run.group("rbar"), run.group("gap")
    if rb:
        md.append("Rebar radius: the 0.60 beam packing with one bar along x at mid-height, its rebar radius 1, 1e-2, "
                  "1e-3 and 1e-4 times the matrix radius 5 mm. The bar's spheres stay 7.66 mm apart (the overlapping "
                  "chain of the 5 mm bar; thinner bars are beads on the same line), so the rebar count stays the same "
                  "and only the radius changes (the targets are then the matrix spheres holding a bead). Target "
                  "detection uses cells sized by matrix + rebar radius, so the time should not grow as the bar thins.\n")
        md += table(["rebar radius / matrix radius", "rebar spheres", "spheres", "targets", "deleted", "runs",
                     "operation s"],
                    [[m["param"], fmt(m.get("rebar"), ".0f"), f"{m['atoms']:,.0f}", f"{m['targets']:.0f}",
                      f"{m['deleted']:.0f}", m["repeats"], f"{m['op_seconds']:.3f}"] for m in rb])
        thin = [m for m in rb if num(m["param"]) is not None and num(m["param"]) < 1]
        if thin:
            ts = [m["op_seconds"] for m in thin]
            md.append(f"\nAcross the thin bars ({thin[0]['param']} to {thin[-1]['param']}; the same beads, "
                      f"{min(m['targets'] for m in thin):.0f} to {max(m['targets'] for m in thin):.0f} targets): "
                      f"largest over smallest median time {max(ts) / min(ts):.2f}. The 5 mm bar (ratio 1) has more "
                      "targets, hence its longer time.")
    if gp:
        md.append(f"\nSearch gap (`search`, in units of rmax; the default is 2 rmax), on the scene of "
                  f"{run.atoms('gap'):,} spheres: the candidate search grows only until it has enough spheres, and is "
                  "capped by the box diagonal, so the time should stay flat up to `search 1e20`.\n")
        md += table(["search / rmax", "targets", "relocated", "deleted", "rounds", "runs", "operation s"],
                    [[m["param"], f"{m['targets']:.0f}", f"{m['relocated']:.0f}", f"{m['deleted']:.0f}",
                      fmt(m.get("rounds"), ".0f"), m["repeats"], f"{m['op_seconds']:.3f}"] for m in gp])
        ts = [m["op_seconds"] for m in gp]
        md.append(f"\nLargest over smallest median time across the gaps: {max(ts) / min(ts):.2f}. The blocks of the "
                  "schedule are at least one interaction reach wide, and the reach includes the gap: a larger gap means "
                  f"fewer, larger blocks ({fmt(gp[0].get('rounds'), '.0f')} rounds at {gp[0]['param']} rmax, "
                  f"{fmt(gp[-1].get('rounds'), '.0f')} at {gp[-1]['param']}), hence less work that can run at once on "
                  "several processes.")
    return md if rb or gp else md + ["Not run."]


def relaxation(run):
    if not run.curves:
        return []
    return ["\n## Relaxation: largest overlap against run time\n"] + table(
        ["scene", "dump", "seconds", "atoms", "matrix-bar overlap / rmin", "matrix-matrix overlap / rmin"],
        [[c["scene"], c["chunk"], c["seconds"], c["atoms"], c["matrix_rebar"], c["matrix_matrix"]] for c in run.curves])


def scaling(run):
    """One bar in growing scenes, then a growing number of bars in one scene; and their points for the plot."""
    if not any(r["scene"].startswith("scaling") for r in run.rows):
        return [], [], []
    md, pts = ["\n## Scaling\n"], {}
    for name, text in (("scaling_size", "One bar 0.125 m long in scenes of growing size (the beam packing cut or "
                        "replicated): the work (targets) stays the same while the scene grows."),
                       ("scaling_targets", "\nA growing number of bars ({bars}) in one scene (the beam packing "
                        "replicated 2 x 4 x 1): the work grows, the scene does not.")):
        by_point = {}    # a point: the scene's size and its bars (param)
        for r in run.rows:
            if r["scene"] == name:
                by_point.setdefault((r["atoms"], r["param"]), []).append(r)
        ms = sorted((summarize(rs) for rs in by_point.values()), key=lambda m: (m["atoms"] or 0, num(m["param"]) or 0))
        bars = sorted({num(m["param"]) for m in ms if num(m["param"]) is not None})
        text = text.format(bars=f"{bars[0]:g} to {bars[-1]:g}" if bars else "")
        md += [text, ""] + table(["spheres", "targets", "deleted", "runs", "operation s", "process s", "peak MB"],
                                 [[f"{m['atoms']:.0f}", f"{m['targets']:.0f}", f"{m['deleted']:.0f}", m["repeats"],
                                   f"{m['op_seconds']:.3f}", f"{m['wall_seconds']:.2f}",
                                   f"{(m['peak_kb'] or 0) / 1024:.0f}"] for m in ms])
        pts[name] = [(m["atoms"], m["targets"], m["op_seconds"]) for m in ms]
    return md, pts["scaling_size"], pts["scaling_targets"]


def figures(run, img_dir, size_pts, target_pts):
    """Error against run time (every compared scene's methods, relaxation curves); time against size."""
    floor, pts = 1e-16, {"fix": [], "delete": []}
    for scene in compared_scenes(run):
        for m in run.group(scene, "1"):
            if m["method"] != "relax" and m["op_seconds"] is not None:
                pts["fix" if m["method"].startswith("fix") else "delete"].append(
                    (m["op_seconds"], max(m["overlap"] or 0, floor)))
    series = [("fix reinforce/invert", "with points pt 7 ps 1.5", pts["fix"]),
              ("delete_atoms overlap", "with points pt 5 ps 1.5", pts["delete"])]
    series += [(f"dynamic relaxation, {s}", "with linespoints pt 1",
                [(float(c["seconds"]), max(float(c["matrix_rebar"]), floor)) for c in run.curves
                 if c["scene"] == s and float(c["seconds"]) > 0]) for s in dict.fromkeys(c["scene"] for c in run.curves)]
    plot.loglog(os.path.join(img_dir, "error_time.png"), "Error against run time (1 process; overlaps of 0 drawn at "
                "1e-16)", "run time of the operation (s)", "largest remaining overlap / rmin", [s for s in series if s[2]])
    md = ["\n![error against run time](img/error_time.png)\n"]
    if size_pts and target_pts:
        plot.loglog(os.path.join(img_dir, "time_size.png"), "Cost follows the work (targets), not the scene size",
                    "spheres in the scene  /  targets", "relocation time (s)",
                    [("x = spheres, one bar (same targets)", "with linespoints pt 7", [(a, s) for a, _, s in size_pts]),
                     ("x = targets, more bars (same scene)", "with linespoints pt 5",
                      sorted((t, s) for _, t, s in target_pts))])
        md.append("\n![time against scene size](img/time_size.png)\n")
    return md
