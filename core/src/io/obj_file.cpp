// Wavefront OBJ: faces through tinyobjloader (its double build), vertex coordinates from the file's text by
// std::from_chars. tinyobjloader's own number parser accumulates digit by digit and is off by one unit in the last
// place on about half of the Stanford bunny's coordinates, so gq reads the `v` lines again, correctly rounded; the
// two reads must agree on the number of vertices.
#include <tiny_obj_loader.h>

#include <sstream>

#include "io/mesh_readers.h"
#include "io/mesh_text.h"

namespace gq::io {
namespace {

// The `v` lines of the file, split into lines as tinyobjloader splits them ('\n', "\r\n" or '\r').
template <class T> Status readVertexLines(const std::string& path, const std::string& text, std::vector<Vec3<T>>& out) {
  std::size_t begin = 0, lineNumber = 0;
  while (begin < text.size()) {
    std::size_t end = begin;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
    const std::string_view line(text.data() + begin, end - begin);
    ++lineNumber;
    begin = end + 1;
    if (end < text.size() && text[end] == '\r' && begin < text.size() && text[begin] == '\n') ++begin;

    std::size_t pos = 0;
    while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t')) ++pos;
    if (pos + 1 >= line.size() || line[pos] != 'v' || (line[pos + 1] != ' ' && line[pos + 1] != '\t')) continue;
    pos += 2;
    Vec3<T> p;
    if (Status s = readVertexCoordinates(path, lineNumber, line, pos, p); !s.ok()) return s;
    out.push_back(p);  // an optional w or colour after x y z is not geometry
  }
  return Status();
}

}  // namespace

template <class T> Status readObj(const std::string& path, const std::string& text, MeshData<T>& out) {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::string warn, err;
  std::istringstream stream(text);
  // No material reader: `mtllib` lines open no other file. Polygons are triangulated below, on the exact vertices.
  if (!tinyobj::LoadObj(&attrib, &shapes, nullptr, &warn, &err, &stream, nullptr, /*triangulate=*/false,
                        /*default_vcols_fallback=*/false)) {
    while (!err.empty() && (err.back() == '\n' || err.back() == '.')) err.pop_back();
    return Status::owned(StatusCode::ParseError, "cannot parse mesh file '" + path + "': " + (err.empty() ? "invalid OBJ" : err));
  }
  std::vector<Vec3<T>> positions;
  if (Status s = readVertexLines(path, text, positions); !s.ok()) return s;
  if (positions.size() * 3 != attrib.vertices.size())
    return Status::owned(StatusCode::ParseError, "cannot parse mesh file '" + path + "': " + std::to_string(positions.size()) +
                              " vertex lines but " + std::to_string(attrib.vertices.size() / 3) + " vertices");

  std::vector<TriangleIndices> triangles;
  std::vector<std::uint32_t> polygon;
  for (const tinyobj::shape_t& shape : shapes) {
    const tinyobj::mesh_t& mesh = shape.mesh;
    std::size_t offset = 0;
    for (const unsigned char corners : mesh.num_face_vertices) {
      if (offset + corners > mesh.indices.size())
        return Status::owned(StatusCode::ParseError, "cannot parse mesh file '" + path + "': a face has more than 255 corners");
      polygon.clear();
      for (std::size_t c = 0; c < corners; ++c) {
        const int index = mesh.indices[offset + c].vertex_index;
        if (index < 0 || std::size_t(index) >= positions.size())
          return Status::owned(StatusCode::ParseError, "cannot parse mesh file '" + path + "': a face refers to a vertex outside the " +
                                    std::to_string(positions.size()) + " vertices");
        polygon.push_back(std::uint32_t(index));
      }
      offset += corners;
      triangulatePolygon(polygon, positions, triangles);
    }
    if (offset != mesh.indices.size())
      return Status::owned(StatusCode::ParseError, "cannot parse mesh file '" + path + "': a face has more than 255 corners");
  }
  if (triangles.empty()) return Status::owned(StatusCode::ParseError, "mesh file '" + path + "' contains no triangles");
  out = joinVertices(positions, triangles);
  return Status();
}

template Status readObj<float>(const std::string&, const std::string&, MeshData<float>&);
template Status readObj<double>(const std::string&, const std::string&, MeshData<double>&);

}  // namespace gq::io
