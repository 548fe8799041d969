// MoveIt-setup-assistant style "never in collision" pairs: sample random configurations within the joint limits,
// check every pair the structure does not already exclude (adjacent / same link; the SRDF's own list is ignored so
// it can be regenerated), and keep the pairs that never touched.
#include <sstream>

#include "gq/urdf/self_collision.h"
#include "internal.h"

namespace gq::urdf {
namespace {

// The model's ACM without the SRDF entries.
template <class T> std::shared_ptr<RobotModel<T>> withoutSrdfPairs(const RobotModel<T>& model) {
  auto copy = std::make_shared<RobotModel<T>>(model);
  for (std::size_t i = 0; i < copy->allowed.size(); ++i)
    if (copy->allowedReason[i].rfind("srdf:", 0) == 0) {
      copy->allowed[i] = 0;
      copy->allowedReason[i].clear();
    }
  return copy;
}

bool isStructural(const std::string& reason) { return reason == "adjacent" || reason == "same link"; }

}  // namespace

template <class T>
Status neverColliding(std::shared_ptr<const RobotModel<T>> model, std::uint64_t samples, std::uint64_t seed,
                      NeverCollidingResult& result) {
  if (!model) return Status::invalid("neverColliding needs a model");
  if (samples == 0) return Status::invalid("neverColliding needs at least one sample");
  const auto structural = withoutSrdfPairs(*model);
  SelfCollisionChecker<T> checker(structural);
  const std::size_t n = model->links.size();
  NeverCollidingResult out;
  out.contactCount.assign(n * n, 0);
  out.samples = samples;
  std::uint64_t rng = seed;
  for (std::uint64_t k = 0; k < samples; ++k) {
    CollisionResult r;
    Status s = checker.checkSelfCollision(randomConfiguration(*structural, rng), r);
    if (!s.ok()) return s;
    for (const LinkPair& p : r.pairs) ++out.contactCount[p.a * n + p.b];
  }
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      if (!structural->isAllowed(a, b) && !model->links[a].shapes.empty() && !model->links[b].shapes.empty() &&
          out.contactCount[a * n + b] == 0)
        out.never.push_back({a, b});
  result = std::move(out);
  return {};
}

template <class T> std::string writeSrdfDisableCollisions(const RobotModel<T>& model, const std::vector<LinkPair>& never) {
  std::ostringstream os;
  const std::size_t n = model.links.size();
  os << "<?xml version=\"1.0\"?>\n<robot name=\"" << model.name << "\">\n";
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b) {
      if (model.links[a].shapes.empty() || model.links[b].shapes.empty()) continue;
      const std::string& reason = model.allowedReason[a * n + b];
      const bool isNever = std::find(never.begin(), never.end(), LinkPair{a, b}) != never.end();
      if (!isStructural(reason) && !isNever) continue;
      os << "  <disable_collisions link1=\"" << model.links[a].name << "\" link2=\"" << model.links[b].name
         << "\" reason=\"" << (isStructural(reason) ? "Adjacent" : "Never") << "\"/>\n";
    }
  os << "</robot>\n";
  return os.str();
}

template Status neverColliding<float>(std::shared_ptr<const RobotModel<float>>, std::uint64_t, std::uint64_t,
                                      NeverCollidingResult&);
template Status neverColliding<double>(std::shared_ptr<const RobotModel<double>>, std::uint64_t, std::uint64_t,
                                       NeverCollidingResult&);
template std::string writeSrdfDisableCollisions<float>(const RobotModel<float>&, const std::vector<LinkPair>&);
template std::string writeSrdfDisableCollisions<double>(const RobotModel<double>&, const std::vector<LinkPair>&);

}  // namespace gq::urdf
