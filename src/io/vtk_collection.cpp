// A ParaView collection (.pvd): the files of a series with their simulated
// times, so that ParaView plays them at the true times.
#include "sandflow/core/error.hpp"
#include "sandflow/io/vtk.hpp"

namespace sf::io {
namespace {

// File names may hold any character; the attribute must stay XML.
std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    const char* entity = c == '&'    ? "&amp;"
                         : c == '<'  ? "&lt;"
                         : c == '>'  ? "&gt;"
                         : c == '"'  ? "&quot;"
                         : c == '\'' ? "&apos;"
                                     : nullptr;
    if (entity)
      out += entity;
    else
      out += c;
  }
  return out;
}

}  // namespace

void writeCollectionPvd(const std::vector<CollectionEntry>& entries, std::ostream& out) {
  std::string xml =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" "
      "byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (const CollectionEntry& e : entries)
    xml += "    <DataSet timestep=\"" + formatNumber(e.time) + "\" part=\"" +
           std::to_string(e.part) + "\" name=\"" + escaped(e.name) + "\" file=\"" +
           escaped(e.file) + "\"/>\n";
  xml += "  </Collection>\n</VTKFile>\n";
  out << xml;
}

}  // namespace sf::io
