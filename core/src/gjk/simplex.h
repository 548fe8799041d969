#pragma once
// Closest point of a GJK simplex (1 to 4 support points) to the origin, by signed volumes (after Montanari,
// Petrinic, Barbieri 2017): every sub-simplex is tried through its barycentric coordinates and the closest one
// that contains its projection of the origin wins. The simplex is reduced to that sub-simplex.
#include "gjk/gjk.h"

namespace gq::detail {

template <class T> struct SimplexClosest {
  Vec3<T> v = Vec3<T>::Zero();                            // closest point of the simplex to the origin
  std::array<T, 4> lambda = {T(1), T(0), T(0), T(0)};     // barycentric weights of the reduced simplex
  bool containsOrigin = false;                            // a full tetrahedron with the origin inside
};

// Reduces `s` to the sub-simplex supporting the closest point and returns it with its weights.
template <class T> SimplexClosest<T> closestOnSimplex(GjkSimplex<T>& s);

// a- and b-witnesses of the closest point: sum of lambda_i * a_i (resp. b_i).
template <class T> void simplexWitnesses(const GjkSimplex<T>& s, const std::array<T, 4>& lambda, Vec3<T>& a, Vec3<T>& b);

}  // namespace gq::detail
