# shellcheck shell=bash disable=SC2154
# Case E6, six discs settling together (thesis §6.1): sourced by
# scripts/validate (root, app, out, plots, quick, smoke, plotOnly set).
# examples/dkt-six.tcl with the six discs, and with case E's pair and a
# single disc in the same channel for the hindered-settling comparison; the
# table is also dkt-six-summary.csv.
e6_cells=120 e6_time=100 e6_every=200
[[ $quick -eq 1 ]] && e6_cells=64 e6_every=100
[[ $smoke -eq 1 ]] && e6_cells=24 e6_time=2 e6_every=20
if [[ $plotOnly -eq 0 ]]; then
  echo "== case E6: six settling discs, $e6_cells cells across (discs $((e6_cells / 8)) across): hindered settling and mixing"
  echo "discs,U,Re,centroid_speed,speed_ratio,spread_start,spread_end,spread_max,crossed,crossings,closest,time,tU,seconds" \
    >"$out/dkt-six-summary.csv"
  e6_single=
  for count in 1 2 6; do
    e6_start=$SECONDS
    line=$("$app" "$root/examples/dkt-six.tcl" -count "$count" -cells "$e6_cells" -time "$e6_time" \
             -every "$e6_every" -csv "$out/dkt-six-$count.csv" | tee "$out/dkt-six-$count.txt" | tail -n 1)
    e6_secs=$((SECONDS - e6_start))
    # summary: discs N U u Re r centroid speed v spread s0 -> s1 d (max m) crossed c of N crossings k closest q d, t T (t U/d tu)
    read -r u re vc s0 s1 smax crossed crossings closest < <(sed -E \
      's/.*U ([^ ]+) Re ([^ ]+) centroid speed ([^ ]+) spread ([^ ]+) -> ([^ ]+) d \(max ([^ ]+)\) crossed ([^ ]+) of [^ ]+ crossings ([^ ]+) closest ([^ ]+) d, .*/\1 \2 \3 \4 \5 \6 \7 \8 \9/' <<<"$line")
    read -r t tu < <(sed -E 's/.*, t ([^ ]+) \(t U\/d ([^ ]+)\)$/\1 \2/' <<<"$line")
    [[ $count -eq 1 ]] && e6_single=$vc
    ratio=$(awk -v v="$vc" -v s="$e6_single" 'BEGIN { printf (s + 0 > 0 ? "%.3f" : "-"), v / s }')
    printf "%d disc(s): U %s (Re %s)  centroid speed %s (%s of one disc's)  spread %s -> %s d (max %s)  crossed the centreline %s of %s (%s crossings)  closest %s d  t U/d %s, %s s\n" \
      "$count" "$u" "$re" "$vc" "$ratio" "$s0" "$s1" "$smax" "$crossed" "$count" "$crossings" "$closest" "$tu" "$e6_secs"
    echo "$count,$u,$re,$vc,$ratio,$s0,$s1,$smax,$crossed,$crossings,$closest,$t,$tu,$e6_secs" >>"$out/dkt-six-summary.csv"
  done
  echo
fi
"$app" -c "$(cat <<'TCL'
lassign $argv out plots
proc csv {n} {file join $::out dkt-six-$n.csv}
plot [file join $plots validation-e6-settling.png] [csv 6] -x t \
    -series [list centroid -title "six discs: mean height"] \
    -series [list centroid -file [csv 2] -title "the pair of case E" -dash dashed] \
    -series [list centroid -file [csv 1] -title "one disc" -dash dotted] \
    -key topright -size {900 500} -title "Six discs (case E6): hindered settling" \
    -xlabel "time" -ylabel "mean height of the discs (d)"
set series {}
foreach k {1 2 3 4 5 6} {
    lappend series -series [list x$k -title "disc $k" -dash [expr {$k % 2 ? "solid" : "dashed"}]]
}
plot [file join $plots validation-e6-mixing.png] [csv 6] -x t {*}$series \
    -reference {constant 4 -title "centreline" -dash dotted} \
    -yrange {0 8} -key off -size {900 500} \
    -title "Six discs (case E6): lateral positions (solid: started left, dashed: right)" \
    -xlabel "time" -ylabel "x (d), channel 0..8"
TCL
)" "$out" "$plots" >/dev/null
drawn+=(validation-e6-settling.png validation-e6-mixing.png)
