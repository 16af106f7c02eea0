"""README.md's figures ("What it gives", between two marks): sentences filled from the benchmark run, so the
figures a reader sees first are the ones docs/benchmarks.md has. Called by bench/report.py.
"""
import sys

from results import DEFAULTS, DELETE, FIT, NO_REGROWTH, PAPER, find, num, span, summary

BEGIN = "<!-- written by bench/report.py from the benchmark run (bench/run.sh): do not edit -->"
END = "<!-- end of what bench/report.py writes -->"


def write(run, readme):
    """Replaces what lies between README's marks."""
    text = open(readme).read()
    if BEGIN not in text or END not in text:
        sys.exit(f"report.py: {readme} lacks the marks of the part it writes")
    head, rest = text.split(BEGIN, 1)
    open(readme, "w").write(f"{head}{BEGIN}\n" + "\n".join(bullets(run)) + f"\n{END}{rest.split(END, 1)[1]}")
    print(f"wrote the figures of {readme}")


def bullets(run):
    """README.md's "What it gives": the figures a reader sees first, from this run."""
    meta = run.meta
    out = [f"From the benchmark run started {meta.get('started', '?')} at commit {meta.get('commit', '?')}, with that "
           f"commit's defaults; it took {meta.get('minutes', '?')} minutes (the machine and its load: "
           "[docs/benchmarks.md](docs/benchmarks.md)).\n"]
    beams = [s for s in summary(run) if s[0].startswith("beam")]
    fix64 = find(run.group("beam064", "1"), DEFAULTS)
    if fix64:
        out.append(f"* The paper's beam at solid fraction 0.64: {fix64['targets']:.0f} targets, {fix64['relocated']:.0f} "
                   f"relocated, {fix64['deleted']:.0f} deleted (the paper's worst case deleted {PAPER['worst_deleted']})."
                   f" The largest residual overlap is {fix64['overlap']:.1e} rmin, and the fix takes "
                   f"{fix64['op_seconds']:.3f} s (one process).")
    if beams:
        shell = lambda q: num(q["shell_ratio"])  # noqa: E731
        text = (f"* Against `delete_atoms overlap` on the same beams (one process, [docs/benchmarks.md]"
                f"(docs/benchmarks.md)): the defaults take {span([f['op_seconds'] / b['op_seconds'] for _, f, _, _, b, _ in beams], '.1f')} "
                f"times its time (the seed paper's `size fit` "
                f"{span([fi['op_seconds'] / b['op_seconds'] for _, _, fi, _, b, _ in beams if fi], '.1f')}) and delete "
                f"{span([f['deleted'] for _, f, _, _, _, _ in beams], '.0f')} spheres where it deletes "
                f"{span([b['deleted'] for _, _, _, _, b, _ in beams], ',.0f')}.")
        shells = [shell(q) for s, *_ in beams for q in [run.quality_of(s, DEFAULTS)] if q]
        dels = [shell(q) for s, _, _, _, b, _ in beams for q in [run.quality_of(s, DELETE, b["param"])] if q]
        q60, f60 = run.quality_of("beam060", DEFAULTS), run.quality_of("beam060", FIT)
        lmp60, around60 = (next((r for r in run.grown if r["scene"] == "beam060" and r["kind"] == k), None)
                           for k in ("lammps", "around"))
        if shells:
            text += (f" The matrix within 2 rmax of the bars keeps {span(shells, '.2f')} of its bulk solid fraction"
                     + (f" ({shell(q60):.3f} at 0.60" if q60 else "")
                     + (f", where the same law grown around the bars by LAMMPS has {shell(lmp60):.3f}" if q60 and lmp60
                        else "") + (f" and `size fit` {shell(f60):.3f}" if q60 and f60 else "") + (")" if q60 else "")
                     + (f", against {span(dels, '.2f')} after `delete_atoms`" if dels else "") + ".")
        fix60 = find(run.group("beam060", "1"), DEFAULTS)
        grow = [f"{float(r['wall_seconds']) / fix60['op_seconds']:,.0f} {what}" for r, what in
                ((lmp60, "times as long (LAMMPS, the beam's own law)"), (around60, "times (this project's fast grower)"))
                if r and fix60]
        if grow:
            text += " Growing that packing around the bars takes " + " or ".join(grow) + "."
        relaxed = [(f, r) for _, f, _, _, _, r in beams if r]
        if relaxed:
            text += (f" Against dynamic relaxation ({relaxed[0][1]['param']}): "
                     f"{span([100 * f['op_seconds'] / r['op_seconds'] for f, r in relaxed], '.1f')}% of its run time, "
                     f"and {span([f['overlap'] for f, _ in relaxed], '.0e')} overlap where it stops at "
                     f"{span([r['overlap'] for _, r in relaxed], '.0e')}.")
        out.append(text)
    fn, en = (find(run.group("narrow", "1"), m) for m in (DEFAULTS, NO_REGROWTH))
    qn, qe = (run.quality_of("narrow", m) for m in (DEFAULTS, NO_REGROWTH))
    if fn:
        text = (f"* Where the matrix radii are close (4 to 5 mm, the narrow scene), most targets find no void: the "
                f"regrowth makes room, and the defaults delete {fn['deleted']:.0f} of {fn['targets']:.0f} targets in "
                f"{fn['op_seconds']:.1f} s")
        if qn and num(qn["shell_vs_reference"]) is not None:
            text += (f"; the layer against the bars is {num(qn['shell_vs_reference']):+.3f} of shell ratio from a "
                     "packing grown around them")
        if en:
            text += (f" (`regrow no`, the relocation alone: {en['deleted']:.0f} deleted in "
                     f"{en['op_seconds']:.1f} s" + (f", {num(qe['shell_vs_reference']):+.3f}" if qe and
                                                     num(qe["shell_vs_reference"]) is not None else "") + ")")
        out.append(text + ".")
    fl = find(run.group("liggghts", "1"), DEFAULTS)
    if fl:
        out.append(f"* The LIGGGHTS example (a packing settled under gravity, two bars): {fl['targets']:.0f} targets, "
                   f"{fl['deleted']:.0f} deleted, {fl['op_seconds']:.1f} s.")
    fc, dc = find(run.group("cage", "1"), DEFAULTS), [m for m in run.group("cage", "1") if m["method"] == DELETE]
    if fc:
        out.append(f"* The cage example's scene (five hooked bars and their stirrups in {run.atoms('cage'):,} spheres): "
                   f"{fc['targets']:,.0f} targets, {fc['deleted']:,.0f} deleted, {fc['op_seconds']:.1f} s on one process"
                   + (f", where `delete_atoms overlap` deletes {max(dc, key=lambda m: float(m['param']))['deleted']:,.0f}"
                      if dc else "") + ".")
    s1 = find(run.group("speedup_slab", "1"), DEFAULTS) or find(run.group("slab", "1"), DEFAULTS)
    s2 = find(run.group("speedup_slab", "2"), DEFAULTS)
    if s1:
        out.append(f"* A slab of {run.atoms('speedup_slab', 'slab'):,} spheres with a mesh of bars: {s1['targets']:,.0f} "
                   f"targets, {s1['deleted']:.0f} deleted, {s1['op_seconds']:.1f} s on one process"
                   + (f" and {s2['op_seconds']:.1f} s on two" if s2 else "")
                   + f" (the paper's slab took {PAPER['slab_hours']} hours).")
    return out
