#pragma once
// The deliberate differences of gq::fcl from FCL 0.7 (tests/fcl/deliberate_differences.txt: id | pair | FCL 0.7
// answers | gq::fcl answers | test); docs/fcl.md's table is generated from the same file by scripts/fcl-differences.
#include <fstream>
#include <string>
#include <vector>

namespace gq::fcltest {

struct Difference {
  std::string id, pair, fcl, gq, test;
};

inline std::vector<Difference> readDifferences() {
  std::ifstream in(std::string(GQ_SOURCE_DIR) + "/tests/fcl/deliberate_differences.txt");
  std::vector<Difference> list;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    for (std::size_t at = 0;;) {
      const std::size_t bar = line.find(" | ", at);
      f.push_back(line.substr(at, bar == std::string::npos ? std::string::npos : bar - at));
      if (bar == std::string::npos) break;
      at = bar + 3;
    }
    if (f.size() == 5) list.push_back({f[0], f[1], f[2], f[3], f[4]});
  }
  return list;
}

}  // namespace gq::fcltest
