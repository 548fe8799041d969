// Wavefront OBJ: "v x y z [w]" positions and "f a b c ..." faces whose corners are "i", "i/t", "i//n" or "i/t/n"
// (1-based, negative = relative to the vertices read so far). Everything else is skipped.
#include "cook/obj_reader.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace gq::detail {
namespace {

// Ear clipping is O(n^3) in the corner count; larger polygons (never seen in practice, common in fuzzed files) are
// fanned, which is exact for convex ones.
constexpr std::size_t kMaxEarClippingCorners = 64;

using Vec3d = Vec3<double>;
using Vec2d = Eigen::Vector2d;

class Line {
 public:
  explicit Line(std::string_view text) : rest_(text) {}
  // The next whitespace-separated token, empty at the end of the line.
  std::string_view token() {
    std::size_t b = 0;
    while (b < rest_.size() && (rest_[b] == ' ' || rest_[b] == '\t')) ++b;
    std::size_t e = b;
    while (e < rest_.size() && rest_[e] != ' ' && rest_[e] != '\t') ++e;
    const std::string_view t = rest_.substr(b, e - b);
    rest_ = rest_.substr(e);
    return t;
  }

 private:
  std::string_view rest_;
};

bool parseNumber(std::string_view t, double& v) {
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);  // from_chars takes no sign but '-'
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  return r.ec == std::errc() && r.ptr == t.data() + t.size();
}

// A face corner's vertex index (the part before the first '/'), resolved to 0-based; false if malformed or 0.
bool parseCorner(std::string_view t, std::size_t verticesSoFar, std::int64_t& index) {
  t = t.substr(0, t.find('/'));
  long long i = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), i);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size() || i == 0) return false;
  index = i > 0 ? i - 1 : std::int64_t(verticesSoFar) + i;
  return index >= 0;
}

// Newell's normal: twice the vector area of the polygon, robust for non-planar and concave polygons.
Vec3d newellNormal(const std::vector<Vec3d>& p) {
  Vec3d n = Vec3d::Zero();
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    n += Vec3d((p[j].y() - p[i].y()) * (p[j].z() + p[i].z()), (p[j].z() - p[i].z()) * (p[j].x() + p[i].x()),
               (p[j].x() - p[i].x()) * (p[j].y() + p[i].y()));
  return n;
}

// The polygon in the plane of its two non-dominant normal axes, counter-clockwise.
std::vector<Vec2d> projectCounterClockwise(const std::vector<Vec3d>& p, const Vec3d& normal) {
  int drop = 0;
  normal.cwiseAbs().maxCoeff(&drop);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const double sign = normal[drop] < 0 ? -1.0 : 1.0;
  std::vector<Vec2d> q;
  q.reserve(p.size());
  for (const auto& x : p) q.emplace_back(x[u], sign * x[v]);
  return q;
}

double cross(const Vec2d& a, const Vec2d& b, const Vec2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

bool isConvex(const std::vector<Vec2d>& q) {
  for (std::size_t i = 0; i < q.size(); ++i)
    if (cross(q[i], q[(i + 1) % q.size()], q[(i + 2) % q.size()]) < 0) return false;
  return true;
}

bool insideOrOnTriangle(const Vec2d& p, const Vec2d& a, const Vec2d& b, const Vec2d& c) {
  return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

void fan(const std::vector<std::uint32_t>& corners, std::vector<TriangleIndices>& out) {
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) out.push_back({corners[0], corners[i], corners[i + 1]});
}

// Ear clipping of a counter-clockwise polygon: repeatedly cuts a convex corner whose triangle holds no other corner.
// A pass without an ear (self-intersecting or degenerate rest) fans what is left.
void clipEars(std::vector<std::uint32_t> corners, std::vector<Vec2d> q, std::vector<TriangleIndices>& out) {
  while (corners.size() > 3) {
    const std::size_t n = corners.size();
    bool clipped = false;
    for (std::size_t i = 0; i < n && !clipped; ++i) {
      const std::size_t a = (i + n - 1) % n, c = (i + 1) % n;
      if (cross(q[a], q[i], q[c]) <= 0) continue;
      bool empty = true;
      for (std::size_t k = 0; k < n && empty; ++k)
        if (k != a && k != i && k != c && q[k] != q[a] && q[k] != q[i] && q[k] != q[c])
          empty = !insideOrOnTriangle(q[k], q[a], q[i], q[c]);
      if (!empty) continue;
      out.push_back({corners[a], corners[i], corners[c]});
      corners.erase(corners.begin() + std::ptrdiff_t(i));
      q.erase(q.begin() + std::ptrdiff_t(i));
      clipped = true;
    }
    if (!clipped) break;
  }
  fan(corners, out);
}

void triangulate(const std::vector<std::uint32_t>& corners, const std::vector<Vec3d>& positions,
                 std::vector<TriangleIndices>& out) {
  if (corners.size() == 3 || corners.size() > kMaxEarClippingCorners) return fan(corners, out);
  std::vector<Vec3d> p;
  for (std::uint32_t i : corners) p.push_back(positions[i]);
  const Vec3d normal = newellNormal(p);
  if (!(normal.squaredNorm() > 0) || !std::isfinite(normal.squaredNorm())) return fan(corners, out);
  const std::vector<Vec2d> q = projectCounterClockwise(p, normal);
  if (isConvex(q)) return fan(corners, out);
  clipEars(corners, q, out);
}

struct FloatKeyHash {
  std::size_t operator()(const std::array<std::uint32_t, 3>& k) const {
    return (std::size_t(k[0]) * 0x9E3779B97F4A7C15ull) ^ (std::size_t(k[1]) * 0xC2B2AE3D27D4EB4Full) ^ k[2];
  }
};

// Keeps the referenced vertices in order of first reference and joins identical coordinates (+0 and -0 alike).
void compactVertices(const std::vector<Vec3d>& positions, std::vector<TriangleIndices>& triangles,
                     std::vector<Vec3d>& vertices) {
  constexpr std::uint32_t kUnset = 0xffffffffu;
  std::vector<std::uint32_t> remap(positions.size(), kUnset);
  std::unordered_map<std::array<std::uint32_t, 3>, std::uint32_t, FloatKeyHash> byCoordinates;
  for (auto& t : triangles)
    for (auto& i : t) {
      if (remap[i] == kUnset) {
        std::array<std::uint32_t, 3> key;
        for (int k = 0; k < 3; ++k) {
          const float f = float(positions[i][k]) + 0.0f;  // -0 + 0 = +0
          std::memcpy(&key[k], &f, sizeof f);
        }
        const auto [it, added] = byCoordinates.emplace(key, std::uint32_t(vertices.size()));
        if (added) vertices.push_back(positions[i]);
        remap[i] = it->second;
      }
      i = remap[i];
    }
}

Status lineError(const std::string& name, std::size_t line, const char* what) {
  return Status::parseError("cannot parse mesh file '" + name + "' line " + std::to_string(line) + ": " + what);
}

}  // namespace

Status readObj(std::string_view text, const std::string& name, MeshData<double>& out) {
  std::vector<Vec3d> positions;
  std::vector<std::int64_t> corners;       // every face's corners, 0-based, checked once all vertices are read
  std::vector<std::size_t> faceEnds;       // end of each face in `corners`
  std::vector<std::size_t> faceLines;      // line of each face, for messages
  std::size_t lineNumber = 0;
  while (!text.empty()) {
    ++lineNumber;
    const std::size_t eol = text.find('\n');
    std::string_view lineText = text.substr(0, eol);
    text = eol == std::string_view::npos ? std::string_view() : text.substr(eol + 1);
    if (!lineText.empty() && lineText.back() == '\r') lineText.remove_suffix(1);
    Line line(lineText);
    const std::string_view keyword = line.token();
    if (keyword == "v") {
      Vec3d p;
      for (int k = 0; k < 3; ++k) {
        double x = 0;
        if (!parseNumber(line.token(), x)) return lineError(name, lineNumber, "a vertex needs three numbers");
        p[k] = double(float(x));  // float, as assimp reads STL and DAE
      }
      positions.push_back(p);
    } else if (keyword == "f") {
      const std::size_t begin = corners.size();
      for (std::string_view t = line.token(); !t.empty(); t = line.token()) {
        std::int64_t index = 0;
        if (!parseCorner(t, positions.size(), index)) return lineError(name, lineNumber, "bad face corner");
        corners.push_back(index);
      }
      if (corners.size() - begin < 3) {
        corners.resize(begin);  // a point or a line: no surface
        continue;
      }
      faceEnds.push_back(corners.size());
      faceLines.push_back(lineNumber);
    }
  }
  if (positions.size() >= std::size_t(0xffffffffu)) return Status::parseError("mesh file '" + name + "' is too large");
  std::vector<TriangleIndices> triangles;
  std::vector<std::uint32_t> face;
  for (std::size_t f = 0, begin = 0; f < faceEnds.size(); begin = faceEnds[f++]) {
    face.clear();
    for (std::size_t c = begin; c < faceEnds[f]; ++c) {
      if (corners[c] >= std::int64_t(positions.size()))
        return lineError(name, faceLines[f], "vertex index out of range");
      face.push_back(std::uint32_t(corners[c]));
    }
    triangulate(face, positions, triangles);
  }
  if (triangles.empty()) return Status::parseError("mesh file '" + name + "' contains no triangles");
  MeshData<double> data;
  compactVertices(positions, triangles, data.vertices);
  data.triangles = std::move(triangles);
  out = std::move(data);
  return Status();
}

}  // namespace gq::detail
