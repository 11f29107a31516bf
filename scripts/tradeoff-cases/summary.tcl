# scripts/tradeoff's summary (docs/accuracy.md), run by sandflow:
#
#   sandflow scripts/tradeoff-cases/summary.tcl OUT PLOTS ?MODE?
#
# Reads OUT/jobs.csv (the manifest) and each job's row in OUT/rows/ (a job
# without one is "failed", with the end of its log); fills the errors taken
# from a reference run (sediment and light: the finest sediment resolution
# run's settling speed); writes OUT/results.csv; finds each problem's Pareto
# front (no other run both faster and more accurate); draws
# PLOTS/tradeoff-PROBLEM.png (error against wall time, log-log, a series a
# knob, the front joined), PLOTS/tradeoff-couette-solidratio.png (the
# Couette errors of each solid-ratio setting against resolution) and
# PLOTS/tradeoff-force-noise.png (the settling disc's fluid force with the
# stair-step solid ratio and others); and writes OUT/tables.md (printed too).
lassign $argv out plots mode
if {$plots eq {}} {
    puts stderr "usage: sandflow scripts/tradeoff-cases/summary.tcl OUT PLOTS ?MODE?"
    exit 2
}
file mkdir [file join $out plotdata] $plots

# ---- CSV ---------------------------------------------------------------------------
proc parseCsv {line} {
    set fields {}
    set field {}
    set quoted 0
    set n [string length $line]
    for {set i 0} {$i < $n} {incr i} {
        set c [string index $line $i]
        if {$quoted} {
            if {$c eq "\""} {
                if {[string index $line [expr {$i + 1}]] eq "\""} {
                    append field "\""
                    incr i
                } else {
                    set quoted 0
                }
            } else {
                append field $c
            }
        } elseif {$c eq "\""} {
            set quoted 1
        } elseif {$c eq ","} {
            lappend fields $field
            set field {}
        } else {
            append field $c
        }
    }
    lappend fields $field
    return $fields
}
proc readCsv {file} {
    set f [open $file]
    set lines [split [string trimright [read $f] "\n"] "\n"]
    close $f
    set header [parseCsv [lindex $lines 0]]
    set out {}
    foreach line [lrange $lines 1 end] {
        set d {}
        foreach k $header v [parseCsv $line] { dict set d $k $v }
        lappend out $d
    }
    return $out
}
proc csvField {s} {
    if {[string match {*[,\"]*} $s]} { return "\"[string map {\" \"\"} $s]\"" }
    return $s
}
proc writeCsv {file header rows} {
    set f [open $file w]
    puts $f [join $header ,]
    foreach r $rows { puts $f [join [lmap k $header {csvField [dict get $r $k]}] ,] }
    close $f
}
proc num {x} { expr {[string is double -strict $x]} }
proc g3 {x} { if {![num $x]} { return $x }; format %.3g $x }
proc secs {x} {
    if {![num $x]} { return $x }
    if {$x < 0.01} { return [format %.4f $x] }
    if {$x < 10} { return [format %.2f $x] }
    format %.0f $x
}

# ---- the rows ------------------------------------------------------------------------
set keys {problem knob setting resolution status error error2 value wall_s cpu_s steps nodes message}
# The cost a run is placed by: its CPU seconds (on a shared machine the wall
# time also counts the other work), its wall time where the CPU time is under
# 0.02 s (the CPU clock counts in 10 ms ticks) or missing.
proc cost {r} {
    set c [dict get $r cpu_s]
    if {[string is double -strict $c] && $c >= 0.02} { return $c }
    return [dict get $r wall_s]
}
set rows {}
# In the order the jobs were made (their ids), not the order they ran in.
foreach m [lsort -command {apply {{a b} {
    expr {[scan [dict get $a id] %d] - [scan [dict get $b id] %d]}
}}} [readCsv [file join $out jobs.csv]]] {
    set file [file join $out rows [dict get $m id].csv]
    if {[file exists $file]} {
        set r [lindex [readCsv $file] 0]
        if {![dict exists $r cpu_s]} { dict set r cpu_s {} }
    } else {
        set r [dict create]
        foreach k $keys { dict set r $k {} }
        foreach k {problem knob setting resolution} { dict set r $k [dict get $m $k] }
        dict set r status failed
        set log [file join $out logs [dict get $m id].txt]
        set tail {}
        if {[file exists $log]} {
            set f [open $log]
            set tail [string trim [join [lrange [split [string trim [read $f]] "\n"] end-1 end] " "]]
            close $f
        }
        dict set r message "no result (the job crashed, timed out or did not run): $tail"
    }
    dict set r id [dict get $m id]
    lappend rows $r
}

# The sediment reference: the finest resolution run that finished.
set uref {}
set refRes 0
foreach r $rows {
    if {[dict get $r problem] eq "sediment" && [dict get $r knob] eq "resolution" &&
        [dict get $r status] eq "ok" && [dict get $r resolution] > $refRes} {
        set refRes [dict get $r resolution]
        set uref [dict get $r value]
        set refId [dict get $r id]
    }
}
set rows [lmap r $rows {
    if {[dict get $r problem] in {sediment light} && [dict get $r status] eq "ok" && $uref ne {}} {
        if {[dict get $r id] eq $refId} {
            dict set r status reference
            dict set r message "U = [dict get $r value] ([dict get $r message])"
        } else {
            dict set r error [format %.6g [expr {abs([dict get $r value] / $uref - 1)}]]
        }
    }
    set r
}]
writeCsv [file join $out results.csv] $keys $rows

# ---- Pareto fronts and plots -------------------------------------------------------
set problems {}
foreach p {couette poiseuille sediment light collision contact} {
    foreach r $rows { if {[dict get $r problem] eq $p} { lappend problems $p; break } }
}
foreach r $rows { if {[dict get $r problem] ni $problems} { lappend problems [dict get $r problem] } }
array set titles {
    couette    "Cylindrical Couette: velocity L2 error against the exact u(r)"
    poiseuille "Poiseuille flow: L2 error against the exact parabola"
    sediment   "Settling disc: settling-speed error against the finest run"
    light      "Light discs: settling-speed error against the sediment reference"
    collision  "Two-disc collision: restitution error (mean of 20 entry phases)"
    contact    "Pressed ellipse: contact-force error (RMS over eight angles)"
}
set onFront {}
foreach p $problems {
    set pts {}
    foreach r $rows {
        if {[dict get $r problem] ne $p || [dict get $r status] ne "ok"} continue
        if {![num [dict get $r error]] || ![num [cost $r]]} continue
        if {[dict get $r error] <= 0 || [cost $r] <= 0} continue
        dict set r seconds [cost $r]
        lappend pts $r
    }
    set best inf
    set front {}
    foreach r [lsort -command {apply {{a b} {
        set c [expr {[dict get $a seconds] - [dict get $b seconds]}]
        if {$c == 0} { set c [expr {[dict get $a error] - [dict get $b error]}] }
        expr {$c < 0 ? -1 : $c > 0 ? 1 : 0}
    }}} $pts] {
        if {[dict get $r error] < $best} {
            set best [dict get $r error]
            lappend front $r
            lappend onFront [dict get $r id]
        }
    }
    if {![llength $pts]} continue
    set series {}
    set knobs {}
    foreach r $pts { if {[dict get $r knob] ni $knobs} { lappend knobs [dict get $r knob] } }
    foreach k $knobs {
        set file [file join $out plotdata $p-$k.csv]
        writeCsv $file {seconds error setting resolution} [lmap r $pts {
            if {[dict get $r knob] ne $k} continue
            set r
        }]
        lappend series -series [list error -file $file -x seconds -style points -title $k]
    }
    set file [file join $out plotdata $p-front.csv]
    writeCsv $file {seconds error setting resolution} $front
    lappend series -series [list error -file $file -x seconds -style lines -dash dashed \
                                -title "Pareto front"]
    plot [file join $plots tradeoff-$p.png] $file -x seconds {*}$series -logx 1 -logy 1 \
        -key bottomleft -size {900 600} -title $titles($p) \
        -xlabel "CPU time of the run (s, one thread; its wall time where under 0.02 s)" -ylabel "relative error"
}

# ---- tables -------------------------------------------------------------------------
set md {}
lappend md "# scripts/tradeoff ($mode): results" ""
lappend md "Times: the run itself (scene and steps), one thread: wall-clock and CPU seconds; the fronts and plots place a run by its CPU time (its wall time under 0.02 s of CPU). * marks the Pareto front of its problem."
if {$uref ne {}} {
    lappend md "Sediment and light: error against the finest run's settling speed U = [format %.5g $uref] (Re [format %.3f [expr {$uref / 0.02}]], $refRes cells per diameter)."
}
array set error2Name {
    couette torque poiseuille - sediment "force noise" light "force noise" collision "worst phase"
    contact "worst angle"
}
foreach p $problems {
    set knobs {}
    foreach r $rows {
        if {[dict get $r problem] eq $p && [dict get $r knob] ni $knobs} { lappend knobs [dict get $r knob] }
    }
    foreach k $knobs {
        lappend md "" "## $p: $k" ""
        lappend md "| setting | resolution | error | $error2Name($p) | wall s | CPU s | steps | nodes | status |"
        lappend md "|---|---|---|---|---|---|---|---|---|"
        foreach r $rows {
            if {[dict get $r problem] ne $p || [dict get $r knob] ne $k} continue
            set mark [expr {[dict get $r id] in $onFront ? " *" : ""}]
            set status [dict get $r status]
            if {$status ni {ok}} {
                set msg [dict get $r message]
                if {[string length $msg] > 90} { set msg "[string range $msg 0 86]..." }
                append status ": $msg"
            }
            lappend md "| [dict get $r setting] | [dict get $r resolution] | [g3 [dict get $r error]]$mark | [g3 [dict get $r error2]] | [secs [dict get $r wall_s]] | [secs [dict get $r cpu_s]] | [dict get $r steps] | [dict get $r nodes] | $status |"
        }
    }
}

# ---- the Couette solid ratio under refinement -----------------------------------------
# Velocity error and signed torque error of each setting at each resolution,
# and the order: the least-squares slope of log(error) against log(resolution).
set r1 0.1; set r2 0.3
set exactTorque [expr {4 * acos(-1) * 4.166e-2 * 0.1 * $r1 ** 2 * $r2 ** 2 / ($r2 ** 2 - $r1 ** 2)}]
proc slope {xs ys} {
    set n [llength $xs]
    if {$n < 2} { return {} }
    set sx 0.0; set sy 0.0; set sxx 0.0; set sxy 0.0
    foreach x $xs y $ys {
        set x [expr {log($x)}]; set y [expr {log($y)}]
        set sx [expr {$sx + $x}]; set sy [expr {$sy + $y}]
        set sxx [expr {$sxx + $x * $x}]; set sxy [expr {$sxy + $x * $y}]
    }
    expr {-($n * $sxy - $sx * $sy) / ($n * $sxx - $sx * $sx)}
}
set srSeries {}
set srLines {}
foreach s {exact 1 2 4 8} {
    set pts {}
    foreach r $rows {
        if {[dict get $r problem] ne "couette" || [dict get $r status] ne "ok"} continue
        if {!(([dict get $r knob] eq "resolution" && $s eq "exact") ||
              ([dict get $r knob] eq "solidratio" && [dict get $r setting] eq $s))} continue
        dict set r torque_signed [format %.4g [expr {([dict get $r value] - $exactTorque) / $exactTorque}]]
        lappend pts $r
    }
    if {![llength $pts]} continue
    set pts [lsort -command {apply {{a b} {
        expr {[dict get $a resolution] < [dict get $b resolution] ? -1 : 1}
    }}} $pts]
    set file [file join $out plotdata couette-solidratio-$s.csv]
    writeCsv $file {resolution error error2 torque_signed wall_s cpu_s} $pts
    set title [expr {$s eq "exact" ? "exact areas" : $s eq "1" ? "1 (stair steps)" : "$s x $s subcells"}]
    lappend srSeries -series [list error -file $file -x resolution -style linespoints -title $title]
    set xs [lmap r $pts {dict get $r resolution}]
    set v [slope $xs [lmap r $pts {dict get $r error}]]
    set t [slope $xs [lmap r $pts {expr {abs([dict get $r torque_signed])}}]]
    lappend srLines "| $s | [join [lmap r $pts {g3 [dict get $r error]}] " / "] | [g3 $v] | [join [lmap r $pts {format %+.2e [dict get $r torque_signed]}] " / "] | [g3 $t] | [join [lmap r $pts {secs [cost $r]}] " / "] |"
    set srRes $xs
}
if {[llength $srLines]} {
    lappend md "" "## couette: solid ratio under refinement" ""
    lappend md "Cells per diameter of the inner cylinder: [join $srRes " / "]. Order: least-squares slope of log error against log resolution."
    lappend md "" "| solid ratio | velocity L2 | order | torque error (signed) | order | CPU s |"
    lappend md "|---|---|---|---|---|---|"
    lappend md {*}$srLines
    set file [file join $out plotdata couette-solidratio-exact.csv]
    plot [file join $plots tradeoff-couette-solidratio.png] $file -x resolution {*}$srSeries \
        -reference {power 4.9e-3 16 -2 -title "second order" -dash dotted} \
        -logx 1 -logy 1 -key bottomleft -size {900 600} \
        -title "Couette: velocity error of each solid ratio under refinement" \
        -xlabel "cells per inner-cylinder diameter" -ylabel "velocity L2 error"
}

# ---- the stair-step force noise --------------------------------------------------------
set noise {}
set first {}
foreach s {1 2 exact} {
    set file [file join $out force-noise-$s.csv]
    if {![file exists $file]} continue
    if {$first eq {}} { set first $file }
    set title [expr {$s eq "exact" ? "exact areas" : $s eq "1" ? "1 (stair steps)" : "$s x $s subcells"}]
    lappend noise -series [list fluidfy -file $file -x y -title $title \
                               -dash [expr {$s eq "1" ? "solid" : $s eq "2" ? "dashed" : "dotted"}]]
}
if {[llength $noise]} {
    plot [file join $plots tradeoff-force-noise.png] $first -x y {*}$noise \
        -xreverse 1 -key bottomleft -size {900 600} \
        -title "Settling disc, last diameter of the fall: the fluid's vertical force, each step" \
        -xlabel "height of the disc's centre (d)" -ylabel "fluid force (driving force 0.942)"
}

set f [open [file join $out tables.md] w]
puts $f [join $md "\n"]
close $f
puts [join $md "\n"]
set failed [llength [lmap r $rows { if {[dict get $r status] ne "failed"} continue; set r }]]
puts "\n[llength $rows] jobs: [expr {[llength $rows] - $failed}] with a row, $failed failed"
