#!/usr/bin/env bash
# ctest validate_script (issue 25): scripts/validate --smoke with this build,
# run in an empty folder. Every case (B A D E, and C E6 F G H from
# scripts/validate-cases/) must print its table in full and the plots must be
# drawn and named on the "plots in" line, and the script must leave nothing in
# the folder it ran in: case D's table once went to a file named "none seen"
# there (an awk printf whose "... > 0 ? ..." parsed as a redirection).
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
expect "case C heading" 1 '^== case C: sedimenting ellipse'
expect "case C, each density ratio" 3 \
  "^ratio (1\.0015|1\.005|1\.0075) +Re $number +angle 45 -> +$number deg \( *$number from vertical\)   last third: angle $number\.\.$number, x/W $number\.\.$number   fall $number a, [0-9]+ s$"
expect "case E6 heading" 1 '^== case E6: six settling discs'
expect "case E6, one, two and six discs" 3 \
  "^[126] disc\(s\): U $number \(Re $number\)  centroid speed $number \(($number|-) of one disc's\)  spread "
expect "case F heading" 1 '^== case F: plug erosion, unbonded and bonded'
expect "case F, each run: discs, bonds, first eroded" 2 \
  "^(unbonded|bonded  ) discs [0-9]+ \(held [0-9]+\), bonds [0-9]+; larger disc at the constriction "
expect "case F, each run: eroded, flux drop" 2 \
  "^(unbonded|bonded  ) eroded [0-9]+, removed [0-9]+, bonds broken [0-9]+; largest flux drop $number at t $number"
expect "case F, each run: where the bonds broke" 2 "^(unbonded|bonded  ) broken bonds [0-9]+: main axis "
expect "case G heading" 1 '^== case G: bed erosion and saltation'
expect "case G bed" 1 '^bed: [0-9]+ grains'
expect "case G, each g" 2 \
  "^g (0   |0\.5 ) first grain to move ([0-9]+|none) at t ($number|never) \(rank ([0-9]+|-) by height; most exposed [0-9]+\); started [0-9]+, eroded [0-9]+ "
expect "case G, the first grains compared" 1 '^(the same grain moves|different grains move) first'
expect "case H heading" 1 '^== case H: hydraulic fracturing and borehole breakout'
expect "case H, each run" 4 \
  "^(fracture|breakout) +(neutral|anisotropic) +seed [0-9]+  discs [0-9]+  coordination $number  bonds [0-9]+  broken "
expect "case H, over the seeds" 4 "^(fracture|breakout) (neutral|anisotropic) +[0-9]+ seeds: broken "
expect "case H, the thesis's numbers" 1 '^thesis: fracturing, neutral: 37 / 116 / 403'
expect "plots" 1 "^plots in "
# Each case's plots: drawn, and named on the "plots in" line. (Case F's
# snapshots, G's beds and H's maps of the breaks are copied or drawn only
# when the smoke run made them: not required here.)
plots=(validation-couette validation-couette-tau validation-sediment validation-dkt
       validation-c-angle validation-c-lateral validation-e6-settling validation-e6-mixing
       validation-f-flux validation-f-pressure validation-g-transport validation-g-height
       validation-h-fracture validation-h-breakout validation-h-growth)
named=$(grep -E "^plots in " "$tmp/log")
for plot in "${plots[@]}"; do
  [[ -s $tmp/plots/$plot.png ]] || problems+=("no plot $plot.png")
  [[ " $named " == *" $plot.png "* ]] || problems+=("$plot.png not named on the \"plots in\" line")
done
stray=$(ls -A "$tmp/work")
[[ -n $stray ]] && problems+=("files left in the working folder: $stray")

if [[ ${#problems[@]} -gt 0 ]]; then
  printf 'FAILED: %s\n' "${problems[@]}"
  exit 1
fi
echo "validate_script: every case printed its table, ${#plots[@]} plots, nothing left behind"
