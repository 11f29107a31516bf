#include "vtk_polydata.hpp"

namespace sf::io::vtp {

void Cells::add(std::size_t firstPoint, std::size_t points) {
  for (std::size_t k = 0; k < points; ++k) connectivity += std::to_string(firstPoint + k) + ' ';
  end += points;
  offsets += std::to_string(end) + ' ';
  ++count;
}

std::string stringValues(const std::vector<std::string>& strings) {
  std::string text;
  for (const std::string& s : strings) {
    for (unsigned char c : s) text += std::to_string(int(c)) + ' ';
    text += "0 ";
  }
  return text;
}

namespace {

void writeCells(const char* tag, const Cells& cells, std::ostream& out) {
  out << "      <" << tag << ">\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">"
      << cells.connectivity << "</DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" << cells.offsets
      << "</DataArray>\n      </" << tag << ">\n";
}

}  // namespace

void writePolyData(const PolyData& data, std::ostream& out) {
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
         "byte_order=\"LittleEndian\">\n  <PolyData>\n";
  if (!data.fieldData.empty()) {
    xml << "    <FieldData>\n";
    for (const Array& a : data.fieldData)
      xml << "      <Array type=\"" << a.type << "\" Name=\"" << a.name << "\" NumberOfTuples=\""
          << a.tuples << "\" format=\"ascii\">" << a.values << "</Array>\n";
    xml << "    </FieldData>\n";
  }
  xml << "    <Piece NumberOfPoints=\"" << data.nPoints << "\" NumberOfVerts=\"0\" NumberOfLines=\""
      << data.lines.count << "\" NumberOfStrips=\"0\" NumberOfPolys=\"" << data.polys.count
      << "\">\n"
      << "      <Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
      << data.points.str() << "      </DataArray></Points>\n      <CellData";
  if (!data.scalars.empty()) xml << " Scalars=\"" << data.scalars << "\"";
  if (!data.vectors.empty()) xml << " Vectors=\"" << data.vectors << "\"";
  xml << ">\n";
  for (const Array& a : data.cellData)
    xml << "        <DataArray type=\"" << a.type << "\" Name=\"" << a.name
        << "\" NumberOfComponents=\"" << a.components << "\" format=\"ascii\">" << a.values
        << "</DataArray>\n";
  xml << "      </CellData>\n";
  writeCells("Lines", data.lines, xml);
  writeCells("Polys", data.polys, xml);
  xml << "    </Piece>\n  </PolyData>\n</VTKFile>\n";
  out << xml.str();
}

}  // namespace sf::io::vtp
