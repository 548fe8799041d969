// Reducing a contact polygon to the few points that span it (contact_features.h).
#include "contacts/contact_features.h"

namespace gq::detail {

// The deepest point, the one farthest from it, the farthest from their line on each side (signed area), then the
// deepest of the others up to maxKeep. A solver holding four points gets the largest quadrilateral of the polygon
// whose first corner carries the exact depth.
template <class T>
int reduceContactPoints(const Vec3<T>* p, const T* separation, int count, const Vec3<T>& n, int maxKeep, int* keep) {
  if (count <= maxKeep) {
    for (int i = 0; i < count; ++i) keep[i] = i;
    return count;
  }
  std::array<bool, kMaxFeaturePoints> taken{};
  int k = 0;
  const auto take = [&](int i) {
    if (i >= 0 && k < maxKeep && !taken[i]) taken[i] = true, keep[k++] = i;
  };
  int first = 0;
  for (int i = 1; i < count; ++i)
    if (separation[i] < separation[first]) first = i;
  take(first);
  int second = first == 0 ? 1 : 0;
  for (int i = 0; i < count; ++i)
    if ((p[i] - p[first]).squaredNorm() > (p[second] - p[first]).squaredNorm()) second = i;
  take(second);
  const Vec3<T> edge = p[second] - p[first];
  int third = -1, fourth = -1;
  T most = 0, least = 0;
  for (int i = 0; i < count; ++i) {
    const T a = edge.cross(p[i] - p[first]).dot(n);  // signed area x 2
    if (a > most) most = a, third = i;
    if (a < least) least = a, fourth = i;
  }
  take(third);
  take(fourth);
  while (k < maxKeep) {
    int next = -1;
    for (int i = 0; i < count; ++i)
      if (!taken[i] && (next < 0 || separation[i] < separation[next])) next = i;
    if (next < 0) break;
    take(next);
  }
  return k;
}

template int reduceContactPoints<float>(const Vec3<float>*, const float*, int, const Vec3<float>&, int, int*);
template int reduceContactPoints<double>(const Vec3<double>*, const double*, int, const Vec3<double>&, int, int*);

}  // namespace gq::detail
