#!/bin/sh
# Tool force against stroke of the block forging for mu = 0, 0.2, 0.5 and sticking (mu = 1000:
# the Coulomb cap never binds), at resolutions 1 to 3, through the runner; then the mean force
# over the last 10% of the stroke per run (friction_table.md) and the curves (force_stroke.png).
# Usage: friction_study.sh [contact policy: effective_mass|paper|penalty] [output directory]
#        RKPM_RUN=path/to/rkpm_run to use a runner other than build/tools/runner/rkpm_run.
# Runs one after the other on one thread (about 25 minutes in all on a 2-core machine, most of
# it at resolution 3); a run whose summary.json says completed is not repeated.
set -e
contact=${1:-effective_mass}
out=${2:-results/05_block_forging/friction_study}
root=$(cd "$(dirname "$0")/../.." && pwd)
run=${RKPM_RUN:-$root/build/tools/runner/rkpm_run}
[ -x "$run" ] || { echo "no runner at $run: build it (cmake --build build --target rkpm_run) or set RKPM_RUN" >&2; exit 1; }
mkdir -p "$out"
resolutions="1 2 3"
frictions="0 0.2 0.5 1000"

for K in $resolutions; do
  for mu in $frictions; do
    d="$out/$contact-r$K-mu$mu"
    grep -qs '"status": "completed"' "$d/summary.json" && continue
    echo "block_forging, $contact, resolution $K, mu = $mu"
    OMP_NUM_THREADS=1 "$run" block_forging --quadrature q4 --enforcement "$contact" --resolution "$K" \
      --set friction="$mu" --threads 1 --no-plots --quiet --out "$d"
    grep -qs '"status": "completed"' "$d/summary.json" || { echo "the run in $d did not complete" >&2; exit 1; }
  done
done

# Mean force over the last 10% of the stroke: history.csv holds the force averaged over each
# output interval (column tool_force_N_per_m), so the mean is the interval-weighted mean of the
# intervals ending in the window (the stroke grows linearly with time: the last 10% of the time).
mean_last_tenth() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
           { t[NR] = $(col["time_s"]); f[NR] = $(col["tool_force_N_per_m"]); n = NR }
           END { T = t[n]; s = 0; w = 0
                 for (i = 3; i <= n; ++i) if (t[i] > 0.9 * T) { dt = t[i] - t[i - 1]; s += f[i] * dt; w += dt }
                 printf "%.1f", s / w / 1e6 }' "$1"
}

table="$out/friction_table_$contact.md"
{
  echo "Top tool force (MN/m), mean over the last 10% of the stroke (270-300 mm), Q4, contact $contact"
  echo
  printf "| mu |"; for K in $resolutions; do printf " resolution %s |" "$K"; done; echo
  printf "|---|"; for K in $resolutions; do printf -- "---|"; done; echo
  for mu in $frictions; do
    label=$mu; [ "$mu" = 1000 ] && label="sticking (1000)"
    printf "| %s |" "$label"
    for K in $resolutions; do printf " %s |" "$(mean_last_tenth "$out/$contact-r$K-mu$mu/history.csv")"; done
    echo
  done
} > "$table"
cat "$table"

plot="$out/force_stroke_$contact.png"
{
  echo "set terminal pngcairo size 900,600; set output '$plot'"
  echo "set datafile separator ','; set key top left; set grid; set termoption noenhanced"
  echo "set xlabel 'stroke (mm)'; set ylabel 'top tool force (MN/m)'"
  echo "set title 'block forging, Q4, $contact: force against stroke (dash: resolution)'"
  printf "plot "
  c=0
  for mu in $frictions; do
    c=$((c + 1))
    for K in $resolutions; do
      label="mu = $mu, K = $K"; [ "$mu" = 1000 ] && label="sticking, K = $K"
      printf "'%s' u (500-\$2):(\$5/1e6) every ::1 w l lc %d dt %d lw 1.5 t '%s', " \
        "$out/$contact-r$K-mu$mu/history.csv" "$c" "$K" "$label"
    done
  done
  echo "1/0 notitle"
} | gnuplot
echo "wrote $table and $plot"
