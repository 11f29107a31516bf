#!/usr/bin/env bash
# ctest validate_script (issue 25): scripts/validate --smoke with this build,
# run in an empty folder. Every case must print its table in full and the
# plots must be drawn, and the script must leave nothing in the folder it ran
# in: case D's table once went to a file named "none seen" there (an awk
# printf whose "... > 0 ? ..." parsed as a redirection).
#
#   validate_script_test.sh BUILD_DIR
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "$1" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/work"
cd "$tmp/work" || exit 1
start=$(date +%s)
"$root/scripts/validate" --smoke --build "$build" --out "$tmp/out" --plots "$tmp/plots" \
  >"$tmp/log" 2>"$tmp/errors"
status=$?
cat "$tmp/log"
echo "(scripts/validate --smoke: exit status $status, $(($(date +%s) - start)) s)"
problems=()
[[ $status -eq 0 ]] || problems+=("exit status $status; its stderr: $(tail -n 5 "$tmp/errors")")

# COUNT lines of the output match the extended regular expression.
expect() {
  local what=$1 count=$2 pattern=$3 n
  n=$(grep -cE -- "$pattern" "$tmp/log")
  [[ $n -eq $count ]] || problems+=("$what: $n lines match /$pattern/, expected $count")
}
number='[-+]?[0-9.]+(e[-+][0-9]+)?'
expect "case headings" 4 '^== case [BADE]:'
expect "case B convergence, stationary and translating, 20 and 40 cells" 4 \
  "^ +(20|40) +$number +[0-9]+ +$number +"
expect "case B tau sweep" 2 "^ +(0\.625|1\.000) +$number +$number +$number +$number$"
expect "case B interior" 2 "^ +(equilibrium|collide) +$number +$number +$number$"
expect "case B solid ratio" 5 "^ +(exact|1|2|4|8) +$number +$number +$number$"
expect "case B transient" 2 "^ +$number +(1\.00|0\.75) +$number +$number +"
expect "case A drag" 2 "^ +(20|40) cells  h $number +[0-9]+ steps  drag $number  lift $number$"
expect "case D, each run" 3 \
  "^(central/explicit|euler/explicit|central/implicit) +terminal Re $number   x/L over the last half $number\.\.$number   oscillation period ($number|none seen)$"
expect "case E summary" 1 "^mean settling speed $number, Re $number; closest approach $number d"
expect "plots" 1 "^plots in "
for plot in validation-couette validation-couette-tau validation-sediment validation-dkt; do
  [[ -s $tmp/plots/$plot.png ]] || problems+=("no plot $plot.png")
done
stray=$(ls -A "$tmp/work")
[[ -n $stray ]] && problems+=("files left in the working folder: $stray")

if [[ ${#problems[@]} -gt 0 ]]; then
  printf 'FAILED: %s\n' "${problems[@]}"
  exit 1
fi
echo "validate_script: every case printed its table, 4 plots, nothing left behind"
