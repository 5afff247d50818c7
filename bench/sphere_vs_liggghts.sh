#!/bin/sh
# The 2000-bead direct shear in grainlab and in LIGGGHTS 3.8 (Debian package
# liggghts; a comparison bench only, never a dependency of grainlab), one
# thread each, alternated: shear-phase steps/s and particle-steps/s, whole-test
# wall time (medians) and phi_p, psi_p side by side. The inputs, the deck and
# what differs between the two set-ups: bench/liggghts/.
#
#   bench/sphere_vs_liggghts.sh [--quick] [--repeats N] [--strain S] [--keep DIR]
#     --quick: one run each to 2 % strain (about 2 minutes on a quiet machine)
#     default: three runs each to 10 % strain (about 6 minutes)
exec /usr/bin/python3 "$(dirname "$0")/liggghts/compare.py" "$@"
