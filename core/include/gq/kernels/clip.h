#pragma once
// Clipping a polygon to a rectangle, written once: the contact sets' incident faces clipped to a box face
// (core's generateContacts) and FCL's box-box contact sets (the FCL adapter).
namespace gq::kernels {

// A point in a rectangle's frame: (c[0], c[1]) in its plane, c[2] a value interpolated along (the height over it).
template <class T> struct RectanglePoint {
  T c[3];
};

// Sutherland-Hodgman: the polygon in[0, count) (or a segment, or a point) clipped to |c[0]| <= hx, |c[1]| <= hy, the
// two buffers (`capacity` points each) swapped per side. Returns the count left; `result` points at them. A convex
// polygon of n corners keeps at most n + 4.
template <class T>
int clipToRectangle(RectanglePoint<T>* in, RectanglePoint<T>* scratch, int count, int capacity, T hx, T hy,
                    RectanglePoint<T>*& result);

}  // namespace gq::kernels
