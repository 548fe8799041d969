// Geometries and poses: Sphere, Capsule, Box, Plane, ConvexMesh, TriangleMesh (with its cooking report), HeightField,
// Cylinder, Cone, Ellipsoid, and CustomShape (Python callables), each validated once into a prepared shape.
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <vector>

#include "common.h"
#include "custom_callbacks.h"
#include "gq/custom_shapes.h"

namespace gqpy {

namespace {

struct Sphere : GeometryObject {};
struct Capsule : GeometryObject {};
struct Box : GeometryObject {};
struct Plane : GeometryObject {};
struct ConvexMesh : GeometryObject {};
struct TriangleMesh : GeometryObject {};
struct HeightField : GeometryObject {};
struct Cylinder : GeometryObject {};
struct Cone : GeometryObject {};
struct Ellipsoid : GeometryObject {};
struct CustomShape : GeometryObject {};

// Prepares `g` in the object's scalar type; ValueError (or the Status's exception) when validation fails.
template <class Obj, class T> Obj make(const gq::Geometry<T>& g, const char* what) {
  Obj obj;
  obj.f32 = std::is_same_v<T, float>;
  gq::Shape<T> shape;
  check(gq::Shape<T>::make(g, shape), what);
  if constexpr (std::is_same_v<T, float>) obj.f = std::move(shape); else obj.d = std::move(shape);
  return obj;
}

template <class Obj, class Fn> Obj byDtype(const py::object& dtype, Fn&& fn) {
  return isFloat32(dtype) ? fn(float{}) : fn(double{});
}

template <class T> gq::MeshScale<T> meshScale(const py::object& scale) {
  if (scale.is_none()) return gq::MeshScale<T>();
  if (PyFloat_Check(scale.ptr()) || PyLong_Check(scale.ptr())) return gq::MeshScale<T>(scale.cast<T>());
  return gq::MeshScale<T>(vec3<T>(scale, "scale"));
}

template <class T> std::vector<gq::Vec3<T>> points(const py::handle& obj, const char* what) {
  const auto arr = rowsArray<T>(obj, 3, what);
  std::vector<gq::Vec3<T>> out(std::size_t(arr.shape(0)));
  const auto* base = reinterpret_cast<const unsigned char*>(arr.data());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const T* row = reinterpret_cast<const T*>(base + i * std::size_t(arr.strides(0)));
    out[i] = gq::Vec3<T>(row[0], row[1], row[2]);
  }
  return out;
}

std::vector<gq::TriangleIndices> faces(const py::handle& obj) {
  const py::array arr = py::array::ensure(obj);
  if (!arr) {
    PyErr_Clear();
    throw py::type_error("faces: expected an integer array of shape (M, 3)");
  }
  const char kind = arr.dtype().kind();
  if (kind != 'i' && kind != 'u' && !(arr.size() == 0))
    throw py::type_error("faces: dtype must be an integer type, not " + dtypeText(arr.dtype()));
  if (arr.ndim() != 2 || arr.shape(1) != 3) throw py::value_error("faces: expected shape (M, 3)");
  const auto idx = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(arr);
  std::vector<gq::TriangleIndices> out(std::size_t(idx.shape(0)));
  const std::int64_t* v = idx.data();
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const std::int64_t x = v[3 * i + std::size_t(k)];
      if (x < 0 || x > std::int64_t(0xfffffffe))
        throw py::value_error("faces: index " + std::to_string(x) + " of triangle " + std::to_string(i) +
                              " is out of range");
      out[i][std::size_t(k)] = std::uint32_t(x);
    }
  return out;
}

template <class T> class PythonCallbacks final : public gq::CustomGeometryCallbacks<T> {
 public:
  PythonCallbacks(py::object support, py::object raycast, gq::Bounds3<T> bounds, bool convex,
                  std::shared_ptr<CallbackErrors> errors)
      : support_(std::move(support)), raycast_(std::move(raycast)), bounds_(bounds), convex_(convex),
        errors_(std::move(errors)) {}
  ~PythonCallbacks() override {
    py::gil_scoped_acquire gil;
    support_ = py::object();
    raycast_ = py::object();
  }
  const char* name() const override { return "python"; }
  gq::Bounds3<T> localBounds() const override { return bounds_; }
  bool isConvex() const override { return convex_; }
  gq::Vec3<T> support(const gq::Vec3<T>& dir) const override {
    py::gil_scoped_acquire gil;
    try {
      const py::object r = support_(py::make_tuple(double(dir.x()), double(dir.y()), double(dir.z())));
      return vec3<T>(r, "support callback result");
    } catch (std::exception& e) {
      errors_->record(std::string("support callback: ") + e.what());
      return gq::Vec3<T>::Zero();
    }
  }
  bool raycast(const gq::Vec3<T>& origin, const gq::Vec3<T>& dir, T maxDist, gq::HitFlags flags,
               gq::RaycastHit<T>& hit) const override {
    py::gil_scoped_acquire gil;
    try {
      if (raycast_.is_none()) return false;
      const py::object r = raycast_(py::make_tuple(double(origin.x()), double(origin.y()), double(origin.z())),
                                    py::make_tuple(double(dir.x()), double(dir.y()), double(dir.z())),
                                    double(maxDist));
      if (r.is_none()) return false;
      const py::tuple t = r.cast<py::tuple>();
      if (t.size() != 2) throw py::value_error("expected None or (distance, normal)");
      hit.distance = t[0].cast<T>();
      hit.normal = vec3<T>(t[1], "raycast callback normal");
      hit.position = origin + dir * hit.distance;
      hit.flags = flags & (gq::HitFlag::Position | gq::HitFlag::Normal);
      return true;
    } catch (std::exception& e) {
      errors_->record(std::string("raycast callback: ") + e.what());
      return false;
    }
  }

 private:
  py::object support_, raycast_;
  gq::Bounds3<T> bounds_;
  bool convex_;
  std::shared_ptr<CallbackErrors> errors_;
};

py::dict cookReport(const GeometryObject& g) {
  py::dict d;
  d["input_triangles"] = g.cookReport.inputTriangles;
  d["removed_degenerate"] = g.cookReport.removedDegenerate;
  d["cooked_triangles"] = g.cookReport.cookedTriangles;
  d["bvh_bytes"] = g.cookReport.bvhBytes;
  return d;
}

template <class G, class T> const G& alt(const GeometryObject& g) {
  return g.geometry<T>().template get<G>();
}

}  // namespace

void rethrowCallbackError(const GeometryObject& g) {
  if (!g.callbackErrors) return;
  std::string message;
  {
    std::lock_guard<std::mutex> lock(g.callbackErrors->mutex);
    if (!g.callbackErrors->failed) return;
    g.callbackErrors->failed = false;
    message = std::move(g.callbackErrors->message);
  }
  throw std::runtime_error(message);
}

void bindGeometry(py::module_& m) {
  py::class_<Pose>(m, "Pose", "A rigid pose: position + unit quaternion (x, y, z, w); x_world = q * x_local + p.")
      .def(py::init([](const py::object& position, const py::object& quaternion) {
             Pose p;
             const gq::Vec3<double> t = position.is_none() ? gq::Vec3<double>::Zero() : vec3<double>(position, "position");
             gq::Quat<double> q = gq::Quat<double>::Identity();
             if (!quaternion.is_none()) {
               const auto a = py::array_t<double, py::array::forcecast>::ensure(quaternion);
               if (!a || a.ndim() != 1 || a.size() != 4) {
                 PyErr_Clear();
                 throw py::value_error("quaternion: expected 4 numbers (x, y, z, w)");
               }
               q = gq::Quat<double>(a.at(3), a.at(0), a.at(1), a.at(2));
             }
             return Pose(gq::Transform<double>(t, q));
           }),
           py::arg("position") = py::none(), py::arg("quaternion") = py::none())
      .def_static("from_array", [](const py::object& a) { return Pose(poseFromSequence(a, "pose")); },
                  "From 7 numbers (px, py, pz, qx, qy, qz, qw).")
      .def_static("from_matrix", [](const py::object& mat) {
            const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(mat);
            if (!a || a.ndim() != 2 || a.shape(0) < 3 || a.shape(1) != 4 || a.shape(0) > 4) {
              PyErr_Clear();
              throw py::value_error("matrix: expected a (4, 4) or (3, 4) homogeneous transform");
            }
            gq::Mat3<double> r;
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j) r(i, j) = a.at(i, j);
            gq::Quat<double> q(r);
            q.normalize();
            return Pose(gq::Transform<double>(gq::Vec3<double>(a.at(0, 3), a.at(1, 3), a.at(2, 3)), q));
          })
      .def_property_readonly("position", [](const Pose& p) { return gq::Vec3<double>(p.d.p); })
      .def_property_readonly("quaternion", [](const Pose& p) {
        auto a = newArray<double>({4});
        auto* v = a.mutable_data();
        v[0] = p.d.q.x(); v[1] = p.d.q.y(); v[2] = p.d.q.z(); v[3] = p.d.q.w();
        return a;
      }, "(x, y, z, w)")
      .def("to_array", [](const Pose& p) {
        auto a = newArray<double>({7});
        auto* v = a.mutable_data();
        v[0] = p.d.p.x(); v[1] = p.d.p.y(); v[2] = p.d.p.z();
        v[3] = p.d.q.x(); v[4] = p.d.q.y(); v[5] = p.d.q.z(); v[6] = p.d.q.w();
        return a;
      }, "(px, py, pz, qx, qy, qz, qw)")
      .def("matrix", [](const Pose& p) {
        Eigen::Matrix<double, 4, 4, Eigen::RowMajor> mat = p.d.toIsometry().matrix();
        return mat;
      })
      .def("__mul__", [](const Pose& a, const Pose& b) { return Pose(a.d * b.d); })
      .def("inverse", [](const Pose& p) { return Pose(p.d.getInverse()); })
      .def("transform_point", [](const Pose& p, const py::object& x) { return gq::Vec3<double>(p.d.transform(vec3<double>(x, "point"))); })
      .def("__repr__", [](const Pose& p) {
        return "Pose(position=(" + std::to_string(p.d.p.x()) + ", " + std::to_string(p.d.p.y()) + ", " +
               std::to_string(p.d.p.z()) + "), quaternion=(" + std::to_string(p.d.q.x()) + ", " +
               std::to_string(p.d.q.y()) + ", " + std::to_string(p.d.q.z()) + ", " + std::to_string(p.d.q.w()) + "))";
      });

  py::class_<GeometryObject>(m, "Geometry", "A validated geometry (float32 or float64, chosen by its inputs).")
      .def_property_readonly("dtype", [](const GeometryObject& g) { return g.f32 ? py::dtype::of<float>() : py::dtype::of<double>(); })
      .def_property_readonly("type", [](const GeometryObject& g) { return std::string(g.typeName()); })
      .def_property_readonly("local_bounds", [](const GeometryObject& g) {
        const auto b = g.f32 ? g.f.localBounds().min.cast<double>().eval() : g.d.localBounds().min;
        const auto c = g.f32 ? g.f.localBounds().max.cast<double>().eval() : g.d.localBounds().max;
        return py::make_tuple(gq::Vec3<double>(b), gq::Vec3<double>(c));
      })
      .def("__repr__", [](const GeometryObject& g) {
        return std::string("<geomquery ") + g.typeName() + " " + g.dtypeName() + ">";
      });

  py::class_<Sphere, GeometryObject>(m, "Sphere")
      .def(py::init([](double r, const py::object& dtype) {
             return byDtype<Sphere>(dtype, [&](auto t) {
               using T = decltype(t);
               return make<Sphere, T>(gq::SphereGeometry<T>(T(r)), "Sphere");
             });
           }),
           py::arg("radius"), py::arg("dtype") = py::none())
      .def_property_readonly("radius", [](const Sphere& g) {
        return g.f32 ? double(alt<gq::SphereGeometry<float>, float>(g).radius) : alt<gq::SphereGeometry<double>, double>(g).radius;
      });

  py::class_<Capsule, GeometryObject>(m, "Capsule", "Capsule along local X: segment (+-half_height, 0, 0), radius.")
      .def(py::init([](double r, double hh, const py::object& dtype) {
             return byDtype<Capsule>(dtype, [&](auto t) {
               using T = decltype(t);
               return make<Capsule, T>(gq::CapsuleGeometry<T>(T(r), T(hh)), "Capsule");
             });
           }),
           py::arg("radius"), py::arg("half_height"), py::arg("dtype") = py::none())
      .def_property_readonly("radius", [](const Capsule& g) {
        return g.f32 ? double(alt<gq::CapsuleGeometry<float>, float>(g).radius) : alt<gq::CapsuleGeometry<double>, double>(g).radius;
      })
      .def_property_readonly("half_height", [](const Capsule& g) {
        return g.f32 ? double(alt<gq::CapsuleGeometry<float>, float>(g).halfHeight) : alt<gq::CapsuleGeometry<double>, double>(g).halfHeight;
      });

  py::class_<Box, GeometryObject>(m, "Box", "Box with half extents (hx, hy, hz).")
      .def(py::init([](const py::object& he, const py::object& dtype) {
             const bool f32 = dtype.is_none() ? arrayIsFloat32(he, "half_extents") : isFloat32(dtype);
             if (f32) return make<Box, float>(gq::BoxGeometry<float>(vec3<float>(he, "half_extents")), "Box");
             return make<Box, double>(gq::BoxGeometry<double>(vec3<double>(he, "half_extents")), "Box");
           }),
           py::arg("half_extents"), py::arg("dtype") = py::none())
      .def_property_readonly("half_extents", [](const Box& g) {
        return g.f32 ? alt<gq::BoxGeometry<float>, float>(g).halfExtents.cast<double>().eval()
                     : alt<gq::BoxGeometry<double>, double>(g).halfExtents;
      });

  py::class_<Plane, GeometryObject>(m, "Plane", "The plane x = 0 of its pose, normal +X; solid half-space x <= 0.")
      .def(py::init([](const py::object& dtype) {
             return byDtype<Plane>(dtype, [&](auto t) {
               using T = decltype(t);
               return make<Plane, T>(gq::PlaneGeometry<T>(), "Plane");
             });
           }),
           py::arg("dtype") = py::none());

  py::class_<ConvexMesh, GeometryObject>(m, "ConvexMesh", "The convex hull of points (N, 3); dtype from the array.")
      .def(py::init([](const py::object& pts, const py::object& scale) {
             const auto cook = [&](auto t) {
               using T = decltype(t);
               std::shared_ptr<const gq::ConvexMesh<T>> hull;
               check(gq::cookConvexMesh(points<T>(pts, "points"), hull), "ConvexMesh");
               return make<ConvexMesh, T>(gq::ConvexMeshGeometry<T>(hull, meshScale<T>(scale)), "ConvexMesh");
             };
             return arrayIsFloat32(pts, "points") ? cook(float{}) : cook(double{});
           }),
           py::arg("points"), py::arg("scale") = py::none())
      .def_property_readonly("vertices", [](const ConvexMesh& g) {
        const auto out = [](const auto& mesh) {
          using T = typename std::decay_t<decltype(mesh.vertices[0])>::Scalar;
          auto a = newArray<T>({py::ssize_t(mesh.vertices.size()), 3});
          for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
            for (int k = 0; k < 3; ++k) a.mutable_at(py::ssize_t(i), k) = mesh.vertices[i][k];
          return py::object(a);
        };
        return g.f32 ? out(*alt<gq::ConvexMeshGeometry<float>, float>(g).mesh)
                     : out(*alt<gq::ConvexMeshGeometry<double>, double>(g).mesh);
      })
      .def_property_readonly("polygon_count", [](const ConvexMesh& g) {
        return g.f32 ? alt<gq::ConvexMeshGeometry<float>, float>(g).mesh->polygons.size()
                     : alt<gq::ConvexMeshGeometry<double>, double>(g).mesh->polygons.size();
      });

  py::class_<TriangleMesh, GeometryObject>(
      m, "TriangleMesh", "A cooked triangle mesh from vertices (N, 3) and faces (M, 3); dtype from the vertices.")
      .def(py::init([](const py::object& verts, const py::object& tris, const py::object& scale, bool doubleSided) {
             const auto cook = [&](auto t) {
               using T = decltype(t);
               std::shared_ptr<const gq::TriangleMesh<T>> mesh;
               gq::MeshCookReport report;
               check(gq::cookTriangleMesh(points<T>(verts, "vertices"), faces(tris), mesh, &report), "TriangleMesh");
               auto obj = make<TriangleMesh, T>(
                   gq::TriangleMeshGeometry<T>(mesh, meshScale<T>(scale),
                                               doubleSided ? gq::MeshGeometryFlag::DoubleSided : gq::MeshGeometryFlag::None),
                   "TriangleMesh");
               obj.hasCookReport = true;
               obj.cookReport = report;
               return obj;
             };
             return arrayIsFloat32(verts, "vertices") ? cook(float{}) : cook(double{});
           }),
           py::arg("vertices"), py::arg("faces"), py::arg("scale") = py::none(), py::arg("double_sided") = false)
      .def_property_readonly("cook_report", [](const TriangleMesh& g) { return cookReport(g); },
                             "input_triangles, removed_degenerate, cooked_triangles, bvh_bytes")
      .def_property_readonly("triangle_count", [](const TriangleMesh& g) {
        return g.f32 ? alt<gq::TriangleMeshGeometry<float>, float>(g).mesh->inputTriangleCount()
                     : alt<gq::TriangleMeshGeometry<double>, double>(g).mesh->inputTriangleCount();
      });

  py::class_<HeightField, GeometryObject>(
      m, "HeightField",
      "Samples heights[r, c] at local (r * row_scale, h * height_scale, c * column_scale); normals face +Y.")
      .def(py::init([](const py::object& heights, const py::object& holes, double hs, double rs, double cs,
                       bool doubleSided) {
             const auto cook = [&](auto t) {
               using T = decltype(t);
               const auto h = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(heights);
               if (!h || h.ndim() != 2) {
                 PyErr_Clear();
                 throw py::value_error("heights: expected a 2-D array (rows, columns)");
               }
               gq::HeightFieldDesc<T> desc;
               desc.rows = std::uint32_t(h.shape(0));
               desc.columns = std::uint32_t(h.shape(1));
               desc.heights.assign(h.data(), h.data() + h.size());
               if (!holes.is_none()) {
                 const auto ho = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(holes);
                 if (!ho || ho.ndim() != 1) {
                   PyErr_Clear();
                   throw py::value_error("holes: expected a 1-D array of cell indices");
                 }
                 for (py::ssize_t i = 0; i < ho.size(); ++i) {
                   if (ho.at(i) < 0) throw py::value_error("holes: negative cell index");
                   desc.holes.push_back(std::uint32_t(ho.at(i)));
                 }
               }
               std::shared_ptr<const gq::HeightField<T>> hf;
               check(gq::cookHeightField(desc, hf), "HeightField");
               return make<HeightField, T>(
                   gq::HeightFieldGeometry<T>(hf, T(hs), T(rs), T(cs),
                                              doubleSided ? gq::MeshGeometryFlag::DoubleSided : gq::MeshGeometryFlag::None),
                   "HeightField");
             };
             return arrayIsFloat32(heights, "heights") ? cook(float{}) : cook(double{});
           }),
           py::arg("heights"), py::arg("holes") = py::none(), py::arg("height_scale") = 1.0,
           py::arg("row_scale") = 1.0, py::arg("column_scale") = 1.0, py::arg("double_sided") = false);

  py::class_<Cylinder, GeometryObject>(m, "Cylinder", "Cylinder along local X: |x| <= half_height, y^2 + z^2 <= r^2.")
      .def(py::init([](double r, double hh, const py::object& dtype) {
             return byDtype<Cylinder>(dtype, [&](auto t) {
               using T = decltype(t);
               gq::CustomGeometry<T> c;
               check(gq::makeCylinder(T(r), T(hh), c), "Cylinder");
               return make<Cylinder, T>(c, "Cylinder");
             });
           }),
           py::arg("radius"), py::arg("half_height"), py::arg("dtype") = py::none());

  py::class_<Cone, GeometryObject>(m, "Cone", "Cone along local X: base disk at x = -half_height, apex at +half_height.")
      .def(py::init([](double r, double hh, const py::object& dtype) {
             return byDtype<Cone>(dtype, [&](auto t) {
               using T = decltype(t);
               gq::CustomGeometry<T> c;
               check(gq::makeCone(T(r), T(hh), c), "Cone");
               return make<Cone, T>(c, "Cone");
             });
           }),
           py::arg("radius"), py::arg("half_height"), py::arg("dtype") = py::none());

  py::class_<Ellipsoid, GeometryObject>(m, "Ellipsoid", "x^2/a^2 + y^2/b^2 + z^2/c^2 <= 1 for radii (a, b, c).")
      .def(py::init([](const py::object& radii, const py::object& dtype) {
             return byDtype<Ellipsoid>(dtype, [&](auto t) {
               using T = decltype(t);
               gq::CustomGeometry<T> c;
               check(gq::makeEllipsoid(vec3<T>(radii, "radii"), c), "Ellipsoid");
               return make<Ellipsoid, T>(c, "Ellipsoid");
             });
           }),
           py::arg("radii"), py::arg("dtype") = py::none());

  py::class_<CustomShape, GeometryObject>(
      m, "CustomShape",
      "A shape from Python callables: support(direction) -> point, optional raycast(origin, direction, max_distance)"
      " -> None or (distance, normal), local bounds (min, max). Convex shapes take part in every query.")
      .def(py::init([](const py::object& support, const py::object& bounds, const py::object& raycast, bool convex,
                       const py::object& dtype) {
             if (!PyCallable_Check(support.ptr())) throw py::type_error("support: expected a callable");
             if (!raycast.is_none() && !PyCallable_Check(raycast.ptr()))
               throw py::type_error("raycast: expected a callable or None");
             const py::tuple b = py::reinterpret_borrow<py::object>(bounds).cast<py::tuple>();
             if (b.size() != 2) throw py::value_error("bounds: expected (min, max)");
             auto errors = std::make_shared<CallbackErrors>();
             const auto build = [&](auto t) {
               using T = decltype(t);
               const gq::Bounds3<T> lb = gq::Bounds3<T>::fromMinMax(vec3<T>(b[0], "bounds min"), vec3<T>(b[1], "bounds max"));
               if (!gq::isFinite(lb.min) || !gq::isFinite(lb.max) || lb.isEmpty())
                 throw py::value_error("bounds: expected finite (min, max) with min <= max");
               auto cb = std::make_shared<PythonCallbacks<T>>(support, raycast, lb, convex, errors);
               auto obj = make<CustomShape, T>(gq::CustomGeometry<T>(cb), "CustomShape");
               obj.callbackErrors = errors;
               return obj;
             };
             return isFloat32(dtype) ? build(float{}) : build(double{});
           }),
           py::arg("support"), py::arg("bounds"), py::arg("raycast") = py::none(), py::arg("convex") = true,
           py::arg("dtype") = py::none());
}

}  // namespace gqpy
