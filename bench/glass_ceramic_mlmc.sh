#!/usr/bin/env bash
# 000's toughness study (Sec. 5, Fig. 8) at the paper's grid, h = 2 um, by multilevel Monte Carlo over real
# microstructures: for each crystal fraction, `peristep sample --rule mlmc` on grids h = 8, 4, 2 um (a seed
# is the same material on all three), to a standard error of SE (relative, default 2%) of the mean K_IC.
# Resumable: every specimen is kept in OUT_DIR/mlmc_fNN.samples, so a study stopped at any point continues
# with the same command.
#
#   bench/glass_ceramic_mlmc.sh OUT_DIR [SE] [PILOT]
#   LAUNCH="mpirun -n 2 -x OMP_NUM_THREADS=1" to run two specimens at a time; FRACTIONS="0.2 0.8" for some
#   fractions; PERISTEP / PERISTEP_FMU for copies of the binaries (a rebuild cannot then change them
#   mid-study); TABLE_ONLY=1 to redraw the table and figure from OUT_DIR.
#
# Writes OUT_DIR/mlmc_fNN.csv (per level) and mlmc_fNN_summary.csv (the estimate) for each fraction, and
# OUT_DIR/toughness_mlmc.csv (f, estimate, se, samples per level, sample seconds, plain Monte Carlo's cost)
# with OUT_DIR/toughness_mlmc.png: mean and 95% interval per fraction, the phases' K_IC, a linear fit.
set -euo pipefail
out=${1:?usage: glass_ceramic_mlmc.sh OUT_DIR [SE] [PILOT]}
se=${2:-0.02}
pilot=${3:-5}
here=$(cd "$(dirname "$0")/.." && pwd)
peristep=${PERISTEP:-$here/build/host/peristep}
fmu=(); [ -n "${PERISTEP_FMU:-}" ] && fmu=(--fmu "$PERISTEP_FMU")
read -r -a launch <<< "${LAUNCH:-}"
fractions=${FRACTIONS:-0.2 0.4 0.6 0.8}
mkdir -p "$out"
cd "$out"

# The paper's plate at h = 2 um and its loading: U_D in steps of 4e-3 um to 1 um (a run ends when the
# crack has crossed the plate).
cat > mlmc.toml <<'TOML'
[parameters]
scene = "glassCeramic"
nx = 401
ny = 201
Lx = 800e-6
Ly = 400e-6
deltaOverH = 3.0
poissonRatio = 0.25
seed = 1

[loading]
input = "loadDisplacement"
from = 0.0
to = 1e-6
steps = 250
TOML

for f in $fractions; do
  [ -n "${TABLE_ONLY:-}" ] && break
  tag=$(python3 -c "print(round(100 * $f))")
  "${launch[@]}" "$peristep" sample mlmc.toml --set crystalFraction="$f" --rule mlmc --grids 3 \
    --quantity toughnessKIC --se "$se" --pilot "$pilot" --out "mlmc_f$tag.h5" "${fmu[@]}"
done

python3 - <<'PY'
import csv, glob, os
rows = []
for summary in sorted(glob.glob("mlmc_f*_summary.csv")):
    tag = summary[len("mlmc_f"):-len("_summary.csv")]
    s = next(csv.DictReader(open(summary)))
    levels = list(csv.DictReader(open(f"mlmc_f{tag}.csv")))
    rows.append([int(tag) / 100, s["estimate"], s["se"], s["target_se"],
                 "/".join(l["pairs"] for l in levels), s["sample_seconds"], s["threads_per_sample"],
                 s["plain_mc_samples"], s["plain_mc_seconds"]])
with open("toughness_mlmc.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["f", "mean_KIC", "se_KIC", "target_se", "pairs_per_level", "sample_seconds", "threads_per_sample",
                "plain_mc_samples", "plain_mc_seconds"])
    w.writerows(rows)
PY
column -t -s, toughness_mlmc.csv

if command -v gnuplot > /dev/null && [ "$(wc -l < toughness_mlmc.csv)" -gt 1 ]; then
  gnuplot <<'GP'
set terminal pngcairo size 900,600 noenhanced
set output "toughness_mlmc.png"
set datafile separator ","
set key top left
set xlabel "crystal fraction f"
set ylabel "K_IC [MPa m^0.5]"
set title "Glass-ceramic toughness at h = 2 um, multilevel Monte Carlo (grids 8, 4, 2 um): mean and 95% interval"
set xrange [0:1]
set yrange [0:4]
k(x) = a + b * x
a = 0.75; b = 2.75
fit k(x) "toughness_mlmc.csv" using 1:($2/1e6):($3/1e6) yerrors via a, b
plot "toughness_mlmc.csv" using 1:($2/1e6):(1.96*$3/1e6) with yerrorbars pt 7 title "PeriStep, MLMC", \
     k(x) with lines dashtype 2 title sprintf("linear fit %.2f + %.2f f", a, b), \
     0.75 with lines dashtype 3 lc rgb "gray40" title "glass, 000 Table 1 (0.75)", \
     3.5 with lines dashtype 4 lc rgb "gray40" title "crystal, 000 Table 1 (3.5)"
GP
  echo "wrote $out/toughness_mlmc.csv and $out/toughness_mlmc.png"
fi
