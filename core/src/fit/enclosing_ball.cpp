// Smallest enclosing balls (Welzl 1991, in the move-to-front form of Gaertner 1999): points that fall outside the
// ball of the current support set are moved to the front and added to the support, at most D + 1 deep. The ball
// through a support set is the one centred in the set's affine hull (a small Gram system). The final radius is the
// largest distance of a point from the centre, so rounding never leaves a point outside.
#include <Eigen/Dense>

#include <list>

#include "fit/fit_internal.h"

namespace gq::fit {
namespace {

template <int D> struct Miniball {
  using V = Eigen::Matrix<double, D, 1>;
  std::list<V> points;
  V centre = V::Zero();
  double radius2 = -1;
  std::vector<V> support;

  // The smallest ball with every support point on its boundary (centre in their affine hull).
  void ballOfSupport() {
    if (support.empty()) {
      radius2 = -1;
      return;
    }
    const V& p0 = support[0];
    const int m = int(support.size()) - 1;
    if (m == 0) {
      centre = p0;
      radius2 = 0;
      return;
    }
    Eigen::MatrixXd a(D, m);
    Eigen::VectorXd rhs(m);
    for (int j = 0; j < m; ++j) {
      a.col(j) = support[j + 1] - p0;
      rhs[j] = 0.5 * a.col(j).squaredNorm();
    }
    const Eigen::MatrixXd gram = a.transpose() * a;
    const Eigen::VectorXd lambda = gram.completeOrthogonalDecomposition().solve(rhs);
    centre = p0 + a * lambda;
    radius2 = 0;
    for (const V& s : support) radius2 = std::max(radius2, (s - centre).squaredNorm());
  }

  void moveToFront(typename std::list<V>::iterator end) {
    ballOfSupport();
    if (int(support.size()) == D + 1) return;
    for (auto it = points.begin(); it != end;) {
      auto next = std::next(it);
      if ((*it - centre).squaredNorm() > radius2 * (1 + 1e-12) || radius2 < 0) {
        support.push_back(*it);
        moveToFront(it);
        support.pop_back();
        if (it != points.begin()) points.splice(points.begin(), points, it);
      }
      it = next;
    }
  }
};

template <int D>
void enclosing(const std::vector<Eigen::Matrix<double, D, 1>>& pts, Eigen::Matrix<double, D, 1>& centre,
               double& radius) {
  Miniball<D> mb;
  mb.points.assign(pts.begin(), pts.end());
  mb.moveToFront(mb.points.end());
  centre = mb.centre;
  radius = 0;
  for (const auto& p : pts) radius = std::max(radius, (p - centre).norm());
}

}  // namespace

void enclosingCircle(const std::vector<Eigen::Vector2d>& pts, Eigen::Vector2d& centre, double& radius) {
  enclosing<2>(pts, centre, radius);
}

void enclosingSphere(const std::vector<Vec3d>& pts, Vec3d& centre, double& radius) {
  enclosing<3>(pts, centre, radius);
}

Mat3d principalAxes(const std::vector<Vec3d>& pts) {
  Vec3d mean = Vec3d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= double(pts.size());
  Mat3d cov = Mat3d::Zero();
  for (const auto& p : pts) cov += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Mat3d> eig(cov);
  Mat3d r;
  for (int i = 0; i < 3; ++i) r.col(i) = eig.eigenvectors().col(2 - i);  // eigenvalues come in increasing order
  if (r.determinant() < 0) r.col(2) = -r.col(2);
  return r;
}

}  // namespace gq::fit
