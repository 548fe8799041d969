// Batched forms over gq/batch.h: (N, 3) rays and points, (N, 7) poses. Each runs without the GIL on gq's thread pool
// and answers bitwise what the loop of single queries answers. Outputs keep the geometry's dtype.
#include <chrono>
#include <limits>
#include <vector>

#include "batch_util.h"
#include "common.h"
#include "custom_callbacks.h"

namespace gqpy {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

template <class Fn> py::object byGeometry(const GeometryObject& g, Fn&& fn) {
  return g.f32 ? fn(float{}) : fn(double{});
}

template <class T> py::array_t<T> vec3Out(std::size_t n) { return newArray<T>({py::ssize_t(n), 3}); }

// Closest hit of each ray, written by the batch straight into the numpy arrays (gq::RayHitColumns).
template <class T>
py::tuple raycastBatch(const GeometryObject& g, const py::handle& origins, const py::handle& dirs, const py::handle& p,
                       double maxDistance, bool bothSides, std::uint32_t threads, bool normalize,
                       BatchScratchObject* scratch) {
  gq::HitFlags flags = gq::kDefaultHitFlags;
  if (bothSides) flags |= gq::HitFlag::MeshBothSides;
  const RayRows<T> r = rayRows<T>(origins, dirs, maxDistance, flags, normalize, "raycast_batch");
  const std::size_t n = r.count;
  const gq::Transform<T> tf = pose<T>(p, "pose");
  auto has = newArray<bool>({py::ssize_t(n)});
  auto dist = newArray<T>({py::ssize_t(n)});
  auto pos = vec3Out<T>(n), nrm = vec3Out<T>(n);
  auto face = newArray<std::int64_t>({py::ssize_t(n)});
  gq::RayHitColumns<T> out;
  out.hit = reinterpret_cast<std::uint8_t*>(has.mutable_data());
  out.distance = dist.mutable_data();
  out.position = pos.mutable_data();
  out.normal = nrm.mutable_data();
  out.faceIndex = face.mutable_data();
  const ScratchUse use(scratch);
  runBatch([&](gq::Status* st) { return gq::raycastBatch(r.batch, g.shape<T>(), tf, out, st, use.settings(threads)); },
           n, "raycast_batch");
  rethrowCallbackError(g);
  return py::make_tuple(has, dist, pos, nrm, face);
}

// The face index of each ray's closest hit (-1: a miss or a shape without faces); only FaceIndex is asked for, and
// the batch writes the int64 array directly.
template <class T>
py::array_t<std::int64_t> raycastFaces(const GeometryObject& g, const py::handle& origins, const py::handle& dirs,
                                       const py::handle& p, double maxDistance, bool bothSides, std::uint32_t threads,
                                       bool normalize, BatchScratchObject* scratch) {
  gq::HitFlags flags = gq::HitFlags(gq::HitFlag::FaceIndex);
  if (bothSides) flags |= gq::HitFlag::MeshBothSides;
  const RayRows<T> r = rayRows<T>(origins, dirs, maxDistance, flags, normalize, "raycast_batch_faces");
  const std::size_t n = r.count;
  const gq::Transform<T> tf = pose<T>(p, "pose");
  auto face = newArray<std::int64_t>({py::ssize_t(n)});
  gq::RayHitColumns<T> out;
  out.faceIndex = face.mutable_data();
  const ScratchUse use(scratch);
  runBatch([&](gq::Status* st) { return gq::raycastBatch(r.batch, g.shape<T>(), tf, out, st, use.settings(threads)); },
           n, "raycast_batch_faces");
  rethrowCallbackError(g);
  return face;
}

std::size_t poseCount(const py::handle& a, const py::handle& b) {
  for (const py::handle& h : {a, b})
    if (py::isinstance<py::array>(h) && py::reinterpret_borrow<py::array>(h).ndim() == 2)
      return std::size_t(py::reinterpret_borrow<py::array>(h).shape(0));
    else if (py::isinstance<py::list>(h) && py::len(h) > 0 && py::isinstance<py::sequence>(py::reinterpret_borrow<py::list>(h)[0]))
      return py::len(h);
  throw py::value_error("poses0 or poses1 must be an (N, 7) array of poses (px, py, pz, qx, qy, qz, qw)");
}

template <class T> gq::StridedArray<gq::Transform<T>> stridedPoses(const std::vector<gq::Transform<T>>& v) {
  return gq::StridedArray<gq::Transform<T>>(v.data(), v.size());
}

}  // namespace

void bindBatches(py::module_& m) {
  py::class_<BatchScratchObject>(
      m, "BatchScratch",
      "Memory kept between ray batches against a triangle mesh (gq::BatchScratch): pass it as scratch= to"
      " raycast_batch or raycast_batch_faces casting batch after batch, and the batches reuse the arrays an earlier"
      " call grew instead of allocating and faulting in fresh ones (about 76 bytes a ray in float64, 44 in float32)."
      " Calls passing one scratch from several Python threads take turns. The answers are the same with or without"
      " it.")
      .def(py::init<>())
      .def_property_readonly("bytes", [](BatchScratchObject& s) {
            py::gil_scoped_release release;  // a batch holding the lock takes the GIL back before it unlocks
            std::lock_guard<std::mutex> hold(s.lock);
            return s.scratch.bytes();
          }, "Bytes held now.")
      .def("release", [](BatchScratchObject& s) {
            py::gil_scoped_release release;
            std::lock_guard<std::mutex> hold(s.lock);
            s.scratch.release();
          }, "Frees the memory held (a later batch grows it again).");
  // Benchmark support (comparisons/bench_python.py): the seconds the C++ calls alone take, timed in C++, as the
  // reference the Python entries are measured against.
  m.def("_time_raycast_batch_faces",
        [](const py::handle& origins, const py::handle& dirs, const GeometryObject& g, std::uint32_t threads,
           BatchScratchObject* scratch) {
          if (g.f32) throw py::type_error("_time_raycast_batch_faces: float64 geometry expected");
          const RayRows<double> r =
              rayRows<double>(origins, dirs, std::numeric_limits<double>::infinity(),
                              gq::HitFlag::FaceIndex | gq::HitFlag::MeshBothSides, false, "_time_raycast_batch_faces");
          const gq::RayBatch<double>& rays = r.batch;
          const std::size_t n = r.count;
          std::vector<gq::RaycastHit<double>> hits(n);
          std::vector<std::uint8_t> has(n, 0);
          const ScratchUse use(scratch);
          py::gil_scoped_release release;
          const auto t0 = std::chrono::steady_clock::now();
          const gq::Status s = gq::raycastBatch(rays, g.shape<double>(), gq::Transform<double>(), hits.data(), has.data(),
                                                nullptr, use.settings(threads));
          const auto t1 = std::chrono::steady_clock::now();
          if (!s.ok()) throw std::runtime_error(s.toString());
          return std::chrono::duration<double>(t1 - t0).count();
        },
        py::arg("origins"), py::arg("directions"), py::arg("geometry"), py::arg("threads") = 0,
        py::arg("scratch") = py::none());
  m.def("_time_overlap_loop",
        [](const GeometryObject& g0, const Pose& p0, const GeometryObject& g1, const Pose& p1, std::size_t calls) {
          if (g0.f32 || g1.f32) throw py::type_error("_time_overlap_loop: float64 geometries expected");
          std::size_t hits = 0;
          const auto t0 = std::chrono::steady_clock::now();
          for (std::size_t i = 0; i < calls; ++i) {
            bool out = false;
            const gq::Transform<double>* volatile pose0 = &p0.d;  // one call per iteration, not hoisted
            if (gq::overlap(g0.d, *pose0, g1.d, p1.d, out).ok() && out) ++hits;
          }
          const auto t1 = std::chrono::steady_clock::now();
          return py::make_tuple(std::chrono::duration<double>(t1 - t0).count(), hits);
        });

  m.def("raycast_batch",
        [](const py::handle& origins, const py::handle& dirs, const GeometryObject& g, const py::handle& p,
           double maxDistance, bool bothSides, std::uint32_t threads, bool normalize, BatchScratchObject* scratch) {
          return byGeometry(g, [&](auto t) {
            return py::object(
                raycastBatch<decltype(t)>(g, origins, dirs, p, maxDistance, bothSides, threads, normalize, scratch));
          });
        },
        py::arg("origins"), py::arg("directions"), py::arg("geometry"), py::arg("pose") = py::none(),
        py::arg("max_distance") = kInf, py::arg("both_sides") = false, py::arg("threads") = 0,
        py::arg("normalize") = false, py::arg("scratch") = py::none(),
        "Closest hit of each ray (N, 3) along unit directions (N, 3): (hit (N,) bool, distance (N,) (inf on a miss),"
        " position (N, 3), normal (N, 3), face_index (N,) int64 (-1: none)). normalize: the directions may have any"
        " non-zero length (each is divided by its length in the batch). scratch: a BatchScratch whose memory a mesh"
        " batch reuses across calls (None: each call allocates its own).");
  m.def("raycast_batch_faces",
        [](const py::handle& origins, const py::handle& dirs, const GeometryObject& g, const py::handle& p,
           double maxDistance, bool bothSides, std::uint32_t threads, bool normalize, BatchScratchObject* scratch) {
          return byGeometry(g, [&](auto t) {
            return py::object(
                raycastFaces<decltype(t)>(g, origins, dirs, p, maxDistance, bothSides, threads, normalize, scratch));
          });
        },
        py::arg("origins"), py::arg("directions"), py::arg("geometry"), py::arg("pose") = py::none(),
        py::arg("max_distance") = kInf, py::arg("both_sides") = false, py::arg("threads") = 0,
        py::arg("normalize") = false, py::arg("scratch") = py::none(),
        "Face index (N,) int64 of each ray's closest hit, -1 on a miss; computes nothing else. normalize, scratch: as"
        " raycast_batch.");

  m.def("overlap_batch",
        [](const GeometryObject& g0, const py::handle& poses0, const GeometryObject& g1, const py::handle& poses1,
           std::uint32_t threads) {
          requireSameDtype(g0, g1, "overlap_batch");
          const std::size_t n = poseCount(poses0, poses1);
          return byGeometry(g0, [&](auto t) {
            using T = decltype(t);
            const auto a = poseRows<T>(poses0, n, "poses0");
            const auto b = poseRows<T>(poses1, n, "poses1");
            auto out = newArray<bool>({py::ssize_t(n)});
            auto* o = reinterpret_cast<std::uint8_t*>(out.mutable_data());
            std::fill(o, o + n, std::uint8_t(0));
            runBatch([&](gq::Status* st) {
              return gq::overlapBatch(g0.shape<T>(), stridedPoses(a), g1.shape<T>(), stridedPoses(b), o, st, batchSettings(threads));
            }, n, "overlap_batch");
            rethrowCallbackError(g0);
            rethrowCallbackError(g1);
            return py::object(out);
          });
        },
        py::arg("geometry0"), py::arg("poses0"), py::arg("geometry1"), py::arg("poses1"), py::arg("threads") = 0,
        "overlap() of geometry0 at poses0[i] and geometry1 at poses1[i] (N, 7); one side may be a single pose.");

  m.def("distance_batch",
        [](const GeometryObject& g0, const py::handle& poses0, const GeometryObject& g1, const py::handle& poses1,
           std::uint32_t threads) {
          requireSameDtype(g0, g1, "distance_batch");
          const std::size_t n = poseCount(poses0, poses1);
          return byGeometry(g0, [&](auto t) {
            using T = decltype(t);
            const auto a = poseRows<T>(poses0, n, "poses0");
            const auto b = poseRows<T>(poses1, n, "poses1");
            std::vector<gq::DistanceResult<T>> r(n);
            runBatch([&](gq::Status* st) {
              return gq::distanceBatch(g0.shape<T>(), stridedPoses(a), g1.shape<T>(), stridedPoses(b), r.data(), st, batchSettings(threads));
            }, n, "distance_batch");
            rethrowCallbackError(g0);
            rethrowCallbackError(g1);
            auto dist = newArray<T>({py::ssize_t(n)});
            auto p0 = vec3Out<T>(n), p1 = vec3Out<T>(n), nrm = vec3Out<T>(n);
            for (std::size_t i = 0; i < n; ++i) {
              dist.mutable_data()[i] = r[i].distance;
              for (int k = 0; k < 3; ++k) {
                p0.mutable_data()[3 * i + k] = r[i].point0[k];
                p1.mutable_data()[3 * i + k] = r[i].point1[k];
                nrm.mutable_data()[3 * i + k] = r[i].normal[k];
              }
            }
            return py::object(py::make_tuple(dist, p0, p1, nrm));
          });
        },
        py::arg("geometry0"), py::arg("poses0"), py::arg("geometry1"), py::arg("poses1"), py::arg("threads") = 0,
        "distance() per pose pair: (distance (N,), point0 (N, 3), point1 (N, 3), normal (N, 3)).");

  m.def("penetration_batch",
        [](const GeometryObject& g0, const py::handle& poses0, const GeometryObject& g1, const py::handle& poses1,
           std::uint32_t threads) {
          requireSameDtype(g0, g1, "penetration_batch");
          const std::size_t n = poseCount(poses0, poses1);
          return byGeometry(g0, [&](auto t) {
            using T = decltype(t);
            const auto a = poseRows<T>(poses0, n, "poses0");
            const auto b = poseRows<T>(poses1, n, "poses1");
            std::vector<gq::PenetrationResult<T>> r(n);
            runBatch([&](gq::Status* st) {
              return gq::penetrationBatch(g0.shape<T>(), stridedPoses(a), g1.shape<T>(), stridedPoses(b), r.data(), st, batchSettings(threads));
            }, n, "penetration_batch");
            rethrowCallbackError(g0);
            rethrowCallbackError(g1);
            auto pen = newArray<bool>({py::ssize_t(n)});
            auto dir = vec3Out<T>(n);
            auto depth = newArray<T>({py::ssize_t(n)});
            for (std::size_t i = 0; i < n; ++i) {
              pen.mutable_data()[i] = r[i].penetrating;
              depth.mutable_data()[i] = r[i].depth;
              for (int k = 0; k < 3; ++k) dir.mutable_data()[3 * i + k] = r[i].direction[k];
            }
            return py::object(py::make_tuple(pen, dir, depth));
          });
        },
        py::arg("geometry0"), py::arg("poses0"), py::arg("geometry1"), py::arg("poses1"), py::arg("threads") = 0,
        "penetration() per pose pair: (penetrating (N,), direction (N, 3), depth (N,)).");

  m.def("point_distance_batch",
        [](const py::handle& points, const GeometryObject& g, const py::handle& p, std::uint32_t threads) {
          return byGeometry(g, [&](auto t) {
            using T = decltype(t);
            const auto pts = rowsArray<T>(points, 3, "points");
            const std::size_t n = std::size_t(pts.shape(0));
            const gq::Transform<T> tf = pose<T>(p, "pose");
            std::vector<gq::PointDistanceResult<T>> r(n);
            runBatch([&](gq::Status* st) {
              return gq::pointDistanceBatch(strided(pts), g.shape<T>(), tf, r.data(), st, batchSettings(threads));
            }, n, "point_distance_batch");
            auto dist = newArray<T>({py::ssize_t(n)});
            auto closest = vec3Out<T>(n);
            auto index = newArray<std::int64_t>({py::ssize_t(n)});
            for (std::size_t i = 0; i < n; ++i) {
              dist.mutable_data()[i] = r[i].distance;
              index.mutable_data()[i] = r[i].closestIndex == gq::kInvalidFaceIndex ? -1 : std::int64_t(r[i].closestIndex);
              for (int k = 0; k < 3; ++k) closest.mutable_data()[3 * i + k] = r[i].closestPoint[k];
            }
            return py::object(py::make_tuple(dist, closest, index));
          });
        },
        py::arg("points"), py::arg("geometry"), py::arg("pose") = py::none(), py::arg("threads") = 0,
        "point_distance() per point (N, 3): (distance (N,), closest_point (N, 3), triangle index (N,) int64).");
}

}  // namespace gqpy
