#include "judge.h"

#include <cmath>
#include <cstdio>

namespace gq::compare {
namespace {

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

struct Expected {
  double scale, margin, tolerance;
  double spread = 0;  // change of the exact value under input moves of tolerance * scale (relative)
  // A boolean is judged only when the exact configuration is farther than the tolerance from flipping it.
  bool booleanDecidable() const { return std::abs(margin) > tolerance * scale; }
};

// Folds a boolean answer and an optional value into a verdict.
Verdict decide(const Expected& e, bool gotBool, bool expBool, std::optional<double> got, std::optional<double> exp) {
  Verdict v;
  if (gotBool != expBool) {
    v.outcome = e.booleanDecidable() ? Outcome::WrongBoolean : Outcome::Ambiguous;
    if (v.outcome == Outcome::WrongBoolean) return v;
  }
  if (got && exp) {
    v.error = std::abs(*got - *exp) / e.scale;
    if (!std::isfinite(*v.error) || *v.error > e.tolerance + e.spread) v.outcome = Outcome::BeyondTolerance;
  }
  return v;
}

// Raycasts and sweeps: the hit boolean, then the hit distance (`got` empty = no hit).
Verdict decideHit(const Expected& e, const nlohmann::json& expect, std::optional<double> got) {
  const bool exp = expect.at("hit").get<bool>();
  std::optional<double> want;
  if (exp) want = expect.at("distance").get<double>();
  Verdict v = decide(e, got.has_value(), exp, got && want ? got : std::nullopt, got && want ? want : std::nullopt);
  v.answer = got ? "hit at " + number(*got) : "miss";
  v.exact = want ? "hit at " + number(*want) : "miss";
  return v;
}

// The stored spread for this tolerance ("1e-09", "1e-07", "1e-04"); 0 when the answer is insensitive.
double spreadAt(const nlohmann::json& spread, double tolerance) {
  char key[16];
  std::snprintf(key, sizeof key, "%.0e", tolerance);
  const auto it = spread.find(key);
  return it == spread.end() ? 0.0 : it->get<double>();
}

}  // namespace

double toleranceFor(cases::Precision precision, const std::string& toleranceClass) {
  if (precision == cases::Precision::Float) return 1e-4;
  return toleranceClass == "analytic" ? 1e-9 : 1e-7;
}

const char* toString(Outcome o) {
  switch (o) {
    case Outcome::Correct: return "correct";
    case Outcome::Ambiguous: return "ambiguous boolean (within tolerance of flipping)";
    case Outcome::WrongBoolean: return "wrong boolean";
    case Outcome::BeyondTolerance: return "value beyond tolerance";
    case Outcome::Unsupported: return "unsupported";
    case Outcome::Failed: return "failed";
  }
  return "";
}

Verdict judge(const std::string& family, cases::Precision precision, const nlohmann::json& expect,
              const cases::Result& result) {
  Verdict v;
  if (!result.ok) {
    v.outcome = result.error.rfind("unsupported", 0) == 0 ? Outcome::Unsupported : Outcome::Failed;
    v.answer = result.error;
    return v;
  }
  Expected e{expect.at("scale").get<double>(), expect.at("margin").get<double>(),
             toleranceFor(precision, expect.at("class").get<std::string>())};
  if (const auto it = expect.find("spread"); it != expect.end()) e.spread = spreadAt(*it, e.tolerance);
  if (family == "overlap") {
    const bool got = std::get<cases::OverlapOut>(result.fields).overlap, exp = expect.at("overlap").get<bool>();
    v = decide(e, got, exp, std::nullopt, std::nullopt);
    v.answer = got ? "overlap" : "apart";
    v.exact = std::string(exp ? "overlap" : "apart") + " (signed distance " + number(e.margin) + ")";
  } else if (family == "penetration") {
    const auto& out = std::get<cases::PenetrationOut>(result.fields);
    const bool exp = expect.at("penetrating").get<bool>();
    const double depth = expect.at("depth").get<double>();
    const bool both = out.penetrating && exp;
    v = decide(e, out.penetrating, exp, both ? std::optional<double>(out.depth) : std::nullopt,
               both ? std::optional<double>(depth) : std::nullopt);
    v.answer = out.penetrating ? "depth " + number(out.depth) : "not penetrating";
    v.exact = exp ? "depth " + number(depth) : "apart by " + number(e.margin);
  } else if (family == "distance") {
    const double got = std::get<cases::DistanceOut>(result.fields).distance;
    const double exp = expect.at("distance").get<double>();
    v = decide(e, got <= 0, exp <= 0, got, exp);
    v.answer = "distance " + number(got);
    v.exact = "distance " + number(exp);
  } else if (family == "raycast") {
    const auto& hits = std::get<cases::RaycastOut>(result.fields).hits;
    v = decideHit(e, expect, hits.empty() ? std::nullopt : std::optional<double>(hits.front().distance));
  } else if (family == "sweep") {
    const auto& out = std::get<cases::SweepOut>(result.fields);
    v = decideHit(e, expect, out.hit ? std::optional<double>(out.distance) : std::nullopt);
  } else if (family == "pointDistance") {
    const double got = std::get<cases::PointDistanceOut>(result.fields).distance;
    const double exp = expect.at("distance").get<double>();
    v = decide(e, false, false, got, exp);
    v.answer = "distance " + number(got);
    v.exact = "distance " + number(exp);
  }
  return v;
}

}  // namespace gq::compare
