#pragma once
// A cheap, conservative proof that one of a box's face axes separates it from a mesh triangle, read straight from the
// triangle's mesh-space vertices (no world triangle is built). The exact box-triangle test (overlapBoxTriangle) asks
// these three axes first, on the world triangle brought into the box's frame; here the same box-frame coordinates come
// from one matrix, y = A v + t (A = R^T L, t = R^T (p - c): box rotation R and centre c, mesh linear map L and
// position p). A triangle counts as separated only when all three vertices lie beyond a face by more than a guard, a
// relative epsilon of every magnitude in either computation (far above their rounding), so the exact test answers
// "separated" for every triangle this one rejects: the pair's boolean is unchanged. The same test on a BVH node's box
// (its centre against the face, less its projected radius) skips whole subtrees: a box's own axes cull far more of a
// rotated mesh than the axis-aligned box test alone (measured on boxes against the rotated bunny).
#include <algorithm>

#include "gq/geometry.h"
#include "gq/math.h"
#include "gq/tolerances.h"
#include "gq/transform.h"

namespace gq::detail {

template <class T> class BoxFaceCull {
 public:
  // meshBox: the mesh's local (cooked) bounds, bounding |v|.
  BoxFaceCull(const BoxGeometry<T>& box, const Transform<T>& pose, const Mat3<T>& meshToWorld, const Vec3<T>& meshPosition,
              const Bounds3<T>& meshBox) {
    const Mat3<T> rt = pose.q.toRotationMatrix().transpose();
    a_ = rt * meshToWorld;
    t_ = rt * (meshPosition - pose.p);
    const T vertexMax = std::max(meshBox.min.cwiseAbs().maxCoeff(), meshBox.max.cwiseAbs().maxCoeff());
    const T scale = std::max({box.halfExtents.maxCoeff(), meshPosition.cwiseAbs().maxCoeff() + pose.p.cwiseAbs().maxCoeff() +
                                                           meshToWorld.cwiseAbs().rowwise().sum().maxCoeff() * vertexMax});
    limit_ = box.halfExtents.array() + T(tol::Rel<T>::kEpsilon) * scale;
    absA_ = a_.cwiseAbs();
  }

  // Whether a box face axis separates the mesh-space box `b` (a BVH node's) by more than the guard: its centre's
  // box-frame coordinate lies beyond the face by more than the node's projected radius |A| extents.
  bool separatesBox(const Bounds3<T>& b) const {
    const Vec3<T> y = a_ * b.center() + t_;
    const Vec3<T> r = absA_ * b.extents();
    return ((y.cwiseAbs() - r).array() > limit_.array()).any();
  }

  // Whether a box face axis separates the triangle of mesh-space vertices v[0..2] by more than the guard.
  bool separates(const Vec3<T>* v) const {
    for (int k = 0; k < 3; ++k) {
      const T y0 = a_.row(k).dot(v[0]) + t_[k];
      const T y1 = a_.row(k).dot(v[1]) + t_[k];
      const T y2 = a_.row(k).dot(v[2]) + t_[k];
      if ((y0 > limit_[k] && y1 > limit_[k] && y2 > limit_[k]) ||
          (y0 < -limit_[k] && y1 < -limit_[k] && y2 < -limit_[k]))
        return true;
    }
    return false;
  }

 private:
  Mat3<T> a_, absA_;
  Vec3<T> t_;
  Vec3<T> limit_;  // half extents plus the guard
};

}  // namespace gq::detail
