// Scenes (gq/scene.h): many geometry instances in a dynamic AABB tree, queried at once; float32 or float64 per scene.
#include <pybind11/stl.h>

#include <limits>
#include <memory>
#include <vector>

#include "batch_util.h"
#include "common.h"
#include "gq/scene.h"
#include "results.h"

namespace gqpy {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

class PyScene {
 public:
  explicit PyScene(bool f32) : f32_(f32) {}

  bool f32() const { return f32_; }
  template <class T> gq::Scene<T>& get() {
    if constexpr (std::is_same_v<T, float>) return f_; else return d_;
  }
  template <class Fn> auto with(Fn&& fn) { return f32_ ? fn(f_) : fn(d_); }
  void requireDtype(const GeometryObject& g, const char* what) const {
    if (g.f32 != f32_)
      throw py::type_error(std::string(what) + ": a " + g.dtypeName() + " geometry in a " +
                           (f32_ ? "float32" : "float64") + " scene");
  }

 private:
  bool f32_;
  gq::Scene<double> d_;
  gq::Scene<float> f_;
};

template <class T> using SceneT = gq::Scene<T>;
template <class S> using ScalarOf = typename std::decay_t<S>::Scalar;

gq::SceneFilter maskFilter(std::uint32_t mask) {
  gq::SceneFilter f;
  f.mask = mask;
  return f;
}

template <class T> struct SceneTag;
template <class T> struct SceneTag<gq::Scene<T>> { using type = T; };
template <class S> using ST = typename SceneTag<std::decay_t<S>>::type;

}  // namespace

void bindScene(py::module_& m) {
  py::class_<PyScene>(m, "Scene",
                      "Geometry instances (id, pose, mask) in a dynamic AABB tree; queries answer what looping over"
                      " every instance would, ties to the smaller id.")
      .def(py::init([](const py::object& dtype) { return std::make_unique<PyScene>(isFloat32(dtype)); }),
           py::arg("dtype") = py::none())
      .def_property_readonly("dtype", [](const PyScene& s) { return s.f32() ? py::dtype::of<float>() : py::dtype::of<double>(); })
      .def("add",
           [](PyScene& s, std::uint64_t id, const GeometryObject& g, const py::handle& p, std::uint32_t mask) {
             s.requireDtype(g, "Scene.add");
             s.with([&](auto& sc) {
               using T = ST<decltype(sc)>;
               check(sc.add(id, g.shape<T>(), pose<T>(p, "pose"), mask), "Scene.add");
               return 0;
             });
           },
           py::arg("id"), py::arg("geometry"), py::arg("pose") = py::none(), py::arg("mask") = 0xffffffffu)
      .def("remove", [](PyScene& s, std::uint64_t id) { s.with([&](auto& sc) { check(sc.remove(id), "Scene.remove"); return 0; }); })
      .def("set_pose",
           [](PyScene& s, std::uint64_t id, const py::handle& p) {
             s.with([&](auto& sc) {
               using T = ST<decltype(sc)>;
               check(sc.setPose(id, pose<T>(p, "pose")), "Scene.set_pose");
               return 0;
             });
           },
           py::arg("id"), py::arg("pose"))
      .def("set_mask", [](PyScene& s, std::uint64_t id, std::uint32_t mask) {
        s.with([&](auto& sc) { check(sc.setMask(id, mask), "Scene.set_mask"); return 0; });
      })
      .def("rebuild", [](PyScene& s) { s.with([](auto& sc) { sc.rebuild(); return 0; }); })
      .def("clear", [](PyScene& s) { s.with([](auto& sc) { sc.clear(); return 0; }); })
      .def("__len__", [](PyScene& s) { return s.with([](auto& sc) { return sc.size(); }); })
      .def("__contains__", [](PyScene& s, std::uint64_t id) { return s.with([&](auto& sc) { return sc.contains(id); }); })
      .def("ids", [](PyScene& s) {
        std::vector<std::uint64_t> ids;
        s.with([&](auto& sc) { check(sc.ids(ids), "Scene.ids"); return 0; });
        return ids;
      })
      .def("pose", [](PyScene& s, std::uint64_t id) {
        return s.with([&](auto& sc) {
          using T = ST<decltype(sc)>;
          gq::Transform<T> t;
          check(sc.pose(id, t), "Scene.pose");
          return Pose(t.template cast<double>());
        });
      })
      .def("bounds", [](PyScene& s, std::uint64_t id) {
        return s.with([&](auto& sc) {
          using T = ST<decltype(sc)>;
          gq::Bounds3<T> b;
          check(sc.bounds(id, b), "Scene.bounds");
          return py::make_tuple(gq::Vec3<double>(b.min.template cast<double>()), gq::Vec3<double>(b.max.template cast<double>()));
        });
      })
      .def("raycast",
           [](PyScene& s, const py::handle& origin, const py::handle& dir, double maxDistance, bool any,
              std::uint32_t mask) -> py::object {
             return s.with([&](auto& sc) -> py::object {
               using T = ST<decltype(sc)>;
               gq::SceneRaycastHit<T> hit;
               bool has = false;
               const auto o = vec3<T>(origin, "origin");
               const auto d = vec3<T>(dir, "direction");
               if (any) check(sc.raycastAny(o, d, T(maxDistance), hit, has, gq::kDefaultHitFlags, maskFilter(mask)), "Scene.raycast");
               else check(sc.raycastClosest(o, d, T(maxDistance), hit, has, gq::kDefaultHitFlags, maskFilter(mask)), "Scene.raycast");
               if (!has) return py::none();
               return py::make_tuple(hit.id, PyRaycastHit::from(hit.hit));
             });
           },
           py::arg("origin"), py::arg("direction"), py::arg("max_distance") = kInf, py::arg("any_hit") = false,
           py::arg("mask") = 0xffffffffu, "(id, RaycastHit) of the closest hit (any_hit: some hit), or None.")
      .def("raycast_all",
           [](PyScene& s, const py::handle& origin, const py::handle& dir, double maxDistance, std::uint32_t maxHits,
              std::uint32_t mask) {
             if (maxHits == 0) throw py::value_error("Scene.raycast_all: max_hits must be >= 1");
             return s.with([&](auto& sc) {
               using T = ST<decltype(sc)>;
               std::vector<gq::SceneRaycastHit<T>> hits(maxHits);
               std::uint32_t count = 0;
               check(sc.raycastAll(vec3<T>(origin, "origin"), vec3<T>(dir, "direction"), T(maxDistance),
                                   gq::kDefaultHitFlags | gq::HitFlag::MeshMultiple, maxHits, hits.data(), count,
                                   maskFilter(mask)),
                     "Scene.raycast_all");
               py::list out;
               for (std::uint32_t i = 0; i < count; ++i) out.append(py::make_tuple(hits[i].id, PyRaycastHit::from(hits[i].hit)));
               return out;
             });
           },
           py::arg("origin"), py::arg("direction"), py::arg("max_distance") = kInf, py::arg("max_hits") = 16,
           py::arg("mask") = 0xffffffffu, "[(id, RaycastHit)] sorted by distance then id.")
      .def("sweep",
           [](PyScene& s, const py::handle& dir, double maxDistance, const GeometryObject& g, const py::handle& p,
              double inflation, std::uint32_t mask) -> py::object {
             s.requireDtype(g, "Scene.sweep");
             return s.with([&](auto& sc) -> py::object {
               using T = ST<decltype(sc)>;
               gq::SceneSweepHit<T> hit;
               bool has = false;
               check(sc.sweepClosest(vec3<T>(dir, "direction"), T(maxDistance), g.shape<T>(), pose<T>(p, "pose"), hit,
                                     has, gq::kDefaultHitFlags, T(inflation), maskFilter(mask)),
                     "Scene.sweep");
               if (!has) return py::none();
               return py::make_tuple(hit.id, PySweepHit::from(hit.hit));
             });
           },
           py::arg("direction"), py::arg("max_distance"), py::arg("geometry"), py::arg("pose") = py::none(),
           py::arg("inflation") = 0.0, py::arg("mask") = 0xffffffffu, "(id, SweepHit) of the first instance hit, or None.")
      .def("overlap",
           [](PyScene& s, const GeometryObject& g, const py::handle& p, std::uint32_t mask) {
             s.requireDtype(g, "Scene.overlap");
             std::vector<std::uint64_t> ids;
             s.with([&](auto& sc) {
               using T = ST<decltype(sc)>;
               check(sc.overlapAll(g.shape<T>(), pose<T>(p, "pose"), ids, maskFilter(mask)), "Scene.overlap");
               return 0;
             });
             return ids;
           },
           py::arg("geometry"), py::arg("pose") = py::none(), py::arg("mask") = 0xffffffffu,
           "Ids (ascending) of the instances the geometry overlaps.")
      .def("nearest",
           [](PyScene& s, const GeometryObject& g, const py::handle& p, double maxDistance, std::uint32_t mask) -> py::object {
             s.requireDtype(g, "Scene.nearest");
             return s.with([&](auto& sc) -> py::object {
               using T = ST<decltype(sc)>;
               gq::SceneDistanceResult<T> r;
               bool found = false;
               check(sc.nearest(g.shape<T>(), pose<T>(p, "pose"), T(maxDistance), r, found, maskFilter(mask)), "Scene.nearest");
               if (!found) return py::none();
               return py::make_tuple(r.id, PyDistance::from(r.result));
             });
           },
           py::arg("geometry"), py::arg("pose") = py::none(), py::arg("max_distance") = kInf,
           py::arg("mask") = 0xffffffffu, "(id, DistanceResult) of the nearest instance within max_distance, or None.")
      .def("overlapping_pairs",
           [](PyScene& s, PyScene* other) {
             std::vector<gq::ScenePair> pairs;
             if (other && other->f32() != s.f32()) throw py::type_error("Scene.overlapping_pairs: scenes of different dtypes");
             s.with([&](auto& sc) {
               using T = ST<decltype(sc)>;
               if (other) check(sc.overlappingPairs(other->get<T>(), pairs), "Scene.overlapping_pairs");
               else check(sc.overlappingPairs(pairs), "Scene.overlapping_pairs");
               return 0;
             });
             auto out = newArray<std::uint64_t>({py::ssize_t(pairs.size()), 2});
             for (std::size_t i = 0; i < pairs.size(); ++i) {
               out.mutable_at(py::ssize_t(i), 0) = pairs[i].id0;
               out.mutable_at(py::ssize_t(i), 1) = pairs[i].id1;
             }
             return out;
           },
           py::arg("other") = nullptr, "(K, 2) uint64 ids of overlapping instance pairs, sorted.")
      .def("raycast_batch",
           [](PyScene& s, const py::handle& origins, const py::handle& dirs, double maxDistance, std::uint32_t mask,
              std::uint32_t threads, bool normalize) {
             return s.with([&](auto& sc) {
               using T = ST<decltype(sc)>;
               const RayRows<T> r =
                   rayRows<T>(origins, dirs, maxDistance, gq::kDefaultHitFlags, normalize, "Scene.raycast_batch");
               const gq::RayBatch<T>& rays = r.batch;
               const std::size_t n = r.count;
               std::vector<gq::SceneRaycastHit<T>> hits(n);
               std::vector<std::uint8_t> has(n, 0);
               const gq::SceneFilter filter = maskFilter(mask);
               runBatch([&](gq::Status* st) {
                 return gq::raycastBatch(rays, sc, hits.data(), has.data(), st, batchSettings(threads), filter);
               }, n, "Scene.raycast_batch");
               auto hit = newArray<bool>({py::ssize_t(n)});
               auto ids = newArray<std::int64_t>({py::ssize_t(n)});
               auto dist = newArray<T>({py::ssize_t(n)});
               auto pos = newArray<T>({py::ssize_t(n), 3});
               auto nrm = newArray<T>({py::ssize_t(n), 3});
               auto face = newArray<std::int64_t>({py::ssize_t(n)});
               for (std::size_t i = 0; i < n; ++i) {
                 const bool h = has[i] != 0;
                 hit.mutable_data()[i] = h;
                 ids.mutable_data()[i] = h ? std::int64_t(hits[i].id) : -1;
                 dist.mutable_data()[i] = h ? hits[i].hit.distance : std::numeric_limits<T>::infinity();
                 face.mutable_data()[i] = h ? faceIndex(hits[i].hit.faceIndex) : -1;
                 for (int k = 0; k < 3; ++k) {
                   pos.mutable_data()[3 * i + k] = h ? hits[i].hit.position[k] : T(0);
                   nrm.mutable_data()[3 * i + k] = h ? hits[i].hit.normal[k] : T(0);
                 }
               }
               return py::make_tuple(hit, ids, dist, pos, nrm, face);
             });
           },
           py::arg("origins"), py::arg("directions"), py::arg("max_distance") = kInf, py::arg("mask") = 0xffffffffu,
           py::arg("threads") = 0, py::arg("normalize") = false,
           "Closest hit of each ray: (hit, id (-1: none), distance, position, normal, face_index). normalize: the"
           " directions may have any non-zero length.")
      .def("raycast_all_batch",
           [](PyScene& s, const py::handle& origins, const py::handle& dirs, double maxDistance, std::uint32_t maxHits,
              bool bothSides, std::uint32_t mask, std::uint32_t threads, bool normalize) {
             if (maxHits == 0) throw py::value_error("Scene.raycast_all_batch: max_hits must be >= 1");
             return s.with([&](auto& sc) {
               using T = ST<decltype(sc)>;
               gq::HitFlags flags = gq::kDefaultHitFlags | gq::HitFlag::MeshMultiple;
               if (bothSides) flags |= gq::HitFlag::MeshBothSides;
               const RayRows<T> r =
                   rayRows<T>(origins, dirs, maxDistance, flags, normalize, "Scene.raycast_all_batch");
               const gq::RayBatch<T>& rays = r.batch;
               const std::size_t n = r.count;
               const gq::SceneFilter filter = maskFilter(mask);
               std::vector<std::uint32_t> counts(n, 0);
               gq::SceneHitsOutput<T> out;
               out.counts = counts.data();
               runBatch([&](gq::Status* st) {
                 return gq::raycastAllBatch(rays, sc, maxHits, out, st, batchSettings(threads), filter);
               }, n, "Scene.raycast_all_batch");
               std::vector<std::uint64_t> offsets(n, 0);
               std::uint64_t total = 0;
               for (std::size_t i = 0; i < n; ++i) { offsets[i] = total; total += counts[i]; }
               std::vector<gq::SceneRaycastHit<T>> hits(total);
               out.offsets = offsets.data();
               out.hits = hits.data();
               runBatch([&](gq::Status* st) {
                 return gq::raycastAllBatch(rays, sc, maxHits, out, st, batchSettings(threads), filter);
               }, n, "Scene.raycast_all_batch");
               auto ray = newArray<std::int64_t>({py::ssize_t(total)});
               auto ids = newArray<std::int64_t>({py::ssize_t(total)});
               auto dist = newArray<T>({py::ssize_t(total)});
               auto pos = newArray<T>({py::ssize_t(total), 3});
               auto face = newArray<std::int64_t>({py::ssize_t(total)});
               for (std::size_t i = 0; i < n; ++i)
                 for (std::uint32_t k = 0; k < counts[i]; ++k) {
                   const std::size_t j = std::size_t(offsets[i]) + k;
                   ray.mutable_data()[j] = std::int64_t(i);
                   ids.mutable_data()[j] = std::int64_t(hits[j].id);
                   dist.mutable_data()[j] = hits[j].hit.distance;
                   face.mutable_data()[j] = faceIndex(hits[j].hit.faceIndex);
                   for (int c = 0; c < 3; ++c) pos.mutable_data()[3 * j + c] = hits[j].hit.position[c];
                 }
               return py::make_tuple(ray, ids, dist, pos, face);
             });
           },
           py::arg("origins"), py::arg("directions"), py::arg("max_distance") = kInf, py::arg("max_hits") = 16,
           py::arg("both_sides") = false, py::arg("mask") = 0xffffffffu, py::arg("threads") = 0,
           py::arg("normalize") = false,
           "Up to max_hits hits of each ray, sorted per ray: (ray_index, id, distance, position, face_index), flat."
           " normalize: the directions may have any non-zero length.");
}

}  // namespace gqpy
