#pragma once
// Exact answers computed independently of gq and FCL, in long double:
//  - support extents (closed forms) decide every pair with a Halfspace or Plane;
//  - sphere/capsule pairs by segment-segment distance; sphere-box by clamping; point-triangle (Ericson's regions)
//    for spheres against convex polytopes, triangles and meshes;
//  - polytope pairs (Box, Convex, TriangleP, Mesh triangles) by the separating-axis theorem over face normals and
//    all edge-edge cross products.
// `known` is false for pairs without an exact reference here (curved against curved or polytope, capsule-polytope).
#include "fcl_scenes.h"

namespace gq::fcltest {

struct ExactAnswer {
  bool known = false;
  bool colliding = false;
  long double distance = 0;   // signed (negative: penetration depth) where distanceKnown
  bool distanceKnown = false;
};

ExactAnswer exactAnswer(const TestShape& a, const ::fcl::Transform3d& pa, const TestShape& b, const ::fcl::Transform3d& pb);

// Separation certificate: min over b of n.x minus max over a of n.x along the world direction n (from a to b), with
// closed-form supports. A positive value proves the shapes disjoint (a separating plane), and bounds their distance
// from below; it equals the distance when n is the direction between the closest points.
long double certifiedGap(const TestShape& a, const ::fcl::Transform3d& pa, const TestShape& b, const ::fcl::Transform3d& pb,
                         const ::fcl::Vector3d& n);

// Exact penetration depth (minimum translation) where a closed form is known: sphere/capsule pairs (radii minus the
// segment distance) and polytope pairs Box/Convex (SAT: the least overlap over face normals and edge-edge axes).
// False for other pairs or when the shapes do not overlap.
bool exactDepth(const TestShape& a, const ::fcl::Transform3d& pa, const TestShape& b, const ::fcl::Transform3d& pb,
                long double& depth);

// A sphere's contact with one triangle (index into mesh.faces) of a mesh: the triangle's point nearest the centre
// and the depth r - its distance (negative: apart).
void exactSphereTriangleContact(const TestShape& sphere, const ::fcl::Transform3d& ps, const TestShape& mesh,
                                const ::fcl::Transform3d& pm, int triangle, ::fcl::Vector3d& nearest,
                                long double& depth);

}  // namespace gq::fcltest
