// STL. Binary: an 80-byte header, a little-endian uint32 triangle count and 50 bytes per triangle (normal, three
// vertices as 32-bit floats, attribute bytes); a file is binary when its size is exactly 84 + 50 * count, as
// assimp decides too (binary headers may begin with "solid"). ASCII: `solid`, then facets of `facet normal ...`,
// `outer loop`, three `vertex x y z`, `endloop`, `endfacet`, closed by `endsolid`; several solids may follow each
// other. Coordinates are exact: binary floats as stored, ASCII numbers correctly rounded in T.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "io/mesh_readers.h"
#include "io/mesh_text.h"

namespace gq::io {
namespace {

template <class T> Status readBinaryStl(const std::string& path, const std::string& text, std::uint32_t count,
                                        MeshData<T>& out) {
  if (count == 0) return Status::owned(StatusCode::ParseError, "mesh file '" + path + "' contains no triangles");
  std::vector<Vec3<T>> positions;
  std::vector<TriangleIndices> triangles;
  positions.reserve(std::size_t(count) * 3);
  triangles.reserve(count);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* record = text.data() + 84 + std::size_t(t) * 50;
    for (int c = 0; c < 3; ++c) {
      float xyz[3];
      std::memcpy(xyz, record + 12 + 12 * c, sizeof xyz);
      if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
        return Status::owned(StatusCode::ParseError, "cannot parse mesh file '" + path + "': triangle " + std::to_string(t) +
                                  " has a coordinate that is not a finite number");
      positions.push_back(Vec3<T>(T(xyz[0]), T(xyz[1]), T(xyz[2])));
    }
    const auto base = std::uint32_t(3 * t);
    triangles.push_back({base, base + 1, base + 2});
  }
  out = joinVertices(positions, triangles);
  return Status();
}

template <class T> Status readAsciiStl(const std::string& path, const std::string& text, MeshData<T>& out) {
  enum class State { Outside, InSolid, InFacet };
  State state = State::Outside;
  std::vector<Vec3<T>> positions;
  std::vector<TriangleIndices> triangles;
  std::size_t facetVertices = 0, begin = 0, lineNumber = 0, facetLine = 0;
  while (begin < text.size()) {
    std::size_t end = begin;
    while (end < text.size() && text[end] != '\n') ++end;
    const std::string_view line(text.data() + begin, end - begin);
    begin = end + 1;
    ++lineNumber;
    std::size_t pos = 0;
    const std::string_view keyword = nextToken(line, pos);
    if (keyword.empty()) continue;
    const auto expect = [&](State wanted) { return state == wanted; };
    if (keyword == "solid") {
      if (!expect(State::Outside)) return lineError(path, lineNumber, "'solid' inside a solid");
      state = State::InSolid;  // the rest of the line is the solid's name
    } else if (keyword == "endsolid") {
      if (!expect(State::InSolid)) return lineError(path, lineNumber, "'endsolid' outside a solid or inside a facet");
      state = State::Outside;
    } else if (keyword == "facet") {
      if (!expect(State::InSolid)) return lineError(path, lineNumber, "'facet' outside a solid or inside a facet");
      state = State::InFacet;
      facetVertices = 0;
      facetLine = lineNumber;
    } else if (keyword == "outer" || keyword == "endloop") {
      if (!expect(State::InFacet)) return lineError(path, lineNumber, "'" + std::string(keyword) + "' outside a facet");
    } else if (keyword == "vertex") {
      if (!expect(State::InFacet)) return lineError(path, lineNumber, "'vertex' outside a facet");
      Vec3<T> p;
      if (Status s = readVertexCoordinates(path, lineNumber, line, pos, p); !s.ok()) return s;
      if (!nextToken(line, pos).empty()) return lineError(path, lineNumber, "vertex with more than 3 coordinates");
      if (++facetVertices > 3) return lineError(path, lineNumber, "facet with more than 3 vertices");
      positions.push_back(p);
    } else if (keyword == "endfacet") {
      if (!expect(State::InFacet)) return lineError(path, lineNumber, "'endfacet' outside a facet");
      if (facetVertices != 3)
        return lineError(path, lineNumber, "facet with " + std::to_string(facetVertices) + " vertices");
      const auto base = std::uint32_t(positions.size() - 3);
      triangles.push_back({base, base + 1, base + 2});
      state = State::InSolid;
    } else {
      return lineError(path, lineNumber, "unexpected '" + std::string(keyword.substr(0, 40)) + "'");
    }
  }
  // A missing final `endsolid` is tolerated (some writers omit it); a cut facet is not.
  if (state == State::InFacet) return lineError(path, facetLine, "the file ends inside this facet");
  if (triangles.empty()) return Status::owned(StatusCode::ParseError, "mesh file '" + path + "' contains no triangles");
  out = joinVertices(positions, triangles);
  return Status();
}

}  // namespace

template <class T> Status readStl(const std::string& path, const std::string& text, MeshData<T>& out) {
  if (text.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, text.data() + 80, 4);  // little-endian by format (and on every supported host)
    if (std::uint64_t(text.size()) == 84 + 50 * std::uint64_t(count)) return readBinaryStl(path, text, count, out);
  }
  std::size_t pos = 0;
  if (nextToken(std::string_view(text).substr(0, std::min<std::size_t>(text.size(), 4096)), pos) != "solid") {
    std::string why = "neither an ASCII STL (it does not begin with 'solid') nor a binary STL";
    if (text.size() >= 84) {
      std::uint32_t count = 0;
      std::memcpy(&count, text.data() + 80, 4);
      why += " (" + std::to_string(count) + " triangles need " + std::to_string(84 + 50 * std::uint64_t(count)) +
             " bytes, the file has " + std::to_string(text.size()) + ")";
    } else {
      why += " (shorter than the 84-byte binary header)";
    }
    return Status::owned(StatusCode::ParseError, "cannot parse mesh file '" + path + "': " + why);
  }
  return readAsciiStl(path, text, out);
}

template Status readStl<float>(const std::string&, const std::string&, MeshData<float>&);
template Status readStl<double>(const std::string&, const std::string&, MeshData<double>&);

}  // namespace gq::io
