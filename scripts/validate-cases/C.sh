# shellcheck shell=bash disable=SC2154
# Case C, the sedimenting ellipse (thesis §5.2; Huang, Hu & Joseph 1998):
# sourced by scripts/validate (root, app, out, plots, quick, smoke, plotOnly
# set). examples/sediment-ellipse.tcl at the thesis's two density ratios,
# 1.0015 and 1.005, and at 1.0075 (where ours turns broadside), in a channel
# 60 a tall (the thesis: 150 a; docs/validation.md shows the shorter channel
# does not change the result); the table is also ellipse-summary.csv.
c_cells=60 c_height=60 c_time=0 c_every=500
[[ $quick -eq 1 ]] && c_cells=40 c_height=40 c_every=250
[[ $smoke -eq 1 ]] && c_cells=20 c_height=12 c_time=15 c_every=40
c_ratios=(1.0015 1.005 1.0075)
if [[ $plotOnly -eq 0 ]]; then
  echo "== case C: sedimenting ellipse, $c_cells cells across (ellipse $((c_cells / 5)) cells long), channel ${c_height} a tall"
  echo "ratio,Re,angle_end,from_vertical,angle_min,angle_max,x_min,x_max,fall,time,seconds" >"$out/ellipse-summary.csv"
  for ratio in "${c_ratios[@]}"; do
    c_start=$SECONDS
    line=$("$app" "$root/examples/sediment-ellipse.tcl" -ratio "$ratio" -cells "$c_cells" -height "$c_height" \
             -time "$c_time" -every "$c_every" -csv "$out/ellipse-$ratio.csv" | tee "$out/ellipse-$ratio.txt" | tail -n 1)
    c_secs=$((SECONDS - c_start))
    # summary: ratio R Re RE angle A0 -> A1 deg (from vertical V deg), last third angle LO..HI x/W XL..XH, fall F a in t T
    read -r re a1 fv alo ahi xlo xhi fall t < <(sed -E \
      's/.*Re ([^ ]+) angle [^ ]+ -> ([^ ]+) deg \(from vertical ([^ ]+) deg\), last third angle ([^ ]+)\.\.([^ ]+) x\/W ([^ ]+)\.\.([^ ]+), fall ([^ ]+) a in t ([^ ]+)$/\1 \2 \3 \4 \5 \6 \7 \8 \9/' <<<"$line")
    printf "ratio %-7s Re %-6s angle 45 -> %6s deg (%4s from vertical)   last third: angle %s..%s, x/W %s..%s   fall %s a, %s s\n" \
      "$ratio" "$re" "$a1" "$fv" "$alo" "$ahi" "$xlo" "$xhi" "$fall" "$c_secs"
    echo "$ratio,$re,$a1,$fv,$alo,$ahi,$xlo,$xhi,$fall,$t,$c_secs" >>"$out/ellipse-summary.csv"
  done
  echo
fi
"$app" -c "$(cat <<'TCL'
lassign $argv out plots
proc csv {r} {file join $::out ellipse-$r.csv}
plot [file join $plots validation-c-angle.png] [csv 1.0015] -x fall \
    -series [list angle -title "density ratio 1.0015 (thesis Re 0.30)"] \
    -series [list angle -file [csv 1.005] -title "1.005 (thesis Re 0.80)" -dash dashed] \
    -series [list angle -file [csv 1.0075] -title "1.0075" -dash dotted] \
    -reference {constant 90 -title "vertical" -dash dashdot} \
    -yrange {-10 170} -key topleft -size {900 560} -title "Sedimenting ellipse (case C): orientation as it falls" \
    -xlabel "fall (major axis lengths a)" -ylabel "major axis from the horizontal (degrees)"
plot [file join $plots validation-c-lateral.png] [csv 1.0015] -x fall \
    -series [list x_over_W -title "density ratio 1.0015"] \
    -series [list x_over_W -file [csv 1.005] -title "1.005" -dash dashed] \
    -series [list x_over_W -file [csv 1.0075] -title "1.0075" -dash dotted] \
    -reference {constant 0.5 -title "centreline" -dash dashdot} \
    -yrange {0.25 0.75} -key topright -size {900 420} -title "Sedimenting ellipse (case C): lateral position" \
    -xlabel "fall (major axis lengths a)" -ylabel "x / W"
TCL
)" "$out" "$plots" >/dev/null
drawn+=(validation-c-angle.png validation-c-lateral.png)
