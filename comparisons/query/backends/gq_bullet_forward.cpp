#include "gq_bullet_forward.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "bullet_backend.h"

namespace gq::cases {
namespace {

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}

// gq-query's own arguments: the case file (the positional argument) and --repeat.
bool commandLine(std::string& casesPath, int& repeat) {
  std::ifstream f("/proc/self/cmdline", std::ios::binary);
  std::vector<std::string> args;
  for (std::string a; std::getline(f, a, '\0');) args.push_back(a);
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) == 0) {
      const bool takesValue = a.find('=') == std::string::npos;
      if (a.rfind("--repeat", 0) == 0) {
        const std::string v = takesValue ? (i + 1 < args.size() ? args[i + 1] : "1") : a.substr(a.find('=') + 1);
        repeat = std::max(1, std::atoi(v.c_str()));
      }
      if (takesValue) ++i;
    } else {
      casesPath = a;
    }
  }
  return !casesPath.empty();
}

bool readLines(const std::string& command, std::vector<std::string>& lines, std::string& error) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) {
    error = "cannot run " + command;
    return false;
  }
  char* buf = nullptr;
  std::size_t cap = 0;
  for (ssize_t n; (n = getline(&buf, &cap, pipe)) > 0;) lines.emplace_back(buf, buf[n - 1] == '\n' ? n - 1 : n);
  std::free(buf);
  if (pclose(pipe) != 0) {
    error = command + " failed";
    return false;
  }
  return true;
}

bool isOtherPrecision(const nlohmann::json& r) {
  return r.contains("error") && r["error"].is_string() &&
         r["error"].get<std::string>().rfind(kBulletPrecisionUnsupported, 0) == 0;
}

Vec3d vec(const nlohmann::json& v) { return Vec3d(v.at(0), v.at(1), v.at(2)); }
std::optional<Vec3d> optionalVec(const nlohmann::json& j, const char* key) {
  if (!j.contains(key)) return std::nullopt;
  return vec(j[key]);
}

// A helper's result line back into the Result it was written from (result_writer.cpp's fields).
Result resultFromJson(QueryKind kind, const nlohmann::json& j) {
  if (!j.value("ok", false)) return Result::failure(j.value("error", std::string("failed")), j.value("ns", 0.0));
  Result r;
  r.ok = true;
  r.ns = j.value("ns", 0.0);
  switch (kind) {
    case QueryKind::Raycast: {
      RaycastOut out;
      for (const auto& h : j.at("hits")) {
        RayHitOut hit;
        hit.distance = h.at("distance");
        hit.position = optionalVec(h, "position");
        hit.normal = optionalVec(h, "normal");
        hit.faceIndex = h.value("faceIndex", kNoFace);
        if (h.contains("u")) hit.uv = std::array<double, 2>{h["u"].get<double>(), h["v"].get<double>()};
        out.hits.push_back(hit);
      }
      r.fields = out;
      break;
    }
    case QueryKind::Overlap: r.fields = OverlapOut{j.at("overlap").get<bool>()}; break;
    case QueryKind::Penetration:
      r.fields = PenetrationOut{j.at("penetrating").get<bool>(), vec(j.at("direction")), j.at("depth").get<double>()};
      break;
    case QueryKind::Distance:
      r.fields = DistanceOut{j.at("distance").get<double>(), vec(j.at("point0")), vec(j.at("point1")),
                             vec(j.at("normal"))};
      break;
    case QueryKind::Sweep: {
      SweepOut out;
      out.hit = j.at("hit").get<bool>();
      if (out.hit) {
        out.distance = j.at("distance");
        out.position = optionalVec(j, "position");
        out.normal = optionalVec(j, "normal");
        out.faceIndex = j.value("faceIndex", kNoFace);
        out.initialOverlap = j.value("initialOverlap", false);
      }
      r.fields = out;
      break;
    }
    default: return Result::failure("unsupported: gq-bullet answers raycast, overlap, penetration, distance, sweep");
  }
  return r;
}

}  // namespace

Result GqBulletForwardingBackend::run(const Case& c, int) {
  if (!started_) {
    started_ = true;
    std::string casesPath;
    int repeat = 1;
    if (!commandLine(casesPath, repeat)) {
      error_ = "unsupported: gq-bullet runs through gq-query (it reads the case file from the command line)";
    } else {
      const std::string dir = std::filesystem::canonical("/proc/self/exe").parent_path().string();
      const std::string args = " --backend gq-bullet --repeat " + std::to_string(repeat) + " " + shellQuote(casesPath);
      std::vector<std::string> floatLines, doubleLines;
      if (readLines(shellQuote(dir + "/gq-query-bullet") + args, floatLines, error_) &&
          readLines(shellQuote(dir + "/gq-query-bullet64") + args, doubleLines, error_)) {
        // Helpers answer non-blank input lines in order; map them back to line numbers.
        std::ifstream in(casesPath);
        std::size_t lineNo = 0, answer = 0;
        lineAnswer_.assign(1, std::string());
        for (std::string line; std::getline(in, line);) {
          ++lineNo;
          const bool blank = line.find_first_not_of(" \t\r") == std::string::npos;
          std::string chosen;
          if (!blank && answer < floatLines.size() && answer < doubleLines.size()) {
            const nlohmann::json d = nlohmann::json::parse(doubleLines[answer], nullptr, false);
            chosen = (!d.is_discarded() && isOtherPrecision(d)) ? floatLines[answer] : doubleLines[answer];
            ++answer;
          }
          lineAnswer_.push_back(chosen);
        }
      }
    }
  }
  if (c.line >= lineAnswer_.size() || lineAnswer_[c.line].empty())
    return Result::failure(error_.empty() ? "gq-bullet: no helper answer for this line" : error_);
  const nlohmann::json j = nlohmann::json::parse(lineAnswer_[c.line], nullptr, false);
  if (j.is_discarded()) return Result::failure("gq-bullet: unreadable helper line");
  try {
    return resultFromJson(c.query, j);
  } catch (const nlohmann::json::exception& e) {
    return Result::failure(std::string("gq-bullet: helper line: ") + e.what());
  }
}

}  // namespace gq::cases
