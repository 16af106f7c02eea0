#!/usr/bin/env python3
"""The benchmark's plots, all drawn by gnuplot (scripts/setup.sh installs it).

    plot.py OUT.svg TITLE < rows      a profile plot (scripts/run-beam.sh)

rows: tab-separated "label lo hi phi se" (distance bins in rmax; lines starting
with # skipped); each label is one line, in the order first seen. From Python:
profile(path, title, series) with series [(label, [(lo, hi, phi, se), ...])],
and loglog(path, title, x_label, y_label, series) with series
[(label, style, [(x, y), ...])], style a gnuplot "with" clause.
"""
import math
import subprocess
import sys


# Colours that stay apart on white (gnuplot's sixth default, yellow, does not).
COLOURS = "\n".join(f"set linetype {n + 1} lc rgb '{c}'" for n, c in enumerate(
    ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#7f7f7f"]))


def gnuplot(script):
    """Runs a gnuplot script; its errors stop the caller."""
    done = subprocess.run(["gnuplot"], input=script, text=True, capture_output=True)
    if done.returncode != 0:
        raise RuntimeError(f"gnuplot failed: {done.stderr.strip()}")


def quoted(text, enhanced=True):
    """A gnuplot string; in labels "_" would start a subscript."""
    text = text.replace("'", "''")
    return "'" + (text.replace("_", "\\_") if enhanced else text) + "'"


def curves(series):
    """Inline data blocks (one per curve) and their plot clauses."""
    blocks, clauses = [], []
    for n, (label, style, points) in enumerate(series):
        rows = [p for p in points if all(math.isfinite(v) for v in p)]
        if not rows:
            continue
        blocks.append(f"$d{n} << EOD\n" + "\n".join(" ".join(f"{v:.10g}" for v in p) for p in rows) + "\nEOD")
        clauses.append(f"$d{n} {style} title {quoted(label)}")
    if not clauses:
        raise ValueError("plot: no finite point to plot")
    return "\n".join(blocks), ", \\\n  ".join(clauses)


def profile(path, title, series, x_label="distance from the nearest rebar surface (rmax)",
            y_label="matrix solid fraction"):
    """Solid fraction against distance, one line with error bars per series."""
    data, plots = curves([(label, "using 1:2:3 with yerrorlines lw 2 pt 7 ps 0.5",
                           [(0.5 * (lo + hi), phi, se) for lo, hi, phi, se in rows]) for label, rows in series])
    gnuplot(f"""set terminal svg size 960,470 font 'sans,12' background rgb 'white'
set output {quoted(path, False)}
{data}
set title {quoted(title)}
set xlabel {quoted(x_label)}
set ylabel {quoted(y_label)}
set yrange [0:*]
set grid ytics
set key outside right top Left reverse samplen 2 width -6
{COLOURS}
plot {plots}
""")


def loglog(path, title, x_label, y_label, series):
    """Points or lines on log-log axes, as PNG."""
    data, plots = curves([(label, "using 1:2 " + style, points) for label, style, points in series])
    gnuplot(f"""set terminal pngcairo size 1000,650
set output {quoted(path, False)}
{data}
set logscale xy
set format y '10^{{%L}}'
set title {quoted(title)}
set xlabel {quoted(x_label)}
set ylabel {quoted(y_label)}
set key outside right
{COLOURS}
plot {plots}
""")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.split("\n\n")[1])
    series = {}
    for line in sys.stdin:
        if line.strip() and not line.startswith("#"):
            label, *values = line.rstrip("\n").split("\t")
            series.setdefault(label, []).append(tuple(float(v) for v in values))
    profile(sys.argv[1], sys.argv[2], list(series.items()))


if __name__ == "__main__":
    main()
