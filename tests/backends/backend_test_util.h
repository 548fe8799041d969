#pragma once
// Helpers for the native-backend tests: case lines built as JSON, run through a backend by name ("bullet" runs
// through `gq-query --backend bullet`, which forwards to the two Bullet builds), results parsed back.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "backend.h"
#include "runner.h"

namespace gq::cases::test {

using json = nlohmann::json;

template <class T> struct PrecisionOf;
template <> struct PrecisionOf<float> { static constexpr const char* name = "float"; };
template <> struct PrecisionOf<double> { static constexpr const char* name = "double"; };

inline json vec(double x, double y, double z) { return json::array({x, y, z}); }
inline json pose(const json& p, const json& q = json::array({0, 0, 0, 1})) { return {{"p", p}, {"q", q}}; }
// Quaternion [x,y,z,w] of a rotation by `angle` about the unit axis (ax, ay, az).
inline json axisAngle(double ax, double ay, double az, double angle) {
  const double s = std::sin(angle / 2);
  return json::array({ax * s, ay * s, az * s, std::cos(angle / 2)});
}
inline json sphere(double r) { return {{"type", "sphere"}, {"radius", r}}; }
inline json capsule(double r, double hh) { return {{"type", "capsule"}, {"radius", r}, {"halfHeight", hh}}; }
inline json box(double x, double y, double z) { return {{"type", "box"}, {"halfExtents", vec(x, y, z)}}; }
inline json plane() { return {{"type", "plane"}}; }
inline json convex(const json& points) { return {{"type", "convex"}, {"points", points}}; }

inline json pairCase(const char* query, const char* precision, const json& g0, const json& p0, const json& g1,
                     const json& p1) {
  return {{"id", query}, {"precision", precision}, {"query", query}, {"geom0", g0}, {"pose0", p0},
          {"geom1", g1}, {"pose1", p1}};
}

inline std::vector<json> parseLines(const std::string& text) {
  std::vector<json> out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) out.push_back(json::parse(line));
  return out;
}

// Runs gq-query (the program, so the Bullet forwarding is exercised) on the cases.
inline std::vector<json> runProgram(const std::string& backend, const std::vector<json>& cases) {
  static int counter = 0;
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("gq_backends_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++) + ".jsonl");
  {
    std::ofstream out(file);
    for (const json& c : cases) out << c.dump() << '\n';
  }
  const std::string command = std::string(GQ_QUERY_EXE) + " --backend " + backend + " " + file.string();
  std::string text;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) text.append(buffer, n);
    pclose(pipe);
  }
  std::filesystem::remove(file);
  return parseLines(text);
}

// Runs the cases through the named backend in this process ("bullet": through the program).
inline std::vector<json> runBackend(const std::string& backend, const std::vector<json>& cases) {
  if (backend == "bullet") return runProgram(backend, cases);
  std::string text;
  for (const json& c : cases) text += c.dump() + "\n";
  std::istringstream in(text);
  std::ostringstream out;
  std::unique_ptr<Backend> b = makeBackend(backend);
  if (!b) return {};
  runCases(in, GQ_SOURCE_DIR "/comparisons/cases/examples", *b, 1, out);
  return parseLines(out.str());
}

inline json runOne(const std::string& backend, const json& c) {
  const std::vector<json> r = runBackend(backend, {c});
  return r.size() == 1 ? r[0] : json();
}

inline double num(const json& v) { return v.get<double>(); }
inline double dist3(const json& a, double x, double y, double z) {
  return std::sqrt(std::pow(num(a[0]) - x, 2) + std::pow(num(a[1]) - y, 2) + std::pow(num(a[2]) - z, 2));
}

}  // namespace gq::cases::test
