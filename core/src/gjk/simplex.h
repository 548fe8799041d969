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

// The sub-simplex supporting the closest point: indices into the simplex, weights (in the indices' order) and the
// closest point. The solver's own candidate type: chooseOnSimplex returns it without a conversion.
template <class T> struct SimplexChoice {
  std::array<std::uint32_t, 4> index = {0, 0, 0, 0};
  std::array<T, 4> lambda = {T(1), T(0), T(0), T(0)};
  std::uint32_t count = 1;
  Vec3<T> v = Vec3<T>::Zero();
  bool containsOrigin = false;
};

// Finds the closest sub-simplex and leaves `s` as it is (GJK keeps the simplex for a step that does not progress).
template <class T> SimplexChoice<T> chooseOnSimplex(const GjkSimplex<T>& s);
// Reduces `s` to the chosen sub-simplex.
template <class T> void reduceSimplex(GjkSimplex<T>& s, const SimplexChoice<T>& choice);
// Both: reduces `s` to the sub-simplex supporting the closest point and returns it with its weights.
template <class T> SimplexClosest<T> closestOnSimplex(GjkSimplex<T>& s);

// a- and b-witnesses of the closest point: sum of lambda_i * a_i (resp. b_i).
template <class T> void simplexWitnesses(const GjkSimplex<T>& s, const std::array<T, 4>& lambda, Vec3<T>& a, Vec3<T>& b);

}  // namespace gq::detail
