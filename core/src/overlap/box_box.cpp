// Box/box overlap: the 15-axis separating-axis test (overlap/box_box_sat.h); touching counts as overlapping.
#include "overlap/box_box_sat.h"
#include "overlap/overlap.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers
namespace {

template <class T> bool noSeparatingAxis(const BoxPair<T>& pair) {
  bool separated = false;
  forEachBoxAxis(pair, [&](const BoxAxis<T>& axis) { return separated = axis.overlap < T(0); });
  return !separated;
}

}  // namespace

template <class T>
bool overlapBoxBox(const BoxGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1) {
  return noSeparatingAxis(boxPair(g0, p0, g1, p1));
}

template <class T> bool overlapBoxBox(const Vec3<T>& h0, const Vec3<T>& h1, const Mat3<T>& r01, const Vec3<T>& t01) {
  return noSeparatingAxis(boxPair(h0, h1, r01, t01));
}

template bool overlapBoxBox<float>(const BoxGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&);
template bool overlapBoxBox<double>(const BoxGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&);
template bool overlapBoxBox<float>(const Vec3<float>&, const Vec3<float>&, const Mat3<float>&, const Vec3<float>&);
template bool overlapBoxBox<double>(const Vec3<double>&, const Vec3<double>&, const Mat3<double>&, const Vec3<double>&);

}  // namespace gq::kernels
