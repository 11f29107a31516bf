#!/bin/bash
# Runs one GUI test command, and runs it once more when the only thing that
# went wrong is LeakSanitizer's own tracer crashing at exit ("Tracer caught
# signal 11 ... LeakSanitizer has encountered a fatal error"). That crash is
# the sanitizer runtime's, not a leak report, and comes now and then in a
# process with many threads alive at exit (the workbench has a dozen: Mesa's
# llvmpipe and disk-cache threads for Togl's and EGL's contexts, OpenMP's,
# Tcl's notifier); see google/sanitizers#1353. A leak report, a sanitizer
# error or a failed test fails as before, and so does a second tracer crash.
set -u
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for attempt in 1 2; do
  "$@" > >(tee "$log") 2>&1
  rc=$?
  wait  # for tee
  if ((rc == 0)) || ! grep -q "^Tracer caught signal" "$log" ||
    ! grep -q "LeakSanitizer has encountered a fatal error" "$log"; then
    exit $rc
  fi
  ((attempt == 1)) && echo "lsan_retry: LeakSanitizer's tracer crashed at exit" \
    "(a sanitizer-runtime fault, not a leak): running the test once more"
done
exit $rc
