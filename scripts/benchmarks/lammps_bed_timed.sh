#!/bin/bash
# LAMMPS on the DEM benchmark bed, timed from sandflow's settled bed (a data
# file from `sandflow_dem_bed --lammps-data`) instead of settling 100,000
# steps itself: shared/peers/lammps-bed's own input, given that file as its
# bed and no settle steps. Usage: lammps_bed_timed.sh DATA [NP]
# Prints the fields of shared/peers/lammps-bed/run.sh: "lammps_psps=<x>
# contacts_per_disc=<x> timed_s=<x>", plus from=warm.
set -eu
data=$(realpath "$1"); np=${2:-1}
here=$(cd "$(dirname "$0")" && pwd)
input=${SANDFLOW_LAMMPS_INPUT:-$here/../../../shared/peers/lammps-bed/in.bed2d}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT; cd "$work"
command -v lmp >/dev/null || { echo "lammps not installed (apt-get install lammps)"; exit 2; }
n=$(awk '$2 == "atoms" { print $1; exit }' "$data")
w=$(awk '$3 == "xlo" { print $2; exit }' "$data")
ln -s "$data" "bed$n.data"  # the name the input reads
run=(lmp); [[ $np -gt 1 ]] && run=(mpirun --allow-run-as-root -np "$np" lmp)
"${run[@]}" -in "$input" -var N "$n" -var W "$w" -var SETTLE 0 -var TIMED 2000 \
  -log none -screen out.log >/dev/null
t=$(grep "Loop time" out.log | tail -n 1 | awk '{print $4}')
c=$(grep -E "^ +2000 " out.log | tail -n 1 | awk '{print $4}')
python3 -c "print(f'lammps_psps={$n*2000/$t:.4g} contacts_per_disc={$c/2/$n:.3f} timed_s={$t} from=warm')"
