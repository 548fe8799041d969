"""Robot self-collision from URDF (+ SRDF) on gq::urdf.

``Robot(urdf, srdf=None, mode="hull", package_paths=())``: ``mode`` says how mesh links are modelled (mesh, hull,
box, box-aabb, capsule, sphere, best-primitive); box, sphere and cylinder elements stay exact. ``check(q)`` says
whether configuration q (one value per ``variables`` entry) collides, ``colliding_pairs(q)`` names the link pairs,
``check_batch(Q)`` answers an (N, dof) array in parallel without the GIL (each answer is ``check``'s), and
``self_distance(q)`` returns (signed distance, (link_a, link_b), point_a, point_b).
"""

from ._geomquery import Robot  # noqa: F401

__all__ = ["Robot"]
