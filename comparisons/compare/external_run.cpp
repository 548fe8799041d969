#include "external_run.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

namespace gq::compare {
namespace {

cases::Vec3d vec(const nlohmann::json& v) { return cases::Vec3d(v.at(0), v.at(1), v.at(2)); }

// A gq-query result line back into the Result fields the judge reads.
cases::Result resultFromLine(const std::string& family, const std::string& line) {
  const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return cases::Result::failure("unreadable result line");
  if (!j.value("ok", false)) return cases::Result::failure(j.value("error", std::string("failed")), j.value("ns", 0.0));
  cases::Result r;
  r.ok = true;
  r.ns = j.value("ns", 0.0);
  try {
    if (family == "overlap") {
      r.fields = cases::OverlapOut{j.at("overlap").get<bool>()};
    } else if (family == "penetration") {
      cases::PenetrationOut p;
      p.penetrating = j.at("penetrating").get<bool>();
      p.depth = j.value("depth", 0.0);
      if (j.contains("direction")) p.direction = vec(j["direction"]);
      r.fields = p;
    } else if (family == "distance") {
      cases::DistanceOut d;
      d.distance = j.at("distance").get<double>();
      r.fields = d;
    } else if (family == "raycast") {
      cases::RaycastOut out;
      for (const auto& h : j.at("hits")) {
        cases::RayHitOut hit;
        hit.distance = h.at("distance").get<double>();
        out.hits.push_back(hit);
      }
      r.fields = out;
    } else if (family == "pointDistance") {
      cases::PointDistanceOut p;
      p.distance = j.at("distance").get<double>();
      r.fields = p;
    } else if (family == "sweep") {
      cases::SweepOut s;
      s.hit = j.at("hit").get<bool>();
      s.distance = j.value("distance", 0.0);
      r.fields = s;
    } else {
      return cases::Result::failure("unsupported: family " + family);
    }
  } catch (const nlohmann::json::exception& e) {
    return cases::Result::failure(std::string("result line: ") + e.what());
  }
  return r;
}

}  // namespace

bool isExternalBackend(const std::string& name) { return name == "bullet" || name == "gq-bullet"; }

std::vector<CaseRecord> runBackendExternal(const std::string& gqQuery, const std::string& name,
                                           const std::vector<LoadedCase>& cases, int repeat) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("gq-compare-" + std::to_string(getpid()) + "-" + name + ".jsonl")).string();
  {
    std::ofstream f(path);
    for (const LoadedCase& c : cases) f << c.text << '\n';
  }
  std::vector<std::string> lines;
  const std::string command = "'" + gqQuery + "' --backend " + name + " --repeat " + std::to_string(repeat) +
                              " '" + path + "' 2>/dev/null";
  if (FILE* p = popen(command.c_str(), "r")) {
    char* buf = nullptr;
    std::size_t cap = 0;
    for (ssize_t n; (n = getline(&buf, &cap, p)) > 0;) lines.emplace_back(buf, buf[n - 1] == '\n' ? n - 1 : n);
    std::free(buf);
    pclose(p);
  }
  std::filesystem::remove(path);
  std::vector<CaseRecord> records;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const cases::Result r = i < lines.size() && lines.size() == cases.size()
                                ? resultFromLine(cases[i].family, lines[i])
                                : cases::Result::failure("gq-query --backend " + name + " gave no answer");
    records.push_back({&cases[i], name, judge(cases[i].family, cases[i].input.precision, cases[i].expect, r), r.ns});
  }
  return records;
}

}  // namespace gq::compare
