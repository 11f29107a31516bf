# One stability map of scripts/stability --maps (docs/stability.md) as a PNG,
# drawn by sandflow's plot: a mark for each point, coloured by its outcome.
#
#   sandflow tests/stability/map_plot.tcl OUT.png DIR NAME TITLE XLABEL YLABEL LOGX LOGY
#
# DIR/NAME-OUTCOME.csv (x,y: the points of that outcome, as scripts/stability
# writes them) for OUTCOME ok, warned, refused, stopped, silent; the ones
# with no points are missing and left out of the key.
lassign $argv out dir name title xlabel ylabel logx logy
set styles {
    ok      {green  circle   1.6 "ok"}
    warned  {orange diamond  1.8 "warned"}
    refused {grey   square   1.5 "refused"}
    stopped {blue   triangle 1.7 "stopped"}
    silent  {red    downtriangle 2.6 "SILENT / FAILED"}
}
set series {}
set first {}
set xs {}
set ys {}
dict for {outcome style} $styles {
    set file [file join $dir $name-$outcome.csv]
    if {![file exists $file]} continue
    if {$first eq {}} { set first $file }
    set f [open $file]
    foreach line [lrange [split [string trim [read $f]] \n] 1 end] {
        lassign [split $line ,] x y
        lappend xs $x
        lappend ys $y
    }
    close $f
    lassign $style color mark size label
    lappend series -series [list y -file $file -x x -title $label -style points \
                                -color $color -mark $mark -marksize $size]
}
if {$first eq {}} { puts stderr "map_plot: no points for $name in $dir"; exit 1 }
# The range: the points with a margin, so that none sits on the frame.
proc range {values log} {
    set lo [tcl::mathfunc::min {*}$values]
    set hi [tcl::mathfunc::max {*}$values]
    if {$log} { return [list [expr {$lo / 1.6}] [expr {$hi * 1.6}]] }
    set pad [expr {$hi > $lo ? 0.06 * ($hi - $lo) : 0.5}]
    return [list [expr {$lo - $pad}] [expr {$hi + $pad}]]
}
plot $out $first {*}$series -title $title -xlabel $xlabel -ylabel $ylabel \
    -logx $logx -logy $logy -xrange [range $xs $logx] -yrange [range $ys $logy] \
    -key outside -size {900 560}
