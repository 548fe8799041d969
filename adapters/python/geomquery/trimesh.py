"""trimesh's ray and proximity queries on gq: replace ``mesh.ray`` / ``trimesh.proximity`` by changing one import.

``RayMeshIntersector(mesh)`` and ``ProximityQuery(mesh)`` take any object with ``vertices`` (n, 3) and ``faces``
(m, 3) arrays (a ``trimesh.Trimesh`` qualifies) and keep trimesh's signatures, return shapes and dtypes (float64
points and distances, int64 indices, bool masks). The mesh is cooked once (a BVH in gq) and the cooked mesh is
cached by content: intersectors and proximity queries of the same vertices and faces share it.

Conventions kept from trimesh: directions need not be unit (they are normalised); rays are half-lines from their
origins; ``intersects_first`` answers -1 on a miss; ``signed_distance`` is positive inside the mesh.
"""

import collections
import hashlib
import threading

import numpy as np

from . import _geomquery as _gq

__all__ = ["RayMeshIntersector", "ProximityQuery", "cooked_mesh"]

_CACHE_SIZE = 8
_cache = collections.OrderedDict()
_cache_lock = threading.Lock()

# A direction no axis-aligned or diagonal face of a typical mesh contains: the inside test casts along it.
_INSIDE_DIRECTION = np.array([0.5773502691896258, 0.5773502691896258, 0.5773502691896257]) + np.array(
    [0.0123, -0.0078, 0.0031]
)
_INSIDE_DIRECTION /= np.linalg.norm(_INSIDE_DIRECTION)


class _Cooked:
    """A mesh cooked once: the gq TriangleMesh, a one-instance scene for multi-hit rays, face normals."""

    def __init__(self, vertices, faces):
        self.vertices = vertices
        self.faces = faces
        self.mesh = _gq.TriangleMesh(vertices, faces)
        self._scene = None
        self._normals = None
        self._lock = threading.Lock()
        lo, hi = vertices.min(axis=0), vertices.max(axis=0)
        self.center = (lo + hi) * 0.5
        self.radius = float(np.linalg.norm(hi - lo)) * 0.5

    @property
    def scene(self):
        with self._lock:
            if self._scene is None:
                scene = _gq.Scene()
                scene.add(0, self.mesh)
                self._scene = scene
            return self._scene

    @property
    def face_normals(self):
        with self._lock:
            if self._normals is None:
                tri = self.vertices[self.faces]
                n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
                length = np.linalg.norm(n, axis=1)
                length[length == 0] = 1.0
                self._normals = n / length[:, None]
            return self._normals


def _mesh_arrays(mesh):
    try:
        vertices = mesh.vertices
        faces = mesh.faces
    except AttributeError:
        raise TypeError("expected a mesh with `vertices` (n, 3) and `faces` (m, 3) arrays") from None
    vertices = np.ascontiguousarray(vertices, dtype=np.float64)
    faces = np.asarray(faces)
    if faces.size and faces.dtype.kind not in "iu":
        raise TypeError("faces: dtype must be an integer type, not %s" % faces.dtype)
    faces = np.ascontiguousarray(faces, dtype=np.int64)
    if vertices.ndim != 2 or vertices.shape[1] != 3:
        raise ValueError("vertices: expected shape (n, 3), got %s" % (vertices.shape,))
    if faces.ndim != 2 or faces.shape[1] != 3:
        raise ValueError("faces: expected shape (m, 3), got %s" % (faces.shape,))
    if len(faces) == 0:
        raise ValueError("the mesh has no faces")
    return vertices, faces


def cooked_mesh(mesh):
    """The cooked gq mesh of ``mesh`` (cached by the content of its vertices and faces)."""
    vertices, faces = _mesh_arrays(mesh)
    key = hashlib.blake2b(vertices.tobytes() + b"|" + faces.tobytes(), digest_size=20).digest()
    with _cache_lock:
        cooked = _cache.get(key)
        if cooked is not None:
            _cache.move_to_end(key)
            return cooked
    cooked = _Cooked(vertices, faces)
    with _cache_lock:
        _cache[key] = cooked
        while len(_cache) > _CACHE_SIZE:
            _cache.popitem(last=False)
    return cooked


def _float64_rows(array):
    """``array`` as float64 rows gq reads in place (a contiguous last axis, rows stored forward): no copy when it
    already is one, e.g. a C-ordered float64 array or a row-strided view of one."""
    array = np.asarray(array, dtype=np.float64)
    if array.ndim == 2 and not (array.strides[1] == 8 and array.strides[0] > 0 and array.flags.aligned):
        array = np.ascontiguousarray(array)
    return array


def _rays(ray_origins, ray_directions):
    """Origins and directions as float64 (n, 3) rows; the directions are normalised by the batch (normalize=True),
    which raises ValueError for a zero-length one."""
    origins = _float64_rows(ray_origins)
    directions = _float64_rows(ray_directions)
    if origins.ndim != 2 or origins.shape[1] != 3:
        raise ValueError("ray_origins: expected shape (n, 3), got %s" % (origins.shape,))
    if directions.shape != origins.shape:
        raise ValueError("ray_directions: expected shape %s, got %s" % (origins.shape, directions.shape))
    return origins, directions


class RayMeshIntersector:
    """trimesh.ray.ray_triangle.RayMeshIntersector's API, answered by gq's mesh BVH (in parallel, without the GIL)."""

    def __init__(self, mesh):
        self.mesh = mesh
        self._cooked = None

    @property
    def _gq(self):
        if self._cooked is None:
            self._cooked = cooked_mesh(self.mesh)
        return self._cooked

    def intersects_first(self, ray_origins, ray_directions, **kwargs):
        """Index of the first triangle each ray hits, -1 on a miss: (n,) int64."""
        origins, directions = _rays(ray_origins, ray_directions)
        return _gq.raycast_batch_faces(origins, directions, self._gq.mesh, None, float("inf"), True, 0, True)

    def intersects_any(self, ray_origins, ray_directions, **kwargs):
        """Whether each ray hits the mesh: (n,) bool."""
        return self.intersects_first(ray_origins, ray_directions) >= 0

    def intersects_id(
        self, ray_origins, ray_directions, multiple_hits=True, max_hits=20, return_locations=False, **kwargs
    ):
        """(index_tri, index_ray[, locations]): every hit (up to max_hits a ray), or each ray's first hit."""
        origins, directions = _rays(ray_origins, ray_directions)
        cooked = self._gq
        if not multiple_hits or max_hits == 1:
            hit, distance, position, _, face = _gq.raycast_batch(origins, directions, cooked.mesh, None,
                                                                  float("inf"), True, 0, True)
            index_ray = np.nonzero(hit)[0].astype(np.int64)
            index_tri = face[index_ray]
            locations = position[index_ray]
        else:
            index_ray, _, _, locations, index_tri = cooked.scene.raycast_all_batch(
                origins, directions, float("inf"), int(max_hits), True, normalize=True
            )
        if return_locations:
            return index_tri, index_ray, locations
        return index_tri, index_ray

    def intersects_location(self, ray_origins, ray_directions, multiple_hits=True, **kwargs):
        """(locations (m, 3), index_ray (m,), index_tri (m,))."""
        index_tri, index_ray, locations = self.intersects_id(
            ray_origins, ray_directions, multiple_hits=multiple_hits, return_locations=True, **kwargs
        )
        return locations, index_ray, index_tri

    def contains_points(self, points):
        """Whether each point is inside the (watertight) mesh: (n,) bool."""
        return _contains(self._gq, points)


def _contains(cooked, points):
    pts = np.ascontiguousarray(points, dtype=np.float64)
    if pts.ndim != 2 or pts.shape[1] != 3:
        raise ValueError("points: expected shape (n, 3), got %s" % (pts.shape,))
    directions = np.broadcast_to(_INSIDE_DIRECTION, pts.shape)
    # The first surface a ray from inside a closed mesh meets faces away from the ray (its outward normal points
    # along the ray).
    face = _gq.raycast_batch_faces(pts, np.ascontiguousarray(directions), cooked.mesh, None, float("inf"), True)
    inside = np.zeros(len(pts), dtype=bool)
    hit = face >= 0
    inside[hit] = cooked.face_normals[face[hit]] @ _INSIDE_DIRECTION > 0
    return inside


class ProximityQuery:
    """trimesh.proximity.ProximityQuery's API on gq's point-mesh distance (in parallel, without the GIL)."""

    def __init__(self, mesh):
        self._mesh = mesh
        self._cooked = None

    @property
    def _gq(self):
        if self._cooked is None:
            self._cooked = cooked_mesh(self._mesh)
        return self._cooked

    def on_surface(self, points):
        """(closest (m, 3), distance (m,), triangle_id (m,)): the nearest point of the surface to each point."""
        pts = np.ascontiguousarray(points, dtype=np.float64)
        if pts.ndim != 2 or pts.shape[1] != 3:
            raise ValueError("points: expected shape (m, 3), got %s" % (pts.shape,))
        distance, closest, triangle = _gq.point_distance_batch(pts, self._gq.mesh)
        return closest, distance, triangle

    def vertex(self, points):
        """(distance (m,), vertex_id (m,)): the nearest vertex to each point."""
        pts = np.ascontiguousarray(points, dtype=np.float64)
        vertices = self._gq.vertices
        d2 = ((pts[:, None, :] - vertices[None, :, :]) ** 2).sum(axis=2) if len(pts) * len(vertices) < 2e7 else None
        if d2 is None:
            ids = np.array([np.argmin(((vertices - p) ** 2).sum(axis=1)) for p in pts], dtype=np.int64)
        else:
            ids = np.argmin(d2, axis=1).astype(np.int64)
        return np.linalg.norm(vertices[ids] - pts, axis=1), ids

    def signed_distance(self, points):
        """(m,) distance to the surface, positive inside the mesh (trimesh's sign)."""
        _, distance, _ = self.on_surface(points)
        inside = _contains(self._gq, points)
        distance = distance.copy()
        distance[~inside] *= -1.0
        return distance


def signed_distance(mesh, points):
    """trimesh.proximity.signed_distance: positive inside."""
    return ProximityQuery(mesh).signed_distance(points)


def closest_point(mesh, points):
    """trimesh.proximity.closest_point: (closest, distance, triangle_id)."""
    return ProximityQuery(mesh).on_surface(points)
