#!/bin/bash
# The speed-accuracy trade of a scene: runs build/sweep (a converged CPU reference, cached,
# then a grid of faster settings on both devices), prints its table, and plots render
# CPU-seconds against relative MSE with gnuplot (Debian package gnuplot-nox) into OUT.png.
# A path-traced camera gets two panels: each estimator against the converged image of its
# own kind (noise), and against the full light transport (noise and bias), both with the
# largest 0.1 % of the error terms dropped (bench/sweep_run.h: TrimmedRelativeMse).
#
# usage: bench/sweep.sh SCENE.xml OUT [sweep options: --scale F --ref-spp N --camera N --reps N]
#        RT_SWEEP_REPLOT=1 bench/sweep.sh SCENE.xml OUT: only plot OUT.tsv again
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
scene="$1"; out="$2"; shift 2
if [ -z "${RT_SWEEP_REPLOT:-}" ]; then
  "$here/build/sweep" "$scene" --tsv "$out.tsv" "$@" | tee "$out.md"
fi
if ! command -v gnuplot >/dev/null; then
  echo "(no gnuplot: apt-get install gnuplot-nox to get the plot)"; exit 0
fi
# Columns: 1 axis, 2 setting, 3 device, 4 spp, 6 CPU-s, 8 rel. MSE, 10 rel. MSE vs full,
# 12 and 13 the same with the largest 0.1 % of the error terms dropped (path tracing).
series() {  # AXIS DEVICE: a gnuplot `using` filter of the rows of that axis and device
  echo "(strcol(1) eq \"$1\" && strcol(3) eq \"$2\" ? \$6 : 1/0)"
}
if grep -q $'^estimator\t' "$out.tsv"; then
  plots=""
  while IFS= read -r name; do
    plots+="\"$out.tsv\" using (strcol(1) eq \"estimator\" && strcol(2) eq \"$name\" ? \$6 : 1/0):COL with linespoints title \"$name\", "
  done < <(awk -F'\t' '$1 == "estimator" && !seen[$2]++ { print $2 }' "$out.tsv")
  plots+="\"$out.tsv\" using $(series spp cl):COL with linespoints dt 2 lw 2 title \"the camera's own, OpenCL, spp 1-256\", "
  plots+="\"$out.tsv\" using $(series precision cpu):COL with points pt 11 ps 2 title \"--precision double, CPU\", "
  plots+="\"$out.tsv\" using $(series stop cpu):COL with points pt 7 ps 2 title \"stop rules (CPU)\""
  gnuplot <<GP
set terminal pngcairo size 1500,800 noenhanced
set output "$out.png"
set logscale xy
set xlabel "render CPU-seconds"
set key below
set datafile separator "\t"
set multiplot layout 1,2 title "$(basename "$scene"): estimators, spp 4-64 (CPU)"
set title "against the converged image of the same estimator (noise), largest 0.1 % dropped"
set ylabel "relative MSE, largest 0.1 % of terms dropped"
plot ${plots//COL/12}
set title "against the full light transport (noise and bias), largest 0.1 % dropped"
unset key
plot ${plots//COL/13}
unset multiplot
GP
else
  gnuplot <<GP
set terminal pngcairo size 1000,750 noenhanced
set output "$out.png"
set title "$(basename "$scene"): render CPU-seconds against error (relative MSE vs converged reference)"
set logscale xy
set xlabel "render CPU-seconds (user + system)"
set ylabel "relative MSE"
set key below
set datafile separator "\t"
plot "$out.tsv" using $(series spp cpu):8 with linespoints title "CPU reference, float, spp 1-64", \
     "$out.tsv" using $(series spp cl):8 with linespoints title "OpenCL specialized, float, spp 1-64", \
     "$out.tsv" using $(series precision cpu):8 with linespoints dt 2 title "CPU reference, --precision double, spp 4-64", \
     "$out.tsv" using $(series precision cl):8 with linespoints dt 2 title "OpenCL, --precision double, spp 4-64", \
     "$out.tsv" using $(series kernel cl-generic):8 with points pt 5 ps 1.5 title "OpenCL generic, 16 spp", \
     "$out.tsv" using $(series math cl):8 with points pt 9 ps 1.5 title "OpenCL fast math, 16 spp", \
     "$out.tsv" using $(series bvh cpu):8 with points pt 2 title "CPU, BVH variants, 16 spp", \
     "$out.tsv" using $(series bvh cl):8 with points pt 3 title "OpenCL, BVH variants, 16 spp", \
     "$out.tsv" using $(series dielectric cpu):8 with points pt 7 title "choose by Fresnel, CPU (16, 64 spp)", \
     "$out.tsv" using $(series stop cpu):8 with points pt 13 ps 1.5 title "stop rules (CPU)"
GP
fi
echo "plot: $out.png"
