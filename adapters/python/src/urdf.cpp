// geomquery.urdf: a robot's self-collision model (plugins/urdf) with check, check_batch and self_distance.
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "batch_util.h"
#include "common.h"
#include "gq/urdf/robot.h"
#include "gq/urdf/self_collision.h"

namespace gqpy {

namespace {

// check and self_distance use one checker; check_batch runs gq::urdf's batch on gq's pool (one checker per worker),
// whose answers are the single checker's.
class Robot {
 public:
  Robot(const std::string& urdf, const std::string& srdf, const std::string& mode,
        const std::vector<std::string>& packagePaths) {
    gq::urdf::LoadOptions options;
    check(gq::urdf::parseMode(mode, options), "Robot mode");
    options.packagePaths = packagePaths;
    auto model = std::make_shared<gq::urdf::RobotModel<double>>();
    check(gq::urdf::loadRobot(urdf, srdf, options, *model), "Robot");
    model_ = model;
    checker_ = std::make_unique<gq::urdf::SelfCollisionChecker<double>>(model_);
  }

  const gq::urdf::RobotModel<double>& model() const { return *model_; }

  std::vector<double> config(const py::handle& q) const {
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(q);
    if (!a || a.ndim() != 1) {
      PyErr_Clear();
      throw py::value_error("q: expected a 1-D array of " + std::to_string(model_->variables.size()) + " joint values");
    }
    return std::vector<double>(a.data(), a.data() + a.size());
  }

  py::object check1(const py::handle& q, bool allPairs) {
    const auto v = config(q);
    gq::urdf::CollisionResult r;
    gq::urdf::CollisionRequest req;
    req.allPairs = allPairs;
    check(checker_->checkSelfCollision(v, r, req), "Robot.check");
    if (!allPairs) return py::bool_(r.colliding);
    py::list pairs;
    for (const auto& p : r.pairs) pairs.append(py::make_tuple(model_->links[p.a].name, model_->links[p.b].name));
    return pairs;
  }

  py::array_t<bool> checkBatch(const py::handle& qs, unsigned threads) {
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(qs);
    const std::size_t dof = model_->variables.size();
    if (!a || a.ndim() != 2 || std::size_t(a.shape(1)) != dof) {
      PyErr_Clear();
      throw py::value_error("Q: expected an (N, " + std::to_string(dof) + ") array of configurations");
    }
    const std::size_t n = std::size_t(a.shape(0));
    const auto configs = gq::StridedArray<double>::fromBytes(a.data(), n, dof * sizeof(double));
    std::vector<std::uint8_t> out(n, 0);
    runBatch([&](gq::Status* st) {
      return gq::urdf::checkSelfCollisionBatch<double>(model_, configs, dof, out.data(), st, batchSettings(threads));
    }, n, "Robot.check_batch");
    auto result = newArray<bool>({py::ssize_t(n)});
    std::copy(out.begin(), out.end(), result.mutable_data());
    return result;
  }

  py::tuple selfDistance(const py::handle& q) {
    const auto v = config(q);
    gq::urdf::SelfDistanceResult<double> r;
    check(checker_->selfDistance(v, r), "Robot.self_distance");
    return py::make_tuple(r.distance, py::make_tuple(model_->links[r.pair.a].name, model_->links[r.pair.b].name),
                          r.point0, r.point1);
  }

 private:
  std::shared_ptr<const gq::urdf::RobotModel<double>> model_;
  std::unique_ptr<gq::urdf::SelfCollisionChecker<double>> checker_;
};

}  // namespace

void bindUrdf(py::module_& m) {
  py::class_<Robot>(m, "Robot", "A URDF (+ SRDF) robot's self-collision model (float64).")
      .def(py::init([](const std::string& urdf, const py::object& srdf, const std::string& mode,
                       const std::vector<std::string>& packagePaths) {
             return std::make_unique<Robot>(urdf, srdf.is_none() ? std::string() : srdf.cast<std::string>(), mode,
                                            packagePaths);
           }),
           py::arg("urdf"), py::arg("srdf") = py::none(), py::arg("mode") = "hull",
           py::arg("package_paths") = std::vector<std::string>(),
           "mode: how mesh links are modelled: mesh, hull, box, box-aabb, capsule, sphere, best-primitive or fit:<tolerance> (metres).")
      .def_property_readonly("name", [](const Robot& r) { return r.model().name; })
      .def_property_readonly("variables", [](const Robot& r) { return r.model().variables; },
                             "Joint names of the configuration vector, in order.")
      .def_property_readonly("links", [](const Robot& r) {
        std::vector<std::string> names;
        for (const auto& l : r.model().links) names.push_back(l.name);
        return names;
      })
      .def_property_readonly("home", [](const Robot& r) { return r.model().home; })
      .def_property_readonly("limits", [](const Robot& r) {
        std::vector<std::pair<double, double>> out;
        for (const auto& name : r.model().variables)
          for (const auto& j : r.model().joints)
            if (j.name == name) out.emplace_back(j.lower, j.upper);
        return out;
      }, "(lower, upper) of each variable (continuous joints: -pi, pi).")
      .def("check", [](Robot& r, const py::handle& q) { return r.check1(q, false); }, py::arg("q"),
           "Whether configuration q collides with itself.")
      .def("colliding_pairs", [](Robot& r, const py::handle& q) { return r.check1(q, true); }, py::arg("q"),
           "[(link_a, link_b)] of every colliding link pair, sorted.")
      .def("check_batch", &Robot::checkBatch, py::arg("Q"), py::arg("threads") = 0,
           "Collision of each configuration (N, dof), in parallel without the GIL: bool (N,).")
      .def("self_distance", &Robot::selfDistance, py::arg("q"),
           "(distance, (link_a, link_b), point_a, point_b): signed, < 0 a penetration depth.");
}

}  // namespace gqpy
