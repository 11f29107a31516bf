// ::sf::scriptOptions: the options of a script run with arguments
// (`sandflow examples/dkt.tcl -cells 60`), described once as a tcllib cmdline
// table, so that every example parses them the same way and answers -help.
#include "sandflow/tcl/session.hpp"

namespace sf::tcl {
namespace {

constexpr const char* kScriptOptions = R"tcl(
namespace eval ::sf {
  # SPEC: {{name.arg default help} ...}, as tcllib's cmdline takes. Reads the
  # global argv and returns a dict keyed -name with every option's value.
  # -help (or -?) prints the options and ends the calling script; an unknown
  # option, a missing value or a stray word is an error naming it and the
  # options.
  proc scriptOptions {spec} {
    package require cmdline
    upvar #0 argv argv
    set title "options:"  ;# (cmdline puts the script's name before it)
    set names {}
    foreach row $spec { lappend names -[lindex [split [lindex $row 0] .] 0] }
    set words [expr {[info exists argv] ? $argv : {}}]
    if {"-help" in $words || "-?" in $words} {
      puts [string trimright [cmdline::usage $spec $title]]
      return -level 2 {}
    }
    set choices [expr {[llength $names] < 3 ? [join $names " or "] :
                       "[join [lrange $names 0 end-1] {, }], or [lindex $names end]"}]
    for {set i 0} {$i < [llength $words]} {incr i 2} {
      set word [lindex $words $i]
      if {$word ni $names} {
        set what [expr {[string index $word 0] eq "-" ? "bad option" : "stray word"}]
        return -code error -errorcode [list SANDFLOW VALUE OPTION $word] \
            "$what \"$word\": must be $choices (-help describes them)"
      }
      if {$i + 1 >= [llength $words]} {
        return -code error -errorcode [list SANDFLOW VALUE OPTION $word] "value for \"$word\" missing"
      }
    }
    set options {}
    foreach {key value} [cmdline::getoptions words $spec $title] { dict set options -$key $value }
    set argv {}
    return $options
  }
}
)tcl";

}  // namespace

int defineScriptOptions(Tcl_Interp* interp) {
  return Tcl_Eval(interp, kScriptOptions);
}

}  // namespace sf::tcl
