#include "io/mesh_text.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace gq::io {

Status readFileText(const std::string& path, std::string& text) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) return Status::owned(StatusCode::FileError, "mesh file '" + path + "' is a folder");
  std::ifstream in(path, std::ios::binary);
  if (!in.good()) return Status::owned(StatusCode::FileError, "cannot open mesh file '" + path + "'");
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return Status::owned(StatusCode::FileError, "cannot read mesh file '" + path + "'");
  text = std::move(content);
  return Status();
}

template <class T> bool parseNumber(std::string_view token, T& out) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return false;  // "+-1"
  }
  if (token.empty()) return false;
  const char* first = token.data();
  const char* last = first + token.size();
  T value{};
  auto [end, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range) {
    // Overflow is rejected below; underflow rounds to zero or a subnormal as the cast of the exact value does.
    long double wide = 0;
    auto [wideEnd, wideEc] = std::from_chars(first, last, wide);
    if (wideEc != std::errc() || wideEnd != last) return false;
    value = T(wide);
    end = wideEnd;
    ec = std::errc();
  }
  if (ec != std::errc() || end != last || !std::isfinite(value)) return false;
  out = value;
  return true;
}

std::string_view nextToken(std::string_view line, std::size_t& pos) {
  const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (pos < line.size() && isSpace(line[pos])) ++pos;
  const std::size_t begin = pos;
  while (pos < line.size() && !isSpace(line[pos])) ++pos;
  return line.substr(begin, pos - begin);
}

Status lineError(const std::string& path, std::size_t line, const std::string& what) {
  return Status::owned(StatusCode::ParseError, "cannot parse mesh file '" + path + "': line " + std::to_string(line) + ": " + what);
}

template <class T>
Status readVertexCoordinates(const std::string& path, std::size_t lineNumber, std::string_view line, std::size_t& pos,
                             Vec3<T>& p) {
  for (int k = 0; k < 3; ++k) {
    const std::string_view token = nextToken(line, pos);
    if (token.empty()) return lineError(path, lineNumber, "vertex with fewer than 3 coordinates");
    if (!parseNumber(token, p[k]))
      return lineError(path, lineNumber, "vertex coordinate '" + std::string(token) + "' is not a finite number");
  }
  return Status();
}

template <class T>
void triangulatePolygon(const std::vector<std::uint32_t>& polygon, const std::vector<Vec3<T>>& positions,
                        std::vector<TriangleIndices>& out) {
  const std::size_t n = polygon.size();
  if (n < 3) return;
  if (n == 3) {
    out.push_back({polygon[0], polygon[1], polygon[2]});
    return;
  }
  // Newell normal; the polygon is projected on the coordinate plane most orthogonal to it.
  Vec3<double> normal = Vec3<double>::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3<double> a = positions[polygon[i]].template cast<double>();
    const Vec3<double> b = positions[polygon[(i + 1) % n]].template cast<double>();
    normal += Vec3<double>((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                           (a.x() - b.x()) * (a.y() + b.y()));
  }
  int drop = 0;
  normal.cwiseAbs().maxCoeff(&drop);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const double orientation = normal[drop] >= 0 ? 1.0 : -1.0;  // counter-clockwise in (u, v) when positive
  const auto at = [&](std::uint32_t id) {
    const Vec3<T>& p = positions[id];
    return std::array<double, 2>{double(p[u]), double(p[v])};
  };
  const auto cross = [](const std::array<double, 2>& o, const std::array<double, 2>& a,
                        const std::array<double, 2>& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };

  std::vector<std::uint32_t> rest(polygon);
  while (rest.size() > 3) {
    const std::size_t m = rest.size();
    bool clipped = false;
    for (std::size_t j = 0; j < m && !clipped; ++j) {
      const std::size_t k = (j + 1) % m;  // from the second corner: a convex polygon becomes the fan of its first
      const std::uint32_t ia = rest[(k + m - 1) % m], ib = rest[k], ic = rest[(k + 1) % m];
      const auto a = at(ia), b = at(ib), c = at(ic);
      if (orientation * cross(a, b, c) <= 0) continue;  // reflex or collinear corner
      bool empty = true;
      for (std::size_t q = 0; q < m && empty; ++q) {
        const std::uint32_t iq = rest[q];
        if (iq == ia || iq == ib || iq == ic) continue;
        const auto p = at(iq);
        empty = !(orientation * cross(a, b, p) >= 0 && orientation * cross(b, c, p) >= 0 &&
                  orientation * cross(c, a, p) >= 0);
      }
      if (!empty) continue;
      out.push_back({ia, ib, ic});
      rest.erase(rest.begin() + std::ptrdiff_t(k));
      clipped = true;
    }
    if (!clipped) break;  // no ear: a degenerate (collinear or self-touching) rest
  }
  for (std::size_t i = 1; i + 1 < rest.size(); ++i) out.push_back({rest[0], rest[i], rest[i + 1]});
}

namespace {

template <class T> struct PositionKey {
  T x, y, z;
  bool operator==(const PositionKey& o) const { return x == o.x && y == o.y && z == o.z; }
};

template <class T> struct PositionHash {
  std::size_t operator()(const PositionKey<T>& k) const {
    std::size_t h = 0;
    for (T c : {k.x, k.y, k.z}) {
      const T normalised = c + T(0);  // -0 + 0 = +0: equal keys hash alike
      std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t> bits;
      std::memcpy(&bits, &normalised, sizeof bits);
      h = (h ^ std::size_t(bits)) * 0x9E3779B97F4A7C15ull;
    }
    return h;
  }
};

}  // namespace

template <class T> MeshData<T> joinVertices(const std::vector<Vec3<T>>& positions,
                                            const std::vector<TriangleIndices>& triangles) {
  constexpr std::uint32_t kUnset = ~std::uint32_t(0);
  std::vector<std::uint32_t> remap(positions.size(), kUnset);
  std::unordered_map<PositionKey<T>, std::uint32_t, PositionHash<T>> byPosition;
  byPosition.reserve(positions.size());
  MeshData<T> out;
  out.triangles.reserve(triangles.size());
  for (const TriangleIndices& t : triangles) {
    TriangleIndices joined{};
    for (int c = 0; c < 3; ++c) {
      std::uint32_t& id = remap[t[c]];
      if (id == kUnset) {
        const Vec3<T>& p = positions[t[c]];
        const auto [it, inserted] =
            byPosition.emplace(PositionKey<T>{p.x(), p.y(), p.z()}, std::uint32_t(out.vertices.size()));
        if (inserted) out.vertices.push_back(p);
        id = it->second;
      }
      joined[c] = id;
    }
    out.triangles.push_back(joined);
  }
  return out;
}

template bool parseNumber<float>(std::string_view, float&);
template bool parseNumber<double>(std::string_view, double&);
template Status readVertexCoordinates<float>(const std::string&, std::size_t, std::string_view, std::size_t&,
                                             Vec3<float>&);
template Status readVertexCoordinates<double>(const std::string&, std::size_t, std::string_view, std::size_t&,
                                              Vec3<double>&);
template void triangulatePolygon<float>(const std::vector<std::uint32_t>&, const std::vector<Vec3<float>>&,
                                        std::vector<TriangleIndices>&);
template void triangulatePolygon<double>(const std::vector<std::uint32_t>&, const std::vector<Vec3<double>>&,
                                         std::vector<TriangleIndices>&);
template MeshData<float> joinVertices<float>(const std::vector<Vec3<float>>&, const std::vector<TriangleIndices>&);
template MeshData<double> joinVertices<double>(const std::vector<Vec3<double>>&,
                                               const std::vector<TriangleIndices>&);

}  // namespace gq::io
