#pragma once
// Helpers of the batched forms: strided numpy rows as gq::StridedArray, (N, 7) poses, and batch Status -> exception.
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include "common.h"
#include "gq/batch.h"

namespace gqpy {

template <class T> gq::StridedArray<gq::Vec3<T>> strided(const py::array_t<T>& rows) {
  return gq::StridedArray<gq::Vec3<T>>::fromBytes(rows.data(), std::size_t(rows.shape(0)),
                                                  rows.shape(0) > 0 ? std::size_t(rows.strides(0)) : sizeof(gq::Vec3<T>));
}

// A batch of rays over (N, 3) origin and direction rows; the rows are held here, so the batch's views stay valid.
// normalize: directions of any non-zero length, normalized by the batch on its threads (RayBatch::normalizeDirections).
template <class T> struct RayRows {
  py::array_t<T> origins, dirs;
  gq::RayBatch<T> batch;
  std::size_t count = 0;
};

template <class T>
RayRows<T> rayRows(const py::handle& origins, const py::handle& dirs, double maxDistance, gq::HitFlags flags,
                   bool normalize, const char* what) {
  RayRows<T> r;
  r.origins = rowsArray<T>(origins, 3, "origins");
  r.dirs = rowsArray<T>(dirs, 3, "directions");
  r.count = std::size_t(r.origins.shape(0));
  if (std::size_t(r.dirs.shape(0)) != r.count)
    throw py::value_error(std::string(what) + ": " + std::to_string(r.count) + " origins and " +
                          std::to_string(r.dirs.shape(0)) + " directions");
  r.batch.origins = strided(r.origins);
  r.batch.unitDirs = strided(r.dirs);
  r.batch.maxDist = T(maxDistance);
  r.batch.hitFlags = flags;
  r.batch.normalizeDirections = normalize;
  return r;
}

// Poses from an (N, 7) array (px, py, pz, qx, qy, qz, qw), or one pose (None, a Pose, 7 numbers) repeated `count`
// times (count 0: an (N, 7) array is required).
template <class T>
std::vector<gq::Transform<T>> poseRows(const py::handle& obj, std::size_t count, const char* what) {
  if (obj.is_none() || py::isinstance<Pose>(obj) ||
      (py::isinstance<py::sequence>(obj) && !py::isinstance<py::array>(obj) && py::len(obj) == 7 &&
       !py::isinstance<py::sequence>(py::reinterpret_borrow<py::sequence>(obj)[0])) ||
      (py::isinstance<py::array>(obj) && py::reinterpret_borrow<py::array>(obj).ndim() == 1)) {
    if (count == 0) throw py::value_error(std::string(what) + ": expected an (N, 7) array of poses");
    return std::vector<gq::Transform<T>>(count, pose<T>(obj, what));
  }
  const auto rows = rowsArray<T>(obj, 7, what);
  const std::size_t n = std::size_t(rows.shape(0));
  if (count != 0 && n != count)
    throw py::value_error(std::string(what) + ": " + std::to_string(n) + " poses for " + std::to_string(count) +
                          " items");
  std::vector<gq::Transform<T>> out(n);
  const auto* base = reinterpret_cast<const unsigned char*>(rows.data());
  for (std::size_t i = 0; i < n; ++i) {
    const T* v = reinterpret_cast<const T*>(base + i * std::size_t(rows.strides(0)));
    out[i].p = gq::Vec3<T>(v[0], v[1], v[2]);
    out[i].q = gq::Quat<T>(v[6], v[3], v[4], v[5]);
  }
  return out;
}

// Raises for a failed batch: the batch-level Status, or the first failing item's Status (statuses given).
inline void checkBatch(const gq::Status& s, const std::vector<gq::Status>& statuses, const char* what) {
  if (s.code == gq::StatusCode::Ok) return;
  if (s.code != gq::StatusCode::Warning) raiseStatus(s, what);
  for (std::size_t i = 0; i < statuses.size(); ++i)
    if (!statuses[i].ok())
      raiseStatus(statuses[i], std::string(what) + ": item " + std::to_string(i) + " (" + std::to_string(s.index()) +
                                   " of " + std::to_string(statuses.size()) + " failed)");
}

// Runs `run(statuses)` without the GIL; when items failed, runs it again collecting their Status and raises.
template <class Run> void runBatch(Run&& run, std::size_t count, const char* what) {
  gq::Status s;
  {
    py::gil_scoped_release release;
    s = run(static_cast<gq::Status*>(nullptr));
  }
  if (s.code == gq::StatusCode::Ok) return;
  std::vector<gq::Status> statuses;
  if (s.code == gq::StatusCode::Warning) {
    statuses.resize(count);
    py::gil_scoped_release release;
    s = run(statuses.data());
  }
  checkBatch(s, statuses, what);
}

inline gq::BatchSettings batchSettings(std::uint32_t threads) {
  gq::BatchSettings s;
  s.threads = threads;
  return s;
}

// geomquery.BatchScratch: a gq::BatchScratch with a lock, so two Python threads passing one scratch to batches that
// run without the GIL take turns instead of sharing its arrays.
struct BatchScratchObject {
  gq::BatchScratch scratch;
  std::mutex lock;
};

// The scratch a batch call uses: none, or the object's scratch locked for the call (taken without the GIL).
class ScratchUse {
 public:
  explicit ScratchUse(BatchScratchObject* object) : object_(object) {
    if (object_ == nullptr) return;
    py::gil_scoped_release release;
    object_->lock.lock();
  }
  ~ScratchUse() {
    if (object_ != nullptr) object_->lock.unlock();
  }
  ScratchUse(const ScratchUse&) = delete;
  ScratchUse& operator=(const ScratchUse&) = delete;
  gq::BatchSettings settings(std::uint32_t threads) const {
    gq::BatchSettings s = batchSettings(threads);
    s.scratch = object_ != nullptr ? &object_->scratch : nullptr;
    return s;
  }

 private:
  BatchScratchObject* object_;
};

}  // namespace gqpy
