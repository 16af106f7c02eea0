#!/usr/bin/env bash
# Puts a table a script wrote into a README between its markers: the lines
# after "<!-- written by ... from TABLE: ..." up to the next "<!-- end of
# what ..." are replaced by TABLE's contents. Run from the folder the
# marker's TABLE path is relative to.
#   fill_readme_block.sh README TABLE
set -euo pipefail
readme=$1 table=$2
grep -qF "from $table:" "$readme" || { echo "fill_readme_block: no marker for $table in $readme"; exit 1; }
awk -v name="$table" 'FNR == NR {text = text $0 "\n"; next}
     /^<!-- written by / && index($0, " from " name ":") {print; printf "%s", text; skip = 1; next}
     /^<!-- end of what / {skip = 0}
     !skip {print}' "$table" "$readme" > "$readme.new"
mv "$readme.new" "$readme"
