#!/bin/bash
# The kernel names no command or option of the command language in its
# messages (issue 23): it names fields and sf::Remedy values, and the Tcl
# layer words them. Fails listing each string literal in lb, dem, coupling,
# sim, core or geometry that holds an option (-name) or a quoted command.
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
dirs=()
for room in core geometry lb dem coupling sim; do
  dirs+=("$root/src/$room" "$root/include/sandflow/$room")
done
# A literal's text, then an option ("-tau", " -cells") or an escaped quote
# opening a command ("\"lattice create").
literal='"([^"\\]|\\.)*'
pattern="$literal((^|[ (\"])-[a-z]{3,}|\\\\\"[a-z]+ [a-z-]+)"
found=$(grep -rnE --include='*.cpp' --include='*.hpp' "$pattern" "${dirs[@]}" |
  grep -vE '^[^:]+:[0-9]+:\s*(//|#include)' || true)
if [[ -n $found ]]; then
  echo "kernel messages that name the command language (name the field, or give an sf::Remedy):"
  echo "$found"
  exit 1
fi
echo "no kernel message names a command or option"
