# png_helpers.tcl -- reading the PNG pictures snapshot writes, for the tests.

# A PNG picture (8-bit RGB, as snapshot writes it) as {width height rows}, each
# row a flat list r g b r g b ... Decoded here, with all five row filters
# (tcllib's readPng reads only unfiltered rows).
proc readPng {file} {
    set f [open $file rb]
    set data [read $f]
    close $f
    if {[string range $data 0 7] ne "\x89PNG\r\n\x1a\n"} {error "$file: not a PNG file"}
    set at 8
    set idat ""
    while {$at < [string length $data]} {
        binary scan $data @${at}Ia4 length type
        set body [string range $data [expr {$at + 8}] [expr {$at + 7 + $length}]]
        switch -- $type {
            IHDR {binary scan $body IIcucu width height depth colour}
            IDAT {append idat $body}
        }
        incr at [expr {12 + $length}]
    }
    if {$depth != 8 || $colour != 2} {error "$file: not 8-bit RGB"}
    set raw [zlib decompress $idat]
    set stride [expr {3 * $width}]
    set previous [lrepeat $stride 0]
    set rows {}
    for {set j 0} {$j < $height} {incr j} {
        set start [expr {$j * ($stride + 1)}]
        binary scan $raw @${start}cu filter
        binary scan $raw @[expr {$start + 1}]cu$stride line
        set row {}
        for {set k 0} {$k < $stride} {incr k} {
            set x [lindex $line $k]
            set a [expr {$k >= 3 ? [lindex $row [expr {$k - 3}]] : 0}]
            set b [lindex $previous $k]
            set c [expr {$k >= 3 ? [lindex $previous [expr {$k - 3}]] : 0}]
            switch -- $filter {
                0 {}
                1 {incr x $a}
                2 {incr x $b}
                3 {incr x [expr {($a + $b) / 2}]}
                4 {
                    set p [expr {$a + $b - $c}]
                    set pa [expr {abs($p - $a)}]
                    set pb [expr {abs($p - $b)}]
                    set pc [expr {abs($p - $c)}]
                    incr x [expr {$pa <= $pb && $pa <= $pc ? $a : ($pb <= $pc ? $b : $c)}]
                }
            }
            lappend row [expr {$x & 255}]
        }
        lappend rows $row
        set previous $row
    }
    list $width $height $rows
}
