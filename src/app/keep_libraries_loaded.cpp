// In the sanitizer build only (CMakeLists.txt adds this file to the
// application when SANDFLOW_SANITIZE is on): no shared library is ever
// unloaded. Mesa's GLX unloads its driver (swrast_dri.so) when Tk closes the
// display at exit, before LeakSanitizer looks; what the driver keeps for the
// life of the process then shows as "<unknown module>", which
// tests/lsan.supp cannot name. A dlclose defined in the executable stands in
// for libc's in every library.
extern "C" int dlclose(void*) {
  return 0;
}
