# Case F, plug erosion (Cook 2001 §6.2.1): examples/plug-erosion.tcl run
# unbonded and bonded. Sourced by scripts/validate (root, app, out, plots,
# quick, smoke and plotOnly set; set -euo pipefail on).
#   full:  the thesis's channel 100 x 40 at h = 0.25 (64,000 nodes), ~200 discs, T = 300
#   quick: the half-size channel 50 x 20 (16,000 nodes), ~50 discs, T = 300
#   smoke: a 30 x 14 channel, ~20 discs, T = 2 (numbers meaningless)
plugArgs=()
[[ $quick -eq 1 ]] && plugArgs=(-length 50 -height 20 -discs 50)
[[ $smoke -eq 1 ]] && plugArgs=(-length 30 -height 14 -discs 20 -time 2 -frames 1 -movie 0)
if [[ $plotOnly -eq 0 ]]; then
  echo "== case F: plug erosion, unbonded and bonded (${plugArgs[*]:-the channel of the thesis, 100 x 40, h 0.25, 200 discs})"
  echo "run,discs,held,bonds,exposed,exposed_r,first,first_r,first_t,exposed_first,exposed_rank,at_constriction,eroded,removed,broken,flux_drop,flux_drop_t,dp_rise" \
    >"$out/plug-summary.csv"
  for bonded in 0 1; do
    run=$([[ $bonded -eq 1 ]] && echo bonded || echo unbonded)
    dir=$out/plug-$run
    rm -rf "$dir"
    "$app" "$root/examples/plug-erosion.tcl" -bonded "$bonded" -threads 1 "${plugArgs[@]}" -out "$dir" \
      >"$out/plug-$run.txt"
    # "summary: key value key value ..." -> sum[key]=value
    declare -A sum=()
    read -r -a kv <<<"$(sed -n 's/^summary: //p' "$out/plug-$run.txt")"
    for ((i = 0; i + 1 < ${#kv[@]}; i += 2)); do sum[${kv[i]}]=${kv[i + 1]}; done
    # The blockage: the largest fall of the flux through the constriction
    # below its running maximum over the last 10 time units, relative to
    # that maximum; and how much the upstream-downstream pressure difference
    # rose over the same window.
    drop=$(awk -F, 'NR > 1 { t[n] = $1; q[n] = $2; dp[n] = $3 - $4; n++ }
      END {
        best = 0; bt = 0; rise = 0
        for (i = 0; i < n; i++) {
          m = -1e30; dmin = 1e30
          for (j = i; j >= 0 && t[i] - t[j] <= 10; j--) { if (q[j] > m) m = q[j]; if (dp[j] < dmin) dmin = dp[j] }
          if (m > 0 && (m - q[i]) / m > best) { best = (m - q[i]) / m; bt = t[i]; rise = dp[i] - dmin }
        }
        printf "%.3f %.1f %.3g", best, bt, rise
      }' "$dir/history.csv")
    read -r fdrop fdropt dprise <<<"$drop"
    echo "$run,${sum[discs]},${sum[held]},${sum[bonds]},${sum[exposed]},${sum[exposed_r]},${sum[first]},${sum[first_r]},${sum[first_t]},${sum[exposed_first]},${sum[exposed_rank]},${sum[at_constriction]},${sum[eroded]},${sum[removed]},${sum[broken]},$fdrop,$fdropt,$dprise" \
      >>"$out/plug-summary.csv"
    atC=no; [[ ${sum[at_constriction]} -eq 1 ]] && atC=yes
    larger=no; [[ ${sum[exposed_first]} -eq 1 ]] && larger=yes
    printf "%-8s discs %s (held %s), bonds %s; larger disc at the constriction %s (r %s); first eroded %s (r %s) at t %s\n" \
      "$run" "${sum[discs]}" "${sum[held]}" "${sum[bonds]}" "${sum[exposed]}" "${sum[exposed_r]}" \
      "${sum[first]}" "${sum[first_r]}" "${sum[first_t]}"
    printf "%-8s first eroded at the constriction: %s; it is the larger disc there: %s (the larger one eroded as number %s)\n" \
      "$run" "$atC" "$larger" "${sum[exposed_rank]}"
    printf "%-8s eroded %s, removed %s, bonds broken %s; largest flux drop %s at t %s, pressure difference rise %s\n" \
      "$run" "${sum[eroded]}" "${sum[removed]}" "${sum[broken]}" "$fdrop" "$fdropt" "$dprise"
    # Where the bonds broke: the main axis of the breaks' positions (degrees
    # from x), how elongated their cloud is (the spread along the main axis
    # over the spread across it) and their mean distance from the constriction.
    frac=$(awk -F, 'NR > 1 { x[n] = $2; y[n] = $3; n++; sx += $2; sy += $3 }
      END {
        if (n < 2) { printf "%d - - -", n; exit }
        mx = sx / n; my = sy / n
        for (i = 0; i < n; i++) { a += (x[i] - mx)^2; b += (x[i] - mx) * (y[i] - my); c += (y[i] - my)^2 }
        a /= n; b /= n; c /= n
        d = sqrt(((a - c) / 2)^2 + b^2); l1 = (a + c) / 2 + d; l2 = (a + c) / 2 - d
        ang = 0.5 * atan2(2 * b, a - c) * 45 / atan2(1, 1)
        printf "%d %.0f %.2f {%.1f %.1f}", n, ang, sqrt(l1 / (l2 > 1e-12 ? l2 : 1e-12)), mx, my
      }' "$dir/bonds-broken.csv")
    read -r nb fang felong fcentre <<<"$frac"
    printf "%-8s broken bonds %s: main axis %s deg, elongation %s, centred at %s\n" "$run" "$nb" "$fang" "$felong" "$fcentre"
    unset sum
  done
  echo
fi
if [[ -f $out/plug-unbonded/history.csv && -f $out/plug-bonded/history.csv ]]; then
  "$app" -c "$(cat <<'TCL'
lassign $argv out plots
set u [file join $out plug-unbonded history.csv]
set b [file join $out plug-bonded history.csv]
set size {900 640}
plot [file join $plots validation-f-flux.png] $u -x time \
    -series [list flux -title "flux, unbonded"] \
    -series [list flux -file $b -title "flux, bonded" -dash dashed] \
    -series [list eroded -axis y2 -title "eroded discs, unbonded" -dash dotted] \
    -series [list broken -file $b -axis y2 -title "broken bonds, bonded" -dash dashdot] \
    -key topleft -size $size -title "Plug erosion (case F): flux through the constriction" \
    -xlabel "time since the forcing started" -ylabel "flux (integral of rho u_x)" \
    -y2label "eroded discs / broken bonds"
plot [file join $plots validation-f-pressure.png] $u -x time \
    -series [list p_up -title "upstream, unbonded"] \
    -series [list p_down -title "downstream, unbonded"] \
    -series [list p_gap -title "in the gap, unbonded" -dash dotted] \
    -series [list p_up -file $b -title "upstream, bonded" -dash dashed] \
    -series [list p_down -file $b -title "downstream, bonded" -dash dashed] \
    -key bottomleft -size $size -title "Plug erosion (case F): pressure at the probes (c_s^2 rho - p_0)" \
    -xlabel "time since the forcing started" -ylabel "pressure"
TCL
)" "$out" "$plots" >/dev/null
  drawn+=(validation-f-flux.png validation-f-pressure.png)
  # The last picture of each run (the example's snapshot).
  for run in unbonded bonded; do
    last=$(ls "$out/plug-$run"/plug-*.png 2>/dev/null | sort -t- -k3 -n | tail -n 1)
    if [[ -n $last ]]; then
      cp "$last" "$plots/validation-f-$run.png"
      drawn+=("validation-f-$run.png")
    fi
  done
fi
