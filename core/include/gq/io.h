#pragma once
// Mesh files (library gq_io, CMake target gq::io): the only part of gq that reads files, so gq::core needs no file
// parser. OBJ and STL are read by gq itself with every coordinate exact; the other formats go through assimp.
#include <string>

#include "gq/cooking.h"
#include "gq/status.h"

namespace gq {

// Loads a triangle mesh file into `out`: every mesh of the file merged into one vertex/triangle list, polygons
// triangulated, vertices at identical positions joined (in T, in order of first use by a triangle), points and
// lines dropped. Formats:
// - OBJ (.obj): vertex coordinates are the correctly rounded values of the file's decimal text in T (in double, the
//   nearest double to each number as written), faces through tinyobjloader; `f` indices may be negative (relative).
// - STL (.stl): binary STL (32-bit floats by format) read exactly; ASCII STL parsed by gq, correctly rounded in T.
// - every other format assimp reads (DAE, PLY, 3DS, ...): through assimp, whose coordinates are 32-bit floats. All
//   meshes are placed in the frame of the file's root applying every node's transform, except that a DAE root-node
//   transform (its up-axis) is dropped when `ignoreRootTransform` is set (what ROS tools do).
// Missing or unreadable file: FileError; malformed, empty (no triangles), out-of-range face index or a coordinate
// that is not a finite number: ParseError naming the file (and the line, for OBJ and ASCII STL). On error `out` is
// left unchanged.
template <class T>
Status loadMeshFile(const std::string& path, MeshData<T>& out, bool ignoreRootTransform = false);

}  // namespace gq
