# Case G: bed erosion and saltation (Cook 2001 §6.2.2), sourced by
# scripts/validate (root, app, out, plots, quick, smoke, plotOnly set).
# examples/bed-erosion.tcl: one bed of superquadric grains consolidated from a
# line of sources, then eroded by a forcing that starts at t = 0, with g = 0
# and with g = 0.5 (both from the same bed, kept as a checkpoint).
# Full: the thesis's 300 x 32 channel at spacing 0.4 (525 grains) for t = 200
# (20,000 steps: both of the thesis's onsets, t = 40 and 130, and the
# transport after them; the thesis ran 50,000); quick: a bed 60 long; smoke:
# 24 long at spacing 0.8 for t = 2.
g_length=300 g_spacing=0.4 g_layers=7 g_time=200 g_every=100
[[ $quick -eq 1 ]] && g_length=60
[[ $smoke -eq 1 ]] && g_length=24 g_spacing=0.8 g_layers=3 g_time=2 g_every=50
if [[ $plotOnly -eq 0 ]]; then
  echo "== case G: bed erosion and saltation, a ${g_length} x 32 channel at spacing ${g_spacing}, forcing 0.04, t = ${g_time}"
  g_bed=$out/bed-erosion-bed.sfck
  rm -f "$g_bed"
  echo "g,first,t_first,exposed,rank,started,eroded,out,max_moving,mean_flux,mean_height,max_height,seconds" \
    >"$out/bed-erosion.csv"
  g_firsts=()
  for g_g in 0 0.5; do
    rm -rf "$out/bed-erosion-g$g_g"
    if ! "$app" "$root/examples/bed-erosion.tcl" -g "$g_g" -forcing 0.04 -length "$g_length" -spacing "$g_spacing" \
        -layers "$g_layers" -time "$g_time" -every "$g_every" -bed "$g_bed" \
        -out "$out/bed-erosion-g$g_g" >"$out/bed-erosion-g$g_g.txt" 2>&1; then
      echo "case G: the run with g = $g_g failed ($out/bed-erosion-g$g_g.txt):" >&2
      tail -n 8 "$out/bed-erosion-g$g_g.txt" >&2
      exit 1
    fi
    [[ $g_g == 0 ]] && sed -n 's/^bed: /bed: /p' "$out/bed-erosion-g$g_g.txt"
    # summary: g G first ID at t T exposed ID (the first is rank R in height) started N eroded N
    #          out N max_moving N mean_flux Q mean_height H max_height H run S s
    g_line=$(grep '^summary:' "$out/bed-erosion-g$g_g.txt")
    read -r _ _ _ _ g_first _ _ g_t _ g_exposed _ _ _ _ g_rank _ _ _ g_started _ g_eroded _ g_out \
         _ g_moving _ g_flux _ g_meanh _ g_maxh _ g_secs _ <<<"$g_line"
    g_rank=${g_rank%)}
    g_firsts+=("$g_first")
    printf "g %-4s first grain to move %s at t %s (rank %s by height; most exposed %s); started %s, eroded %s (%s out), most moving at once %s; mean flux %s; moving grains above the bed: mean %s, max %s (%s s)\n" \
      "$g_g" "$g_first" "$g_t" "$g_rank" "$g_exposed" "$g_started" "$g_eroded" "$g_out" "$g_moving" \
      "$g_flux" "$g_meanh" "$g_maxh" "$g_secs"
    echo "$g_g,$g_first,$g_t,$g_exposed,$g_rank,$g_started,$g_eroded,$g_out,$g_moving,$g_flux,$g_meanh,$g_maxh,$g_secs" \
      >>"$out/bed-erosion.csv"
  done
  if [[ ${g_firsts[0]} == "${g_firsts[1]}" ]]; then
    echo "the same grain moves first with g = 0 and g = 0.5: ${g_firsts[0]} (thesis: the same exposed grain, t = 40 and 130)"
  else
    echo "different grains move first: ${g_firsts[0]} (g = 0), ${g_firsts[1]} (g = 0.5) (thesis: the same exposed grain, t = 40 and 130)"
  fi
  echo
fi
# Plots from the runs' series (and the last picture of each bed).
"$app" -c "$(cat <<'TCL'
lassign $argv out plots
set size {900 560}
set g0 [file join $out bed-erosion-g0 series.csv]
set g5 [file join $out bed-erosion-g0.5 series.csv]
plot [file join $plots validation-g-transport.png] $g0 -x time \
    -series {started -title "grains that have moved, g = 0"} \
    -series [list started -file $g5 -title "grains that have moved, g = 0.5"] \
    -series {flux -axis y2 -dash dashed -title "mass flux, g = 0 (right axis)"} \
    -series [list flux -file $g5 -axis y2 -dash dashed -title "mass flux, g = 0.5 (right axis)"] \
    -key topleft -size $size -title "Bed erosion (case G): grains set moving and mass flux" \
    -xlabel "time since the forcing started" -ylabel "grains moved (displaced > 1)" \
    -y2label "sum(m vx) / L"
plot [file join $plots validation-g-height.png] $g0 -x time \
    -series {max_height -title "highest moving grain, g = 0"} \
    -series [list max_height -file $g5 -title "highest moving grain, g = 0.5"] \
    -series {mean_height -dash dashed -title "mean, g = 0"} \
    -series [list mean_height -file $g5 -dash dashed -title "mean, g = 0.5"] \
    -key topleft -size $size -title "Bed erosion (case G): height of the moving grains above the bed" \
    -xlabel "time since the forcing started" -ylabel "centre height above the bed's surface"
TCL
)" "$out" "$plots" >/dev/null
drawn+=(validation-g-transport.png validation-g-height.png)
for g_g in 0 0.5; do
  # the picture at the end of the run: bed-tT.png with the largest T
  g_last=$(find "$out/bed-erosion-g$g_g" -maxdepth 1 -name 'bed-t*.png' 2>/dev/null \
             | sed 's/.*bed-t//; s/\.png$//' | sort -g | tail -n 1)
  if [[ -n $g_last ]]; then
    cp "$out/bed-erosion-g$g_g/bed-t$g_last.png" "$plots/validation-g-bed-g$g_g.png"
    drawn+=("validation-g-bed-g$g_g.png")
  fi
done
