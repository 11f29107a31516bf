#!/usr/bin/env bash
# ctest tradeoff_script (issue 26): scripts/tradeoff --smoke with this build,
# run in an empty folder. Every job must leave its row in results.csv (none
# "failed"; "unstable" and "refused" are results), every problem and knob
# must appear, the tables and the eight plots must be written, and nothing
# may be left in the folder it ran in.
#
#   tradeoff_script_test.sh BUILD_DIR
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "$1" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/work"
cd "$tmp/work" || exit 1
start=$(date +%s)
"$root/scripts/tradeoff" --smoke --build "$build" --out "$tmp/out" --plots "$tmp/plots" \
  >"$tmp/log" 2>"$tmp/errors"
status=$?
tail -n 3 "$tmp/log"
echo "(scripts/tradeoff --smoke: exit status $status, $(($(date +%s) - start)) s)"
problems=()
[[ $status -eq 0 ]] || problems+=("exit status $status; its stderr: $(tail -n 5 "$tmp/errors")")

csv=$tmp/out/results.csv
jobs=$(wc -l <"$tmp/out/jobs.txt" 2>/dev/null || echo 0)
if [[ ! -s $csv ]]; then
  problems+=("no results.csv")
else
  header=$(head -n 1 "$csv")
  [[ $header == problem,knob,setting,resolution,status,error,error2,value,wall_s,cpu_s,steps,nodes,message ]] ||
    problems+=("results.csv header: $header")
  rows=$(($(wc -l <"$csv") - 1))
  [[ $rows -eq $jobs && $jobs -gt 0 ]] || problems+=("results.csv has $rows rows for $jobs jobs")
  failed=$(grep -c ',failed,' "$csv")
  [[ $failed -eq 0 ]] || problems+=("$failed jobs failed: $(grep ',failed,' "$csv" | head -n 3)")
  for pk in couette,resolution couette,solidratio couette,tau poiseuille,forcing poiseuille,tau \
            sediment,resolution sediment,solidratio sediment,integrator light,coupling \
            collision,integrator contact,polygon contact,superquadric couette,accuracy sediment,accuracy; do
    grep -q "^$pk,.*,ok," "$csv" || problems+=("no ok row for $pk")
  done
  # A number in every ok row's error and wall time (the sediment reference has none).
  bad=$(awk -F, 'NR > 1 && $5 == "ok" && ($6 !~ /^[0-9.e+-]+$/ || $9 !~ /^[0-9.e+-]+$/)' "$csv" | head -n 3)
  [[ -z $bad ]] || problems+=("ok rows without an error or a wall time: $bad")
fi
grep -q '^## couette: solid ratio under refinement' "$tmp/out/tables.md" 2>/dev/null ||
  problems+=("tables.md lacks the Couette solid-ratio table")
for plot in couette poiseuille sediment light collision contact couette-solidratio force-noise; do
  [[ -s $tmp/plots/tradeoff-$plot.png ]] || problems+=("no plot tradeoff-$plot.png")
done
# The job list for a batch system: one line per job, the same as jobs.txt.
printed=$("$root/scripts/tradeoff" --smoke --build "$build" --out "$tmp/out2" --print-jobs | wc -l)
[[ $printed -eq $jobs ]] || problems+=("--print-jobs printed $printed lines for $jobs jobs")
stray=$(ls -A "$tmp/work")
[[ -n $stray ]] && problems+=("files left in the working folder: $stray")

if [[ ${#problems[@]} -gt 0 ]]; then
  printf 'FAILED: %s\n' "${problems[@]}"
  exit 1
fi
echo "tradeoff_script: $jobs jobs, every one with its row, 8 plots, nothing left behind"
