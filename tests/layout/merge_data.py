#!/usr/bin/env python3
"""Appends the atoms of a reinforce_layout data file to a scene's data file
(ids after the scene's, types shifted by an offset), for a host without
`read_data ... add append` (LIGGGHTS 3.8).
    merge_data.py SCENE.data BARS.data TYPE_OFFSET OUT.data"""
import sys


def split(path):
    with open(path) as f:
        head, body = f.read().split("\nAtoms", 1)
    rows = [line.split() for line in body.splitlines()[1:] if line.strip()]
    return head, rows


scene_head, scene = split(sys.argv[1])
_, bars = split(sys.argv[2])
offset = int(sys.argv[3])
count = len(scene) + len(bars)
lines = []
for line in scene_head.splitlines():
    words = line.split()
    if words[1:] == ["atoms"]:
        line = "%d atoms" % count
    lines.append(line)
with open(sys.argv[4], "w") as out:
    out.write("\n".join(lines) + "\n\nAtoms\n\n")
    for r in scene:
        out.write(" ".join(r) + "\n")
    for k, r in enumerate(bars, start=len(scene) + 1):
        out.write(" ".join([str(k), str(int(r[1]) + offset)] + r[2:]) + "\n")
