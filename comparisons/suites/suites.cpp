// The suite list and the two sizes: embedded (in memory, for scripts/demo and the ctest) and the committed files.
#include "suite.h"

namespace gq::suites {

void emitBothPrecisions(nlohmann::json base, const std::string& id, std::vector<nlohmann::json>& out) {
  for (const char* precision : {"double", "float"}) {
    nlohmann::json j;
    j["id"] = id + "/" + precision;
    j["precision"] = precision;
    for (auto it = base.begin(); it != base.end(); ++it) j[it.key()] = it.value();
    out.push_back(std::move(j));
  }
}

SuiteOptions embeddedOptions() {
  SuiteOptions o;
  o.randomPerPair = 1;
  o.orientations = 1;
  o.randomRays = 4;
  o.randomPoints = 4;
  o.randomSweeps = 1;
  return o;
}

SuiteOptions fileOptions() {
  SuiteOptions o;
  o.seed = 7;
  o.randomPerPair = 4;
  o.orientations = 2;
  o.randomRays = 16;
  o.randomPoints = 16;
  o.randomSweeps = 3;
  return o;
}

std::vector<Suite> makeSuites(const SuiteOptions& options) {
  std::vector<Suite> suites = {{"overlap", {}}, {"penetration", {}}, {"distance", {}}, {"raycast", {}},
                               {"pointDistance", {}}, {"sweep", {}}};
  addPairSuites(options, suites[0].cases, suites[1].cases, suites[2].cases);
  addRaySuite(options, suites[3].cases);
  addPointSuite(options, suites[4].cases);
  addSweepSuite(options, suites[5].cases);
  return suites;
}

}  // namespace gq::suites
