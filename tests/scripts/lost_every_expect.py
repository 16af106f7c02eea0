#!/usr/bin/env python3
"""The lost-matrix WARNINGs a run of in.lost_every must print, from its dumps
alone (not the fix's f_ID): for each invocation (every 10 steps), the scene
before it (the matrix of the previous dump, before.dump at step 0; the bars
where the dump at its step has them: only the bars move between
invocations) and after it (the dump at its step). Targets: matrix spheres
overlapping a bar sphere by more than tol = 1e-6 of the smaller radius;
deleted: matrix ids gone; of them inside the bars: centre inside a bar
sphere; shrunk: targets still there with a smaller radius; the share kept:
the volume of the targets still there over that of all targets. An
invocation loses matrix when it left a target shrunk or deleted one beyond
those inside the bars; the WARNING comes once per run (its first such
invocation), with that invocation's counts, in the doc page's words.

    lost_every_expect.py BEFORE_DUMP EVERY_DUMP RUN_ENDS...
RUN_ENDS: the last step of each run (e.g. 40 70). Prints one line per
invocation ("INVOCATION step targets deleted inside shrunk share lossy"),
then "EXPECT text" for each WARNING, in order.
"""
import math
import sys


def snapshots(path):
    """{step: {id: (type, x, y, z, r)}}, the last snapshot of each step."""
    out, lines = {}, open(path).read().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            j = i + 4
            while not lines[j].startswith("ITEM: ATOMS"):
                j += 1
            cols = lines[j].split()[2:]
            atoms = {}
            for line in lines[j + 1:j + 1 + n]:
                w = dict(zip(cols, line.split()))
                atoms[int(w["id"])] = (int(w["type"]), float(w["x"]), float(w["y"]), float(w["z"]),
                                       float(w["radius"]))
            out[step] = atoms
            i = j + 1 + n
        else:
            i += 1
    return out


def vol(r):
    return 4.0 / 3.0 * math.pi * r ** 3


before = snapshots(sys.argv[1])
every = snapshots(sys.argv[2])
ends = [int(s) for s in sys.argv[3:]]
prev = next(iter(before.values()))
tol = 1e-6
expect, run, warned = [], 0, False
for step in sorted(every):
    after = every[step]
    bars = [a for a in after.values() if a[0] == 2]
    targets, inside_of = [], {}
    for i, (t, x, y, z, r) in prev.items():
        if t != 1:
            continue
        hit = inside = False
        for (_, bx, by, bz, br) in bars:
            d = math.sqrt((x - bx) ** 2 + (y - by) ** 2 + (z - bz) ** 2)
            if d < r + br - tol * min(r, br):
                hit = True
            if d < br:
                inside = True
        if hit:
            targets.append(i)
            inside_of[i] = inside
    deleted = [i for i in targets if i not in after]
    stray = [i for i, a in prev.items() if a[0] == 1 and i not in after and i not in inside_of]
    if stray:
        print(f"FAIL: step {step}: {len(stray)} matrix spheres deleted that were no target")
        sys.exit(1)
    inside = sum(1 for i in deleted if inside_of[i])
    shrunk = sum(1 for i in targets if i in after and after[i][4] < prev[i][4])
    vb = sum(vol(prev[i][4]) for i in targets)
    va = sum(vol(after[i][4]) for i in targets if i in after)
    share = va / vb if vb > 0 else 0.0
    outside = len(deleted) - inside
    lossy = shrunk > 0 or outside > 0
    print(f"INVOCATION {step} {len(targets)} {len(deleted)} {inside} {shrunk} {share:.2f} {int(lossy)}")
    while run < len(ends) and step > ends[run]:
        run += 1
        warned = False
    if lossy and not warned:
        parts = []
        if shrunk > 0:
            parts.append(f"left {shrunk} targets smaller than their own radius")
        if outside > 0:
            parts.append(f"deleted {outside} targets beyond the {inside} whose centre lies inside the bars")
        expect.append("WARNING: Fix reinforce/invert regrowth " + " and ".join(parts) +
                      f": the targets keep {share:.2f} of their volume")
        warned = True
    prev = after
for text in expect:
    print("EXPECT " + text)
