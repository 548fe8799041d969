#include "report.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>
#include <tuple>
#include <unistd.h>

namespace gq::compare {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  return v[mid];
}

const char* precisionName(cases::Precision p) { return p == cases::Precision::Float ? "float" : "double"; }

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", v);
  return buf;
}

}  // namespace

bool isDisagreement(Outcome o) {
  return o == Outcome::WrongBoolean || o == Outcome::Ambiguous || o == Outcome::BeyondTolerance ||
         o == Outcome::Failed;
}

std::vector<Row> summarize(const std::vector<CaseRecord>& records) {
  std::map<std::tuple<std::string, std::string, std::string>, std::pair<Row, std::pair<std::vector<double>, std::vector<double>>>> acc;
  std::vector<std::tuple<std::string, std::string, std::string>> order;
  for (const CaseRecord& r : records) {
    const auto key = std::make_tuple(r.c->family, r.backend, std::string(precisionName(r.c->input.precision)));
    auto [it, fresh] = acc.try_emplace(key);
    if (fresh) order.push_back(key);
    Row& row = it->second.first;
    row.family = std::get<0>(key), row.backend = std::get<1>(key), row.precision = std::get<2>(key);
    ++row.cases;
    switch (r.verdict.outcome) {
      case Outcome::Unsupported: ++row.unsupported; continue;
      case Outcome::Failed: ++row.failed; continue;
      case Outcome::WrongBoolean: ++row.wrongBooleans; break;
      case Outcome::Ambiguous: ++row.ambiguous; break;
      case Outcome::BeyondTolerance: ++row.beyondTolerance; break;
      case Outcome::Correct: break;
    }
    ++row.answered;
    it->second.second.second.push_back(r.ns);
    if (r.verdict.error) it->second.second.first.push_back(*r.verdict.error);
  }
  std::vector<Row> rows;
  for (const auto& key : order) {
    auto& [row, samples] = acc[key];
    row.withError = samples.first.size();
    row.medianError = median(samples.first);
    row.maxError = samples.first.empty() ? 0 : *std::max_element(samples.first.begin(), samples.first.end());
    row.medianNs = median(samples.second);
    rows.push_back(row);
  }
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    return std::tie(a.family, a.backend, a.precision) < std::tie(b.family, b.backend, b.precision);
  });
  return rows;
}

void printTable(std::ostream& out, const std::vector<Row>& rows) {
  out << std::left << std::setw(14) << "family" << std::setw(12) << "backend" << std::setw(7) << "prec" << std::right
      << std::setw(7) << "cases" << std::setw(9) << "answered" << std::setw(7) << "wrong" << std::setw(7) << "ambig"
      << std::setw(8) << ">tol" << std::setw(11) << "med err" << std::setw(11) << "max err" << std::setw(10)
      << "med ns" << '\n';
  for (const Row& r : rows) {
    out << std::left << std::setw(14) << r.family << std::setw(12) << r.backend << std::setw(7) << r.precision
        << std::right << std::setw(7) << r.cases << std::setw(9) << r.answered << std::setw(7) << r.wrongBooleans
        << std::setw(7) << r.ambiguous << std::setw(8) << r.beyondTolerance << std::setw(11)
        << (r.withError ? sci(r.medianError) : "-") << std::setw(11) << (r.withError ? sci(r.maxError) : "-")
        << std::setw(10) << std::fixed << std::setprecision(0) << r.medianNs << '\n';
    out.unsetf(std::ios::fixed);
  }
  out << "wrong: wrong booleans (exact margin beyond tolerance); ambig: boolean differs within tolerance of "
         "touching; >tol: relative error above tolerance (double 1e-9 analytic, 1e-7 GJK/EPA/mesh; float 1e-4); "
         "errors are |answer - exact| / scale\n";
}

namespace {

bool answered(Outcome o) { return o != Outcome::Unsupported && o != Outcome::Failed; }

// gq first, then gq through its adapters, then the peers in name order.
int backendRank(const std::string& name) {
  if (name == "gq") return 0;
  return name.rfind("gq-", 0) == 0 ? 1 : 2;
}

std::string ratioText(double r) {
  char buf[32];
  std::snprintf(buf, sizeof buf, r >= 10 ? "%.0fx" : "%.1fx", r);
  return buf;
}

}  // namespace

void printSummary(std::ostream& out, const std::vector<Row>& rows, const std::vector<CaseRecord>& records) {
  // Per family x precision: gq's time on each case it answered, to time the others on the same cases.
  std::map<std::pair<std::string, std::string>, std::map<const LoadedCase*, double>> gqNs;
  std::map<std::tuple<std::string, std::string, std::string>, std::vector<const CaseRecord*>> byRow;
  for (const CaseRecord& r : records) {
    const std::string prec = precisionName(r.c->input.precision);
    if (!answered(r.verdict.outcome)) continue;
    if (r.backend == "gq") gqNs[{r.c->family, prec}][r.c] = r.ns;
    byRow[{r.c->family, r.backend, prec}].push_back(&r);
  }
  const auto relativeTime = [&](const Row& row) -> std::string {
    if (row.backend == "gq") return "1";
    const auto g = gqNs.find({row.family, row.precision});
    if (g == gqNs.end()) return "-";
    std::vector<double> mine, theirs;
    for (const CaseRecord* r : byRow[{row.family, row.backend, row.precision}])
      if (auto it = g->second.find(r->c); it != g->second.end()) {
        mine.push_back(r->ns);
        theirs.push_back(it->second);
      }
    const double gqMedian = median(theirs);
    if (mine.empty() || !(gqMedian > 0)) return "-";
    return ratioText(median(mine) / gqMedian);
  };

  std::vector<std::string> families;
  for (const Row& r : rows)
    if (std::find(families.begin(), families.end(), r.family) == families.end()) families.push_back(r.family);
  out << "Accuracy and speed per query family against exact answers (computed in long double, independently of every\n"
         "backend). answered: cases with an answer (the others are unsupported, or rejected as invalid input such as\n"
         "degenerate shapes); wrong: wrong booleans plus values beyond tolerance (double 1e-9 closed forms, 1e-7\n"
         "GJK/EPA and meshes; float 1e-4); err: |answer - exact| / scale; time/gq: the backend's median time over\n"
         "gq's on the cases both answered (above 1: gq is faster).\n";
  for (const std::string& family : families) {
    std::vector<const Row*> shown;
    std::vector<std::string> silent;
    for (const Row& r : rows) {
      if (r.family != family) continue;
      if (r.answered > 0) shown.push_back(&r);
      else if (std::find(silent.begin(), silent.end(), r.backend) == silent.end()) silent.push_back(r.backend);
    }
    // A backend that answers in one precision is not listed as silent for the other.
    for (const Row* r : shown) silent.erase(std::remove(silent.begin(), silent.end(), r->backend), silent.end());
    std::stable_sort(shown.begin(), shown.end(), [](const Row* a, const Row* b) {
      return std::make_tuple(backendRank(a->backend), a->backend, a->precision) <
             std::make_tuple(backendRank(b->backend), b->backend, b->precision);
    });
    out << '\n' << family << '\n';
    out << "  " << std::left << std::setw(12) << "backend" << std::setw(8) << "prec" << std::right << std::setw(10)
        << "answered" << std::setw(7) << "wrong" << std::setw(10) << "med err" << std::setw(10) << "max err"
        << std::setw(9) << "med ns" << std::setw(9) << "time/gq" << '\n';
    for (const Row* r : shown) {
      const std::string answeredText = std::to_string(r->answered) + "/" + std::to_string(r->cases);
      char ns[32];
      std::snprintf(ns, sizeof ns, "%.0f", r->medianNs);
      out << "  " << std::left << std::setw(12) << r->backend << std::setw(8) << r->precision << std::right
          << std::setw(10) << answeredText << std::setw(7) << (r->wrongBooleans + r->beyondTolerance)
          << std::setw(10) << (r->withError ? sci(r->medianError) : "-") << std::setw(10)
          << (r->withError ? sci(r->maxError) : "-") << std::setw(9) << ns << std::setw(9) << relativeTime(*r)
          << '\n';
    }
    if (!silent.empty()) {
      out << "  not answered by:";
      for (std::size_t i = 0; i < silent.size(); ++i) out << (i ? ", " : " ") << silent[i];
      out << '\n';
    }
  }
}

bool writeCsv(const std::string& dir, const std::vector<Row>& rows, std::string& error) {
  std::filesystem::create_directories(dir);
  const std::string date = todayUtc(), machine = machineName(), commit = sourceCommit();
  std::map<std::string, std::ofstream> files;
  for (const Row& r : rows) {
    auto it = files.find(r.family);
    if (it == files.end()) {
      const std::string path = dir + "/compare_" + r.family + ".csv";
      it = files.emplace(r.family, std::ofstream(path)).first;
      if (!it->second) {
        error = "cannot write " + path;
        return false;
      }
      it->second << "date,machine,commit,family,backend,precision,cases,answered,unsupported,failed,wrong_booleans,"
                    "ambiguous,beyond_tolerance,median_rel_error,max_rel_error,median_ns\n";
    }
    it->second << date << ",\"" << machine << "\"," << commit << ',' << r.family << ',' << r.backend << ',' << r.precision << ','
               << r.cases << ',' << r.answered << ',' << r.unsupported << ',' << r.failed << ',' << r.wrongBooleans
               << ',' << r.ambiguous << ',' << r.beyondTolerance << ',';
    if (r.withError) it->second << std::setprecision(3) << r.medianError << ',' << r.maxError;
    else it->second << ',';
    it->second << ',' << std::fixed << std::setprecision(0) << r.medianNs << '\n';
    it->second.unsetf(std::ios::fixed);
  }
  return true;
}

std::size_t countDisagreements(const std::vector<CaseRecord>& records) {
  return std::size_t(std::count_if(records.begin(), records.end(),
                                   [](const CaseRecord& r) { return isDisagreement(r.verdict.outcome); }));
}

std::size_t writeDisagreements(const std::string& path, const std::vector<CaseRecord>& records) {
  std::map<const LoadedCase*, const CaseRecord*> gqAnswer;
  std::map<std::string, std::size_t> unsupported;
  std::vector<std::string> backends;
  for (const CaseRecord& r : records) {
    if (r.backend == "gq") gqAnswer[r.c] = &r;
    if (r.verdict.outcome == Outcome::Unsupported) ++unsupported[r.backend];
    if (std::find(backends.begin(), backends.end(), r.backend) == backends.end()) backends.push_back(r.backend);
  }
  std::ofstream out(path);
  out << "# Disagreements with the exact answers\n\n"
      << "Generated by gq-compare on " << todayUtc() << " (" << machineName() << ", commit " << sourceCommit()
      << "). The exact answer is the "
      << "referee (computed by gq-make-suites in long double, independently of every backend); a backend that "
      << "differs from it is the one that is wrong. Classes: *wrong boolean* (the exact configuration is farther "
      << "than the tolerance from flipping it), *ambiguous boolean* (within tolerance of touching: not counted as "
      << "wrong), *value beyond tolerance* (relative error |answer - exact| / scale above double 1e-9 analytic, "
      << "1e-7 GJK/EPA/mesh, float 1e-4), *failed* (a status other than unsupported). Unsupported cases are "
      << "only counted.\n\n";
  std::size_t listed = 0;
  for (const std::string& backend : backends) {
    std::map<std::string, std::size_t> byClass;
    for (const CaseRecord& r : records)
      if (r.backend == backend && isDisagreement(r.verdict.outcome))
        ++byClass[r.c->family + " / " + r.c->group + " / " + toString(r.verdict.outcome)];
    out << "## " << backend << "\n\n" << unsupported[backend] << " cases unsupported.\n\n";
    if (byClass.empty()) {
      out << "No disagreement.\n\n";
      continue;
    }
    out << "| family / group / class | cases |\n|---|---|\n";
    for (const auto& [k, n] : byClass) out << "| " << k << " | " << n << " |\n";
    out << "\n| case | family | class | relative error | exact | " << backend << " | gq |\n|---|---|---|---|---|---|---|\n";
    for (const CaseRecord& r : records) {
      if (r.backend != backend || !isDisagreement(r.verdict.outcome)) continue;
      std::string gq = "-";
      if (auto it = gqAnswer.find(r.c); it != gqAnswer.end() && backend != "gq")
        gq = std::string(toString(it->second->verdict.outcome)) + ": " + it->second->verdict.answer;
      std::string answer = r.verdict.answer;
      std::replace(answer.begin(), answer.end(), '|', '/');
      std::replace(gq.begin(), gq.end(), '|', '/');
      out << "| " << r.c->id << " | " << r.c->family << " | " << toString(r.verdict.outcome) << " | "
          << (r.verdict.error ? sci(*r.verdict.error) : "-") << " | " << r.verdict.exact << " | " << answer << " | "
          << gq << " |\n";
      ++listed;
    }
    out << '\n';
  }
  return out ? listed : 0;
}

std::string machineName() {
  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  std::ifstream cpu("/proc/cpuinfo");
  std::string line, model = "unknown cpu";
  while (std::getline(cpu, line))
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  std::string name = std::string(host) + ", " + model + ", " + std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) + " cores";
  std::replace(name.begin(), name.end(), '"', '\'');
  return name;
}

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

std::string todayUtc() {
  const std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", std::gmtime(&now));
  return buf;
}

}  // namespace gq::compare
