// Status: 16 bytes, a static message with inline details formatted by toString(), and an owned message shared by
// its copies.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "gq/geometry.h"
#include "gq/query.h"
#include "gq/status.h"

namespace gq {
namespace {

TEST(Status, FitsSixteenBytes) { EXPECT_LE(sizeof(Status), 16u); }

TEST(Status, DefaultIsOkWithAnEmptyMessage) {
  const Status s;
  EXPECT_TRUE(s.ok());
  EXPECT_EQ(s.code, StatusCode::Ok);
  EXPECT_STREQ(s.message(), "");
  EXPECT_EQ(s.toString(), "ok");
}

TEST(Status, WarningIsOkAndKeepsItsMessage) {
  const Status s = Status::warning("flags ignored");
  EXPECT_TRUE(s.ok());
  EXPECT_EQ(s.toString(), "warning: flags ignored");
}

TEST(Status, MessageIsTheStaticTextAndToStringAddsTheDetail) {
  const char* text = "ray direction is not a unit vector";
  const Status s = Status::invalid(text).withLength(1.5f);
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(s.message(), text);  // the same pointer: nothing was copied
  EXPECT_EQ(s.detail(), Status::Detail::Length);
  EXPECT_FLOAT_EQ(s.value(), 1.5f);
  EXPECT_EQ(s.toString(), "invalid argument: ray direction is not a unit vector (length 1.5)");
  EXPECT_EQ(s.detailedMessage(), "ray direction is not a unit vector (length 1.5)");
}

TEST(Status, EachDetailKindIsFormatted) {
  EXPECT_EQ(Status::invalid("bad triangle").withIndex(12).toString(), "invalid argument: bad triangle (index 12)");
  EXPECT_EQ(Status::invalid("bad pose").withNorm(2.0f).toString(), "invalid argument: bad pose (norm 2)");
  EXPECT_EQ(Status::notConverged("GJK stopped").withIterations(64, 0.25f).toString(),
            "not converged: GJK stopped (after 64 iterations, error bound 0.25)");
  EXPECT_EQ(Status::unsupported("no such query").withType(GeometryType::HeightField).toString(),
            std::string("unsupported: no such query (") + toString(GeometryType::HeightField) + ")");
  EXPECT_EQ(Status::unsupported("no such pair").withTypes(GeometryType::Plane, GeometryType::TriangleMesh).toString(),
            std::string("unsupported: no such pair (") + toString(GeometryType::Plane) + " and " +
                toString(GeometryType::TriangleMesh) + ")");
  const Status custom = Status::aboutCustom(StatusCode::InternalError, CustomIssue::BadDistance, "ball");
  EXPECT_EQ(custom.detail(), Status::Detail::CustomName);
  EXPECT_NE(std::string(custom.message()).find("distance"), std::string::npos);
  EXPECT_NE(custom.toString().find("custom geometry 'ball'"), std::string::npos) << custom.toString();
}

TEST(Status, WithCodeKeepsMessageAndDetail) {
  const Status s = Status::notConverged("EPA stopped").withIterations(10, 0.5f).withCode(StatusCode::Warning);
  EXPECT_TRUE(s.ok());
  EXPECT_EQ(s.toString(), "warning: EPA stopped (after 10 iterations, error bound 0.5)");
}

TEST(Status, OwnedMessageIsSharedByCopiesAndSurvivesTheOriginal) {
  std::string path = "/no/such/file.obj";
  std::vector<Status> copies;
  {
    const Status s = Status::owned(StatusCode::FileError, "cannot open mesh file '" + path + "'");
    EXPECT_EQ(s.detail(), Status::Detail::Owned);
    for (int i = 0; i < 3; ++i) copies.push_back(s);
    EXPECT_EQ(copies[0].message(), s.message());  // one text, shared
  }
  path.clear();
  for (const Status& c : copies) EXPECT_EQ(c.toString(), "file error: cannot open mesh file '/no/such/file.obj'");
  Status moved = std::move(copies[0]);
  EXPECT_EQ(moved.toString(), "file error: cannot open mesh file '/no/such/file.obj'");
  copies[1] = moved;
  copies[2] = Status();
  moved = Status::invalid("static again");
  EXPECT_EQ(copies[1].code, StatusCode::FileError);
  EXPECT_STREQ(copies[1].message(), "cannot open mesh file '/no/such/file.obj'");
  EXPECT_EQ(moved.toString(), "invalid argument: static again");
}

TEST(Status, DetailsDoNotReplaceAnOwnedText) {
  const Status s = Status::owned(StatusCode::ParseError, std::string("line 3: bad number")).withIndex(7);
  EXPECT_EQ(s.toString(), "parse error: line 3: bad number");
}

TEST(Status, QueryRejectionNamesTheFieldAndTheNumber) {
  DistanceResult<double> r;
  const Geometry<double> sphere = SphereGeometry<double>(1.0);
  Transform<double> bad;
  bad.q = Quat<double>(2.0, 0.0, 0.0, 0.0);
  const Status s = distance(r, sphere, Transform<double>(), sphere, bad);
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_STREQ(s.message(), "pose1 rotation is not a unit quaternion");
  EXPECT_EQ(s.toString(), "invalid argument: pose1 rotation is not a unit quaternion (norm 2)");
}

TEST(Status, UnsupportedPairNamesBothTypes) {
  bool overlapping = false;
  const Status s = overlap(Geometry<double>(PlaneGeometry<double>()), Transform<double>(),
                           Geometry<double>(PlaneGeometry<double>()), Transform<double>(), overlapping);
  EXPECT_EQ(s.code, StatusCode::Unsupported);
  EXPECT_NE(std::string(s.message()).find("not defined by the spec"), std::string::npos) << s.message();
  const std::string plane = toString(GeometryType::Plane);
  EXPECT_NE(s.toString().find("(" + plane + " and " + plane + ")"), std::string::npos) << s.toString();
}

}  // namespace
}  // namespace gq
