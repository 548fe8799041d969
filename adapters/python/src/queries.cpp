// Single queries: raycast, sweep, overlap, penetration, distance, point distance, bounds, the mesh and heightfield
// queries and triangle contacts. The scalar type is the geometries' (mixing float32 and float64 is a TypeError).
#include <pybind11/stl.h>

#include <limits>
#include <vector>

#include "common.h"
#include "custom_callbacks.h"
#include "gq/contacts.h"
#include "gq/mesh_query.h"
#include "results.h"

namespace gqpy {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <class Fn> auto byGeometry(const GeometryObject& g, Fn&& fn) {
  return g.f32 ? fn(float{}) : fn(double{});
}

gq::HitFlags rayFlags(bool bothSides, bool anyHit, bool multiple) {
  gq::HitFlags f = gq::kDefaultHitFlags | gq::HitFlag::UV;
  if (bothSides) f |= gq::HitFlag::MeshBothSides;
  if (anyHit) f |= gq::HitFlag::AnyHit;
  if (multiple) f |= gq::HitFlag::MeshMultiple;
  return f;
}

struct PyContact {
  gq::Vec3<double> position, normal;
  double separation = 0;
  std::int64_t triangleIndex = -1;
};

struct PyMeshContact {
  gq::Vec3<double> position, normal;
  double depth = 0;
  std::int64_t triangle0 = -1, triangle1 = -1;
};

// The triangles (K, 3, 3) of an array in the scalar type T.
template <class T> std::vector<gq::Triangle<T>> triangles(const py::handle& obj) {
  const auto arr = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!arr || arr.ndim() != 3 || arr.shape(1) != 3 || arr.shape(2) != 3) {
    PyErr_Clear();
    throw py::value_error("triangles: expected an array of shape (K, 3, 3)");
  }
  std::vector<gq::Triangle<T>> out(std::size_t(arr.shape(0)));
  const T* v = arr.data();
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int k = 0; k < 3; ++k) out[i].verts[k] = gq::Vec3<T>(v[9 * i + 3 * k], v[9 * i + 3 * k + 1], v[9 * i + 3 * k + 2]);
  return out;
}

template <class T> py::array_t<T> triangleArray(const gq::Triangle<T>& t) {
  auto a = newArray<T>({3, 3});
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) a.mutable_at(k, j) = t.verts[k][j];
  return a;
}


PyObject* gSlowOverlap = nullptr;
PyTypeObject* gGeometryType = nullptr;
PyTypeObject* gPoseType = nullptr;

// The C++ object of a pybind11 instance of a simple layout (one registered type in its hierarchy), or null.
template <class C> const C* directValue(PyObject* o, PyTypeObject* type) {
  if (!PyObject_TypeCheck(o, type)) return nullptr;
  auto* inst = reinterpret_cast<py::detail::instance*>(o);
  if (!inst->simple_layout) return nullptr;
  return static_cast<const C*>(inst->simple_value_holder[0]);
}

template <class T> bool directPose(PyObject* o, gq::Transform<T>& out) {
  if (o == Py_None) {
    out = gq::Transform<T>();
    return true;
  }
  const Pose* p = directValue<Pose>(o, gPoseType);
  if (!p) return false;
  out = p->get<T>();
  return true;
}

template <class T> bool directOverlap(const GeometryObject& g0, PyObject* p0, const GeometryObject& g1, PyObject* p1,
                                      bool& out) {
  gq::Transform<T> t0, t1;
  if (!directPose(p0, t0) || !directPose(p1, t1)) return false;
  return gq::overlap(g0.shape<T>(), t0, g1.shape<T>(), t1, out).ok();
}

PyObject* fastOverlap(PyObject*, PyObject* const* args, Py_ssize_t nargsf, PyObject* kwnames) {
  const Py_ssize_t nargs = PyVectorcall_NARGS(nargsf);
  if (kwnames == nullptr && nargs == 4) {
    const GeometryObject* g0 = directValue<GeometryObject>(args[0], gGeometryType);
    const GeometryObject* g1 = directValue<GeometryObject>(args[2], gGeometryType);
    if (g0 && g1 && g0->f32 == g1->f32 && !g0->callbackErrors && !g1->callbackErrors) {
      bool out = false;
      const bool done = g0->f32 ? directOverlap<float>(*g0, args[1], *g1, args[3], out)
                                : directOverlap<double>(*g0, args[1], *g1, args[3], out);
      if (done) return PyBool_FromLong(out);
    }
  }
  return PyObject_Vectorcall(gSlowOverlap, args, nargsf, kwnames);
}

}  // namespace

void bindQueries(py::module_& m) {
  py::class_<PyRaycastHit>(m, "RaycastHit")
      .def_readonly("distance", &PyRaycastHit::distance)
      .def_readonly("position", &PyRaycastHit::position)
      .def_readonly("normal", &PyRaycastHit::normal)
      .def_readonly("face_index", &PyRaycastHit::faceIndex, "triangle (mesh), polygon (convex) or -1")
      .def_readonly("u", &PyRaycastHit::u)
      .def_readonly("v", &PyRaycastHit::v)
      .def("__repr__", [](const PyRaycastHit& h) {
        return "RaycastHit(distance=" + std::to_string(h.distance) + ", face_index=" + std::to_string(h.faceIndex) + ")";
      });
  py::class_<PySweepHit>(m, "SweepHit")
      .def_readonly("distance", &PySweepHit::distance)
      .def_readonly("position", &PySweepHit::position)
      .def_readonly("normal", &PySweepHit::normal)
      .def_readonly("face_index", &PySweepHit::faceIndex)
      .def_readonly("initial_overlap", &PySweepHit::initialOverlap);
  py::class_<PyPenetration>(m, "Penetration",
                            "direction * depth translates geometry0 out of geometry1 (direction from 1 towards 0).")
      .def_readonly("penetrating", &PyPenetration::penetrating)
      .def_readonly("direction", &PyPenetration::direction)
      .def_readonly("depth", &PyPenetration::depth)
      .def_readonly("iterations", &PyPenetration::iterations)
      .def("__bool__", [](const PyPenetration& p) { return p.penetrating; });
  py::class_<PyDistance>(m, "DistanceResult",
                         "Signed distance (< 0: minus the penetration depth), witnesses and the unit normal 0 -> 1.")
      .def_readonly("distance", &PyDistance::distance)
      .def_readonly("point0", &PyDistance::point0)
      .def_readonly("point1", &PyDistance::point1)
      .def_readonly("normal", &PyDistance::normal)
      .def("__repr__", [](const PyDistance& d) { return "DistanceResult(distance=" + std::to_string(d.distance) + ")"; });
  py::class_<PyContact>(m, "TriangleContact")
      .def_readonly("position", &PyContact::position)
      .def_readonly("normal", &PyContact::normal)
      .def_readonly("separation", &PyContact::separation)
      .def_readonly("triangle_index", &PyContact::triangleIndex);
  py::class_<PyMeshContact>(m, "MeshContact",
                            "One crossing triangle pair: depth >= 0 along the unit normal from surface 1 to surface 0.")
      .def_readonly("position", &PyMeshContact::position)
      .def_readonly("normal", &PyMeshContact::normal)
      .def_readonly("depth", &PyMeshContact::depth)
      .def_readonly("triangle0", &PyMeshContact::triangle0)
      .def_readonly("triangle1", &PyMeshContact::triangle1);

  m.def("_overlap",
        [](const GeometryObject& g0, const py::handle& p0, const GeometryObject& g1, const py::handle& p1) {
          requireSameDtype(g0, g1, "overlap");
          bool out = false;
          if (g0.f32) check(gq::overlap(g0.f, pose<float>(p0, "pose0"), g1.f, pose<float>(p1, "pose1"), out), "overlap");
          else check(gq::overlap(g0.d, pose<double>(p0, "pose0"), g1.d, pose<double>(p1, "pose1"), out), "overlap");
          rethrowCallbackError(g0);
          rethrowCallbackError(g1);
          return out;
        },
        py::arg("geometry0"), py::arg("pose0"), py::arg("geometry1"), py::arg("pose1"),
        "Whether the two geometries overlap (touching counts).");

  // overlap() is the call hosts make millions of times: a METH_FASTCALL function that reads the geometry and pose
  // objects directly (pybind11's argument dispatch costs more than the query) for the positional form; keywords,
  // other argument types and every failure go through _overlap above, which converts and raises.
  gSlowOverlap = m.attr("_overlap").ptr();
  gGeometryType = reinterpret_cast<PyTypeObject*>(py::type::of<GeometryObject>().ptr());
  gPoseType = reinterpret_cast<PyTypeObject*>(py::type::of<Pose>().ptr());
  static PyMethodDef overlapDef = {"overlap", reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&fastOverlap)),
                                   METH_FASTCALL | METH_KEYWORDS,
                                   "overlap(geometry0, pose0, geometry1, pose1) -> bool: whether the two geometries "
                                   "overlap (touching counts)."};
  m.add_object("overlap", py::reinterpret_steal<py::object>(PyCFunction_NewEx(&overlapDef, nullptr, m.attr("__name__").ptr())));

  m.def("penetration",
        [](const GeometryObject& g0, const py::handle& p0, const GeometryObject& g1, const py::handle& p1) {
          requireSameDtype(g0, g1, "penetration");
          const PyPenetration r = byGeometry(g0, [&](auto t) {
            using T = decltype(t);
            gq::PenetrationResult<T> res;
            check(gq::computePenetration(res, g0.shape<T>(), pose<T>(p0, "pose0"), g1.shape<T>(), pose<T>(p1, "pose1")),
                  "penetration");
            return PyPenetration::from(res);
          });
          rethrowCallbackError(g0);
          rethrowCallbackError(g1);
          return r;
        },
        py::arg("geometry0"), py::arg("pose0"), py::arg("geometry1"), py::arg("pose1"),
        "Minimum translational distance of a convex pair.");

  m.def("distance",
        [](const GeometryObject& g0, const py::handle& p0, const GeometryObject& g1, const py::handle& p1) {
          requireSameDtype(g0, g1, "distance");
          const PyDistance r = byGeometry(g0, [&](auto t) {
            using T = decltype(t);
            gq::DistanceResult<T> res;
            check(gq::distance(res, g0.shape<T>(), pose<T>(p0, "pose0"), g1.shape<T>(), pose<T>(p1, "pose1")),
                  "distance");
            return PyDistance::from(res);
          });
          rethrowCallbackError(g0);
          rethrowCallbackError(g1);
          return r;
        },
        py::arg("geometry0"), py::arg("pose0"), py::arg("geometry1"), py::arg("pose1"),
        "Signed separation distance with witness points and the normal from geometry0 towards geometry1.");

  m.def("raycast",
        [](const py::handle& origin, const py::handle& direction, const GeometryObject& g, const py::handle& p,
           double maxDistance, std::uint32_t maxHits, bool bothSides, bool anyHit) -> py::object {
          if (maxHits == 0) throw py::value_error("raycast: max_hits must be >= 1");
          const std::vector<PyRaycastHit> hits = byGeometry(g, [&](auto t) {
            using T = decltype(t);
            std::vector<gq::RaycastHit<T>> buf(maxHits);
            std::uint32_t count = 0;
            check(gq::raycast(vec3<T>(origin, "origin"), vec3<T>(direction, "direction"), g.shape<T>(),
                              pose<T>(p, "pose"), T(maxDistance), rayFlags(bothSides, anyHit, maxHits > 1), maxHits,
                              buf.data(), count),
                  "raycast");
            std::vector<PyRaycastHit> out;
            for (std::uint32_t i = 0; i < count; ++i) out.push_back(PyRaycastHit::from(buf[i]));
            return out;
          });
          rethrowCallbackError(g);
          if (maxHits > 1) return py::cast(hits);
          return hits.empty() ? py::none() : py::cast(hits[0]);
        },
        py::arg("origin"), py::arg("direction"), py::arg("geometry"), py::arg("pose") = py::none(),
        py::arg("max_distance") = kInf, py::arg("max_hits") = 1, py::arg("both_sides") = false,
        py::arg("any_hit") = false,
        "Raycast along a unit direction: the closest RaycastHit or None (max_hits > 1: a list, meshes report several).");

  m.def("sweep",
        [](const py::handle& direction, double maxDistance, const GeometryObject& g0, const py::handle& p0,
           const GeometryObject& g1, const py::handle& p1, double inflation, bool mtd, bool precise) -> py::object {
          requireSameDtype(g0, g1, "sweep");
          gq::HitFlags flags = gq::kDefaultHitFlags;
          if (mtd) flags |= gq::HitFlag::Mtd;
          if (precise) flags |= gq::HitFlag::PreciseSweep;
          bool has = false;
          const PySweepHit hit = byGeometry(g0, [&](auto t) {
            using T = decltype(t);
            gq::SweepHit<T> h;
            check(gq::sweep(vec3<T>(direction, "direction"), T(maxDistance), g0.shape<T>(), pose<T>(p0, "pose0"),
                            g1.shape<T>(), pose<T>(p1, "pose1"), h, has, flags, T(inflation)),
                  "sweep");
            return PySweepHit::from(h);
          });
          rethrowCallbackError(g0);
          rethrowCallbackError(g1);
          return has ? py::cast(hit) : py::none();
        },
        py::arg("direction"), py::arg("max_distance"), py::arg("geometry0"), py::arg("pose0"), py::arg("geometry1"),
        py::arg("pose1"), py::arg("inflation") = 0.0, py::arg("mtd") = false, py::arg("precise") = false,
        "Sweeps geometry0 along a unit direction against geometry1: a SweepHit or None.");

  m.def("point_distance",
        [](const py::handle& point, const GeometryObject& g, const py::handle& p) {
          return byGeometry(g, [&](auto t) {
            using T = decltype(t);
            gq::PointDistanceResult<T> r;
            check(gq::pointDistance(vec3<T>(point, "point"), g.shape<T>(), pose<T>(p, "pose"), r), "point_distance");
            return py::make_tuple(double(r.distance), gq::Vec3<double>(r.closestPoint.template cast<double>()),
                                  faceIndex(r.closestIndex));
          });
        },
        py::arg("point"), py::arg("geometry"), py::arg("pose") = py::none(),
        "(distance, closest_point, triangle index or -1); distance 0 inside a solid.");

  m.def("bounds",
        [](const GeometryObject& g, const py::handle& p, double offset, const py::object& inflation) {
          return byGeometry(g, [&](auto t) {
            using T = decltype(t);
            gq::Bounds3<T> b;
            const T infl = inflation.is_none() ? T(gq::tol::kDefaultBoundsInflation) : inflation.cast<T>();
            check(gq::computeGeomBounds(b, g.shape<T>(), pose<T>(p, "pose"), T(offset), infl), "bounds");
            return py::make_tuple(gq::Vec3<double>(b.min.template cast<double>()),
                                  gq::Vec3<double>(b.max.template cast<double>()));
          });
        },
        py::arg("geometry"), py::arg("pose") = py::none(), py::arg("offset") = 0.0, py::arg("inflation") = py::none(),
        "World AABB (min, max) of the geometry at the pose.");

  m.def("get_triangle",
        [](const GeometryObject& g, const py::handle& p, std::uint32_t index) {
          return byGeometry(g, [&](auto t) -> py::object {
            using T = decltype(t);
            gq::Triangle<T> tri;
            const auto& geom = g.geometry<T>();
            if (const auto* mesh = geom.template getIf<gq::TriangleMeshGeometry<T>>())
              check(gq::getTriangle(*mesh, pose<T>(p, "pose"), index, tri), "get_triangle");
            else if (const auto* hf = geom.template getIf<gq::HeightFieldGeometry<T>>())
              check(gq::getTriangle(*hf, pose<T>(p, "pose"), index, tri), "get_triangle");
            else
              throw py::type_error("get_triangle: expected a TriangleMesh or a HeightField");
            return triangleArray(tri);
          });
        },
        py::arg("mesh"), py::arg("pose"), py::arg("index"), "World vertices (3, 3) of a triangle.");

  m.def("find_overlapping_triangles",
        [](const GeometryObject& g, const py::handle& p, const GeometryObject& mesh, const py::handle& meshPose) {
          requireSameDtype(g, mesh, "find_overlapping_triangles");
          return byGeometry(g, [&](auto t) {
            using T = decltype(t);
            const auto& geom = mesh.geometry<T>();
            const auto* tm = geom.template getIf<gq::TriangleMeshGeometry<T>>();
            const auto* hf = geom.template getIf<gq::HeightFieldGeometry<T>>();
            if (!tm && !hf) throw py::type_error("find_overlapping_triangles: expected a TriangleMesh or a HeightField");
            const auto gp = pose<T>(p, "pose");
            const auto mp = pose<T>(meshPose, "mesh_pose");
            std::vector<std::uint32_t> all;
            std::vector<std::uint32_t> page(1024);
            for (;;) {
              gq::TriangleOverlapPageResult r;
              const gq::TriangleOverlapPage pg{page.data(), std::uint32_t(page.size()), std::uint32_t(all.size())};
              if (tm) check(gq::findOverlapTriangleMesh(g.geometry<T>(), gp, *tm, mp, pg, r), "find_overlapping_triangles");
              else check(gq::findOverlapHeightField(g.geometry<T>(), gp, *hf, mp, pg, r), "find_overlapping_triangles");
              all.insert(all.end(), page.begin(), page.begin() + r.count);
              if (!r.overflow) break;
            }
            auto a = newArray<std::uint32_t>({py::ssize_t(all.size())});
            std::copy(all.begin(), all.end(), a.mutable_data());
            return a;
          });
        },
        py::arg("geometry"), py::arg("pose"), py::arg("mesh"), py::arg("mesh_pose"),
        "Indices of the mesh's (or heightfield's) triangles a sphere, capsule or box touches.");

  m.def("mesh_triangle_pairs",
        [](const GeometryObject& m0, const py::handle& p0, const GeometryObject& m1, const py::handle& p1,
           double tolerance) {
          requireSameDtype(m0, m1, "mesh_triangle_pairs");
          return byGeometry(m0, [&](auto t) {
            using T = decltype(t);
            const auto* a = m0.geometry<T>().template getIf<gq::TriangleMeshGeometry<T>>();
            const auto* b = m1.geometry<T>().template getIf<gq::TriangleMeshGeometry<T>>();
            if (!a || !b) throw py::type_error("mesh_triangle_pairs: expected two TriangleMesh geometries");
            std::vector<std::uint32_t> pairs;
            bool found = false;
            const auto q0 = pose<T>(p0, "pose0");
            const auto q1 = pose<T>(p1, "pose1");
            check(gq::findOverlapTriangleMeshPairs(
                      [&](std::uint32_t i, std::uint32_t j) {
                        pairs.push_back(i);
                        pairs.push_back(j);
                        return true;
                      },
                      *a, q0, *b, q1, found, T(tolerance)),
                  "mesh_triangle_pairs");
            auto out = newArray<std::uint32_t>({py::ssize_t(pairs.size() / 2), 2});
            std::copy(pairs.begin(), pairs.end(), out.mutable_data());
            return out;
          });
        },
        py::arg("mesh0"), py::arg("pose0"), py::arg("mesh1"), py::arg("pose1"), py::arg("tolerance") = 0.0,
        "(K, 2) pairs of intersecting triangles (tolerance > 0: pairs within that distance).");

  m.def("mesh_contacts",
        [](const GeometryObject& s0, const py::handle& p0, const GeometryObject& s1, const py::handle& p1,
           std::size_t maxContacts) {
          requireSameDtype(s0, s1, "mesh_contacts");
          return byGeometry(s0, [&](auto t) {
            using T = decltype(t);
            std::vector<PyMeshContact> out;
            bool found = false;
            const auto q0 = pose<T>(p0, "pose0");
            const auto q1 = pose<T>(p1, "pose1");
            const gq::MeshContactCallback<T> keep = [&](const gq::MeshContact<T>& c) {
              out.push_back({c.position.template cast<double>(), c.normal.template cast<double>(), double(c.depth),
                             faceIndex(c.triangle0), faceIndex(c.triangle1)});
              return maxContacts == 0 || out.size() < maxContacts;
            };
            gq::Status s;
            {
              py::gil_scoped_release release;  // the callback only appends to `out`
              s = gq::generateMeshContacts(keep, s0.geometry<T>(), q0, s1.geometry<T>(), q1, found);
            }
            check(s, "mesh_contacts");
            return out;
          });
        },
        py::arg("surface0"), py::arg("pose0"), py::arg("surface1"), py::arg("pose1"), py::arg("max_contacts") = 0,
        "Contacts of two triangle meshes or heightfields, one per crossing triangle pair (at most max_contacts; 0: "
        "all), each along the shallower of the pair's two face normals, from surface 1 towards surface 0.");

  m.def("mesh_penetration",
        [](const GeometryObject& g, const py::handle& p, const GeometryObject& mesh, const py::handle& meshPose,
           std::uint32_t maxIterations) {
          requireSameDtype(g, mesh, "mesh_penetration");
          return byGeometry(g, [&](auto t) {
            using T = decltype(t);
            const auto& geom = mesh.geometry<T>();
            const auto* tm = geom.template getIf<gq::TriangleMeshGeometry<T>>();
            const auto* hf = geom.template getIf<gq::HeightFieldGeometry<T>>();
            if (!tm && !hf) throw py::type_error("mesh_penetration: expected a TriangleMesh or a HeightField");
            gq::PenetrationResult<T> r;
            std::uint32_t iterations = 0;
            if (tm)
              check(gq::computeTriangleMeshPenetration(r, g.geometry<T>(), pose<T>(p, "pose"), *tm,
                                                       pose<T>(meshPose, "mesh_pose"), maxIterations, &iterations),
                    "mesh_penetration");
            else
              check(gq::computeHeightFieldPenetration(r, g.geometry<T>(), pose<T>(p, "pose"), *hf,
                                                      pose<T>(meshPose, "mesh_pose"), maxIterations, &iterations),
                    "mesh_penetration");
            PyPenetration out = PyPenetration::from(r);
            out.iterations = iterations;
            return out;
          });
        },
        py::arg("geometry"), py::arg("pose"), py::arg("mesh"), py::arg("mesh_pose"), py::arg("max_iterations") = 4,
        "Iterative penetration of a convex geometry out of a TriangleMesh or HeightField.");

  m.def("sweep_triangles",
        [](const py::handle& direction, double maxDistance, const GeometryObject& g, const py::handle& p,
           const py::handle& tris, double inflation, bool doubleSided, bool anyHit) -> py::object {
          bool has = false;
          const PySweepHit hit = byGeometry(g, [&](auto t) {
            using T = decltype(t);
            const auto list = triangles<T>(tris);
            gq::TriangleSweepSettings<T> s;
            s.inflation = T(inflation);
            s.doubleSided = doubleSided;
            if (anyHit) s.flags |= gq::HitFlag::AnyHit;
            gq::SweepHit<T> h;
            check(gq::sweepTriangles(vec3<T>(direction, "direction"), T(maxDistance), g.geometry<T>(),
                                     pose<T>(p, "pose"), list.data(), std::uint32_t(list.size()), h, has, s),
                  "sweep_triangles");
            return PySweepHit::from(h);
          });
          return has ? py::cast(hit) : py::none();
        },
        py::arg("direction"), py::arg("max_distance"), py::arg("geometry"), py::arg("pose"), py::arg("triangles"),
        py::arg("inflation") = 0.0, py::arg("double_sided") = false, py::arg("any_hit") = false,
        "Sweeps a sphere, capsule or box against world triangles (K, 3, 3); face_index is the array index.");

  m.def("triangle_contacts",
        [](const GeometryObject& g, const py::handle& p, const py::handle& triangle, std::uint32_t index,
           double contactDistance, double meshContactMargin, double toleranceLength) {
          return byGeometry(g, [&](auto t) {
            using T = decltype(t);
            const auto arr = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(triangle);
            if (!arr || arr.ndim() != 2 || arr.shape(0) != 3 || arr.shape(1) != 3) {
              PyErr_Clear();
              throw py::value_error("triangle: expected shape (3, 3)");
            }
            gq::Triangle<T> tri;
            for (int k = 0; k < 3; ++k) tri.verts[k] = gq::Vec3<T>(arr.at(k, 0), arr.at(k, 1), arr.at(k, 2));
            gq::TriangleContactSettings<T> s;
            s.contactDistance = T(contactDistance);
            s.meshContactMargin = T(meshContactMargin);
            s.toleranceLength = T(toleranceLength);
            gq::ContactBuffer<T> buf;
            check(gq::generateTriangleContacts(g.geometry<T>(), pose<T>(p, "pose"), tri, index, buf, s),
                  "triangle_contacts");
            std::vector<PyContact> out;
            for (std::uint32_t i = 0; i < buf.count; ++i) {
              const auto& c = buf.contacts[i];
              out.push_back({c.position.template cast<double>(), c.normal.template cast<double>(), double(c.separation),
                             faceIndex(c.triangleIndex)});
            }
            return out;
          });
        },
        py::arg("geometry"), py::arg("pose"), py::arg("triangle"), py::arg("triangle_index") = 0,
        py::arg("contact_distance") = 0.0, py::arg("mesh_contact_margin") = 0.0, py::arg("tolerance_length") = 1.0,
        "Up to 4 contacts of a capsule, box or convex mesh with one triangle (normal from the triangle to the shape).");
}

}  // namespace gqpy
