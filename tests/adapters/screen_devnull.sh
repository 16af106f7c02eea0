#!/bin/sh
# Runs $REINFORCE_WRAPPED_EXE with the same arguments, but -screen none
# turned into -screen /dev/null: LIGGGHTS 3.8's insert/pack writes to the
# screen unconditionally (Region::reset_random), and expect_error.sh passes
# -screen none.
n=$#
prev=
for a in "$@"; do
  if [ "$prev" = -screen ] && [ "$a" = none ]; then a=/dev/null; fi
  set -- "$@" "$a"
  prev=$a
done
shift "$n"
exec "${REINFORCE_WRAPPED_EXE:?screen_devnull.sh: REINFORCE_WRAPPED_EXE is not set}" "$@"
