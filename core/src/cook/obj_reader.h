#pragma once
// Wavefront OBJ reader for loadMeshFile: positions and faces only (normals, texture coordinates, groups and
// materials carry no geometry for collision). assimp's OBJ importer allocates and fills a 16 MB line cache per file
// (~1.3 ms for a 5-line file, ~35 ms under ASan), so OBJ files are read here instead.
#include <string_view>

#include "gq/cooking.h"
#include "gq/status.h"

namespace gq::detail {

// Parses OBJ text. Faces with more than three corners are triangulated in their plane (fan when convex, ear clipping
// when concave); faces with fewer than three corners (points, lines) are skipped. Only referenced vertices are kept,
// numbered in order of first reference, and vertices with identical coordinates are joined. Coordinates are rounded
// to float, the precision assimp gives the STL and DAE files, so every format loads the same numbers.
// Malformed statements, indices out of range and files without triangles are ParseError naming `name` and the line.
Status readObj(std::string_view text, const std::string& name, MeshData<double>& out);

}  // namespace gq::detail
