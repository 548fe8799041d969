// Signed distance to the convex solids a fit is made of, and their conversion from and to gq geometries.
#include <cmath>
#include <limits>

#include "fit/fit_internal.h"
#include "gq/custom_shapes.h"

namespace gq::fit {
namespace {

// Closest point of a convex planar polygon (counter-clockwise around `normal`) to p.
Vec3d closestOnPolygon(const Solid& s, const Face& f, const Vec3d& p) {
  const Vec3d q = p - (f.normal.dot(p) + f.d) * f.normal;
  bool inside = true;
  const std::size_t n = f.vertices.size();
  for (std::size_t i = 0; i < n && inside; ++i) {
    const Vec3d& a = s.vertices[f.vertices[i]];
    const Vec3d& b = s.vertices[f.vertices[(i + 1) % n]];
    if ((b - a).cross(q - a).dot(f.normal) < 0) inside = false;
  }
  if (inside) return q;
  Vec3d best = s.vertices[f.vertices[0]];
  double bestD = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d& a = s.vertices[f.vertices[i]];
    const Vec3d& b = s.vertices[f.vertices[(i + 1) % n]];
    const Vec3d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    const Vec3d c = a + t * ab;
    const double d = (p - c).squaredNorm();
    if (d < bestD) {
      bestD = d;
      best = c;
    }
  }
  return best;
}

// The largest face-plane value at p and its face, over the packed planes (two faces a round: independent chains).
double mostPlane(const Solid& s, const Vec3d& p, std::size_t& face) {
  const double* pl = s.planes.data();
  const std::size_t n = s.planes.size() / 4;
  double most0 = -std::numeric_limits<double>::infinity(), most1 = most0;
  std::size_t face0 = 0, face1 = 0, i = 0;
  for (; i + 1 < n; i += 2, pl += 8) {
    const double v0 = pl[0] * p.x() + pl[1] * p.y() + pl[2] * p.z() + pl[3];
    const double v1 = pl[4] * p.x() + pl[5] * p.y() + pl[6] * p.z() + pl[7];
    if (v0 > most0) most0 = v0, face0 = i;
    if (v1 > most1) most1 = v1, face1 = i + 1;
  }
  if (i < n) {
    const double v0 = pl[0] * p.x() + pl[1] * p.y() + pl[2] * p.z() + pl[3];
    if (v0 > most0) most0 = v0, face0 = i;
  }
  // Ties go to the lower index, as one scan in order would.
  if (most1 > most0 || (most1 == most0 && face1 < face0)) {
    face = face1;
    return most1;
  }
  face = face0;
  return most0;
}

double polytopeDistance(const Solid& s, const Vec3d& p, Vec3d& gradient) {
  std::size_t mostFace = 0;
  const double most = mostPlane(s, p, mostFace);
  if (most <= 0) {  // inside: the nearest boundary point is the projection on the nearest plane
    gradient = s.faces[mostFace].normal;
    return most;
  }
  // Outside: the closest point lies on a face whose plane has p in front of it.
  double best = std::numeric_limits<double>::infinity();
  Vec3d bestPoint = p;
  const double* pl = s.planes.data();
  for (std::size_t i = 0; i < s.faces.size(); ++i, pl += 4) {
    // A face is no nearer than its plane.
    const double v = pl[0] * p.x() + pl[1] * p.y() + pl[2] * p.z() + pl[3];
    if (v <= 0 || v >= best) continue;
    const Face& f = s.faces[i];
    const Vec3d c = closestOnPolygon(s, f, p);
    const double d = (p - c).norm();
    if (d < best) {
      best = d;
      bestPoint = c;
    }
  }
  gradient = best > 0 ? Vec3d((p - bestPoint) / best) : s.faces[mostFace].normal;
  return best;
}

Vec3d anyPerpendicular(const Mat3d& r) { return r.col(1); }

}  // namespace

double signedDistance(const Solid& s, const Vec3d& p, Vec3d& gradient) {
  switch (s.kind) {
    case Solid::Kind::Sphere: {
      const Vec3d d = p - s.centre;
      const double n = d.norm();
      gradient = n > 0 ? Vec3d(d / n) : Vec3d::UnitX();
      return n - s.radius;
    }
    case Solid::Kind::Capsule: {
      const Vec3d axis = s.rotation.col(0);
      const double t = std::clamp((p - s.centre).dot(axis), -s.halfHeight, s.halfHeight);
      const Vec3d d = p - (s.centre + t * axis);
      const double n = d.norm();
      gradient = n > 0 ? Vec3d(d / n) : anyPerpendicular(s.rotation);
      return n - s.radius;
    }
    case Solid::Kind::Box: {
      const Vec3d q = s.rotation.transpose() * (p - s.centre);
      const Vec3d d = q.cwiseAbs() - s.halfExtents;
      const Vec3d sign(q.x() < 0 ? -1.0 : 1.0, q.y() < 0 ? -1.0 : 1.0, q.z() < 0 ? -1.0 : 1.0);
      if ((d.array() <= 0).all()) {
        int i = 0;
        const double m = d.maxCoeff(&i);
        gradient = s.rotation.col(i) * sign[i];
        return m;
      }
      const Vec3d o = d.cwiseMax(0.0);
      const double n = o.norm();
      gradient = s.rotation * Vec3d(o.cwiseProduct(sign) / n);
      return n;
    }
    case Solid::Kind::Cylinder: {
      const Vec3d q = s.rotation.transpose() * (p - s.centre);
      const double rho = std::hypot(q.y(), q.z());
      const Vec3d radial = rho > 0 ? Vec3d(0, q.y() / rho, q.z() / rho) : Vec3d(0, 1, 0);
      const double sx = q.x() < 0 ? -1.0 : 1.0;
      const double dx = std::abs(q.x()) - s.halfHeight, dr = rho - s.radius;
      if (dx <= 0 && dr <= 0) {
        gradient = dx > dr ? Vec3d(s.rotation.col(0) * sx) : Vec3d(s.rotation * radial);
        return std::max(dx, dr);
      }
      const double ox = std::max(dx, 0.0), orr = std::max(dr, 0.0);
      const double n = std::hypot(ox, orr);
      gradient = s.rotation * Vec3d((ox * sx * Vec3d::UnitX() + orr * radial) / n);
      return n;
    }
    case Solid::Kind::Polytope: return polytopeDistance(s, p, gradient);
  }
  return 0;
}

void packPlanes(Solid& s) {
  s.planes.clear();
  s.planes.reserve(4 * s.faces.size());
  for (const Face& f : s.faces) s.planes.insert(s.planes.end(), {f.normal.x(), f.normal.y(), f.normal.z(), f.d});
}

double volumeOf(const Solid& s) {
  switch (s.kind) {
    case Solid::Kind::Sphere: return 4.0 / 3.0 * M_PI * s.radius * s.radius * s.radius;
    case Solid::Kind::Capsule:
      return M_PI * s.radius * s.radius * (2 * s.halfHeight + 4.0 / 3.0 * s.radius);
    case Solid::Kind::Box: return 8 * s.halfExtents.prod();
    case Solid::Kind::Cylinder: return 2 * M_PI * s.radius * s.radius * s.halfHeight;
    case Solid::Kind::Polytope: break;
  }
  // Pyramids from the centre over each face: a third of the face's area times the centre's depth below its plane.
  double volume = 0;
  for (const Face& f : s.faces) {
    Vec3d area = Vec3d::Zero();
    for (std::size_t i = 0; i < f.vertices.size(); ++i)
      area += s.vertices[f.vertices[i]].cross(s.vertices[f.vertices[(i + 1) % f.vertices.size()]]);
    volume += 0.5 * std::abs(area.dot(f.normal)) * -(f.normal.dot(s.centre) + f.d) / 3.0;
  }
  return volume;
}

Solid polytopeOf(const ConvexMesh<double>& hull) {
  Solid s;
  s.kind = Solid::Kind::Polytope;
  s.vertices = hull.vertices;
  s.faces.reserve(hull.polygons.size());
  for (const auto& poly : hull.polygons) {
    Face f;
    f.vertices.assign(hull.polygonVertices.begin() + poly.indexBase,
                      hull.polygonVertices.begin() + poly.indexBase + poly.indexCount);
    f.normal = poly.normal;
    f.d = poly.d;
    s.faces.push_back(std::move(f));
  }
  s.centre = hull.center;
  packPlanes(s);
  return s;
}

template <class T> Solid polytopeOf(const ConvexMesh<T>& hull, const Transform<T>& pose) {
  Solid s;
  s.kind = Solid::Kind::Polytope;
  const Transform<double> pd = pose.template cast<double>();
  for (const auto& v : hull.vertices) s.vertices.push_back(pd.transform(v.template cast<double>()));
  for (const auto& poly : hull.polygons) {
    Face f;
    f.vertices.assign(hull.polygonVertices.begin() + poly.indexBase,
                      hull.polygonVertices.begin() + poly.indexBase + poly.indexCount);
    // Newell's normal in double, and the plane through the face's outermost vertex: the face vertices are inside.
    Vec3d n = Vec3d::Zero();
    for (std::size_t i = 0; i < f.vertices.size(); ++i)
      n += s.vertices[f.vertices[i]].cross(s.vertices[f.vertices[(i + 1) % f.vertices.size()]]);
    if (n.norm() == 0) n = pd.q * poly.normal.template cast<double>();
    f.normal = n.normalized();
    double reach = -std::numeric_limits<double>::infinity();
    for (std::uint32_t i : f.vertices) reach = std::max(reach, f.normal.dot(s.vertices[i]));
    f.d = -reach;
    s.faces.push_back(std::move(f));
  }
  s.centre = pd.transform(hull.center.template cast<double>());
  packPlanes(s);
  return s;
}

template <class T> Status toSolid(const Geometry<T>& g, const Transform<T>& pose, Solid& out) {
  const Transform<double> pd = pose.template cast<double>();
  Solid s;
  s.centre = pd.p;
  s.rotation = pd.q.normalized().toRotationMatrix();
  switch (g.type()) {
    case GeometryType::Sphere:
      s.kind = Solid::Kind::Sphere;
      s.radius = double(g.template get<SphereGeometry<T>>().radius);
      break;
    case GeometryType::Capsule: {
      const auto& c = g.template get<CapsuleGeometry<T>>();
      s.kind = Solid::Kind::Capsule;
      s.radius = double(c.radius);
      s.halfHeight = double(c.halfHeight);
      break;
    }
    case GeometryType::Box:
      s.kind = Solid::Kind::Box;
      s.halfExtents = g.template get<BoxGeometry<T>>().halfExtents.template cast<double>();
      break;
    case GeometryType::ConvexMesh: {
      const auto& c = g.template get<ConvexMeshGeometry<T>>();
      if (!c.mesh) return Status::invalid("convex part has no cooked hull");
      if (!c.scale.isIdentity()) return Status::unsupported("a scaled convex part cannot be certified");
      s = polytopeOf(*c.mesh, pose);
      break;
    }
    case GeometryType::Custom: {
      const auto* cyl = dynamic_cast<const CylinderCallbacks<T>*>(g.template get<CustomGeometry<T>>().callbacks.get());
      if (cyl == nullptr) return Status::unsupported("only cylinders among custom shapes can be certified");
      s.kind = Solid::Kind::Cylinder;
      s.radius = double(cyl->radius());
      s.halfHeight = double(cyl->halfHeight());
      break;
    }
    default: return Status::unsupported("a fit part must be a sphere, capsule, box, convex mesh or cylinder").withType(g.type());
  }
  out = std::move(s);
  return {};
}

template <class T> Status toGeometry(const Solid& s, std::pair<Geometry<T>, Transform<T>>& out) {
  const Transform<T> pose(s.centre.cast<T>(), Quat<T>(Quat<double>(s.rotation).normalized().cast<T>()));
  switch (s.kind) {
    case Solid::Kind::Sphere: out = {SphereGeometry<T>(T(s.radius)), Transform<T>(s.centre.cast<T>())}; return {};
    case Solid::Kind::Capsule: out = {CapsuleGeometry<T>(T(s.radius), T(s.halfHeight)), pose}; return {};
    case Solid::Kind::Box: out = {BoxGeometry<T>(s.halfExtents.cast<T>()), pose}; return {};
    case Solid::Kind::Cylinder: {
      CustomGeometry<T> c;
      Status st = makeCylinder<T>(T(s.radius), T(s.halfHeight), c);
      if (!st.ok()) return st;
      out = {c, pose};
      return {};
    }
    case Solid::Kind::Polytope: {
      std::vector<Vec3<T>> pts;
      pts.reserve(s.vertices.size());
      for (const Vec3d& v : s.vertices) pts.push_back(v.cast<T>());
      std::shared_ptr<const ConvexMesh<T>> hull;
      Status st = cookConvexMesh(pts, hull);
      if (!st.ok()) return st;
      out = {ConvexMeshGeometry<T>(hull), Transform<T>()};
      return {};
    }
  }
  return Status::internal("unknown solid kind");
}

template Solid polytopeOf<float>(const ConvexMesh<float>&, const Transform<float>&);
template Solid polytopeOf<double>(const ConvexMesh<double>&, const Transform<double>&);
template Status toSolid<float>(const Geometry<float>&, const Transform<float>&, Solid&);
template Status toSolid<double>(const Geometry<double>&, const Transform<double>&, Solid&);
template Status toGeometry<float>(const Solid&, std::pair<Geometry<float>, Transform<float>>&);
template Status toGeometry<double>(const Solid&, std::pair<Geometry<double>, Transform<double>>&);

}  // namespace gq::fit
