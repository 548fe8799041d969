// Clipping an incident feature to a reference face (contact_features.h): Sutherland-Hodgman against the face's edge
// planes, or four axis-aligned half planes for a box face (gq/kernels/clip.h's clipToRectangle).
#include <algorithm>
#include <utility>

#include "contacts/contact_features.h"

namespace gq::kernels {

template <class T>
int clipToRectangle(RectanglePoint<T>* in, RectanglePoint<T>* scratch, int count, int capacity, T hx, T hy,
                    RectanglePoint<T>*& result) {
  RectanglePoint<T>* out = scratch;
  const T limits[2] = {hx, hy};
  for (int e = 0; e < 4 && count > 0; ++e) {
    const int axis = e >> 1;
    const T sign = (e & 1) ? T(-1) : T(1), limit = limits[axis];
    int n = 0;
    for (int i = 0; i < count; ++i) {
      const int next = i + 1 == count ? 0 : i + 1;
      const T da = sign * in[i].c[axis] - limit, db = sign * in[next].c[axis] - limit;
      if (da <= 0 && n < capacity) out[n++] = in[i];
      const bool crosses = (da < 0 && db > 0) || (da > 0 && db < 0);
      if (crosses && n < capacity && (count > 2 || i == 0)) {
        const T t = da / (da - db);
        RectanglePoint<T> q;
        for (int k = 0; k < 3; ++k) q.c[k] = in[i].c[k] + (in[next].c[k] - in[i].c[k]) * t;
        out[n++] = q;
      }
    }
    std::swap(in, out);
    count = n;
  }
  result = in;
  return count;
}

template int clipToRectangle<float>(RectanglePoint<float>*, RectanglePoint<float>*, int, int, float, float,
                                    RectanglePoint<float>*&);
template int clipToRectangle<double>(RectanglePoint<double>*, RectanglePoint<double>*, int, int, double, double,
                                     RectanglePoint<double>*&);

}  // namespace gq::kernels

namespace gq::detail {

namespace {

// A box face: each incident point as (x, y, height over the face) in the face's own frame, clipped to four
// axis-aligned half planes (a quarter of the work of the general polygon's cross products and dot products per edge).
template <class T> int clipToBoxFace(const Feature<T>& reference, Feature<T>& incident) {
  std::array<FacePoint<T>, kMaxFeaturePoints> bufferA, bufferB;
  for (int i = 0; i < incident.count; ++i) {
    const Vec3<T> d = incident.points[i] - reference.centre;
    bufferA[i] = FacePoint<T>{{d.dot(reference.u), d.dot(reference.w), d.dot(reference.normal)}};
  }
  FacePoint<T>* in = nullptr;
  const int count = clipToRectangle(bufferA.data(), bufferB.data(), incident.count, kMaxFeaturePoints, reference.hu,
                                    reference.hw, in);
  for (int i = 0; i < count; ++i)
    incident.points[i] =
        reference.centre + reference.u * in[i].c[0] + reference.w * in[i].c[1] + reference.normal * in[i].c[2];
  incident.count = count;
  return count;
}

}  // namespace

template <class T> int clipToFace(const Feature<T>& reference, Feature<T>& incident) {
  if (reference.unbounded) return incident.count;
  if (reference.rectangle) return clipToBoxFace(reference, incident);
  Vec3<T> centroid = Vec3<T>::Zero();
  for (int i = 0; i < reference.count; ++i) centroid += reference.points[i];
  centroid /= T(reference.count);
  // Two buffers swapped per edge and each point's side distance taken once (copying the clipped polygon back and
  // measuring every point twice cost more than the clipping).
  std::array<Vec3<T>, kMaxFeaturePoints> buffer;
  std::array<T, kMaxFeaturePoints> d;
  Vec3<T>* in = incident.points.data();
  Vec3<T>* out = buffer.data();
  int count = incident.count;
  for (int e = 0; e < reference.count && count > 0; ++e) {
    const Vec3<T>& p0 = reference.points[e];
    const Vec3<T>& p1 = reference.points[e + 1 == reference.count ? 0 : e + 1];
    Vec3<T> side = (p1 - p0).cross(reference.normal);
    if (side.dot(centroid - p0) > 0) side = -side;  // outward, whatever the winding
    // Keep the part of the incident polygon with side . (x - p0) <= 0.
    for (int i = 0; i < count; ++i) d[i] = side.dot(in[i] - p0);
    int n = 0;
    for (int i = 0; i < count; ++i) {
      const int next = i + 1 == count ? 0 : i + 1;
      const Vec3<T>& a = in[i];
      const T da = d[i], db = d[next];
      if (da <= 0 && n < kMaxFeaturePoints) out[n++] = a;
      const bool crosses = (da < 0 && db > 0) || (da > 0 && db < 0);
      if (crosses && n < kMaxFeaturePoints && (count > 2 || i == 0)) out[n++] = a + (in[next] - a) * (da / (da - db));
    }
    std::swap(in, out);
    count = n;
  }
  if (in != incident.points.data()) std::copy(in, in + count, incident.points.data());
  incident.count = count;
  return count;
}

template int clipToFace<float>(const Feature<float>&, Feature<float>&);
template int clipToFace<double>(const Feature<double>&, Feature<double>&);

}  // namespace gq::detail
