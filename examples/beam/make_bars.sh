#!/usr/bin/env bash
# Writes data/bars.data: the seed paper's five straight bars along the beam
# (bars.layout), 65 rebar spheres each (325 in all), radius 5 mm, centres
# 7.65625 mm apart (overlapping: each bar is a clump), from x = 5 mm to
# 495 mm; cover of 40 mm to the bar axis: three bars at the bottom, two at
# the top. Made by the layout command (docs/layout.md), built by the
# README's set-up (REINFORCE_BUILD, default build/).
set -euo pipefail
cd "$(dirname "$0")"
layout=${REINFORCE_BUILD:-../../build}/src/layout/reinforce_layout
[ -x "$layout" ] || { echo "make_bars.sh: $layout was not built (run the README's set-up)"; exit 1; }
"$layout" bars.layout --data data/bars.data
