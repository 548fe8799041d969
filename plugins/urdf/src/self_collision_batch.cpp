// Batches of configurations (gq/urdf/self_collision.h) on core's batch pool: each worker slot owns a checker and a
// configuration buffer, made on the slot's first item; configurations are independent, so every thread count gives
// the single checker's answers.
#include <memory>
#include <vector>

#include "gq/urdf/self_collision.h"

namespace gq::urdf {

namespace {

template <class T> struct Worker {
  std::unique_ptr<SelfCollisionChecker<T>> checker;
  std::vector<T> q;
};

template <class T> Status checkBatchInput(const std::shared_ptr<const RobotModel<T>>& model, const StridedArray<T>& configs,
                                          std::size_t dof, const void* output) {
  if (!model) return Status::invalid("configuration batch: the robot model is null");
  if (dof != model->variables.size()) {
    return Status::invalid("configuration batch: the rows' length is not the model's variable count")
        .withIndex(std::uint32_t(model->variables.size()));
  }
  if (configs.count == 0) return {};
  if (configs.data == nullptr) return Status::invalid("configuration batch: the configurations are null");
  if (configs.stride < dof * sizeof(T)) return Status::invalid("configuration batch: a row's stride is shorter than the row");
  if (output == nullptr) return Status::invalid("configuration batch: the output array is null");
  return {};
}

// Runs check(worker, i) for every configuration with the worker's buffer holding configuration i.
template <class T, class Check>
Status runConfigurations(const std::shared_ptr<const RobotModel<T>>& model, const StridedArray<T>& configs,
                         std::size_t dof, Status* statuses, const BatchSettings& settings, const CheckerOptions& options,
                         const Check& check) {
  std::vector<Worker<T>> workers(batchSlots(settings));
  return forEachBatchItem(configs.count, settings, [&](std::size_t i, std::uint32_t slot) {
    Status s;
    if (slot >= workers.size()) {
      s = Status::invalid("configuration batch: a worker slot beyond batchSlots");
    } else {
      Worker<T>& w = workers[slot];
      if (!w.checker) w.checker = std::make_unique<SelfCollisionChecker<T>>(model, options);
      const T* row = &configs[i];
      w.q.assign(row, row + dof);
      s = check(*w.checker, w.q, i);
    }
    if (statuses) statuses[i] = s;
    return s.ok();
  });
}

}  // namespace

template <class T>
Status checkSelfCollisionBatch(std::shared_ptr<const RobotModel<T>> model, StridedArray<T> configs, std::size_t dof,
                               std::uint8_t* colliding, Status* statuses, const BatchSettings& settings,
                               const CheckerOptions& options) {
  if (Status s = checkBatchInput(model, configs, dof, colliding); !s.ok()) return s;
  CollisionRequest firstOnly;
  firstOnly.allPairs = false;
  return runConfigurations(model, configs, dof, statuses, settings, options,
                           [&](SelfCollisionChecker<T>& checker, const std::vector<T>& q, std::size_t i) {
                             CollisionResult r;
                             const Status s = checker.checkSelfCollision(q, r, firstOnly);
                             colliding[i] = s.ok() && r.colliding ? 1 : 0;
                             return s;
                           });
}

template <class T>
Status selfDistanceBatch(std::shared_ptr<const RobotModel<T>> model, StridedArray<T> configs, std::size_t dof,
                         SelfDistanceResult<T>* results, Status* statuses, const BatchSettings& settings,
                         const CheckerOptions& options) {
  if (Status s = checkBatchInput(model, configs, dof, results); !s.ok()) return s;
  return runConfigurations(model, configs, dof, statuses, settings, options,
                           [&](SelfCollisionChecker<T>& checker, const std::vector<T>& q, std::size_t i) {
                             return checker.selfDistance(q, results[i]);
                           });
}

#define GQ_URDF_BATCH(T)                                                                                              \
  template Status checkSelfCollisionBatch<T>(std::shared_ptr<const RobotModel<T>>, StridedArray<T>, std::size_t,   \
                                             std::uint8_t*, Status*, const BatchSettings&, const CheckerOptions&);   \
  template Status selfDistanceBatch<T>(std::shared_ptr<const RobotModel<T>>, StridedArray<T>, std::size_t,         \
                                       SelfDistanceResult<T>*, Status*, const BatchSettings&, const CheckerOptions&);
GQ_URDF_BATCH(float)
GQ_URDF_BATCH(double)
#undef GQ_URDF_BATCH

}  // namespace gq::urdf
