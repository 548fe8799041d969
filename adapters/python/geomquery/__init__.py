"""GeomQuery: geometry queries (raycast, sweep, overlap, penetration, distance) for numpy, in float32 and float64.

Geometries (Sphere, Capsule, Box, Plane, ConvexMesh, TriangleMesh, HeightField, Cylinder, Cone, Ellipsoid,
CustomShape) are validated once when made; their dtype is chosen by their inputs (arrays) or by ``dtype=``
(float64 by default). Poses are ``Pose(position, quaternion)`` with the quaternion in (x, y, z, w) order, ``None``
(identity) or 7 numbers ``(px, py, pz, qx, qy, qz, qw)``; batched forms take (N, 7) arrays in that order.

Errors raise: ``ValueError`` for invalid input (the message is gq's), ``TypeError`` for wrong or mixed dtypes,
``UnsupportedError`` (a ``NotImplementedError``) for pairs gq does not answer.
"""

from ._geomquery import (  # noqa: F401
    BatchScratch,
    Box,
    Capsule,
    Cone,
    ConvexMesh,
    CustomShape,
    Cylinder,
    DistanceResult,
    Ellipsoid,
    Geometry,
    HeightField,
    NotConvergedError,
    Penetration,
    Plane,
    Pose,
    RaycastHit,
    Scene,
    Sphere,
    SweepHit,
    TriangleContact,
    TriangleMesh,
    UnsupportedError,
    bounds,
    distance,
    distance_batch,
    find_overlapping_triangles,
    get_triangle,
    mesh_penetration,
    mesh_triangle_pairs,
    overlap,
    overlap_batch,
    penetration,
    penetration_batch,
    point_distance,
    point_distance_batch,
    raycast,
    raycast_batch,
    raycast_batch_faces,
    sweep,
    sweep_triangles,
    triangle_contacts,
)

__all__ = [name for name in dir() if not name.startswith("_")]
