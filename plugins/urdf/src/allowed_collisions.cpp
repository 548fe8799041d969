// The allowed-collision matrix, as MoveIt's setup assistant builds it:
//  - links joined by fixed joints form one rigid body: all their pairs are allowed ("adjacent");
//  - two rigid bodies joined by a moving joint are adjacent, and so are bodies joined through bodies without any
//    collision shape (a shapeless body is transparent: its neighbours become each other's neighbours);
//  - a link against itself ("same link": several shapes of one link are never checked against each other);
//  - every SRDF <disable_collisions> pair ("srdf:<reason>").
#include <algorithm>
#include <cmath>
#include <numeric>

#include "internal.h"

namespace gq::urdf::internal {
namespace {

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

template <class T> std::vector<std::uint32_t> rigidBodies(const RobotModel<T>& model) {
  std::vector<std::uint32_t> parent(model.links.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (const auto& j : model.joints)
    if (j.type == JointType::Fixed) parent[findRoot(parent, j.childLink)] = findRoot(parent, j.parentLink);
  for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = findRoot(parent, i);
  return parent;
}

template <class T> void allow(RobotModel<T>& m, std::uint32_t a, std::uint32_t b, const std::string& reason) {
  const std::size_t n = m.links.size();
  if (m.allowed[a * n + b]) return;
  m.allowed[a * n + b] = m.allowed[b * n + a] = 1;
  m.allowedReason[a * n + b] = m.allowedReason[b * n + a] = reason;
}

}  // namespace

template <class T> void computeAllowedCollisions(RobotModel<T>& model, const SrdfData& srdf, std::string& warnings) {
  const std::size_t n = model.links.size();
  model.allowed.assign(n * n, 0);
  model.allowedReason.assign(n * n, std::string());
  for (std::uint32_t i = 0; i < n; ++i) allow(model, i, i, "same link");

  const std::vector<std::uint32_t> body = rigidBodies(model);
  std::vector<std::uint8_t> bodyHasShapes(n, 0);
  for (std::uint32_t i = 0; i < n; ++i)
    if (!model.links[i].shapes.empty()) bodyHasShapes[body[i]] = 1;
  std::vector<std::vector<std::uint32_t>> neighbours(n);  // body graph over moving joints
  for (const auto& j : model.joints)
    if (j.type != JointType::Fixed) {
      neighbours[body[j.parentLink]].push_back(body[j.childLink]);
      neighbours[body[j.childLink]].push_back(body[j.parentLink]);
    }
  // adjacentBody[x][y]: reached from body x over one moving joint, passing only through shapeless bodies.
  std::vector<std::vector<std::uint8_t>> adjacentBody(n, std::vector<std::uint8_t>(n, 0));
  for (std::uint32_t start = 0; start < n; ++start) {
    if (body[start] != start) continue;
    std::vector<std::uint32_t> stack = neighbours[start];
    std::vector<std::uint8_t> seen(n, 0);
    seen[start] = 1;
    while (!stack.empty()) {
      const std::uint32_t b = stack.back();
      stack.pop_back();
      if (seen[b]) continue;
      seen[b] = 1;
      adjacentBody[start][b] = 1;
      if (!bodyHasShapes[b])
        for (std::uint32_t next : neighbours[b]) stack.push_back(next);
    }
  }
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      if (body[a] == body[b] || adjacentBody[body[a]][body[b]]) allow(model, a, b, "adjacent");

  for (const auto& pair : srdf.disabled) {
    const std::int32_t a = model.findLink(pair.link1), b = model.findLink(pair.link2);
    if (a < 0 || b < 0) {
      warnings += "SRDF disables a pair with an unknown link (" + pair.link1 + ", " + pair.link2 + "); ";
      continue;
    }
    allow(model, std::uint32_t(a), std::uint32_t(b), "srdf:" + (pair.reason.empty() ? "unspecified" : pair.reason));
  }
}

// Home = the SRDF group state named "ready", else "home", else "default"; joints it leaves out (and every joint
// when there is none) take 0 clamped into their limits.
template <class T> void chooseHomeConfiguration(RobotModel<T>& model, const SrdfData& srdf) {
  model.home.assign(model.variables.size(), T(0));
  for (std::size_t v = 0; v < model.variables.size(); ++v)
    for (const auto& j : model.joints)
      if (j.variable == std::int32_t(v) && j.type != JointType::Continuous)
        model.home[v] = std::clamp(T(0), j.lower, j.upper);
  model.homeSource = "zero (clamped into the joint limits)";
  for (const char* wanted : {"ready", "home", "default"}) {
    const auto it = std::find_if(srdf.states.begin(), srdf.states.end(), [&](const auto& s) { return s.name == wanted; });
    if (it == srdf.states.end()) continue;
    for (const auto& [joint, value] : it->values) {
      const auto v = std::find(model.variables.begin(), model.variables.end(), joint);
      if (v != model.variables.end()) model.home[std::size_t(v - model.variables.begin())] = T(value);
    }
    model.homeSource = std::string("SRDF group_state '") + wanted + "'";
    return;
  }
}

template void computeAllowedCollisions<float>(RobotModel<float>&, const SrdfData&, std::string&);
template void computeAllowedCollisions<double>(RobotModel<double>&, const SrdfData&, std::string&);
template void chooseHomeConfiguration<float>(RobotModel<float>&, const SrdfData&);
template void chooseHomeConfiguration<double>(RobotModel<double>&, const SrdfData&);

}  // namespace gq::urdf::internal
