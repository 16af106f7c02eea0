"""The benchmark's raw results (a bench/run.sh output folder) and the tables made of them, for bench/report.py.

Holds the named data the page checks against (the seed paper's figures, the goals), the method names (read from
bench/methods.tsv, which run.sh reads too), the loaded run, and its medians.
"""
import csv
import os
import platform
import statistics

# The seed paper's figures (Jerier et al.), and the goals the page checks.
PAPER = {"worst_deleted": "20%", "slab_hours": 12}
GOAL_TIMES_FASTER = {"make_packing.lmp": 10.0, "grow_packing": 1.0}   # growth time / the fix's time, at least
REF_NAME = {"around": "grow_packing", "lammps": "make_packing.lmp"}   # reference.tsv's kinds
SERIES = ("speedup", "gap", "rbar", "scaling")    # scene names of the series (not compared scenes)
METHODS = {m["key"]: m for m in csv.DictReader(open(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                                 "methods.tsv")), delimiter="\t")}
DEFAULTS, FIT, PUSH, NO_REGROWTH, DELETE = (METHODS[k]["method"] for k in ("defaults", "fit", "push", "norgrow", "delete_max"))


# --- load -------------------------------------------------------------------------------------------------------
def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return None


class Run:
    """The raw results of one bench/run.sh run (its TSV files)."""

    def __init__(self, out_dir):
        def read(name, fieldnames=None):
            path = os.path.join(out_dir, name)
            return list(csv.DictReader(open(path), delimiter="\t", fieldnames=fieldnames)) \
                if os.path.exists(path) else []
        self.rows, self.curves, self.quality = read("results.tsv"), read("relax.tsv"), read("quality.tsv")
        self.grown, self.versus, self.profiles = read("reference.tsv"), read("versus.tsv"), read("profile.tsv")
        self.exchange = [(num(r["partners"]), num(r["us"])) for r in read("exchange_cost.tsv", ["partners", "us"])]
        meta = read("meta.tsv")
        self.meta = {r["key"]: r["value"] for r in meta if r["key"] != "skipped" and not r["key"].startswith("load_")}
        self.skipped = [r["value"] for r in meta if r["key"] == "skipped"]
        self.loads = [(r["key"][5:], r["value"]) for r in meta if r["key"].startswith("load_")]
        self.quick = self.meta.get("quick") == "1"
        self.packing = {k[8:]: dict(zip(v.split()[::2], v.split()[1::2]))
                        for k, v in self.meta.items() if k.startswith("packing_")}

    def group(self, scene, np=None):
        """Median figures per (method, param, np) of one scene, in run order."""
        seen = {}
        for r in self.rows:
            if r["scene"] == scene and np in (None, r["np"]):
                seen.setdefault((r["method"], r["param"], r["np"]), []).append(r)
        return [summarize(rs) for rs in seen.values()]

    def scenes(self):
        return list(dict.fromkeys(r["scene"] for r in self.rows))

    def atoms(self, *scenes):
        return next(int(r["atoms"]) for r in self.rows if r["scene"] in scenes)

    def quality_of(self, scene, method, param=None):
        return next((q for q in self.quality if q["scene"] == scene and q["method"] == method
                     and param in (None, q["param"])), None)


# --- tables -----------------------------------------------------------------------------------------------------
def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def summarize(rs):
    m = {f: median([num(r[f]) for r in rs]) for f in rs[0] if f not in ("scene", "method", "param")}
    m.update(scene=rs[0]["scene"], method=rs[0]["method"], param=rs[0]["param"], np=rs[0]["np"], repeats=len(rs))
    return m


def find(g, method, param=None):
    return next((m for m in g if m["method"] == method and param in (None, m["param"])), None)


def fmt(v, spec):
    return "" if v is None else format(v, spec)


def span(values, spec):
    values = [v for v in values if v is not None]
    if not values:
        return None
    lo, hi = format(min(values), spec), format(max(values), spec)
    return lo if lo == hi else f"{lo} to {hi}"


def table(header, rows):
    return ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)] + \
        ["| " + " | ".join("" if c is None else str(c) for c in r) + " |" for r in rows]


def cpu_name():
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            return line.split(":", 1)[1].strip()
    return platform.processor()


def compared_scenes(run):
    return [s for s in run.scenes() if s.split("_")[0] not in SERIES]


def scene_groups(run, scene):
    """A compared scene's medians on 1 process, then on more; the slab's defaults come from its speedup runs."""
    g = run.group(scene, "1") + [m for m in run.group(scene) if m["np"] != "1"]
    return g if find(g, DEFAULTS) else run.group("speedup_" + scene, "1") + g


def summary(run):
    """Per compared scene with delete_atoms: the defaults, size fit, push rmax, delete_atoms (largest cutoff), relax."""
    out = []
    for scene in compared_scenes(run):
        g = scene_groups(run, scene)
        dels = [m for m in g if m["method"] == DELETE]
        if find(g, DEFAULTS) and dels:
            out.append((scene, find(g, DEFAULTS), find(g, FIT), find(g, PUSH),
                        max(dels, key=lambda m: float(m["param"])), find(g, "relax")))
    return out
