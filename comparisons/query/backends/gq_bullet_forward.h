#pragma once
// "gq-bullet": gq answering through the Bullet adapter. Like "bullet", it runs in the helper programs
// gq-query-bullet (float) and gq-query-bullet64 (double), `--backend gq-bullet`, because Bullet's two builds cannot
// share a process. gq-query's in-process runner hands this backend one case at a time, so on its first case it runs
// both helpers over the whole case file named on gq-query's command line (read from /proc/self/cmdline; gq-query
// forwards only "bullet" itself) and then answers each case from the helper line of the matching precision.
#include <string>
#include <vector>

#include "backend.h"

namespace gq::cases {

class GqBulletForwardingBackend final : public Backend {
 public:
  const char* name() const override { return "gq-bullet"; }
  Result run(const Case& c, int repeat) override;

 private:
  bool started_ = false;
  std::string error_;                   // why the helpers gave no answers
  std::vector<std::string> lineAnswer_;  // helper result line per input line number (1-based; blank lines empty)
};

}  // namespace gq::cases
