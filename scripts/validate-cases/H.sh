# Case H, DEM only (Cook 2001 §2.5): hydraulic fracturing and borehole
# breakout in a bonded, radially graded disc specimen, examples/thesis-fracture.tcl
# run in both modes, under neutral and anisotropic confinement, with several
# seeds (the thesis: one extra bond changes the failure). Sourced by
# scripts/validate (root, app, out, plots, quick, smoke and plotOnly set;
# set -euo pipefail on).
#   full:  about 2000 discs, the thesis's loading times (0.1 s, 0.05 s), seeds 1 2 3
#   quick: about 600 discs (sizes scaled up), the same loading, seed 1
#   smoke: about 150 discs, 2 ms of loading, seed 1 (numbers meaningless)
# The full run adds the breakout at a tenth of the thesis's confining stress.
fracSeeds=(1 2 3)
fracArgs=()
[[ $quick -eq 1 ]] && fracSeeds=(1) fracArgs=(-discs 600)
[[ $smoke -eq 1 ]] && fracSeeds=(1) fracArgs=(-discs 150 -time 0.002)
if [[ $plotOnly -eq 0 ]]; then
  echo "== case H: hydraulic fracturing and borehole breakout, seeds ${fracSeeds[*]} (${fracArgs[*]:-about 2000 discs, loading as in the thesis})"
  echo "mode,stress,seed,discs,coordination,bonds,broken_01,broken_04,broken_07,broken,peak_mean,axis,axial,threefold,chi2,seconds" \
    >"$out/fracture-runs.csv"
  # mode, stress, confining-stress factor, seeds: the thesis's four tests with
  # every seed; in the full run also the breakout at a tenth of the thesis's
  # confining stress (the ratio of unloading to bond strength then near the
  # fracturing test's), seed 1.
  fracRuns=()
  for mode in fracture breakout; do
    for stress in neutral anisotropic; do
      fracRuns+=("$mode $stress 1 ${fracSeeds[*]}")
    done
  done
  [[ $quick -eq 0 ]] && fracRuns+=("breakout neutral 0.1 1" "breakout anisotropic 0.1 1")
  for spec in "${fracRuns[@]}"; do
    read -r mode stress factor seeds <<<"$spec"
    label=$mode
    [[ $factor != 1 ]] && label=$mode-x$factor
    for seed in $seeds; do
        dir=$out/fracture-$label-$stress-$seed
        rm -rf "$dir"
        "$app" "$root/examples/thesis-fracture.tcl" -mode "$mode" -stress "$stress" -seed "$seed" \
          -stressscale "$factor" -movie 0 "${fracArgs[@]}" -out "$dir" >"$dir.txt"
        line=$(grep '^summary:' "$dir.txt")
        # "summary: mode M stress S seed N discs D coordination C bonds B broken K at
        #  0.01/0.04/0.07 s a/b/c peak/mean P axis A deg axial X threefold Y time T s"
        read -r -a v <<<"$(sed -E 's#^summary: mode [^ ]+ stress [^ ]+ seed [^ ]+ discs ([^ ]+) coordination ([^ ]+) bonds ([^ ]+) broken ([^ ]+) at 0.01/0.04/0.07 s ([^/]+)/([^/]+)/([^ ]+) peak/mean ([^ ]+) axis ([^ ]+) deg axial ([^ ]+) threefold ([^ ]+) chi2 ([^ ]+) time ([^ ]+) s$#\1 \2 \3 \4 \5 \6 \7 \8 \9#' <<<"$line")"
        # (sed -E has no \10: the last three from the line itself)
        read -r axial threefold chi2 secs <<<"$(sed -E 's#.* axial ([^ ]+) threefold ([^ ]+) chi2 ([^ ]+) time ([^ ]+) s$#\1 \2 \3 \4#' <<<"$line")"
        echo "$label,$stress,$seed,${v[0]},${v[1]},${v[2]},${v[4]},${v[5]},${v[6]},${v[3]},${v[7]},${v[8]},$axial,$threefold,$chi2,$secs" \
          >>"$out/fracture-runs.csv"
        printf "%-13s %-11s seed %s  discs %s  coordination %s  bonds %s  broken %s/%s/%s at 0.01/0.04/0.07 s, %s in all  peak/mean %s  axis %s deg  axial %s  threefold %s  chi2 %s  (%s s)\n" \
          "$label" "$stress" "$seed" "${v[0]}" "${v[1]}" "${v[2]}" "${v[4]}" "${v[5]}" "${v[6]}" "${v[3]}" \
          "${v[7]}" "${v[8]}" "$axial" "$threefold" "$chi2" "$secs"
    done
  done
  # Mean and spread (sample standard deviation) over the seeds; the axis as
  # an axial mean (doubled angles).
  awk -F, 'NR > 1 {
      k = $1 " " $2; if (!(k in n)) order[m++] = k; n[k]++
      for (c = 7; c <= 10; c++) { s[k, c] += $c; q[k, c] += $c * $c }
      for (c = 11; c <= 15; c++) { if (c != 12) { s[k, c] += $c; q[k, c] += $c * $c } }
      cx[k] += cos($12 * 3.14159265 / 90); sx[k] += sin($12 * 3.14159265 / 90)
    }
    function mean(k, c) { return s[k, c] / n[k] }
    function sd(k, c) { return n[k] > 1 ? sqrt(((q[k, c] - s[k, c] * s[k, c] / n[k]) > 0 ? (q[k, c] - s[k, c] * s[k, c] / n[k]) : 0) / (n[k] - 1)) : 0 }
    END {
      for (i = 0; i < m; i++) {
        k = order[i]
        axis = atan2(sx[k], cx[k]) * 90 / 3.14159265; if (axis < 0) axis += 180
        printf "%-25s %d seeds: broken %.0f+-%.0f / %.0f+-%.0f / %.0f+-%.0f at 0.01/0.04/0.07 s, %.0f+-%.0f in all; peak/mean %.2f+-%.2f; axis %.0f deg, axial %.2f+-%.2f; threefold %.2f+-%.2f; chi2 %.1f+-%.1f\n",
          k, n[k], mean(k, 7), sd(k, 7), mean(k, 8), sd(k, 8), mean(k, 9), sd(k, 9), mean(k, 10), sd(k, 10),
          mean(k, 11), sd(k, 11), axis, mean(k, 13), sd(k, 13), mean(k, 14), sd(k, 14), mean(k, 15), sd(k, 15)
      }
    }' "$out/fracture-runs.csv" | tee "$out/fracture-spread.txt"
  echo "thesis: fracturing, neutral: 37 / 116 / 403 broken at 0.01 / 0.04 / 0.07 s, multimodal; anisotropic: failure along the axis perpendicular to the minimum stress (here x, 0 deg); breakout, neutral: three zones about 120 deg apart; anisotropic: bimodal, aligned with the minimum stress (here y, 90 deg)"
  echo
fi
s1=${fracSeeds[0]}
if [[ -f $out/fracture-fracture-neutral-$s1/rose.csv && -f $out/fracture-breakout-anisotropic-$s1/rose.csv ]]; then
  printf 'time,broken\n0.01,37\n0.04,116\n0.07,403\n' >"$out/fracture-thesis.csv"
  hPlots=(validation-h-fracture.png validation-h-breakout.png validation-h-growth.png
          validation-h-fracture-breaks.png validation-h-breakout-breaks.png)
  for png in "${hPlots[@]}"; do rm -f "$plots/$png"; done
  "$app" -c "$(cat <<'TCL'
lassign $argv out plots seeds
proc run {mode stress seed} { file join $::out fracture-$mode-$stress-$seed }
set s1 [lindex $seeds 0]
foreach mode {fracture breakout} {
    set series {}
    set lim 1
    foreach stress {neutral anisotropic} dash {solid dashed} {
        set f [file join [run $mode $stress $s1] rose.csv]
        lappend series -series [list y -file $f -x x -title "$stress" -dash $dash]
        set fd [open $f]
        gets $fd
        while {[gets $fd row] >= 0} { set lim [expr {max($lim, [lindex [split $row ,] 2])}] }
        close $fd
    }
    set lim [expr {1.1 * $lim}]
    plot [file join $plots validation-h-$mode.png] [file join [run $mode neutral $s1] rose.csv] \
        {*}$series -style lines -key topright -size {640 640} \
        -xrange [list -$lim $lim] -yrange [list -$lim $lim] \
        -title "Case H, $mode (seed $s1): broken bonds per 6-degree sector" \
        -xlabel "count x cos(angle)   (x: the larger stress)" -ylabel "count x sin(angle)"
}
# Where the bonds broke (seed 1): each break a point, the hole at the centre.
# (A run with no break has nothing to draw: a smoke run's may have none.)
foreach mode {fracture breakout} lim {0.8 1.1} {
    set series {}
    set first {}
    foreach stress {neutral anisotropic} {
        set f [file join [run $mode $stress $s1] breaks.csv]
        set fd [open $f]
        set rows [llength [split [string trim [read $fd]] \n]]
        close $fd
        if {$rows < 2} continue
        if {$first eq {}} { set first $f }
        lappend series -series [list y -file $f -x x -style points -title $stress]
    }
    if {$first eq {}} continue
    plot [file join $plots validation-h-$mode-breaks.png] $first \
        {*}$series -key topright -size {640 640} -xrange [list -$lim $lim] -yrange [list -$lim $lim] \
        -title "Case H, $mode (seed $s1): where the bonds broke" -xlabel "x (m)" -ylabel "y (m)"
}
set series {}
set dashes {solid dashed dotted dashdot}
foreach seed $seeds {
    if {![file exists [file join [run fracture neutral $seed] series.csv]]} continue
    set dash [lindex $dashes [expr {[llength $series] / 2 % 4}]]
    lappend series -series [list broken -file [file join [run fracture neutral $seed] series.csv] \
                                -title "seed $seed, neutral" -dash $dash]
}
lappend series -series [list broken -file [file join $out fracture-thesis.csv] -title "thesis (neutral)" \
                            -style points]
plot [file join $plots validation-h-growth.png] [file join [run fracture neutral $s1] series.csv] \
    {*}$series -key topleft -size {900 640} \
    -title "Case H, hydraulic fracturing: broken bonds against time" \
    -xlabel "time since the loading began (s)" -ylabel "broken bonds"
TCL
)" "$out" "$plots" "${fracSeeds[*]}" >/dev/null
  for png in "${hPlots[@]}"; do
    if [[ -f $plots/$png ]]; then drawn+=("$png"); fi
  done
fi
