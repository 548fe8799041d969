// gq-urdf: info, check, never and bench on a URDF (+ SRDF) robot. Single thread throughout.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "gq/urdf/fcl_checker.h"
#include "gq/urdf/robot.h"
#include "gq/urdf/self_collision.h"

namespace {

using namespace gq::urdf;
using Clock = std::chrono::steady_clock;

struct CommonOptions {
  std::string urdf, srdf, mode = "hull";
  std::vector<std::string> packagePaths;
};

void addCommon(CLI::App& app, CommonOptions& o) {
  app.add_option("--urdf", o.urdf, "URDF file")->required();
  app.add_option("--srdf", o.srdf, "SRDF file (disable_collisions, group states)");
  app.add_option("--mode", o.mode, "mesh | hull | box | box-aabb | capsule | sphere | best-primitive | fit:<tolerance, metres>");
  app.add_option("--package-path", o.packagePaths, "folder holding ROS packages (repeatable; ROS_PACKAGE_PATH also used)");
}

int fail(const gq::Status& s) {
  std::cerr << "gq-urdf: " << s.toString() << "\n";
  return s.code == gq::StatusCode::InvalidArgument ? 2 : 1;
}

gq::Status load(const CommonOptions& o, const std::string& mode, std::shared_ptr<const RobotModel<double>>& out) {
  LoadOptions lo;
  lo.packagePaths = o.packagePaths;
  gq::Status s = parseMode(mode, lo);
  if (!s.ok()) return s;
  auto model = std::make_shared<RobotModel<double>>();
  s = loadRobot(o.urdf, o.srdf, lo, *model);
  if (!s.ok()) return s;
  if (s.code == gq::StatusCode::Warning) std::cerr << "warning: " << s.detailedMessage() << "\n";
  out = model;
  return {};
}

std::string pairName(const RobotModel<double>& m, const LinkPair& p) {
  return m.links[p.a].name + " - " + m.links[p.b].name;
}

int runInfo(const CommonOptions& o) {
  std::shared_ptr<const RobotModel<double>> m;
  if (gq::Status s = load(o, o.mode, m); !s.ok()) return fail(s);
  std::printf("robot %s: %zu links, %zu joints, %zu variables, %zu shapes, representation %s, memory %.1f KiB\n",
              m->name.c_str(), m->links.size(), m->joints.size(), m->variables.size(), m->shapes.size(),
              o.mode.c_str(), m->memoryBytes() / 1024.0);
  std::printf("\njoints:\n");
  for (const auto& j : m->joints)
    std::printf("  %-28s %-10s %s -> %s  [%g, %g]%s\n", j.name.c_str(), toString(j.type),
                m->links[j.parentLink].name.c_str(), m->links[j.childLink].name.c_str(), double(j.lower),
                double(j.upper), j.mimicJoint >= 0 ? "  (mimic)" : "");
  std::printf("\nshapes (bound: certified upper bound of the two-sided Hausdorff distance between the mesh and its "
              "model, metres; a decomposition's parts share their union's bound):\n");
  for (const auto& sh : m->shapes) {
    const bool mesh = sh.source == ShapeSource::Mesh;
    const std::string as = !mesh ? (sh.source == ShapeSource::Cylinder ? "exact cylinder" : toString(sh.source))
                           : sh.representation == Representation::BoxAabb ? "box-aabb"
                           : sh.fitParts > 1 ? std::string(gq::toString(sh.fitted)) + " x" + std::to_string(sh.fitParts)
                                             : gq::toString(sh.fitted);
    std::printf("  %-20s %-9s as %-18s src tris %6u  model faces %5u  bound %.5f  %7.1f KiB  %s\n",
                m->links[sh.link].name.c_str(), toString(sh.source), as.c_str(), sh.sourceTriangles,
                sh.modelTriangles, double(sh.errorBound), sh.bytes / 1024.0, sh.file.c_str());
  }
  std::printf("\nper link (largest bound of its shapes):\n");
  for (const auto& link : m->links) {
    if (link.shapes.empty()) continue;
    double bound = 0;
    for (std::uint32_t i : link.shapes) bound = std::max(bound, double(m->shapes[i].errorBound));
    std::printf("  %-20s %2zu shape(s)  bound %.5f\n", link.name.c_str(), link.shapes.size(), bound);
  }
  std::size_t checked = 0, allowed = 0;
  for (std::uint32_t a = 0; a < m->links.size(); ++a)
    for (std::uint32_t b = a + 1; b < m->links.size(); ++b) {
      if (m->links[a].shapes.empty() || m->links[b].shapes.empty()) continue;
      (m->isAllowed(a, b) ? allowed : checked)++;
    }
  std::printf("\nlink pairs with shapes: %zu checked, %zu allowed (adjacent / same link / SRDF)\nhome: %s\n", checked,
              allowed, m->homeSource.c_str());
  std::printf("cylinders: exact (gq custom Cylinder), error 0\n");
  return 0;
}

gq::Status readConfiguration(const std::string& path, const RobotModel<double>& m, std::vector<double>& q) {
  std::ifstream in(path);
  if (!in) return gq::Status::owned(gq::StatusCode::FileError, "configuration file '" + path + "' cannot be opened");
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded()) return gq::Status::owned(gq::StatusCode::ParseError, "configuration file '" + path + "' is not valid JSON");
  q = m.home;
  if (j.is_array()) {
    if (j.size() != q.size() || !std::all_of(j.begin(), j.end(), [](auto& v) { return v.is_number(); }))
      return gq::Status::owned(gq::StatusCode::InvalidArgument, "configuration array needs " + std::to_string(q.size()) + " numbers");
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = j[i].get<double>();
    return {};
  }
  if (!j.is_object()) return gq::Status::invalid("configuration must be an array or an object {joint: value}");
  for (auto it = j.begin(); it != j.end(); ++it) {
    const auto v = std::find(m.variables.begin(), m.variables.end(), it.key());
    if (v == m.variables.end() || !it.value().is_number())
      return gq::Status::owned(gq::StatusCode::InvalidArgument, "configuration names unknown joint '" + it.key() + "' or has a non-number value");
    q[std::size_t(v - m.variables.begin())] = it.value().get<double>();
  }
  return {};
}

void progress(std::size_t done, std::size_t total) {
  if (total < 1000 || (done % (total / 100) != 0 && done != total)) return;
  const int width = 40, filled = int(width * done / total);
  std::fprintf(stderr, "\r[%s%s] %3zu%%", std::string(filled, '#').c_str(), std::string(width - filled, ' ').c_str(),
               done * 100 / total);
  if (done == total) std::fprintf(stderr, "\n");
}

int runCheck(const CommonOptions& o, const std::string& config, std::size_t random, std::uint64_t seed) {
  std::shared_ptr<const RobotModel<double>> m;
  if (gq::Status s = load(o, o.mode, m); !s.ok()) return fail(s);
  SelfCollisionChecker<double> checker(m);
  if (random == 0) {
    std::vector<double> q = m->home;
    if (!config.empty())
      if (gq::Status s = readConfiguration(config, *m, q); !s.ok()) return fail(s);
    CollisionResult r;
    const auto t0 = Clock::now();
    if (gq::Status s = checker.checkSelfCollision(q, r); !s.ok()) return fail(s);
    const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
    std::printf("%s (%s) in %.1f us\n", r.colliding ? "COLLIDING" : "collision-free",
                config.empty() ? m->homeSource.c_str() : config.c_str(), us);
    for (const auto& p : r.pairs) std::printf("  %s\n", pairName(*m, p).c_str());
    SelfDistanceResult<double> d;
    if (gq::Status s = checker.selfDistance(q, d); s.ok())
      std::printf("self distance %.6f m between %s\n", d.distance, pairName(*m, d.pair).c_str());
    else
      std::printf("self distance: %s\n", s.toString().c_str());
    return r.colliding ? 3 : 0;
  }
  std::uint64_t rng = seed;
  std::size_t colliding = 0;
  double seconds = 0;
  std::map<LinkPair, std::size_t> counts;
  std::size_t narrow = 0;
  for (std::size_t i = 0; i < random; ++i) {
    const std::vector<double> q = randomConfiguration(*m, rng);
    CollisionResult r;
    const auto t0 = Clock::now();
    if (gq::Status s = checker.checkSelfCollision(q, r); !s.ok()) return fail(s);
    seconds += std::chrono::duration<double>(Clock::now() - t0).count();
    colliding += r.colliding;
    narrow += checker.lastNarrowPhasePairs();
    for (const auto& p : r.pairs) ++counts[p];
    progress(i + 1, random);
  }
  std::printf("%zu of %zu random configurations collide (seed %llu); %.2f us per check, %.2f narrow-phase shape "
              "pairs per check\n", colliding, random, (unsigned long long)seed, 1e6 * seconds / double(random),
              double(narrow) / double(random));
  for (const auto& [p, n] : counts) std::printf("  %6zu  %s\n", n, pairName(*m, p).c_str());
  return 0;
}

int runNever(const CommonOptions& o, std::uint64_t samples, std::uint64_t seed, const std::string& out) {
  std::shared_ptr<const RobotModel<double>> m;
  if (gq::Status s = load(o, o.mode, m); !s.ok()) return fail(s);
  NeverCollidingResult r;
  if (gq::Status s = neverColliding(m, samples, seed, r); !s.ok()) return fail(s);
  const std::string srdf = writeSrdfDisableCollisions(*m, r.never);
  if (out.empty()) {
    std::cout << srdf;
  } else {
    std::ofstream f(out);
    if (!(f << srdf)) return fail(gq::Status::owned(gq::StatusCode::FileError, "cannot write '" + out + "'"));
  }
  std::fprintf(stderr, "%zu link pairs never collided in %llu samples\n", r.never.size(), (unsigned long long)samples);
  return 0;
}

std::string machineName() {
  std::ifstream cpu("/proc/cpuinfo");
  for (std::string line; std::getline(cpu, line);)
    if (line.rfind("model name", 0) == 0) {
      std::string name = line.substr(line.find(':') + 2);
      std::replace(name.begin(), name.end(), ',', ' ');
      return name;
    }
  return "unknown";
}

// The source tree's commit (git rev-parse), or "unknown" outside a git checkout: benchmark rows carry it.
std::string sourceCommit() {
  std::string commit;
  if (FILE* git = popen("git -C '" GQ_SOURCE_DIR "' rev-parse --short=8 HEAD 2>/dev/null", "r")) {
    char buf[64] = {0};
    if (std::fgets(buf, sizeof buf, git)) commit = buf;
    pclose(git);
  }
  while (!commit.empty() && std::isspace(static_cast<unsigned char>(commit.back()))) commit.pop_back();
  return commit.empty() ? "unknown" : commit;
}

// Checks per second over `qs`, or a negative value with the status when the backend cannot answer.
template <class Check> double checksPerSecond(const std::vector<std::vector<double>>& qs, Check&& check, gq::Status& s) {
  CollisionResult r;
  const auto t0 = Clock::now();
  for (const auto& q : qs) {
    s = check(q, r);
    if (!s.ok()) return -1;
  }
  return double(qs.size()) / std::chrono::duration<double>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct BenchOptions {
  std::size_t n = 5000, repetitions = 5;
  std::uint64_t seed = 1;
  std::string csv;
  std::vector<std::string> modes{"mesh", "hull", "best-primitive"};
  std::vector<std::string> backends{"gq", "fcl"};
};

// One backend's median rate (negative: unsupported, with the status).
struct BenchRow {
  std::string backend;
  double rate = -1;
  gq::Status status;
};

// Median over `repetitions` timed runs of the same configurations; gq and FCL alternate within each repetition so
// that machine noise hits both alike.
int runBench(const CommonOptions& o, const BenchOptions& b) {
  std::ofstream out;
  if (!b.csv.empty()) {
    // mode = <URDF file stem>:<representation>; load1 = 1-minute load average at the start (the machine is shared)
    const std::string header =
        "date,machine,commit,load1,mode,backend,checks_per_s_median,repetitions,configurations,ratio";
    std::string existing;
    if (std::ifstream in(b.csv); in && std::getline(in, existing) && existing != header)
      return fail(gq::Status::owned(gq::StatusCode::FileError, "'" + b.csv + "' has other columns than '" + header +
                                              "': not appending to it"));
    out.open(b.csv, std::ios::app);
    if (existing.empty()) out << header << "\n";
    if (!out) return fail(gq::Status::owned(gq::StatusCode::FileError, "cannot write '" + b.csv + "'"));
  }
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  const std::string machine = machineName(), commit = sourceCommit();
  std::string load1 = "unknown";
  if (std::ifstream loadavg("/proc/loadavg"); loadavg) loadavg >> load1;
  const std::string urdfStem = std::filesystem::path(o.urdf).stem().string();
  const bool withGq = std::count(b.backends.begin(), b.backends.end(), "gq") > 0;
  const bool withFcl = std::count(b.backends.begin(), b.backends.end(), "fcl") > 0;
  std::printf("%-15s %-8s %14s %10s   (median of %zu runs of %zu configurations)\n", "mode", "backend",
              "checks/s", "gq/fcl", b.repetitions, b.n);
  for (const std::string& mode : b.modes) {
    std::shared_ptr<const RobotModel<double>> m;
    if (gq::Status s = load(o, mode, m); !s.ok()) return fail(s);
    std::uint64_t rng = b.seed;
    std::vector<std::vector<double>> qs;
    for (std::size_t i = 0; i < b.n; ++i) qs.push_back(randomConfiguration(*m, rng));
    CollisionRequest first;
    first.allPairs = false;
    SelfCollisionChecker<double> gqChecker(m);
    std::unique_ptr<FclSelfCollisionChecker> fclChecker;
    if (withFcl)
      if (gq::Status s = FclSelfCollisionChecker::create(m, fclChecker); !s.ok()) return fail(s);
    BenchRow gqRow{"gq"}, fclRow{"fcl"};
    std::vector<double> gqRates, fclRates;
    for (std::size_t rep = 0; rep < b.repetitions; ++rep) {
      if (withGq)
        gqRates.push_back(checksPerSecond(qs, [&](auto& q, auto& r) { return gqChecker.checkSelfCollision(q, r, first); },
                                          gqRow.status));
      if (withFcl)
        fclRates.push_back(checksPerSecond(
            qs, [&](auto& q, auto& r) { return fclChecker->checkSelfCollision(q, r, first); }, fclRow.status));
    }
    if (withGq) gqRow.rate = gqRow.status.ok() ? median(gqRates) : -1;
    if (withFcl) fclRow.rate = fclRow.status.ok() ? median(fclRates) : -1;
    const double ratio = gqRow.rate > 0 && fclRow.rate > 0 ? gqRow.rate / fclRow.rate : 0;
    for (const BenchRow* row : {&gqRow, &fclRow}) {
      if (!(row->backend == "gq" ? withGq : withFcl)) continue;
      const bool isGq = row->backend == "gq";
      if (row->rate > 0)
        std::printf("%-15s %-8s %14.0f %10s\n", mode.c_str(), row->backend.c_str(), row->rate,
                    isGq && ratio > 0 ? std::to_string(ratio).substr(0, 5).c_str() : "");
      else
        std::printf("%-15s %-8s %14s  (%s)\n", mode.c_str(), row->backend.c_str(), "n/a", row->status.detailedMessage().c_str());
      if (out.is_open())
        out << date << "," << machine << "," << commit << "," << load1 << "," << urdfStem << ":" << mode << "," << row->backend << ","
            << (row->rate > 0 ? std::to_string(row->rate) : "unsupported") << "," << b.repetitions << "," << b.n
            << "," << (isGq ? std::to_string(ratio) : "1") << "\n";
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"gq-urdf: URDF/SRDF robot self-collision with GeomQuery"};
  app.require_subcommand(1);
  CommonOptions common;
  auto* info = app.add_subcommand("info", "links, joints, shapes, triangle counts, certified error bounds, memory");
  addCommon(*info, common);
  std::string config;
  std::size_t random = 0;
  BenchOptions benchOptions;
  std::uint64_t seed = 1, samples = 10000;
  std::string out;
  auto* check = app.add_subcommand("check", "self-collision of one configuration (JSON) or of N random ones");
  addCommon(*check, common);
  check->add_option("--config", config, "JSON: [q0, q1, ...] or {\"joint\": value}; default: the home pose");
  check->add_option("--random", random, "check N random configurations");
  check->add_option("--seed", seed, "random seed");
  auto* never = app.add_subcommand("never", "write the SRDF disable_collisions list (adjacent + never colliding)");
  addCommon(*never, common);
  never->add_option("--samples", samples, "random configurations");
  never->add_option("--seed", seed, "random seed");
  never->add_option("--out", out, "SRDF file to write (default: stdout)");
  auto* bench = app.add_subcommand("bench", "checks/s in mesh, hull and primitive modes, gq next to FCL");
  addCommon(*bench, common);
  bench->add_option("--n", benchOptions.n, "random configurations per mode");
  bench->add_option("--seed", benchOptions.seed, "random seed");
  bench->add_option("--repetitions", benchOptions.repetitions, "timed runs per backend; the median is reported")
      ->check(CLI::PositiveNumber);
  bench->add_option("--modes", benchOptions.modes, "representations to time (default: mesh hull best-primitive)");
  bench->add_option("--backends", benchOptions.backends, "gq and/or fcl (default: both)");
  bench->add_option("--csv", benchOptions.csv, "append rows (median rates) to this CSV");
  CLI11_PARSE(app, argc, argv);
  try {
    if (*info) return runInfo(common);
    if (*check) return runCheck(common, config, random, seed);
    if (*never) return runNever(common, samples, seed, out);
    if (*bench) return runBench(common, benchOptions);
  } catch (const std::exception& e) {
    std::cerr << "gq-urdf: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
