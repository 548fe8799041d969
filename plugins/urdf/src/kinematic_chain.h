#pragma once
// Forward kinematics compiled for repeated checks, shared by gq's and the FCL reference checker. Links joined by
// fixed joints form one rigid body: only bodies (the root and the children of moving joints) are placed per
// configuration, each link keeps a constant pose in its body, and every fixed product is multiplied out once.
// A revolute body's frame is its link frame turned so that the joint axis is its Z axis (x_link = B x_body,
// B z = axis), which makes every joint a turn about Z:
//   R_child = (R_parent * G) * Rz(t),  G = (parent link in its body) * origin * B,  p_child = R_parent * o + p_parent.
// When G is a signed permutation (URDF origins of quarter turns and joint axes along coordinate axes: Panda, UR5),
// R_parent * G only moves columns; Rz(t) mixes two of them. Bodies without shapes below them are not placed.
#include <array>
#include <cstdint>
#include <vector>

#include "gq/urdf/robot.h"

namespace gq::urdf::internal {

template <class T> class KinematicChain {
 public:
  explicit KinematicChain(const RobotModel<T>& model);

  // Places every needed body (x_root = rotations[b] * x_body + positions[b]; both sized bodyCount()); the same
  // InvalidArgument statuses as forwardKinematics, nothing written on failure. Immutable: shareable by threads.
  Status place(const std::vector<T>& q, std::vector<Mat3<T>>& rotations, std::vector<Vec3<T>>& positions) const;

  std::uint32_t bodyOf(std::uint32_t link) const { return linkBody_[link]; }
  // Constant pose of a link in its body's frame.
  const Transform<T>& linkInBody(std::uint32_t link) const { return linkInBody_[link]; }
  std::size_t bodyCount() const { return bodyCount_; }

 private:
  enum class Motion : std::uint8_t { Revolute, Prismatic };
  // One moving joint: places body `child` from body `parent`.
  struct Step {
    Motion motion = Motion::Revolute;
    std::uint32_t parent = 0, child = 0;
    std::uint32_t variable = 0;          // configuration index driving the joint
    T multiplier = T(1), offset = T(0);  // joint value = multiplier * q[variable] + offset (mimic; else 1, 0)
    bool permutation = false;            // G is the signed permutation (column[i] = sign[i] * e_{from[i]})
    std::array<std::uint8_t, 3> from{0, 1, 2};
    Vec3<T> sign = Vec3<T>::Ones();
    Mat3<T> g = Mat3<T>::Identity();
    Vec3<T> o = Vec3<T>::Zero();  // joint origin in the parent body frame
    int originAxis = -1;          // o = o[k] e_k (one nonzero coordinate, most URDF origins): R_parent o is a column
    Vec3<T> d = Vec3<T>::Zero();  // prismatic: the axis in the parent body frame
  };

  // R_parent * G.
  static Mat3<T> turnByOrigin(const Mat3<T>& parent, const Step& s);
  // R_parent * G * Rz(t), written into child (not aliasing parent).
  static void turnAboutZ(const Mat3<T>& parent, const Step& s, T c, T sn, Mat3<T>& child);
  bool valuesWithinLimits(const std::vector<T>& q) const;

  const RobotModel<T>* model_;
  std::vector<Step> steps_;
  std::size_t bodyCount_ = 0;
  std::vector<std::uint32_t> linkBody_;
  std::vector<Transform<T>> linkInBody_;
  std::vector<T> lowest_, highest_;  // per variable, limits with the rounding slack (continuous: the finite range)
};

}  // namespace gq::urdf::internal
