#pragma once
// How much memory one thing may take: a lattice, a picture or a set of bonds
// too big for the machine is refused with its size before anything is
// allocated, rather than failing half way or being killed by the system.
#include <string>

namespace sf {

// The memory sandflow counts on, in bytes: the machine's physical memory
// (sysconf), or less when the environment variable SANDFLOW_MEMORY says so
// (bytes, or a number with K, M, G or T: powers of 1024; other values are
// ignored). 0 when neither is known.
double memoryBytes();

// The share of memoryBytes() that one thing may take: the rest is for the
// scene's other parts, the system and the other programs.
inline constexpr double kMemoryShare = 0.8;

// Throws sf::Error "RESOURCE MEMORY" when `bytes` (not finite: too many to
// count) exceed that share: "WHAT needs 1.32 TiB of memory, more than 80% of
// this machine's 23.4 GiB". `what` names the thing with its size.
void checkMemory(double bytes, const std::string& what);

// Bytes in binary units, three significant digits: "512 MiB", "1.32 TiB".
std::string formatBytes(double bytes);

}  // namespace sf
