#include "sandflow/io/checkpoint.hpp"

#include <bit>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "sandflow/core/checksum.hpp"
#include "sandflow/io/atomic_files.hpp"

namespace sf::io {
namespace {

// PNG's trick: a high byte and a CR LF catch a file mangled by a text transfer.
constexpr char kMagic[8] = {'\x89', 'S', 'F', 'C', 'K', 'P', '\r', '\n'};
constexpr std::uint32_t kByteOrder = 0x01020304;
constexpr std::size_t kHeaderBytes = 8 + 4 + 4 + 8 + 4;

}  // namespace

static_assert(std::endian::native == std::endian::little,
              "checkpoints are little-endian, as the machine's values are written");

void saveCheckpoint(const std::string& path, const sim::Manager& manager,
                    const std::string& session) {
  ByteWriter payload;
  manager.saveState(payload);
  payload.tag("SESS");
  payload.put(session);
  const std::vector<char>& bytes = payload.bytes();
  ByteWriter header;
  header.putRaw(kMagic, sizeof kMagic);
  header.put(std::uint32_t(kCheckpointVersion));
  header.put(kByteOrder);
  header.put(std::uint64_t(bytes.size()));
  header.put(crc32Of(bytes.data(), bytes.size()));
  writeAtomically({{path, [&](std::ostream& out) {
                      out.write(header.bytes().data(), std::streamsize(header.bytes().size()));
                      out.write(bytes.data(), std::streamsize(bytes.size()));
                    }}});
}

Checkpoint loadCheckpoint(const std::string& path, int threads) {
  auto fault = [&](const std::string& code, const std::string& why) {
    return Error(code, "checkpoint \"" + path + "\" " + why);
  };
  std::ifstream file(path, std::ios::binary);
  if (!file) throw fault("IO OPEN", std::string("cannot be read: ") + std::strerror(errno));
  std::vector<char> data((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (file.bad()) throw fault("IO READ", "cannot be read");
  if (data.empty()) throw fault("FORMAT EMPTY", "is empty");
  if (data.size() < sizeof kMagic || std::memcmp(data.data(), kMagic, sizeof kMagic) != 0)
    throw fault("FORMAT FOREIGN", "is not a sandflow checkpoint (no checkpoint header)");
  if (data.size() < kHeaderBytes)
    throw fault("FORMAT TRUNCATED", "is truncated: it ends inside its header");
  ByteReader header(data.data() + sizeof kMagic, kHeaderBytes - sizeof kMagic, 0);
  const auto version = header.get<std::uint32_t>("version");
  const auto order = header.get<std::uint32_t>("byte order");
  const auto size = header.get<std::uint64_t>("size");
  const auto sum = header.get<std::uint32_t>("checksum");
  if (order != kByteOrder)
    throw fault("FORMAT BYTEORDER", "was written on a machine of another byte order");
  if (version < 1 || version > std::uint32_t(kCheckpointVersion))
    throw fault("FORMAT VERSION", "has format version " + std::to_string(version) +
                                      "; this sandflow reads versions 1 to " +
                                      std::to_string(kCheckpointVersion));
  const std::size_t held = data.size() - kHeaderBytes;
  if (size > held)
    throw fault("FORMAT TRUNCATED", "is truncated: it holds " + std::to_string(held) + " of " +
                                        std::to_string(size) + " bytes of scene");
  if (size < held)
    throw fault("FORMAT CORRUPT",
                "is corrupted: " + std::to_string(held - size) + " bytes follow its scene");
  const char* payload = data.data() + kHeaderBytes;
  if (crc32Of(payload, held) != sum)
    throw fault("FORMAT CORRUPT", "is corrupted: its checksum does not match its contents");
  Checkpoint c;
  c.version = int(version);
  c.bytes = static_cast<long long>(data.size());
  try {
    ByteReader in(payload, held, int(version));
    c.manager = std::make_unique<sim::Manager>();
    c.manager->setThreads(threads);
    c.manager->loadState(in);
    in.expectTag("SESS");
    in.get(c.session, "session settings");
    if (in.left() != 0) ByteReader::fail("it holds more than a scene");
  } catch (const Error& e) {
    throw fault("FORMAT CORRUPT", "holds a scene that cannot be loaded: " + std::string(e.what()));
  }
  // A scene whose every field reads well may still be one no run could reach
  // (a negative density, an element off its slot): the invariants decide.
  if (const std::vector<std::string> problems = c.manager->validate(); !problems.empty())
    throw fault(
        "FORMAT CORRUPT",
        "holds a scene that fails its checks: " + problems.front() +
            (problems.size() > 1 ? " (and " + std::to_string(problems.size() - 1) + " more)" : ""));
  return c;
}

}  // namespace sf::io
