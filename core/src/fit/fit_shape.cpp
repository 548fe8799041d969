// fitShape: validation, the representations in order of query cost, the certified bound of each, the measured cost.
#include <chrono>
#include <cmath>
#include <limits>

#include "fit/fit_internal.h"
#include "gq/query.h"

namespace gq {

const char* toString(FitRepresentation r) {
  switch (r) {
    case FitRepresentation::Sphere: return "sphere";
    case FitRepresentation::Capsule: return "capsule";
    case FitRepresentation::Box: return "box";
    case FitRepresentation::Cylinder: return "cylinder";
    case FitRepresentation::SimplifiedHull: return "simplified-hull";
    case FitRepresentation::ConvexHull: return "hull";
    case FitRepresentation::ConvexDecomposition: return "decomposition";
    case FitRepresentation::Mesh: return "mesh";
  }
  return "unknown";
}

namespace fit {
namespace {

template <class T> using Parts = std::vector<std::pair<Geometry<T>, Transform<T>>>;

template <class T> Status validate(const MeshData<T>& mesh) {
  if (mesh.vertices.empty() || mesh.triangles.empty()) return Status::degenerate("mesh to fit is empty");
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!isFinite(mesh.vertices[i])) return Status::invalid("mesh to fit has a non-finite vertex").withIndex(std::uint32_t(i));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    for (std::uint32_t k : mesh.triangles[i])
      if (k >= mesh.vertices.size())
        return Status::invalid("mesh to fit has a vertex index out of range").withIndex(std::uint32_t(i));
  return {};
}

template <class T> Status toDouble(const MeshData<T>& mesh, Surface& surface) {
  std::vector<Vec3d> v;
  v.reserve(mesh.vertices.size());
  for (const auto& p : mesh.vertices) v.push_back(p.template cast<double>());
  return makeSurface(v, mesh.triangles, surface);
}

// The vertices the triangles use.
std::vector<Vec3d> usedVertices(const Surface& s) {
  std::vector<char> used(s.vertices.size(), 0);
  for (const auto& t : s.triangles)
    for (std::uint32_t i : t) used[i] = 1;
  std::vector<Vec3d> out;
  for (std::size_t i = 0; i < used.size(); ++i)
    if (used[i]) out.push_back(s.vertices[i]);
  return out;
}

// The largest amount a vertex sticks out of the solid (<= 0 when it contains them all).
double protrusion(const Solid& s, const std::vector<Vec3d>& pts) {
  double most = -std::numeric_limits<double>::infinity();
  Vec3d g;
  for (const Vec3d& p : pts) most = std::max(most, signedDistance(s, p, g));
  return most;
}

// Parts in T from solids in double, and the solids the T parts stand for (the bound is certified for those).
template <class T>
Status realise(const std::vector<Solid>& solids, Parts<T>& parts, std::vector<Solid>& exact) {
  parts.clear();
  exact.clear();
  for (const Solid& s : solids) {
    std::pair<Geometry<T>, Transform<T>> part;
    Status st = toGeometry<T>(s, part);
    if (!st.ok()) return st;
    Solid back;
    st = toSolid<T>(part.first, part.second, back);
    if (!st.ok()) return st;
    parts.push_back(std::move(part));
    exact.push_back(std::move(back));
  }
  return {};
}

// A primitive in T that still contains the vertices after rounding: grown by what sticks out, a few times.
template <class T>
Status realiseContaining(Solid s, const std::vector<Vec3d>& pts, Parts<T>& parts, std::vector<Solid>& exact) {
  for (int round = 0; round < 4; ++round) {
    Status st = realise<T>({s}, parts, exact);
    if (!st.ok()) return st;
    const double out = protrusion(exact[0], pts);
    if (out <= 0) return {};
    const double grow = 2 * out + 4 * double(std::numeric_limits<T>::epsilon()) * (s.centre.norm() + s.radius +
                                                                                  s.halfHeight + s.halfExtents.norm());
    s.radius += grow;
    s.halfExtents.array() += grow;
    if (s.kind == Solid::Kind::Cylinder) s.halfHeight += grow;
  }
  return Status::internal("a fit part does not contain the mesh after rounding");
}

template <class T> double timeOverlaps(const Parts<T>& parts, const Bounds3<double>& box, double size) {
  const SphereGeometry<T> probe(T(0.05 * size));
  double best = std::numeric_limits<double>::infinity();
  volatile int hits = 0;
  for (int round = 0; round < 5; ++round) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) {
          const Vec3d f((i + 0.5) / 4, (j + 0.5) / 4, (k + 0.5) / 4);
          const Vec3d lo = box.min - 0.1 * (box.max - box.min), hi = box.max + 0.1 * (box.max - box.min);
          const Transform<T> pose(Vec3d(lo + f.cwiseProduct(hi - lo)).cast<T>());
          for (const auto& part : parts) {
            bool o = false;
            if (overlap<T>(probe, pose, part.first, part.second, o).ok() && o) {
              hits = hits + 1;
              break;
            }
          }
        }
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

template <class T> Status meshPart(const MeshData<T>& mesh, Parts<T>& parts) {
  std::shared_ptr<const TriangleMesh<T>> cooked;
  Status s = cookTriangleMesh(mesh.vertices, mesh.triangles, cooked);
  if (!s.ok()) return s;
  parts = {{TriangleMeshGeometry<T>(cooked), Transform<T>()}};
  return {};
}

template <class T> std::uint32_t vertexCount(const std::vector<Solid>& solids) {
  std::uint32_t n = 0;
  for (const Solid& s : solids) n += s.kind == Solid::Kind::Polytope ? std::uint32_t(s.vertices.size()) : 0;
  return n;
}

}  // namespace
}  // namespace fit

template <class T> Status fitShape(const MeshData<T>& mesh, const FitOptions<T>& options, FitResult<T>& result) {
  using namespace fit;
  try {
    if (!std::isfinite(double(options.tolerance)) || !(options.tolerance > T(0)))
      return Status::invalid("fit tolerance must be finite and > 0");
    if (options.maxParts == 0) return Status::invalid("fit maxParts must be >= 1");
    if ((options.allowed & kAllFitRepresentations) == 0) return Status::invalid("no fit representation allowed");
    Status st = validate(mesh);
    if (!st.ok()) return st;
    Surface surface;
    st = toDouble(mesh, surface);
    if (!st.ok()) return st;
    const double tol = double(options.tolerance);
    const std::vector<Vec3d> used = usedVertices(surface);
    std::shared_ptr<const ConvexMesh<double>> hull;
    const Status hullStatus = enclosingHull(used, hull);
    // A flat mesh (no volume) has no solid fit; only the mesh itself stands for it.
    if (!hullStatus.ok() && (options.allowed & fitBit(FitRepresentation::Mesh)) == 0) return hullStatus;

    FitResult<T> out;
    Parts<T> bestParts;
    FitRepresentation bestRep = FitRepresentation::Mesh;
    double bestBound = std::numeric_limits<double>::infinity();
    bool found = false;
    const double hullVolume = hullStatus.ok() ? volumeOf(polytopeOf(*hull)) : 0.0;
    const auto consider = [&](FitRepresentation rep, const Parts<T>& parts, const std::vector<Solid>& exact,
                              double bound) {
      const double ratio = exact.size() == 1 && hullVolume > 0 ? volumeOf(exact[0]) / hullVolume : 0.0;
      out.candidates.push_back({rep, T(bound), std::uint32_t(parts.size()), vertexCount<T>(exact), T(ratio)});
      if (bound < bestBound) {
        bestBound = bound;
        bestParts = parts;
        bestRep = rep;
      }
      if (bound <= tol) found = true;
    };
    const auto allowed = [&](FitRepresentation r) { return (options.allowed & fitBit(r)) != 0; };
    const auto certify = [&](const std::vector<Solid>& exact) {
      return certifiedBound(surface, exact, tol, options.maxBoundPatches).upper;
    };
    // A solid fit: realised in T (containing when asked), its bound certified; in a close fit, primitives are also
    // tried shrunk by half their bound, and the better kept.
    const auto trySolids = [&](FitRepresentation rep, const std::vector<Solid>& solids, bool primitive) -> Status {
      Parts<T> parts;
      std::vector<Solid> exact;
      Status s = options.contain && primitive ? realiseContaining<T>(solids[0], used, parts, exact)
                                              : realise<T>(solids, parts, exact);
      if (!s.ok()) return s;
      double bound = certify(exact);
      if (primitive && !options.contain && bound > tol) {
        Parts<T> tighterParts;
        std::vector<Solid> tighter;
        if (realise<T>({shrunk(solids[0], 0.5 * bound)}, tighterParts, tighter).ok()) {
          const double b = certify(tighter);
          if (b < bound) {
            bound = b;
            parts = std::move(tighterParts);
            exact = std::move(tighter);
          }
        }
      }
      consider(rep, parts, exact, bound);
      return {};
    };

    if (hullStatus.ok()) {
      std::vector<Mat3d> axes;
      const Solid box = fitBox(*hull, axes);
      if (allowed(FitRepresentation::Sphere) && !found)
        if (st = trySolids(FitRepresentation::Sphere, {fitSphere(hull->vertices)}, true); !st.ok()) return st;
      if (allowed(FitRepresentation::Capsule) && !found)
        if (st = trySolids(FitRepresentation::Capsule, {fitCapsule(hull->vertices, axes)}, true); !st.ok()) return st;
      if (allowed(FitRepresentation::Box) && !found)
        if (st = trySolids(FitRepresentation::Box, {box}, true); !st.ok()) return st;
      if (allowed(FitRepresentation::Cylinder) && !found)
        if (st = trySolids(FitRepresentation::Cylinder, {fitCylinder(hull->vertices, axes)}, true); !st.ok())
          return st;
      // The hull's bound decides the rest: a simplified hull is at least as far from the mesh as the hull
      // (within its slack), and a decomposition is only needed when the hull is too far.
      double hullBound = std::numeric_limits<double>::infinity();
      Parts<T> hullParts;
      std::vector<Solid> hullExact;
      if (!found && (allowed(FitRepresentation::SimplifiedHull) || allowed(FitRepresentation::ConvexHull) ||
                     allowed(FitRepresentation::ConvexDecomposition))) {
        if (st = realise<T>({polytopeOf(*hull)}, hullParts, hullExact); !st.ok()) return st;
        hullBound = certify(hullExact);
      }
      if (allowed(FitRepresentation::SimplifiedHull) && !found) {
        // Within the tolerance, the slack is what the hull leaves; beyond it, a tenth of the hull's bound.
        double slack = hullBound < tol ? 0.9 * (tol - hullBound) : 0.1 * hullBound;
        Parts<T> lastParts;
        std::vector<Solid> lastExact;
        double lastBound = std::numeric_limits<double>::infinity();
        for (int attempt = 0; attempt < 3; ++attempt, slack *= 0.5) {
          Solid simple;
          if (!simplifiedHull(*hull, slack, options.contain, simple).ok()) break;
          if (!realise<T>({simple}, lastParts, lastExact).ok()) break;
          lastBound = certify(lastExact);
          if (lastBound <= tol) break;
        }
        if (!lastParts.empty()) consider(FitRepresentation::SimplifiedHull, lastParts, lastExact, lastBound);
      }
      if (allowed(FitRepresentation::ConvexHull) && !found) consider(FitRepresentation::ConvexHull, hullParts, hullExact, hullBound);
      if (allowed(FitRepresentation::ConvexDecomposition) && !found) {
        std::vector<Solid> pieces;
        if (decompose(surface, tol, options.maxParts, options.maxBoundPatches, pieces).ok() && !pieces.empty()) {
          Parts<T> parts;
          std::vector<Solid> exact;
          if (realise<T>(pieces, parts, exact).ok()) {
            // The hull is the one-part decomposition: where the split's bound is not below it (a mesh whose error
            // sits on internal walls no cut reaches, docs/fit.md), the hull stands for the decomposition.
            const double bound = certify(exact);
            if (bound < hullBound || hullParts.empty())
              consider(FitRepresentation::ConvexDecomposition, parts, exact, bound);
            else
              consider(FitRepresentation::ConvexDecomposition, hullParts, hullExact, hullBound);
          }
        }
      }
    }
    if (allowed(FitRepresentation::Mesh) && !found) {
      Parts<T> parts;
      if (st = meshPart(mesh, parts); !st.ok()) return st;
      consider(FitRepresentation::Mesh, parts, {}, 0.0);
    }
    if (out.candidates.empty()) return hullStatus.ok() ? Status::internal("no fit was built") : hullStatus;
    out.parts = std::move(bestParts);
    out.representation = bestRep;
    out.errorBound = T(bestBound);
    if (double(out.errorBound) < bestBound) out.errorBound = std::nextafter(out.errorBound, std::numeric_limits<T>::infinity());
    if (options.measureCost) {
      Parts<T> meshParts;
      if (meshPart(mesh, meshParts).ok()) {
        Bounds3<double> box;
        for (const Vec3d& p : used) box.include(p);
        const double tMesh = timeOverlaps(meshParts, box, surface.size);
        out.relativeCost = tMesh > 0 ? timeOverlaps(out.parts, box, surface.size) / tMesh : 0.0;
      }
    }
    result = std::move(out);
    if (!found) return Status::warning("no allowed fit representation is proven within the tolerance");
    return {};
  } catch (const std::bad_alloc&) {
    return Status::internal("out of memory while fitting");
  } catch (...) {
    return Status::internal("unexpected exception while fitting");
  }
}

template <class T>
Status certifyFit(const MeshData<T>& mesh, const std::vector<std::pair<Geometry<T>, Transform<T>>>& parts, T target,
                  std::uint32_t maxPatches, T& errorBound) {
  using namespace fit;
  try {
    if (!std::isfinite(double(target)) || target < T(0)) return Status::invalid("certify target must be finite and >= 0");
    if (parts.empty()) return Status::invalid("no fit parts to certify");
    Status st = validate(mesh);
    if (!st.ok()) return st;
    Surface surface;
    if (st = toDouble(mesh, surface); !st.ok()) return st;
    std::vector<Solid> solids;
    for (const auto& part : parts) {
      if (Status v = validateGeometry(part.first); !v.ok()) return v;
      if (!part.second.isValid()) return Status::invalid("fit part pose is not a valid transform");
      Solid s;
      if (st = toSolid<T>(part.first, part.second, s); !st.ok()) return st;
      solids.push_back(std::move(s));
    }
    const double b = certifiedBound(surface, solids, double(target), maxPatches).upper;
    T out = T(b);
    if (double(out) < b) out = std::nextafter(out, std::numeric_limits<T>::infinity());
    errorBound = out;
    return {};
  } catch (...) {
    return Status::internal("unexpected exception while certifying a fit");
  }
}

template Status fitShape<float>(const MeshData<float>&, const FitOptions<float>&, FitResult<float>&);
template Status fitShape<double>(const MeshData<double>&, const FitOptions<double>&, FitResult<double>&);
template Status certifyFit<float>(const MeshData<float>&, const std::vector<std::pair<Geometry<float>, Transform<float>>>&,
                                  float, std::uint32_t, float&);
template Status certifyFit<double>(const MeshData<double>&,
                                   const std::vector<std::pair<Geometry<double>, Transform<double>>>&, double,
                                   std::uint32_t, double&);

}  // namespace gq
