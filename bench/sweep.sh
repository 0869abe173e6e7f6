#!/bin/bash
# The speed-accuracy trade of a scene: runs build/sweep (a converged CPU reference, then
# a grid of faster settings on both devices), prints its table, and plots render time
# against relative MSE with gnuplot (Debian package gnuplot-nox) into OUT.png.
#
# usage: bench/sweep.sh SCENE.xml OUT [sweep options: --scale F --ref-spp N --camera N]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
scene="$1"; out="$2"; shift 2
"$here/build/sweep" "$scene" --tsv "$out.tsv" "$@" | tee "$out.md"
if ! command -v gnuplot >/dev/null; then
  echo "(no gnuplot: apt-get install gnuplot-nox to get the plot)"; exit 0
fi
gnuplot <<GP
set terminal pngcairo size 1000,750 noenhanced
set output "$out.png"
set title "$(basename "$scene"): render time against error (relative MSE vs converged reference)"
set logscale xy
set xlabel "render time, seconds"
set ylabel "relative MSE"
set key below
set datafile separator "\t"
plot "$out.tsv" using (strcol(1) eq "spp" && strcol(3) eq "cpu" ? \$6 : 1/0):7 with linespoints title "CPU reference, spp 1-64", \
     "$out.tsv" using (strcol(1) eq "spp" && strcol(3) eq "cl" ? \$6 : 1/0):7 with linespoints title "OpenCL specialized, spp 1-64", \
     "$out.tsv" using (strcol(1) eq "kernel" ? \$6 : 1/0):7 with points pt 5 ps 1.5 title "OpenCL generic, 16 spp", \
     "$out.tsv" using (strcol(1) eq "math" ? \$6 : 1/0):7 with points pt 9 ps 1.5 title "OpenCL fast math, 16 spp", \
     "$out.tsv" using (strcol(1) eq "precision" ? \$6 : 1/0):7 with points pt 11 ps 1.5 title "--precision double, 16 spp (both devices)", \
     "$out.tsv" using (strcol(1) eq "bvh" && strcol(3) eq "cpu" ? \$6 : 1/0):7 with points pt 2 title "CPU, BVH variants, 16 spp", \
     "$out.tsv" using (strcol(1) eq "bvh" && strcol(3) eq "cl" ? \$6 : 1/0):7 with points pt 3 title "OpenCL, BVH variants, 16 spp", \
     "$out.tsv" using (strcol(1) eq "dielectric" ? \$6 : 1/0):7 with points pt 7 title "choose by Fresnel (16, 64 spp)"
GP
echo "plot: $out.png"
