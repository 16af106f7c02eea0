#!/usr/bin/env python3
"""Profile plots: matrix solid fraction against distance from the nearest
rebar surface, one line per method or reference, as an SVG file (the
standard library only, so that the example's script can draw it on a
machine without a plotting program).

    profile_plot.py OUT.svg TITLE < rows

rows: tab-separated "label lo hi phi se" (distance bins in rmax, lines
starting with # skipped); each label is one line, in the order first seen.
From Python: plot(path, title, series) with series a list of
(label, [(lo, hi, phi, se), ...]).
"""
import math
import sys

COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#7f7f7f"]
DASHES = ["", "6,3", "2,3", "8,3,2,3", "", "6,3", "2,3", "8,3,2,3"]


def nice_step(span, ticks=5):
    """A round tick step (1, 2 or 5 times a power of ten) for about `ticks` ticks."""
    if not span > 0:
        return 1.0
    raw = span / ticks
    mag = 10 ** math.floor(math.log10(raw))
    return next(m * mag for m in (1, 2, 5, 10) if m * mag >= raw)


def plot(path, title, series, x_label="distance from the nearest rebar surface (rmax)",
         y_label="matrix solid fraction"):
    pts = [(0.5 * (lo + hi), phi, se) for _, rows in series for lo, hi, phi, se in rows
           if all(math.isfinite(v) for v in (lo, hi, phi, se))]
    if not pts:
        raise ValueError("profile_plot: no finite point to plot")
    x_hi = max(hi for _, rows in series for _, hi, _, _ in rows)
    y_lo = min(0.0, min(p[1] - p[2] for p in pts))
    y_hi = max(p[1] + p[2] for p in pts)
    y_step = nice_step(y_hi - y_lo)
    y_hi = math.ceil(y_hi / y_step) * y_step
    x_step = nice_step(x_hi)
    W, H, left, right, top, bottom = 760, 470, 70, 230, 40, 55
    pw, ph = W - left - right, H - top - bottom

    def X(x):
        return left + pw * x / x_hi

    def Y(y):
        return top + ph * (1 - (y - y_lo) / (y_hi - y_lo))

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>',
           f'<text x="{left}" y="22" font-size="14">{escape(title)}</text>',
           f'<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="black"/>']
    k = 0
    while k * x_step <= x_hi + 1e-12:
        x = k * x_step
        out.append(f'<line x1="{X(x):.1f}" y1="{top + ph}" x2="{X(x):.1f}" y2="{top + ph + 5}" stroke="black"/>')
        out.append(f'<text x="{X(x):.1f}" y="{top + ph + 18}" text-anchor="middle">{x:g}</text>')
        k += 1
    k = 0
    while y_lo + k * y_step <= y_hi + 1e-12:
        y = y_lo + k * y_step
        out.append(f'<line x1="{left - 5}" y1="{Y(y):.1f}" x2="{left + pw}" y2="{Y(y):.1f}" '
                   f'stroke="#ddd"/>')
        out.append(f'<text x="{left - 8}" y="{Y(y) + 4:.1f}" text-anchor="end">{y:.2f}</text>')
        k += 1
    out.append(f'<text x="{left + pw / 2}" y="{H - 12}" text-anchor="middle">{escape(x_label)}</text>')
    out.append(f'<text x="18" y="{top + ph / 2}" text-anchor="middle" '
               f'transform="rotate(-90 18 {top + ph / 2})">{escape(y_label)}</text>')
    for n, (label, rows) in enumerate(series):
        colour, dash = COLOURS[n % len(COLOURS)], DASHES[n % len(DASHES)]
        good = [(0.5 * (lo + hi), phi, se) for lo, hi, phi, se in rows
                if all(math.isfinite(v) for v in (lo, hi, phi, se))]
        line = " ".join(f"{X(x):.1f},{Y(y):.1f}" for x, y, _ in good)
        style = f' stroke-dasharray="{dash}"' if dash else ""
        out.append(f'<polyline points="{line}" fill="none" stroke="{colour}" stroke-width="2"{style}/>')
        for x, y, se in good:
            out.append(f'<line x1="{X(x):.1f}" y1="{Y(y - se):.1f}" x2="{X(x):.1f}" y2="{Y(y + se):.1f}" '
                       f'stroke="{colour}"/>')
        ly = top + 14 + 20 * n
        out.append(f'<line x1="{left + pw + 12}" y1="{ly}" x2="{left + pw + 40}" y2="{ly}" '
                   f'stroke="{colour}" stroke-width="2"{style}/>')
        out.append(f'<text x="{left + pw + 46}" y="{ly + 4}">{escape(label)}</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def escape(text):
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.split("\n\n")[1])
    series = {}
    for line in sys.stdin:
        if not line.strip() or line.startswith("#"):
            continue
        label, lo, hi, phi, se = line.rstrip("\n").split("\t")
        series.setdefault(label, []).append((float(lo), float(hi), float(phi), float(se)))
    plot(sys.argv[1], sys.argv[2], list(series.items()))


if __name__ == "__main__":
    main()
