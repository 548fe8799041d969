// Runs the HelloWorld example and checks where its sphere comes to rest.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace {

TEST(BulletHelloWorld, SphereComesToRestOnTheGroundBox) {
  FILE* out = popen(GQ_HELLO_WORLD_EXE, "r");
  ASSERT_NE(out, nullptr);
  char line[256];
  std::string last;
  int lines = 0;
  while (std::fgets(line, sizeof line, out)) {
    if (std::string(line).rfind("world pos object 1 =", 0) == 0) last = line, ++lines;
  }
  ASSERT_EQ(pclose(out), 0);
  EXPECT_EQ(lines, 150);
  float x = 0, y = 0, z = 0;
  ASSERT_EQ(std::sscanf(last.c_str(), "world pos object 1 = %f,%f,%f", &x, &y, &z), 3);
  EXPECT_NEAR(x, 2, 1e-3);
  EXPECT_NEAR(y, -5, 0.01);  // ground top -6, radius 1
  EXPECT_NEAR(z, 0, 1e-3);
}

}  // namespace
