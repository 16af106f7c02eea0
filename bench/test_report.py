#!/usr/bin/env python3
"""The report's arithmetic on fixed rows with known answers: medians, ratios, ranges and the cost model of
docs/benchmarks.md and README.md's figures (bench/report.py, results.py, report_cost.py, readme_figures.py), and
report.py --check's plausibility checks.

usage: test_report.py [--mutate median]

Writes a small bench/run.sh output folder (three repeats whose mean differs from their median, an even count, a
series, a reference) to a scratch folder, loads it as the report does and checks the figures the page and README
would show. Prints one line per wrong figure, then "PASS: ..." or "FAIL: ...". --mutate median takes the mean for the
median first: the test's own proof that it sees a wrong figure.
"""
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import readme_figures  # noqa: E402
import report  # noqa: E402
import report_cost  # noqa: E402
import results  # noqa: E402
from results import DEFAULTS, DELETE, FIT, NO_REGROWTH, PUSH  # noqa: E402

RESULTS = ("scene atoms method param np rep targets relocated deleted volume_before volume_after overlap solves "
           "op_seconds wall_seconds peak_kb removed rounds rebar balance busiest blocks").split()


def fix_row(scene, method, np, rep, op, deleted=0, targets=100, param="1000", **more):
    r = dict(scene=scene, atoms=30000, method=method, param=param, np=np, rep=rep, targets=targets,
             relocated=targets - deleted, deleted=deleted, volume_before=1.0, volume_after=0.5, overlap=1e-14,
             solves=10, op_seconds=op, wall_seconds=op + 1, peak_kb=40000, removed=0, rounds=24)
    r.update(more)
    return r


def delete_row(scene, cutoff, rep, op, deleted):
    return dict(scene=scene, atoms=30000, method=DELETE, param=cutoff, np=1, rep=rep, deleted=deleted, overlap=0,
                op_seconds=op, wall_seconds=op + 1, peak_kb=40000)


# The rows: every median of three is not their mean; narrow has two repeats (median = their mean).
ROWS = [fix_row("beam060", DEFAULTS, 1, rep, op, deleted=d) for rep, op, d in ((1, 0.1, 0), (2, 0.9, 2), (3, 0.2, 1))]
ROWS += [fix_row("beam060", FIT, 1, rep, op) for rep, op in ((1, 0.05, ), (2, 0.4), (3, 0.1))]
ROWS += [fix_row("beam060", PUSH, 1, rep, op) for rep, op in ((1, 1.0), (2, 0.8), (3, 0.6))]
ROWS += [delete_row("beam060", "0.0125", rep, op, 1115) for rep, op in ((1, 0.05), (2, 0.04), (3, 0.5))]
ROWS += [delete_row("beam060", "0.0075", rep, 0.01, 379) for rep in (1, 2, 3)]
ROWS += [dict(scene="beam060", atoms=30000, method="relax", param="5000 steps", np=1, rep=1, deleted=3, overlap=4e-6,
              op_seconds=20.0, wall_seconds=21.0, peak_kb=50000)]
ROWS += [fix_row("beam050", DEFAULTS, 1, rep, 0.1) for rep in (1, 2, 3)]
ROWS += [fix_row("beam050", FIT, 1, rep, 0.2) for rep in (1, 2, 3)]
ROWS += [delete_row("beam050", "0.0125", rep, 0.1, 932) for rep in (1, 2, 3)]
ROWS += [fix_row("narrow", DEFAULTS, 1, rep, op, deleted=d, targets=1083) for rep, op, d in ((1, 1.0, 600), (2, 3.0, 700))]
ROWS += [fix_row("narrow", NO_REGROWTH, 1, rep, 0.5, deleted=700, targets=1083) for rep in (1, 2)]
ROWS += [fix_row("cage", DEFAULTS, 1, rep, op, deleted=d, targets=900) for rep, op, d in ((1, 4.0, 300), (2, 6.0, 280))]
ROWS += [delete_row("cage", cutoff, 1, 0.1, d) for cutoff, d in (("0.012", 2400), ("0.009", 1500))]
ROWS += [fix_row("speedup_beam060", DEFAULTS, np, rep, op, blocks=96)
         for rep, ops in ((1, (1.0, 0.6)), (2, (1.2, 0.5)), (3, (5.0, 0.7))) for np, op in zip((1, 2), ops)]
ROWS += [fix_row("gap", "fix search", 1, 1, op, param=p) for p, op in (("1", 0.2), ("10", 0.3), ("100", 0.4),
                                                                        ("1e20", 0.5))]
ROWS += [fix_row("rbar", "fix rebar radius", 1, 1, op, param=p) for p, op in (("1", 1.0), ("1e-2", 0.2), ("1e-3", 0.3),
                                                                              ("1e-4", 0.1))]
ROWS += [fix_row("scaling_targets", DEFAULTS, 1, rep, op, param=bars, atoms=230000)
         for bars, rep, op in (("1", 1, 0.1), ("2", 1, 0.2), ("4", 1, 0.4), ("4", 2, 3.0), ("4", 3, 0.5))]
QUALITY = [dict(scene="beam060", method=DEFAULTS, param="1000", shell_ratio=0.95, shell_ratio_se=0.01,
                removed_ratio=1.1, ks=0.01, targets=100, deleted=1),
           dict(scene="beam060", method=DELETE, param="0.0125", shell_ratio=0.80, shell_ratio_se=0.01,
                removed_ratio=2.5, ks=0.02, targets=100, deleted=1115),
           dict(scene="beam050", method=DEFAULTS, param="1000", shell_ratio=0.97, shell_ratio_se=0.01,
                removed_ratio=1.0, ks=0.01, targets=100, deleted=0)]
REFERENCE = [dict(scene="beam060", kind="lammps", seed=48271, matrix=28500, rebar=325, box="0.5 x 0.25 x 0.25",
                  phi=0.60, radii="0.0025-0.0075", wall_seconds=200, cpu_seconds=199, grown="2026-01-01_00:00_UTC",
                  bulk=0.6, shell_ratio=0.99, shell_ratio_se=0.01)]
EXCHANGE = [(1, 10.0), (2, 12.0), (3, 14.0)]    # microseconds: a slope of 2 per partner


# What the page and README say from these rows: (what, the section that says it, the words).
PAGE = [
    ("ratios, beam060", report.ratios, "| beam060 | 4.00 | 2.00 | 16.00 | 0.0100 | 1, 0, 0, 1115 | 1e-14, 4e-06 |"),
    ("ratios, beam050", report.ratios, "| beam050 | 1.00 | 2.00 |  |  | 0, 0, , 932 |"),
    ("README: defaults / delete_atoms across the beams", readme_figures.bullets,
     "the defaults take 1.0 to 4.0 times its time"),
    ("README: size fit / delete_atoms", readme_figures.bullets, "the seed paper's `size fit` 2.0)"),
    ("README: deleted", readme_figures.bullets, "delete 0 to 1 spheres where it deletes 932 to 1,115"),
    ("README: shell ratios", readme_figures.bullets, "keeps 0.95 to 0.97 of its bulk solid fraction (0.950 at 0.60, "
     "where the same law grown around the bars by LAMMPS has 0.990"),
    ("README: growth / operation", readme_figures.bullets, "takes 1,000 times as long (LAMMPS"),
    ("README: against relaxation", readme_figures.bullets, "1.0% of its run time"),
    ("README: the run it is from", readme_figures.bullets,
     "From the benchmark run started 2026-01-01 00:00 UTC at commit abc1234, with that commit's defaults; it took 21.5 "
     "minutes"),
    ("README: the cage", readme_figures.bullets,
     "900 targets, 290 deleted, 5.0 s on one process, where `delete_atoms overlap` deletes 2,400."),
    ("README: narrow", readme_figures.bullets, "the defaults delete 650 of 1083 targets in 2.0 s"),
    ("speedup", report_cost.speedup, "| beam060 | 30,000 | 100 | 24 | 3 | 1.200 | 0.600 | 2.00 |"),
    ("exchange slope", report_cost.speedup, "1 to 26 partners, 2 processes): 2.00 microseconds"),
    # c = 1.2 / 100 s, o = max(0, 0.6 - 0.6) / 24, W = 96 / 24; T(2) = c N / 2 + R m (k(2) - 1) = 0.6 s.
    ("speedup model", report_cost.speedup, "| beam060 | 12.000 | 0.00 | 4.0 | 1.200 | 0.600 |"),
    ("rebar radius: largest over smallest", report_cost.rbar_and_gap, "largest over smallest median time 3.00"),
    ("search gap: largest over smallest", report_cost.rbar_and_gap,
     "Largest over smallest median time across the gaps: 2.50"),
    ("scaling: the bars", lambda run: report_cost.scaling(run)[0], "A growing number of bars (1 to 4) in one scene"),
    ("scaling: one point per bar count", lambda run: report_cost.scaling(run)[0], "| 230000 | 100 | 0 | 3 | 0.500 |"),
]


def write_run(out):
    def tsv(name, columns, rows):
        with open(os.path.join(out, name), "w") as f:
            f.write("\t".join(columns) + "\n")
            for r in rows:
                f.write("\t".join(str(r.get(c, "")) for c in columns) + "\n")
    tsv("results.tsv", RESULTS, ROWS)
    tsv("quality.tsv", ["scene", "method", "param", "shell_ratio", "shell_ratio_se", "removed_ratio", "ks", "targets",
                        "deleted", "moved_nontargets", "bulk", "ref_bulk", "ref_shell_ratio", "shell_vs_reference",
                        "bin_diff_max"], QUALITY)
    tsv("reference.tsv", list(REFERENCE[0]), REFERENCE)
    tsv("meta.tsv", ["key", "value"], [dict(key="quick", value=0), dict(key="commit", value="abc1234"),
                                      dict(key="started", value="2026-01-01 00:00 UTC"), dict(key="minutes", value="21.5")])
    with open(os.path.join(out, "exchange_cost.tsv"), "w") as f:
        f.writelines(f"{k}\t{us}\n" for k, us in EXCHANGE)


def main(argv):
    if argv[1:] == ["--mutate", "median"]:
        def mean(values):
            values = [v for v in values if v is not None]
            return statistics.mean(values) if values else None
        results.median = mean
    elif len(argv) != 1:
        sys.exit(__doc__.split("\n\n")[1])
    wrong, checked = [], 0

    def expect(what, got, want):
        nonlocal checked
        checked += 1
        if got != want:
            wrong.append(f"{what}: {got!r}, want {want!r}")

    def has(what, text, piece):
        nonlocal checked
        checked += 1
        if piece not in text:
            wrong.append(f"{what}: no {piece!r} in\n    " + text.replace("\n", "\n    "))

    with tempfile.TemporaryDirectory() as out:
        write_run(out)
        run = results.Run(out)
        expect("median of three", results.median([0.1, 0.9, 0.2]), 0.2)
        expect("median of two", results.median([1.0, 3.0]), 2.0)
        expect("median skips missing values", results.median([None, 4.0, None]), 4.0)
        expect("span of equal values", results.span([2.0, 2.0004], ".1f"), "2.0")
        expect("span", results.span([4.0, 1.0, 2.5], ".1f"), "1.0 to 4.0")
        d = results.find(run.group("beam060", "1"), DEFAULTS)
        expect("beam060 defaults: median time", d["op_seconds"], 0.2)
        expect("beam060 defaults: median deleted", d["deleted"], 1)
        expect("beam060 defaults: repeats", d["repeats"], 3)
        n = results.find(run.group("narrow", "1"), DEFAULTS)
        expect("narrow defaults: median of two repeats", (n["op_seconds"], n["deleted"]), (2.0, 650))
        for what, section, piece in PAGE:
            has(what, "\n".join(section(run)), piece)
        # report.py --check's plausibility: these rows pass; a target counted twice, an overlap left by the fix and
        # a removed ratio of nan each fail.
        expect("plausible rows", report.implausible(run), [])
        run.rows[0].update(relocated="100", deleted="1")
        run.rows[1]["overlap"] = "0.3"
        run.quality[0]["removed_ratio"] = "nan"
        expect("implausible rows found", len(report.implausible(run)), 3)
    for w in wrong:
        print(f"wrong: {w}")
    print(f"{'FAIL' if wrong else 'PASS'}: {checked - len(wrong)} of {checked} figures of the report right")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
