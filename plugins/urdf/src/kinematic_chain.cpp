// Compiled forward kinematics (kinematic_chain.h): rigid bodies, constant products multiplied out once, one
// sin/cos pair and a two-column mix per revolute joint.
#include "kinematic_chain.h"

#include <cmath>
#include <limits>

#include "internal.h"
#include "sincos.h"

namespace gq::urdf::internal {
namespace {

// Entries this close to 0 or +-1 (a few ulps: quarter turns written as 1.5708 rad in text and rounded through
// rpy -> quaternion -> matrix) count as exact in a signed permutation.
template <class T> constexpr T kUnitEntryTolerance = T(16) * std::numeric_limits<T>::epsilon();

// A rotation B with B * z = axis: a signed permutation for coordinate axes, else any orthonormal completion.
template <class T> Mat3<T> axisToZFrame(const Vec3<T>& axis) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;  // (e_i, e_j, e_k) is right-handed
    if (std::abs(std::abs(axis[k]) - T(1)) > kUnitEntryTolerance<T> || std::abs(axis[i]) > kUnitEntryTolerance<T> ||
        std::abs(axis[j]) > kUnitEntryTolerance<T>)
      continue;
    const T s = axis[k] > 0 ? T(1) : T(-1);      // -e_k: turn the frame half about e_i
    Mat3<T> b = Mat3<T>::Zero();
    b(i, 0) = T(1);
    b(j, 1) = s;
    b(k, 2) = s;
    return b;
  }
  const Vec3<T> u = (std::abs(axis.x()) < T(0.9) ? Vec3<T>::UnitX() : Vec3<T>::UnitY()).cross(axis).normalized();
  Mat3<T> b;
  b << u, axis.cross(u), axis;
  return b;
}

// Fills the step's permutation form when g is a signed permutation.
template <class T, class Step> void detectSignedPermutation(const Mat3<T>& g, Step& s) {
  for (int c = 0; c < 3; ++c) {
    int row = -1;
    for (int r = 0; r < 3; ++r) {
      if (std::abs(std::abs(g(r, c)) - T(1)) <= kUnitEntryTolerance<T>) row = r;
      else if (std::abs(g(r, c)) > kUnitEntryTolerance<T>) return;
    }
    if (row < 0) return;
    s.from[std::size_t(c)] = std::uint8_t(row);
    s.sign[c] = g(row, c) > 0 ? T(1) : T(-1);
  }
  s.permutation = true;
}

}  // namespace

template <class T> KinematicChain<T>::KinematicChain(const RobotModel<T>& model) : model_(&model) {
  const std::size_t links = model.links.size();
  linkBody_.assign(links, 0);
  linkInBody_.assign(links, Transform<T>());
  std::vector<Step> all;
  std::uint32_t bodies = 1;  // body 0: the root link
  for (const Joint<T>& j : model.joints) {
    const Transform<T> origin = linkInBody_[j.parentLink] * j.origin;  // joint frame in the parent body
    if (j.type == JointType::Fixed) {
      linkBody_[j.childLink] = linkBody_[j.parentLink];
      linkInBody_[j.childLink] = origin;
      continue;
    }
    Step s;
    s.parent = linkBody_[j.parentLink];
    s.child = bodies++;
    linkBody_[j.childLink] = s.child;
    s.variable = std::uint32_t(j.mimicJoint >= 0 ? model.joints[std::size_t(j.mimicJoint)].variable : j.variable);
    if (j.mimicJoint >= 0) {
      s.multiplier = j.multiplier;
      s.offset = j.offset;
    }
    const Mat3<T> r = origin.q.toRotationMatrix();
    s.o = origin.p;
    if ((s.o.array() != T(0)).count() == 1) s.o.cwiseAbs().maxCoeff(&s.originAxis);
    if (j.type == JointType::Prismatic) {
      s.motion = Motion::Prismatic;
      s.g = r;
      s.d = r * j.axis;
    } else {
      const Mat3<T> b = axisToZFrame(j.axis);
      s.g = r * b;
      linkInBody_[j.childLink] = Transform<T>(Vec3<T>::Zero(), Quat<T>(Mat3<T>(b.transpose())));
    }
    detectSignedPermutation(s.g, s);
    all.push_back(s);
  }
  // A body is needed when it or a body below it carries shapes; steps come parents first, so one reverse pass.
  std::vector<std::uint8_t> needed(bodies, 0);
  for (std::size_t l = 0; l < links; ++l)
    if (!model.links[l].shapes.empty()) needed[linkBody_[l]] = 1;
  for (auto it = all.rbegin(); it != all.rend(); ++it)
    if (needed[it->child]) needed[it->parent] = 1;
  for (const Step& s : all)
    if (needed[s.child]) steps_.push_back(s);
  bodyCount_ = bodies;
  // The accepted range of each variable, as checkConfiguration decides it.
  const T huge = std::numeric_limits<T>::max();
  lowest_.assign(model.variables.size(), -huge);
  highest_.assign(model.variables.size(), huge);
  for (const Joint<T>& j : model.joints) {
    if (j.variable < 0 || j.type == JointType::Continuous) continue;
    const T slack = limitSlack(j);
    lowest_[std::size_t(j.variable)] = j.lower - slack;
    highest_[std::size_t(j.variable)] = j.upper + slack;
  }
}

// The comparisons fail for NaN, and +-inf lies outside every range: equivalent to checkConfiguration's acceptance.
template <class T> bool KinematicChain<T>::valuesWithinLimits(const std::vector<T>& q) const {
  if (q.size() != lowest_.size()) return false;
  bool ok = true;
  for (std::size_t i = 0; i < q.size(); ++i) ok &= (q[i] >= lowest_[i]) & (q[i] <= highest_[i]);
  return ok;
}

template <class T> inline Mat3<T> KinematicChain<T>::turnByOrigin(const Mat3<T>& parent, const Step& s) {
  if (!s.permutation) return parent * s.g;
  Mat3<T> m;
  for (int c = 0; c < 3; ++c) m.col(c) = s.sign[c] * parent.col(s.from[std::size_t(c)]);
  return m;
}

// child = R_parent * G * Rz(t): columns c m0 + s m1, c m1 - s m0, m2 of m = R_parent * G; for a signed
// permutation G the columns of m are signed columns of R_parent, read directly.
template <class T>
inline void KinematicChain<T>::turnAboutZ(const Mat3<T>& parent, const Step& s, T c, T sn, Mat3<T>& child) {
  if (!s.permutation) {
    const Mat3<T> m = parent * s.g;
    child.col(0) = c * m.col(0) + sn * m.col(1);
    child.col(1) = c * m.col(1) - sn * m.col(0);
    child.col(2) = m.col(2);
    return;
  }
  const auto m0 = parent.col(s.from[0]), m1 = parent.col(s.from[1]);
  const T c0 = c * s.sign[0], s1 = sn * s.sign[1], c1 = c * s.sign[1], s0 = sn * s.sign[0];
  child.col(0) = c0 * m0 + s1 * m1;
  child.col(1) = c1 * m1 - s0 * m0;
  child.col(2) = s.sign[2] * parent.col(s.from[2]);
}

// Bodies that are not needed keep whatever the caller's buffers held.
template <class T>
Status KinematicChain<T>::place(const std::vector<T>& q, std::vector<Mat3<T>>& rotations,
                                std::vector<Vec3<T>>& positions) const {
  if (!valuesWithinLimits(q))
    if (Status s = checkConfiguration(*model_, q); !s.ok()) return s;
  rotations.resize(bodyCount_, Mat3<T>::Identity());
  positions.resize(bodyCount_, Vec3<T>::Zero());
  rotations[0].setIdentity();
  positions[0].setZero();
  for (const Step& s : steps_) {
    const Mat3<T>& parent = rotations[s.parent];
    const T value = s.multiplier * q[s.variable] + s.offset;
    Mat3<T>& child = rotations[s.child];
    if (s.motion == Motion::Revolute) {
      double sine, cosine;
      sinCos(double(value), sine, cosine);
      turnAboutZ(parent, s, T(cosine), T(sine), child);
      if (s.originAxis >= 0) positions[s.child].noalias() = s.o[s.originAxis] * parent.col(s.originAxis);
      else positions[s.child].noalias() = parent * s.o;
    } else {
      child = turnByOrigin(parent, s);
      positions[s.child].noalias() = parent * (s.o + value * s.d);
    }
    positions[s.child] += positions[s.parent];
  }
  return {};
}

template class KinematicChain<float>;
template class KinematicChain<double>;

}  // namespace gq::urdf::internal
