#pragma once
// Pieces shared by gq's own mesh file readers (OBJ, STL): exact number parsing, polygon triangulation, and the
// builder that joins identical vertices the way every loader's output does.
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "gq/cooking.h"
#include "gq/status.h"

namespace gq::io {

// Reads the whole file; FileError when it cannot be opened or read (a folder included).
Status readFileText(const std::string& path, std::string& text);

// Parses `token` (all of it) as a decimal number, correctly rounded to T (std::from_chars: locale-independent; a
// leading '+' is accepted). False when the token is not a number or not finite in T.
template <class T> bool parseNumber(std::string_view token, T& out);

// The next whitespace-separated token of `line` from `pos` (spaces, tabs, '\r'); empty at the end of the line.
std::string_view nextToken(std::string_view line, std::size_t& pos);

// "cannot parse mesh file '<path>': line <n>: <what>"
Status lineError(const std::string& path, std::size_t line, const std::string& what);

// Reads the three coordinates x y z of a vertex from `line` at `pos` (parseNumber each); a lineError naming the file
// and line when one is missing or not a finite number. What follows the third is left to the caller.
template <class T>
Status readVertexCoordinates(const std::string& path, std::size_t lineNumber, std::string_view line, std::size_t& pos,
                             Vec3<T>& p);

// Triangles of a simple polygon given by vertex ids (3 or more), by ear clipping in the plane of its Newell normal:
// a convex polygon gives the fan from its first corner, a concave one only triangles inside it; the polygon's
// winding is kept. Degenerate (collinear) rests are fanned.
template <class T>
void triangulatePolygon(const std::vector<std::uint32_t>& polygon, const std::vector<Vec3<T>>& positions,
                        std::vector<TriangleIndices>& out);

// Turns triangles over source vertices (file order) into MeshData: only vertices used by a triangle are kept, in
// order of first use, and vertices at the same position (bit for bit in T, +0 = -0) become one.
template <class T> MeshData<T> joinVertices(const std::vector<Vec3<T>>& positions,
                                            const std::vector<TriangleIndices>& triangles);

}  // namespace gq::io
