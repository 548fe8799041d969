#include "report.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>
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

bool writeCsv(const std::string& dir, const std::vector<Row>& rows, std::string& error) {
  std::filesystem::create_directories(dir);
  const std::string date = todayUtc(), machine = machineName();
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
      it->second << "date,machine,family,backend,precision,cases,answered,unsupported,failed,wrong_booleans,"
                    "ambiguous,beyond_tolerance,median_rel_error,max_rel_error,median_ns\n";
    }
    it->second << date << ",\"" << machine << "\"," << r.family << ',' << r.backend << ',' << r.precision << ','
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
      << "Generated by gq-compare on " << todayUtc() << " (" << machineName() << "). The exact answer is the "
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

std::string todayUtc() {
  const std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", std::gmtime(&now));
  return buf;
}

}  // namespace gq::compare
