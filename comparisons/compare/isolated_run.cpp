#include "isolated_run.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "backend.h"

namespace gq::compare {
namespace {

std::string oneLine(std::string s) {
  for (char& ch : s)
    if (ch == '\t' || ch == '\n' || ch == '\r') ch = ' ';
  return s;
}

// Child: answers cases[begin..] and writes "index \t outcome \t hasError \t error \t ns \t answer \t exact".
[[noreturn]] void childRun(int fd, const std::string& backendName, const std::vector<LoadedCase>& cases,
                           std::size_t begin, int repeat) {
  // Native libraries print assertion text on stderr before aborting; the verdict records the signal instead.
  if (FILE* quiet = std::freopen("/dev/null", "w", stderr); quiet == nullptr) _exit(1);
  FILE* out = fdopen(fd, "w");
  std::unique_ptr<cases::Backend> backend = cases::makeBackend(backendName);
  for (std::size_t i = begin; i < cases.size() && out != nullptr; ++i) {
    alarm(kCaseTimeLimitSeconds);
    const cases::Result r = backend->run(cases[i].input, repeat);
    const Verdict v = judge(cases[i].family, cases[i].input.precision, cases[i].expect, r);
    std::fprintf(out, "%zu\t%d\t%d\t%.17g\t%.17g\t%s\t%s\n", i, int(v.outcome), v.error ? 1 : 0,
                 v.error ? *v.error : 0.0, r.ns, oneLine(v.answer).c_str(), oneLine(v.exact).c_str());
    std::fflush(out);
  }
  _exit(0);
}

bool parseLine(const std::string& line, std::size_t& index, CaseRecord& rec) {
  std::vector<std::string> f;
  std::stringstream ss(line);
  for (std::string part; std::getline(ss, part, '\t');) f.push_back(part);
  if (f.size() < 5) return false;
  f.resize(7);
  index = std::stoul(f[0]);
  rec.verdict.outcome = Outcome(std::stoi(f[1]));
  if (f[2] == "1") rec.verdict.error = std::strtod(f[3].c_str(), nullptr);
  rec.ns = std::strtod(f[4].c_str(), nullptr);
  rec.verdict.answer = f[5];
  rec.verdict.exact = f[6];
  return true;
}

std::string describeExit(int status) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    return "crashed: signal " + std::to_string(sig) + (sig == SIGALRM ? " (time limit)" : " (" + std::string(strsignal(sig)) + ")");
  }
  return "child exited with status " + std::to_string(WEXITSTATUS(status));
}

}  // namespace

std::vector<CaseRecord> runBackendIsolated(const std::string& backendName, const std::vector<LoadedCase>& cases,
                                           int repeat, const std::function<void()>& onCaseDone) {
  std::vector<CaseRecord> records;
  std::size_t next = 0;
  while (next < cases.size()) {
    int fds[2];
    if (pipe(fds) != 0) break;
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
      close(fds[0]);
      childRun(fds[1], backendName, cases, next, repeat);
    }
    close(fds[1]);
    FILE* in = fdopen(fds[0], "r");
    char* buf = nullptr;
    std::size_t cap = 0;
    while (in != nullptr && getline(&buf, &cap, in) > 0) {
      std::string line(buf);
      if (!line.empty() && line.back() == '\n') line.pop_back();
      std::size_t index = 0;
      CaseRecord rec;
      if (!parseLine(line, index, rec) || index != next) continue;
      rec.c = &cases[index];
      rec.backend = backendName;
      records.push_back(std::move(rec));
      ++next;
      onCaseDone();
    }
    std::free(buf);
    if (in != nullptr) std::fclose(in);
    int status = 0;
    if (pid > 0) waitpid(pid, &status, 0);
    if (next < cases.size()) {
      // The child died on cases[next]: record it and go on after it.
      CaseRecord rec;
      rec.c = &cases[next];
      rec.backend = backendName;
      rec.verdict.outcome = Outcome::Failed;
      rec.verdict.answer = pid > 0 ? describeExit(status) : "fork failed";
      records.push_back(std::move(rec));
      ++next;
      onCaseDone();
    }
  }
  return records;
}

}  // namespace gq::compare
