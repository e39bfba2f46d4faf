#!/usr/bin/env bash
# The glass-ceramic toughness study of Fan et al. (seeds/000 Sec. 5, Fig. 8): for crystal fractions
# f = 20, 40, 60, 80 %, mean and standard deviation of K_IC from
#   PCA:  the PCA field of `REALIZATIONS` microstructures with 20 modes, Smolyak level 1 (41 samples);
#   MC:   `MC` real microstructures (seeds 1..MC).
# Everything goes through `peristep sample`, so an interrupted study resumes where it stopped.
#
#   bench/glass_ceramic_study.sh OUT_DIR [H_UM] [REALIZATIONS] [MC] [STEPS] [UD_MAX_M]
#   e.g. bench/glass_ceramic_study.sh study 40 20000 100 250 1e-6   (the paper's loading: 4e-3 um steps to 1 um)
#   PERISTEP=path/to/peristep PERISTEP_FMU=path/to/PeriStep.fmu to use other builds.
#   LAUNCH="mpirun -n 2" to spread each study's samples over MPI ranks; FRACTIONS="0.2 0.4" for some
#   fractions only; TABLE_ONLY=1 to redraw the table and plot from OUT_DIR (every finished fraction).
#   A study longer than one sitting resumes from the sample stores in OUT_DIR; on another machine, put the
#   finished rows in OUT_DIR/toughness.csv (e.g. a copy of bench/results/glass_ceramic_toughness_h8.csv).
#
# Writes OUT_DIR/toughness.csv (f, method, samples, mean, std (PCA: direct and PCE), MC standard error of the
# mean, wall s, per-sample wall s: median, largest, sum) and OUT_DIR/toughness.png (PCA error bars: PCE std).
set -euo pipefail
out=${1:?usage: glass_ceramic_study.sh OUT_DIR [H_UM] [REALIZATIONS] [MC] [STEPS] [UD_MAX_M]}
h_um=${2:-16}
realizations=${3:-20000}
mc=${4:-100}
steps=${5:-75}
ud_max=${6:-0.3e-6}
here=$(cd "$(dirname "$0")/.." && pwd)
peristep=${PERISTEP:-$here/build/host/peristep}
fmu=(); [ -n "${PERISTEP_FMU:-}" ] && fmu=(--fmu "$PERISTEP_FMU")  # a copy, so a rebuild cannot change it mid-study
read -r -a launch <<< "${LAUNCH:-}"
fractions=${FRACTIONS:-0.2 0.4 0.6 0.8}
mkdir -p "$out"
cd "$out"

# Grid: 800 x 400 um at spacing h (nx - 1 = 800 / h, ny - 1 = 400 / h).
nx=$(python3 -c "print(round(800 / $h_um) + 1)")
ny=$(python3 -c "print(round(400 / $h_um) + 1)")
zeros=$(python3 -c "print(', '.join(['0.0'] * 20))")

scene() {  # scene FILE FRACTION PCA_REALIZATIONS NMODES XI
  cat > "$1" <<TOML
[parameters]
scene = "glassCeramic"
nx = $nx
ny = $ny
Lx = 800e-6
Ly = 400e-6
deltaOverH = 3.0
poissonRatio = 0.25
crystalFraction = $2
seed = 1
pcaRealizations = $3
setUpTimeLimit = 3600.0  # the PCA of 20,000 realizations takes minutes on fine grids
nModes = $4
xi = [$5]

[loading]
input = "loadDisplacement"
from = 0.0
to = $ud_max
steps = $steps
TOML
}

# Column of a CSV header by name (empty when the CSV has none).
colnum() { head -1 "$1" | tr ',' '\n' | { grep -nx "$2" || true; } | cut -d: -f1; }

# Median, largest and sum of the per-sample wall times kept in a sample store (the projection script reads them).
sample_seconds() {
  python3 - "$1" "$here/bench" <<'PY'
import statistics, sys
sys.path.insert(0, sys.argv[2])
from glass_ceramic_projection import sample_seconds
t = sample_seconds(sys.argv[1])
print(f"{statistics.median(t):.1f},{max(t):.1f},{sum(t):.0f}")
PY
}

for f in $fractions; do
  [ -n "${TABLE_ONLY:-}" ] && break  # TABLE_ONLY=1: table and plot from what OUT_DIR holds, nothing run
  tag=$(python3 -c "print(round(100 * $f))")
  scene "pca_f$tag.toml" "$f" "$realizations" 20 "$zeros"
  scene "mc_f$tag.toml" "$f" 0 1 "0.0"
  "${launch[@]}" "$peristep" sample "pca_f$tag.toml" --rule smolyak --level 1 --out "pca_f$tag.h5" "${fmu[@]}"
  "${launch[@]}" "$peristep" sample "mc_f$tag.toml" --rule mc --samples "$mc" --out "mc_f$tag.h5" "${fmu[@]}"
done

# One row per fraction and method whose study has finished (its CSV exists); a row of the previous
# toughness.csv is kept for a study that OUT_DIR no longer holds (a sitting on another machine).
touch toughness.csv
mv toughness.csv toughness.previous
echo "f,method,samples,mean_KIC,std_KIC,pce_std_KIC,se_mean_KIC,wall_s,sample_s_median,sample_s_max,sample_s_sum" \
  > toughness.csv
for tag in 20 40 60 80; do
  for method in pca mc; do
    csv="${method}_f$tag.csv"
    if [ ! -f "$csv" ]; then
      grep "^0.$((tag / 10)),$method," toughness.previous >> toughness.csv || true
      continue
    fi
    row=$(tail -1 "$csv")
    get() { local c; c=$(colnum "$csv" "$1"); [ -n "$c" ] && echo "$row" | cut -d, -f"$c"; }
    echo "0.$((tag / 10)),$method,$(get samples),$(get mean_toughnessKIC),$(get std_toughnessKIC)," \
      "$(get pceStd_toughnessKIC),$(get seMean_toughnessKIC),$(get seconds),$(sample_seconds "${method}_f$tag.samples")" |
      tr -d ' ' >> toughness.csv
  done
done
rm toughness.previous
column -t -s, toughness.csv

if command -v gnuplot > /dev/null; then
  gnuplot <<GP
set terminal pngcairo size 900,600 noenhanced
set output "toughness.png"
set datafile separator ","
set key top left
set xlabel "crystal fraction f"
set ylabel "K_IC [MPa m^0.5]"
set title "Glass-ceramic toughness, h = $h_um um: mean +- one standard deviation"
set xrange [0.1:0.9]
set yrange [0:4.5]
plot "< grep ',pca,' toughness.csv" using (\$1-0.01):(\$4/1e6):(\$6/1e6) with yerrorlines title "PCA, Smolyak level 1 (41 samples)", \
     "< grep ',mc,' toughness.csv" using (\$1+0.01):(\$4/1e6):(\$5/1e6) with yerrorlines title "Monte Carlo ($mc microstructures)", \
     0.75 with lines dashtype 2 lc rgb "gray40" title "glass, 000 Table 1 (0.75)", \
     3.5 with lines dashtype 3 lc rgb "gray40" title "crystal, 000 Table 1 (3.5)"
GP
  echo "wrote $out/toughness.csv and $out/toughness.png"
fi
