#!/usr/bin/env bash
# Writes bar_template.liggghts: the sphere list of one bar (bar.layout) as
# the LIGGGHTS string variable ${bar}, for bars_multisphere.liggghts's
# particletemplate/multisphere. Made by the layout command
# (docs/layout.md), built by the README's set-up (REINFORCE_BUILD, default
# build/).
set -euo pipefail
cd "$(dirname "$0")"
layout=${REINFORCE_BUILD:-../../build}/src/layout/reinforce_layout
[ -x "$layout" ] || { echo "make_bars.sh: $layout was not built (run the README's set-up)"; exit 1; }
"$layout" bar.layout --liggghts bar_template.liggghts
