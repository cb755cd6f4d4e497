#!/usr/bin/env bash
# Scheme comparison of thesis section 5.2.3 (Table 5.1, Fig. 5.1): the
# quarter-circle test (r0 = 0.4, eps = 2^-6, tau = inner tau = h^2, 80
# steps, adaptive mesh) with the nested and the semi-implicit scheme on
# 2 MPI ranks. Prints one row per run (total Newton iterations, time-step
# halvings, wall seconds, final L2 error, DoFs) and writes the L2 error over
# time of all runs to <output>/l2_error.png (the analogue of Fig. 5.1).
# Usage: [MAX_NEWTON=100] benchmarks/scheme_comparison.sh [build dir] [output dir] [levels...]
#   e.g. benchmarks/scheme_comparison.sh build output/scheme_comparison 7 8 9
set -euo pipefail
build=${1:-build}; shift || true
out=${1:-output/scheme_comparison}; shift || true
levels=${*:-7 8 9}
max_newton=${MAX_NEWTON:-100}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
printf '%-5s %-13s %6s %7s %9s %9s %12s %8s\n' level scheme steps newton halvings wall_s l2_error dofs
for level in $levels; do
  for scheme in nested semi-implicit; do
    name=${scheme}_h${level}
    sed -e "s|set Output directory = .*|set Output directory = $out/$name|" \
        -e "s|set Scheme          = nested|set Scheme          = $scheme|" \
        -e "s|set VTU interval = 20|set VTU interval = 0|" \
        "$here/parameter_files/willmore_flow/quarter_circle_h$level.prm" > "$out/$name.prm"
    # as in the thesis, Newton may iterate long (it reported up to 200
    # iterations per step for the semi-implicit scheme) instead of halving
    # the step, so that both schemes take the same 80 time steps
    printf 'subsection Newton\n  set Maximum iterations = %s\nend\n' "$max_newton" >> "$out/$name.prm"
    status=ok
    OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np 2 "$build/willmore_flow" "$out/$name.prm" \
      > "$out/$name.log" 2>&1 || status=failed
    /usr/bin/python3 - "$out/$name/statistics.csv" "$level" "$scheme" "$status" "$out/$name.log" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
halvings = open(sys.argv[5]).read().count("retrying with half the time step")
last = rows[-1]
newton = sum(float(r["newton_iterations"]) for r in rows[1:])
note = "" if sys.argv[4] == "ok" else "  (FAILED, see log)"
print(f'{sys.argv[2]:<5} {sys.argv[3]:<13} {len(rows) - 1:6d} {newton:7.0f} {halvings:9d} '
      f'{float(last["wall_seconds"]):9.1f} {float(last["l2_error"]):12.4e} {float(last["dofs"]):8.0f}{note}')
PY
  done
done
/usr/bin/python3 - "$out" $levels <<'PY'
import csv, os, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
out, levels = sys.argv[1], sys.argv[2:]
fig, ax = plt.subplots(figsize=(7, 4.5))
for level in levels:
    for scheme, style in (("nested", "-"), ("semi-implicit", "--")):
        path = os.path.join(out, f"{scheme}_h{level}", "statistics.csv")
        if not os.path.isfile(path):
            continue
        rows = list(csv.DictReader(open(path)))
        ax.plot([float(r["time"]) for r in rows], [float(r["l2_error"]) for r in rows],
                style, label=f"{scheme}, h = 2^-{level}")
ax.set_yscale("log")
ax.set_xlabel("time")
ax.set_ylabel("L2 error")
ax.set_title("Quarter circle, eps = 2^-6, tau = inner tau = h^2")
ax.legend()
fig.tight_layout()
fig.savefig(os.path.join(out, "l2_error.png"), dpi=120)
print("plot:", os.path.join(out, "l2_error.png"))
PY
