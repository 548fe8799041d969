#pragma once
// gq's own mesh file readers; `text` is the whole file. Each returns ParseError naming the file (and the line where
// there is one) and writes `out` only on success.
#include <string>

#include "gq/cooking.h"
#include "gq/status.h"

namespace gq::io {

template <class T> Status readObj(const std::string& path, const std::string& text, MeshData<T>& out);
template <class T> Status readStl(const std::string& path, const std::string& text, MeshData<T>& out);

}  // namespace gq::io
