#include "sandflow/core/memory.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "sandflow/core/error.hpp"

namespace sf {
namespace {

double physicalBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) : 0.0;
}

// SANDFLOW_MEMORY in bytes, or 0 when it is unset or not a size.
double configuredBytes() {
  const char* text = std::getenv("SANDFLOW_MEMORY");
  if (!text || !*text) return 0.0;
  char* end = nullptr;
  double bytes = std::strtod(text, &end);
  const char* units = "KMGT";
  if (*end && std::strchr(units, *end) && end[1] == '\0')
    bytes *= std::pow(1024.0, double(std::strchr(units, *end) - units + 1));
  else if (*end)
    return 0.0;
  return bytes > 0 && std::isfinite(bytes) ? bytes : 0.0;
}

}  // namespace

double memoryBytes() {
  const double physical = physicalBytes(), configured = configuredBytes();
  if (configured > 0 && (physical == 0 || configured < physical)) return configured;
  return physical;
}

void checkMemory(double bytes, const std::string& what) {
  const double physical = physicalBytes(), available = memoryBytes();
  if (available <= 0 || bytes <= kMemoryShare * available) return;  // NaN and inf fall through
  const std::string machine = available < physical || physical == 0
                                  ? "the " + formatBytes(available) + " that SANDFLOW_MEMORY allows"
                                  : "this machine's " + formatBytes(available);
  throw Error("RESOURCE MEMORY", what + " needs " + formatBytes(bytes) + " of memory, more than " +
                                     formatNumber(kMemoryShare * 100) + "% of " + machine);
}

std::string formatBytes(double bytes) {
  if (!std::isfinite(bytes)) return "more than 1e308 bytes";
  static const char* const units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int k = 0;
  while (k < 6 && bytes >= 1024) bytes /= 1024, ++k;
  // "%.3g" would write 1000 to 1023 as "1e+03".
  const bool whole = k == 0 || (bytes >= 999.5 && bytes < 1024);
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, whole ? "%.0f %s" : "%.3g %s", bytes, units[k]);
  return buffer;
}

}  // namespace sf
